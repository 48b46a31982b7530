"""physai-lint: static analysis for ROS 2 launch files and parameter YAML."""

__version__ = "0.1.0"
