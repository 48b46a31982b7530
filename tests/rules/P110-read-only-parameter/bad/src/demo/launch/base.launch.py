from launch import LaunchDescription
from launch.actions import ExecuteProcess, RegisterEventHandler, TimerAction
from launch.event_handlers import OnProcessStart
from launch_ros.actions import Node


def generate_launch_description():
    driver = Node(package='demo', executable='wheel_driver', name='wheel_driver')
    imu = Node(package='demo', executable='imu_node', name='imu', namespace='sensors')
    set_radius = ExecuteProcess(
        cmd=['ros2', 'param', 'set', '/wheel_driver', 'wheel_radius', '0.05'])
    set_frame = ExecuteProcess(cmd=['ros2 param set sensors/imu frame_id imu_top'], shell=True)
    return LaunchDescription([
        driver,
        imu,
        RegisterEventHandler(OnProcessStart(target_action=driver, on_start=[set_radius])),
        TimerAction(period=2.0, actions=[set_frame]),
    ])
