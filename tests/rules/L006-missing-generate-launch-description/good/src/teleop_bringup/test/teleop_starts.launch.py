# A launch_testing file: `launch_test` loads generate_test_description, not generate_launch_description.
import unittest

import launch_testing
import launch_testing.actions
from launch import LaunchDescription
from launch_ros.actions import Node


def generate_test_description():
    return LaunchDescription([
        Node(package="teleop_twist_joy", executable="teleop_node", name="teleop"),
        launch_testing.actions.ReadyToTest(),
    ])


class TestTeleopStarts(unittest.TestCase):
    def test_started(self, proc_output):
        pass
