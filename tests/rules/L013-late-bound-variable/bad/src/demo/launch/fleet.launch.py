from launch import LaunchDescription
from launch.actions import LogInfo, OpaqueFunction, RegisterEventHandler
from launch.event_handlers import OnProcessExit
from launch_ros.actions import Node

ROBOTS = ['alpha', 'beta']


def robot(context, name):
    return [Node(package='turtlesim', executable='turtlesim_node', name='sim', namespace=name)]


def generate_launch_description():
    ld = LaunchDescription()
    for name in ROBOTS:
        ld.add_action(OpaqueFunction(function=lambda context: robot(context, name)))
    for ns in ROBOTS:
        watched = Node(package='turtlesim', executable='turtlesim_node', name='watched', namespace=ns)
        ld.add_action(watched)

        def done(event, context):
            return [LogInfo(msg='turtle of ' + ns + ' exited')]

        ld.add_action(RegisterEventHandler(OnProcessExit(target_action=watched, on_exit=done)))
    return ld
