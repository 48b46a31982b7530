"""What a file is from its text (physai_lint/sniff.py): the frontend ros2 launch would load it with."""
from __future__ import annotations

import pytest

from physai_lint.sniff import launch_format


@pytest.mark.parametrize("path, text, fmt", [
    ("a.launch.py", "<launch/>", "python"),  # the extension decides, whatever the text
    ("a.LAUNCH.XML", "x = 1", "xml"),
    ("a.yml", "", "yaml"),
    ("a.launch", "\ufeff  <?xml version='1.0'?>\n<launch/>", "xml"),
    ("a.launch", "# comment\nlaunch:\n- log: {message: hi}\n", "yaml"),
    ("a.launch", '"launch":\n- log: {message: hi}\n', "yaml"),
    ("a.launch", "launcher: 1\n", "python"),  # not the key "launch": no frontend takes it
    ("dir.d/launch", "from launch import LaunchDescription\n", "python"),  # a dot in a folder is no extension
    ("a.launch", "launch: int = 1\ndef generate_launch_description(): ...\n", "python"),
    ("a.launch", None, None),  # unknown until read
])
def test_launch_format(path, text, fmt):
    assert launch_format(path, text) == fmt
