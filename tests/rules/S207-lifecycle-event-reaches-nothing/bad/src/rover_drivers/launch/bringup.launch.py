import lifecycle_msgs.msg
from launch import LaunchDescription
from launch.actions import EmitEvent
from launch.events import matches_action
from launch_ros.actions import LifecycleNode, Node
from launch_ros.events.lifecycle import ChangeState
from launch_ros.events.matchers import matches_node_name


def generate_launch_description():
    # the map server runs in the 'maps' namespace: its full name is /maps/map_server
    maps = LifecycleNode(package='nav2_map_server', executable='map_server', name='map_server',
                         namespace='maps', parameters=[{'yaml_filename': '/srv/maps/floor1.yaml'}])
    # a plain Node never receives ChangeState events
    imu = Node(package='imu_complementary_filter', executable='complementary_filter_node',
               name='imu_filter')
    return LaunchDescription([
        maps,
        imu,
        EmitEvent(event=ChangeState(
            lifecycle_node_matcher=matches_node_name('map_server'),
            transition_id=lifecycle_msgs.msg.Transition.TRANSITION_CONFIGURE)),
        EmitEvent(event=ChangeState(
            lifecycle_node_matcher=matches_action(imu),
            transition_id=lifecycle_msgs.msg.Transition.TRANSITION_CONFIGURE)),
    ])
