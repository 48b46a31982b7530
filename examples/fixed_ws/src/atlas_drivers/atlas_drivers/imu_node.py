"""Serial driver for the Atlas base IMU (on-board fusion, publishes orientation directly)."""
import math

import rclpy
from rclpy.node import Node
from sensor_msgs.msg import Imu


class ImuNode(Node):

    def __init__(self):
        super().__init__('imu_node')
        self.port = self.declare_parameter('port', '/dev/ttyUSB1').value
        self.baud_rate = self.declare_parameter('baud_rate', 115200).value
        self.frame_id = self.declare_parameter('frame_id', 'imu_link').value
        rate = self.declare_parameter('rate', 100.0).value
        self.publisher = self.create_publisher(Imu, 'data', 10)
        self.timer = self.create_timer(1.0 / rate, self.poll)

    def poll(self):
        msg = Imu()
        msg.header.stamp = self.get_clock().now().to_msg()
        msg.header.frame_id = self.frame_id
        # The serial protocol is not part of this example; publish a level, resting IMU.
        msg.orientation.w = 1.0
        msg.linear_acceleration.z = 9.80665
        msg.orientation_covariance[0] = math.radians(1.0) ** 2
        self.publisher.publish(msg)


def main(args=None):
    rclpy.init(args=args)
    node = ImuNode()
    try:
        rclpy.spin(node)
    except KeyboardInterrupt:
        pass
    finally:
        node.destroy_node()
        rclpy.try_shutdown()


if __name__ == '__main__':
    main()
