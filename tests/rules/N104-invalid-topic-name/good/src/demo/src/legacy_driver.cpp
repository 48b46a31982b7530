#include <memory>
#include "rclcpp/rclcpp.hpp"

int main(int argc, char ** argv) {
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<rclcpp::Node>("legacy_driver"));
  rclcpp::shutdown();
}
