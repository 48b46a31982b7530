"""Generic walks over the model's dataclasses: the leaf types they hold no model object in, and
each dataclass type's field names, looked up once per type (``dataclasses.fields`` per object was
half the cost of such walks)."""
from __future__ import annotations

import dataclasses
from typing import Any

ATOMS = frozenset({str, int, float, bool, bytes, type(None)})
# Fields that hold source positions, never a model object a walk looks for.
POSITION_FIELDS = frozenset({"span", "name_span", "field_spans"})
_NAMES: dict[type, tuple[str, ...]] = {}


def field_names(kind: type) -> tuple[str, ...]:
    """The field names of a dataclass type, in order; ``()`` for any other type."""
    names = _NAMES.get(kind)
    if names is None:
        names = _NAMES[kind] = tuple(f.name for f in dataclasses.fields(kind)) \
            if dataclasses.is_dataclass(kind) else ()
    return names


def objects(root: Any) -> list[Any]:
    """Every model object in ``root`` (an object, or tuples and lists of them), depth first in
    field order; atoms and positions left out."""
    out: list[Any] = []
    stack: list[tuple[Any, int]] = [(root, 0)]
    pop, push = stack.pop, stack.append
    while stack:
        obj, depth = pop()
        if depth > 60 or type(obj) in ATOMS:
            continue
        if isinstance(obj, (tuple, list)):
            for item in reversed(obj):
                push((item, depth + 1))
            continue
        out.append(obj)
        names = field_names(type(obj))
        for name in reversed(names):
            if name not in POSITION_FIELDS:
                push((getattr(obj, name), depth + 1))
    return out
