from launch import LaunchDescription
from launch.actions import ExecuteProcess, RegisterEventHandler
from launch.event_handlers import OnProcessStart
from launch_ros.actions import Node


def generate_launch_description():
    # Read-only parameters are given at start-up; only writable ones are changed later.
    driver = Node(package='demo', executable='wheel_driver', name='wheel_driver',
                  parameters=[{'wheel_radius': 0.05}])
    imu = Node(package='demo', executable='imu_node', name='imu', namespace='sensors',
               parameters=[{'frame_id': 'imu_top'}])
    set_rpm = ExecuteProcess(cmd=['ros2', 'param', 'set', '/wheel_driver', 'max_rpm', '120.0'])
    set_rate = ExecuteProcess(cmd=['ros2', 'param', 'set', '/sensors/imu', 'rate', '50.0'])
    return LaunchDescription([
        driver,
        imu,
        RegisterEventHandler(OnProcessStart(target_action=driver, on_start=[set_rpm, set_rate])),
    ])
