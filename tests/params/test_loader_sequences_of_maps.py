"""A mapping inside a sequence: rcl (parse_file_events) has no test for it, so one mapping whose
keys hold lists works (ros2_control's gpio_controllers configuration) and the rest is mangled."""
from __future__ import annotations

from physai_lint.params.loader import load_param_file

GPIO = """gpio_controller:
  ros__parameters:
    command_interfaces:
      flange_analog_IOs:
        - interfaces:
          - analog_output1
      flange_vacuum:
        - interfaces: [vacuum]
"""


def test_one_mapping_of_lists_in_a_sequence_is_what_rcl_reads() -> None:
    m = load_param_file("/w/c.yaml", GPIO)
    assert not m.diagnostics and m.ok
    got = {p.name: p.value for b in m.blocks for p in b.params}
    assert got == {"command_interfaces.flange_analog_IOs.interfaces": ["analog_output1"],
                   "command_interfaces.flange_vacuum.interfaces": ["vacuum"]}


def test_scalar_values_and_second_mappings_are_structure_errors() -> None:
    scalar = load_param_file("/w/a.yaml", "n:\n  ros__parameters:\n    a:\n      - x: 1\n")
    second = load_param_file("/w/b.yaml", "n:\n  ros__parameters:\n    a:\n      - x: [1]\n      - y: [2]\n")
    mixed = load_param_file("/w/c.yaml", "n:\n  ros__parameters:\n    a:\n      - 1\n      - x: [1]\n")
    for m, line in ((scalar, 4), (second, 5), (mixed, 5)):
        assert [(d.code, d.span.line) for d in m.diagnostics] == [("P104", line)]
