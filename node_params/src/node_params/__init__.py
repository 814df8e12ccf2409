"""A node's private parameters, read once into a typed config object.

roslaunch and rosparam do not hand a node the types it wants. ``<param value="...">`` and
``name:=value`` on a launch command line turn text into an int only when it has no ``.``,
into a float only when it has one, into a bool only for ``true``/``false``; the rest stays
text. So ``real_time_factor:=1e9`` and ``:=nan`` arrive as the strings ``'1e9'`` and
``'nan'``, ``seed:=abc`` as ``'abc'``, ``paused:=maybe`` as ``'maybe'`` (which Python
finds true). A node that uses such a value as it comes dies with a traceback, or worse,
goes on with it.

Declare the parameters as a dataclass whose fields say what each one is::

    @dataclass(frozen=True)
    class Config:
        rate: float = parameter(50.0, positive, expected="a positive rate in Hz")
        seed: int = parameter(0, non_negative, expected="a whole number >= 0")

    config = read(Config)        # rospy.get_param("~rate", 50.0) ... converted and checked

The field's annotation is its type (``float``, ``int``, ``bool``, ``str``, ``List[T]``,
``Dict``, ``Optional[T]``, ``Any``). What the reader accepts for each:

- ``float``: ints and floats, and text that reads as one (``'1e9'``, ``' 0.5 '``); NaN and
  infinity only when the field says ``allow_nonfinite=True``;
- ``int``: ints, integral floats (``2.0``) and text that reads as either (``'1e3'``);
- ``bool``: booleans, 0 and 1, and the text true/false/yes/no/on/off/1/0 in any case;
  anything else (``'maybe'``) is refused rather than guessed;
- ``str``: text, and numbers (which roslaunch made of text) as their text;
- ``List[T]``: a list or tuple, or YAML text of one (``'[1, 2]'``), each item as ``T``.

Booleans are never numbers here (``True`` is not a rate). A value that cannot be used
raises :class:`ParameterError` (a ValueError) whose text names the parameter, the value as
it was given (its repr) and what is expected::

    ~real_time_factor: 'abc' is not a number; expected 0 (as fast as it can) or ...

Where the value comes from, in order: ``overrides`` (e.g. a command line), the parameter
source (``rospy.get_param`` under ``prefix``, or a mapping), ``defaults`` (e.g. a package's
yaml), the field's default. Wrap a value in :class:`Given` to name it by its own source
(``Given('abc', 'gzserver --seed')``).
"""
from __future__ import annotations

import dataclasses
import math
import typing
from dataclasses import dataclass
from typing import Any, Callable, Dict, Mapping, Optional, Tuple, Union

import yaml

__all__ = ["ParameterError", "Check", "Given", "parameter", "read", "convert",
           "positive", "non_negative", "non_empty", "at_least", "at_most", "between",
           "one_of", "zero_or_at_least", "given_from"]

# The key under which a field's metadata holds its Spec.
METADATA_KEY = "node_params"

# Text accepted for booleans (lower case), as YAML 1.1 and roslaunch read them.
TRUE_WORDS = frozenset({"true", "yes", "on", "1"})
FALSE_WORDS = frozenset({"false", "no", "off", "0"})

# What get_param returns for an unset name (rospy hands the default back as it is).
_UNSET = object()


class ParameterError(ValueError):
    """A parameter that cannot be used: its name (``label``), the value as given, what is
    wrong with it and what is expected."""

    def __init__(self, label: str, given: Any, problem: str, expected: str):
        self.label, self.given, self.problem, self.expected = label, given, problem, expected
        if given is _UNSET:
            text = f"{label} {problem}; expected {expected}"
        else:
            text = f"{label}: {given!r} {problem}; expected {expected}"
        super().__init__(text)


@dataclass(frozen=True)
class Check:
    """A condition on a converted value; ``problem`` describes a value that fails it,
    after the value's repr ("is not positive")."""

    test: Callable[[Any], bool]
    problem: str

    def fails(self, value: Any) -> Optional[str]:
        return None if self.test(value) else self.problem


positive = Check(lambda value: value > 0, "is not positive")
non_negative = Check(lambda value: value >= 0, "is negative")
non_empty = Check(lambda value: len(value) > 0, "is empty")


def _shown(bound: float) -> str:
    """A bound as written: whole numbers in full (4294967295, not 4.29497e+09)."""
    return str(bound) if isinstance(bound, int) else f"{bound:g}"


def at_least(low: float) -> Check:
    return Check(lambda value: value >= low, f"is less than {_shown(low)}")


def at_most(high: float) -> Check:
    return Check(lambda value: value <= high, f"is more than {_shown(high)}")


def between(low: float, high: float) -> Check:
    return Check(lambda value: low <= value <= high, f"is not between {_shown(low)} and {_shown(high)}")


def zero_or_at_least(low: float) -> Check:
    """0 (which usually means "off" or "no limit"), or ``low`` and more."""
    return Check(lambda value: value == 0 or value >= low,
                 f"is neither 0 nor at least {_shown(low)}")


def one_of(*choices: Any) -> Check:
    listed = ", ".join(repr(choice) for choice in choices)
    return Check(lambda value: value in choices, f"is not one of {listed}")


@dataclass(frozen=True)
class Spec:
    """What a field's metadata holds: what is expected (one line, with units) and the
    checks its converted value must pass."""

    expected: str
    checks: Tuple[Check, ...] = ()
    allow_nonfinite: bool = False


@dataclass(frozen=True)
class Given:
    """A value with the name to give it in messages (where it came from)."""

    value: Any
    label: str


def parameter(default: Any = dataclasses.MISSING, *checks: Check, expected: str,
              allow_nonfinite: bool = False,
              default_factory: Any = dataclasses.MISSING) -> Any:
    """A dataclass field that :func:`read` fills from a parameter of the field's name.
    No default (and no default_factory): the parameter must be set."""
    if not expected:
        raise TypeError("parameter(): say what is expected (one line, with units)")
    return dataclasses.field(default=default, default_factory=default_factory,
                             metadata={METADATA_KEY: Spec(expected, checks, allow_nonfinite)})


# --- conversion ---------------------------------------------------------------------------

class _Refused(Exception):
    """Conversion failed: ``problem`` says why (the caller adds name and expectation);
    ``label`` and ``given`` are set when a list item failed."""

    def __init__(self, problem: str, label: Optional[str] = None, given: Any = _UNSET):
        super().__init__(problem)
        self.problem, self.label, self.given = problem, label, given


def _number_text(value: str) -> Optional[float]:
    try:
        return float(value.strip())
    except ValueError:
        return None


def _to_float(value: Any, allow_nonfinite: bool) -> float:
    if isinstance(value, bool):
        raise _Refused("is a boolean, not a number")
    if isinstance(value, (int, float)):
        number = float(value)
    elif isinstance(value, str) and _number_text(value) is not None:
        number = _number_text(value)
    else:
        raise _Refused("is not a number")
    if not allow_nonfinite and not math.isfinite(number):
        raise _Refused("is not a finite number")
    return number


def _to_int(value: Any) -> int:
    if isinstance(value, bool):
        raise _Refused("is a boolean, not a whole number")
    if isinstance(value, int):
        return value
    if isinstance(value, str):
        text = value.strip()
        try:
            return int(text)
        except ValueError:
            value = _number_text(text)
            if value is None:
                raise _Refused("is not a whole number") from None
    if isinstance(value, float) and math.isfinite(value) and value.is_integer():
        return int(value)
    raise _Refused("is not a whole number")


def _to_bool(value: Any) -> bool:
    if isinstance(value, bool):
        return value
    if isinstance(value, int) and value in (0, 1):
        return bool(value)
    if isinstance(value, str):
        word = value.strip().lower()
        if word in TRUE_WORDS:
            return True
        if word in FALSE_WORDS:
            return False
    raise _Refused("is not true or false")


def _to_str(value: Any) -> str:
    if isinstance(value, str):
        return value
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return str(value)  # roslaunch made a number of the text; give the text back
    raise _Refused("is not text")


def _to_list(value: Any, item_type: Any, label: str, allow_nonfinite: bool) -> list:
    if isinstance(value, str):  # <param value="[1, 2]"> arrives as text
        try:
            value = yaml.safe_load(value)
        except yaml.YAMLError:
            raise _Refused("is not a list") from None
    if not isinstance(value, (list, tuple)):
        raise _Refused("is not a list")
    items = []
    for index, item in enumerate(value):
        try:
            items.append(_convert(item_type, item, f"{label}[{index}]", allow_nonfinite))
        except _Refused as refused:
            if refused.label is None:
                refused.label, refused.given = f"{label}[{index}]", item
            raise
    return items


def _convert(kind: Any, value: Any, label: str, allow_nonfinite: bool) -> Any:
    origin, arguments = typing.get_origin(kind), typing.get_args(kind)
    if origin is Union:  # Optional[T]
        if value is None and type(None) in arguments:
            return None
        others = [argument for argument in arguments if argument is not type(None)]
        if len(others) != 1:
            raise TypeError(f"{label}: node_params reads Optional[T], not {kind}")
        return _convert(others[0], value, label, allow_nonfinite)
    if kind is Any:
        return value
    if kind is float:
        return _to_float(value, allow_nonfinite)
    if kind is bool:
        return _to_bool(value)
    if kind is int:
        return _to_int(value)
    if kind is str:
        return _to_str(value)
    if kind is list or origin is list:
        return _to_list(value, arguments[0] if arguments else Any, label, allow_nonfinite)
    if kind is dict or origin is dict:
        if not isinstance(value, dict):
            raise _Refused("is not a mapping")
        return dict(value)
    raise TypeError(f"{label}: node_params cannot read parameters of type {kind}")


def convert(kind: Any, value: Any, label: str, expected: str,
            checks: Tuple[Check, ...] = (), allow_nonfinite: bool = False) -> Any:
    """One value as ``kind`` (float, int, bool, str, List[T], ...), checked; a
    :class:`ParameterError` naming ``label`` and ``value`` when it cannot be used."""
    try:
        converted = _convert(kind, value, label, allow_nonfinite)
    except _Refused as refused:
        raise ParameterError(refused.label or label,
                             value if refused.given is _UNSET else refused.given,
                             refused.problem, expected) from None
    for check in checks if converted is not None else ():  # None: an Optional left out
        problem = check.fails(converted)
        if problem:
            raise ParameterError(label, value, problem, expected)
    return converted


# --- reading a config class ---------------------------------------------------------------

def _getter(source: Union[None, Mapping, Callable[[str, Any], Any]], prefix: str):
    if source is None:
        import rospy  # only here: the rest of the module needs no ROS
        return rospy.get_param
    if isinstance(source, Mapping):
        return lambda name, default: source.get(name[len(prefix):], default)
    return source


def specs(cls) -> Dict[str, Tuple[Any, Spec]]:
    """Every parameter a config class declares: name -> (type, Spec). TypeError for a
    field that does not say what it expects (every field of a config class is a
    parameter, so that none is read without a check)."""
    hints = typing.get_type_hints(cls)
    found = {}
    for field in dataclasses.fields(cls):
        if not field.init:
            continue
        spec = field.metadata.get(METADATA_KEY)
        if spec is None:
            raise TypeError(f"{cls.__name__}.{field.name} is not declared with "
                            "node_params.parameter()")
        found[field.name] = (hints[field.name], spec)
    return found


def read(cls, source: Union[None, Mapping, Callable[[str, Any], Any]] = None,
         prefix: str = "~", overrides: Optional[Mapping[str, Any]] = None,
         defaults: Optional[Mapping[str, Any]] = None):
    """An instance of the dataclass ``cls`` from its parameters.

    ``source``: ``get_param(name, default)`` (None: ``rospy.get_param``), called with
    ``prefix + field name``; or a mapping of field names to values. ``overrides`` win over
    the source, ``defaults`` lose to it; either may wrap values in :class:`Given`. Unknown
    names in either are a TypeError (a mistake in the caller, not the user's).
    Raises :class:`ParameterError` for the first value that cannot be used."""
    declared = specs(cls)
    for extra in (overrides, defaults):
        unknown = sorted(set(extra or {}) - set(declared))
        if unknown:
            raise TypeError(f"{cls.__name__} has no parameters {unknown}")
    get = _getter(source, prefix)
    fields = {field.name: field for field in dataclasses.fields(cls)}
    values = {}
    for name, (kind, spec) in declared.items():
        label = prefix + name
        if overrides is not None and name in overrides:
            given = overrides[name]
        else:
            given = get(label, _UNSET)
            if given is _UNSET and defaults is not None and name in defaults:
                given = defaults[name]
        if isinstance(given, Given):
            label, given = given.label, given.value
        if given is _UNSET:
            field = fields[name]
            if field.default is dataclasses.MISSING and \
                    field.default_factory is dataclasses.MISSING:
                raise ParameterError(label, _UNSET, "is not set", spec.expected)
            continue  # the dataclass fills in its default
        values[name] = convert(kind, given, label, spec.expected, spec.checks,
                               spec.allow_nonfinite)
    return cls(**values)


def given_from(values: Mapping[str, Any], source: str) -> Dict[str, Given]:
    """``values`` (e.g. a package's yaml of defaults) named ``<source>: <name>`` in
    messages."""
    return {name: Given(value, f"{source}: {name}") for name, value in values.items()}
