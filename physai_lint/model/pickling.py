"""Fast pickling for frozen, slotted dataclasses (the whole model: spans, values, launch IR).

Parse results cross process boundaries (``--jobs`` workers send them back pickled), live in the
disk cache as pickles, and findings come back from forked rule groups pickled. For a class that
is both ``frozen`` and ``slots``, ``dataclasses`` pickles through ``__getstate__`` and
``__setstate__``, which call ``dataclasses.fields()`` once per object: on a real workspace
(~180,000 objects) unpickling the parse results cost the parent process about as much CPU as a
second worker saved. ``__reduce__`` here stores the class and the field values as one flat tuple,
and rebuilds the object the way ``__setstate__`` did (``object.__new__`` and
``object.__setattr__``, no ``__init__``), with the field names computed once per class.
"""
from __future__ import annotations

import dataclasses
import operator
from typing import Any

# per class: its field names, and a function returning their values as a tuple
_SHAPES: dict[type, tuple[tuple[str, ...], Any]] = {}


def _shape(cls: type) -> tuple[tuple[str, ...], Any]:
    shape = _SHAPES.get(cls)
    if shape is None:
        names = tuple(f.name for f in dataclasses.fields(cls))
        get: Any
        if len(names) > 1:
            get = operator.attrgetter(*names)
        elif names:
            one = operator.attrgetter(names[0])

            def get(obj: Any) -> tuple[Any, ...]:
                return (one(obj),)
        else:
            def get(obj: Any) -> tuple[Any, ...]:
                return ()
        shape = _SHAPES[cls] = (names, get)
    return shape


def _rebuild(cls: type, *values: Any) -> Any:
    obj: Any = object.__new__(cls)
    setattr_ = object.__setattr__
    for name, value in zip(_shape(cls)[0], values):
        setattr_(obj, name, value)
    return obj


def _reduce(self: Any) -> tuple[Any, ...]:
    # One flat tuple ``(cls, *values)``: a nested ``(cls, values)`` made pickle memoise a second
    # tuple per object, which doubled the cost of dumping (measured on 200,000 spans: 0.40-0.58 s
    # against 0.26 s) and added a fifth to loading.
    cls = type(self)  # a subclass has its own fields: the shape is looked up per class
    return (_rebuild, (cls, *_shape(cls)[1](self)))


def fast_pickle(cls: type) -> type:
    """Give a frozen, slotted dataclass (and its subclasses) the tuple-based ``__reduce__``."""
    cls.__reduce__ = _reduce  # type: ignore[method-assign,assignment]
    return cls


def fast_pickle_module(namespace: dict[str, Any]) -> None:
    """``fast_pickle`` every frozen, slotted dataclass defined in the module whose globals these
    are (call it at the end of the module)."""
    module = namespace.get("__name__")
    for obj in list(namespace.values()):
        if (isinstance(obj, type) and obj.__module__ == module and dataclasses.is_dataclass(obj)
                and "__slots__" in obj.__dict__ and obj.__dataclass_params__.frozen):  # type: ignore[attr-defined]
            fast_pickle(obj)


def fast_init(cls: type) -> type:
    """Give a frozen, slotted dataclass an ``__init__`` that sets each field through its slot's
    descriptor (``member_descriptor.__set__``), bound once per class, instead of the generated
    ``object.__setattr__(self, 'name', value)`` per field: the same object in about half the
    time. For the classes built hundreds of thousands of times in a run (``Span``: ~260,000 on
    the 1,180-file workspace, parameter-file values, texts). Same signature and defaults; classes
    with a ``default_factory``, a ``__post_init__``, keyword-only or ``init=False`` fields keep
    the generated one (apply it after ``@dataclass``)."""
    params = cls.__dataclass_params__  # type: ignore[attr-defined]
    fields = dataclasses.fields(cls)
    if (not params.frozen or "__slots__" not in cls.__dict__ or hasattr(cls, "__post_init__")
            or any(not f.init or f.kw_only or f.default_factory is not dataclasses.MISSING
                   for f in fields)):
        return cls
    env: dict[str, Any] = {}
    args, body = [], []
    for f in fields:
        slot = next(k.__dict__[f.name] for k in cls.__mro__ if f.name in k.__dict__)
        env[f"_set_{f.name}"] = slot.__set__
        if f.default is dataclasses.MISSING:
            args.append(f.name)
        else:
            env[f"_dflt_{f.name}"] = f.default
            args.append(f"{f.name}=_dflt_{f.name}")
        body.append(f"        _set_{f.name}(__dataclass_self__, {f.name})")
    source = (f"def __make__({', '.join(env)}):\n"
              f"    def __init__(__dataclass_self__, {', '.join(args)}):\n" + "\n".join(body or ["        pass"]) +
              "\n    return __init__\n")
    scope: dict[str, Any] = {}
    exec(source, {}, scope)  # noqa: S102 - our own generated code, like dataclasses' own
    init = scope["__make__"](**env)
    init.__qualname__ = f"{cls.__qualname__}.__init__"
    init.__module__ = cls.__module__
    cls.__init__ = init  # type: ignore[misc]
    return cls
