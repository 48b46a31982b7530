// Last stage before the diff drive controller: clamps velocity commands, stops for close
// obstacles and excessive tilt, and zeroes the command when the input goes stale.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

#include "geometry_msgs/msg/twist.hpp"
#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/imu.hpp"
#include "std_msgs/msg/float32.hpp"

#include "atlas_control/safety_controller_parameters.hpp"

class SafetyController : public rclcpp::Node
{
public:
  SafetyController()
  : Node("safety_controller"),
    param_listener_(std::make_shared<safety_controller::ParamListener>(
        get_node_parameters_interface())),
    params_(param_listener_->get_params()),
    last_command_time_(now())
  {
    cmd_pub_ = create_publisher<geometry_msgs::msg::Twist>("cmd_vel_out", 10);
    cmd_sub_ = create_subscription<geometry_msgs::msg::Twist>(
      "cmd_vel_in", 10,
      [this](geometry_msgs::msg::Twist::ConstSharedPtr msg) {
        last_command_ = *msg;
        last_command_time_ = now();
      });
    imu_sub_ = create_subscription<sensor_msgs::msg::Imu>(
      "imu", rclcpp::SensorDataQoS(),
      [this](sensor_msgs::msg::Imu::ConstSharedPtr msg) {
        const auto & q = msg->orientation;
        tilt_ = std::acos(std::clamp(1.0 - 2.0 * (q.x * q.x + q.y * q.y), -1.0, 1.0));
      });
    obstacle_sub_ = create_subscription<std_msgs::msg::Float32>(
      "obstacle_distance", 10,
      [this](std_msgs::msg::Float32::ConstSharedPtr msg) {obstacle_distance_ = msg->data;});
    timer_ = create_wall_timer(
      std::chrono::milliseconds(1000 / params_.publish_rate), [this]() {publish();});
  }

private:
  void publish()
  {
    params_ = param_listener_->get_params();
    geometry_msgs::msg::Twist out;
    const bool stale = (now() - last_command_time_).seconds() > params_.command_timeout;
    if (!stale && tilt_ < params_.max_tilt) {
      out.linear.x = std::clamp(
        last_command_.linear.x, -params_.max_linear_speed, params_.max_linear_speed);
      out.angular.z = std::clamp(
        last_command_.angular.z, -params_.max_angular_speed, params_.max_angular_speed);
      if (out.linear.x > 0.0 && obstacle_distance_ < params_.stop_distance) {
        out.linear.x = 0.0;
      }
    }
    cmd_pub_->publish(out);
  }

  std::shared_ptr<safety_controller::ParamListener> param_listener_;
  safety_controller::Params params_;
  geometry_msgs::msg::Twist last_command_;
  rclcpp::Time last_command_time_;
  double tilt_{0.0};
  float obstacle_distance_{INFINITY};
  rclcpp::Publisher<geometry_msgs::msg::Twist>::SharedPtr cmd_pub_;
  rclcpp::Subscription<geometry_msgs::msg::Twist>::SharedPtr cmd_sub_;
  rclcpp::Subscription<sensor_msgs::msg::Imu>::SharedPtr imu_sub_;
  rclcpp::Subscription<std_msgs::msg::Float32>::SharedPtr obstacle_sub_;
  rclcpp::TimerBase::SharedPtr timer_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<SafetyController>());
  rclcpp::shutdown();
  return 0;
}
