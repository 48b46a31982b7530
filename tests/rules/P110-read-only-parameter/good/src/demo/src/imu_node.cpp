#include "rclcpp/rclcpp.hpp"

class ImuNode : public rclcpp::Node
{
public:
  ImuNode()
  : Node("imu_node")
  {
    rcl_interfaces::msg::ParameterDescriptor frame_desc;
    frame_desc.read_only = true;
    frame_id_ = declare_parameter("frame_id", std::string("imu_link"), frame_desc);
    rate_ = declare_parameter("rate", 100.0);
  }

private:
  std::string frame_id_;
  double rate_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<ImuNode>());
  rclcpp::shutdown();
  return 0;
}
