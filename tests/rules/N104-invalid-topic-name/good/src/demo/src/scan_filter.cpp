#include <memory>
#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/laser_scan.hpp"

class ScanFilter : public rclcpp::Node {
public:
  ScanFilter() : Node("scan_filter") {
    pub_ = create_publisher<sensor_msgs::msg::LaserScan>("scan_filtered", 10);
    sub_ = create_subscription<sensor_msgs::msg::LaserScan>(
      "scan", 10, [this](sensor_msgs::msg::LaserScan::SharedPtr msg) { pub_->publish(*msg); });
  }
private:
  rclcpp::Publisher<sensor_msgs::msg::LaserScan>::SharedPtr pub_;
  rclcpp::Subscription<sensor_msgs::msg::LaserScan>::SharedPtr sub_;
};

int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<ScanFilter>());
  rclcpp::shutdown();
}
