"""How launch_ros types a substituted parameter value (evaluate_parameter_dict: yaml.safe_load)."""
from __future__ import annotations

import pytest

from physai_lint.resolve.params import yaml_type


@pytest.mark.parametrize("text, value", [
    ("['.*']", [".*"]), ("[a*, b]", ["a*", "b"]), ("['&x']", ["&x"]), ("&a 5", 5),
    ("*", None), ("[&a x, *a]", None), ("5", 5), ("on", True)])
def test_stars_and_ampersands_are_yaml_like_any_text(text: str, value: object) -> None:
    # foxglove_bridge's topic_whitelist default "['.*']" is a string array for launch_ros; only a
    # real alias (which could be a bomb) is left unknown rather than guessed a string
    assert yaml_type(text) == value
