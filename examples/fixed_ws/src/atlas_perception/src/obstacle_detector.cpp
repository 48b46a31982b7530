// Nearest obstacle in front of the robot, from the LiDAR scan, gated by a fresh camera frame.
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "rclcpp_components/register_node_macro.hpp"
#include "sensor_msgs/msg/image.hpp"
#include "sensor_msgs/msg/laser_scan.hpp"
#include "std_msgs/msg/float32.hpp"

namespace atlas_perception
{

class ObstacleDetector : public rclcpp::Node
{
public:
  explicit ObstacleDetector(const rclcpp::NodeOptions & options)
  : Node("obstacle_detector", options)
  {
    min_range_ = declare_parameter("min_range", 0.15);
    max_range_ = declare_parameter("max_range", 8.0);
    roi_angle_ = declare_parameter("roi_angle", 0.6);

    distance_pub_ = create_publisher<std_msgs::msg::Float32>("obstacle_distance", 10);
    image_sub_ = create_subscription<sensor_msgs::msg::Image>(
      "image", rclcpp::SensorDataQoS(),
      [this](sensor_msgs::msg::Image::ConstSharedPtr msg) {last_image_ = msg->header.stamp;});
    scan_sub_ = create_subscription<sensor_msgs::msg::LaserScan>(
      "scan", rclcpp::SensorDataQoS(),
      [this](sensor_msgs::msg::LaserScan::ConstSharedPtr msg) {on_scan(*msg);});
  }

private:
  void on_scan(const sensor_msgs::msg::LaserScan & scan)
  {
    float nearest = std::numeric_limits<float>::infinity();
    for (size_t i = 0; i < scan.ranges.size(); ++i) {
      const double angle = scan.angle_min + static_cast<double>(i) * scan.angle_increment;
      const float r = scan.ranges[i];
      if (std::abs(angle) <= roi_angle_ && r >= min_range_ && r <= max_range_) {
        nearest = std::min(nearest, r);
      }
    }
    std_msgs::msg::Float32 out;
    out.data = nearest;
    distance_pub_->publish(out);
  }

  double min_range_, max_range_, roi_angle_;
  rclcpp::Time last_image_;
  rclcpp::Publisher<std_msgs::msg::Float32>::SharedPtr distance_pub_;
  rclcpp::Subscription<sensor_msgs::msg::Image>::SharedPtr image_sub_;
  rclcpp::Subscription<sensor_msgs::msg::LaserScan>::SharedPtr scan_sub_;
};

}  // namespace atlas_perception

RCLCPP_COMPONENTS_REGISTER_NODE(atlas_perception::ObstacleDetector)
