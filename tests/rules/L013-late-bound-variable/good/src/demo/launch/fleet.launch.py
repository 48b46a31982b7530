from functools import partial

from launch import LaunchDescription
from launch.actions import LogInfo, OpaqueFunction, RegisterEventHandler
from launch.event_handlers import OnProcessExit
from launch_ros.actions import Node

ROBOTS = ['alpha', 'beta']
SPARES = ['gamma', 'delta']


def robot(context, name, suffix=''):
    return [Node(package='turtlesim', executable='turtlesim_node', name='sim' + suffix, namespace=name)]


def spare(name):
    # each call has its own `name`: nothing rebinds it
    return OpaqueFunction(function=lambda context: robot(context, name, '_spare'))


def generate_launch_description():
    ld = LaunchDescription()
    suffix = '_main'
    for name in ROBOTS:
        # bound when made: a default argument, kwargs, a partial
        ld.add_action(OpaqueFunction(function=lambda context, name=name: robot(context, name)))
        ld.add_action(OpaqueFunction(function=robot, kwargs={'name': name, 'suffix': '_kw'}))
        ld.add_action(OpaqueFunction(function=partial(robot, name=name, suffix='_p')))
        # `suffix` is not rebound by the loop
        ld.add_action(OpaqueFunction(function=lambda context, name=name: robot(context, name, suffix)))
    for name in SPARES:
        ld.add_action(spare(name))
    for ns in ROBOTS:
        watched = Node(package='turtlesim', executable='turtlesim_node', name='watched', namespace=ns)
        ld.add_action(watched)
        ld.add_action(RegisterEventHandler(OnProcessExit(
            target_action=watched,
            on_exit=lambda event, context, ns=ns: [LogInfo(msg='turtle of ' + ns + ' exited')])))
    return ld
