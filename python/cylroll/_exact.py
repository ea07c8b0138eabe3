"""Exact inputs: Python numbers to the exact decimal text the library reads."""

from __future__ import annotations

import math
import numbers
from decimal import Decimal
from fractions import Fraction
from typing import Any, Union

from ._errors import InvalidParameterError

#: What a parameter may be: exact text (``"0.3"``, ``"1/3"``, ``"1e-3"``;
#: angles also ``"pi/6"``), an ``int``, a ``Fraction`` or a ``Decimal``; a
#: ``float`` only where it is explicitly allowed.
Number = Union[str, int, Fraction, Decimal, float]


#: Longest echo of a given value in a message (as the library's own messages).
ECHO_MAX = 60


def _shorten(text: str) -> str:
    """``text`` cut to at most :data:`ECHO_MAX` characters with its length
    noted, like the library's messages (shortening twice changes nothing)."""
    if len(text) <= ECHO_MAX:
        return text
    return f"{text[:ECHO_MAX - 30]}... ({len(text)} characters)"


def _invalid(name: str, value: Any, allowed: str) -> InvalidParameterError:
    shown = _shorten(str(value))
    exc = InvalidParameterError(f"invalid {name} = {shown!r}: {allowed}")
    exc._set_fields("invalid_parameter", {"name": name, "value": shown, "allowed": allowed})
    return exc


def _fraction_text(q: Fraction) -> str:
    return str(q.numerator) if q.denominator == 1 else f"{q.numerator}/{q.denominator}"


def exact_text(name: str, x: Any, allow_float: bool = False) -> str:
    """The exact text of ``x`` for parameter ``name``.

    ``str`` passes as it is (the library parses it exactly), ``int``,
    ``Fraction`` and ``Decimal`` are written out exactly. A ``float`` (also a
    NumPy float) is refused unless ``allow_float``: then it is taken as the
    binary number it is (``0.1`` becomes 3602879701896397/36028797018963968,
    not 1/10). ``bool`` is refused.
    """
    if isinstance(x, str):
        return x
    if isinstance(x, bool):
        raise TypeError(f"{name}: expected a number, got a bool")
    if isinstance(x, Fraction):
        return _fraction_text(x)
    if isinstance(x, Decimal):
        if not x.is_finite():
            raise _invalid(name, x, "must be a finite number")
        sign, digits, exp = x.as_tuple()
        if isinstance(exp, int) and -60 <= exp <= 60:
            return format(x, "f")
        if abs(x.adjusted()) <= 100_000:
            # as written (1E-5000): the library reads it exactly and quotes it
            # so, where the fraction would be thousands of digits
            return str(x)
        # beyond the library's exponents (and Fraction would build 10**exp)
        raise _invalid(name, x, "the exponent must be within ±100000")
    if isinstance(x, numbers.Integral):
        n = int(x)
        # str() of an int beyond 4300 digits raises Python's own ValueError;
        # Decimal(n) converts without that limit, exactly
        return format(Decimal(n), "f") if n.bit_length() > 13_000 else str(n)
    if isinstance(x, (float, numbers.Real)):
        f = float(x)
        if not math.isfinite(f):
            # 'nan'/'inf' as text are refused too (except a friction
            # coefficient's 'inf'): no spelling to suggest
            raise _invalid(name, x, "must be a finite number")
        if not allow_float:
            raise TypeError(
                f"{name}: a float ({x!r}) is not exact; pass a str such as {repr(str(x))}, "
                "an int, a Fraction or a Decimal (Model(..., allow_float=True) takes a "
                "float's exact binary value)"
            )
        return _fraction_text(Fraction(f))
    raise TypeError(
        f"{name}: expected str, int, Fraction or Decimal (or float with allow_float=True), "
        f"got {type(x).__name__}"
    )


def shortest_text(x: Any) -> str:
    """The shortest decimal that reads back as the float ``x`` in its own
    type: ``repr`` of a float64 (``0.05``), and a NumPy float32, float16 or
    longdouble by its own shortest round-trip decimal, as it prints and as a
    CSV file written from it carries it (float32 0.1 is ``0.1``, not the
    float64 ``0.10000000149011612``)."""
    import numpy as np

    if isinstance(x, np.floating) and np.finfo(x.dtype).nmant != 52:
        return np.format_float_scientific(x, unique=True).replace(".e", "e")
    return repr(float(x))


def time_text(name: str, x: Any) -> str:
    """The exact text of a time or an angle: exact types as in
    :func:`exact_text`; a float by its shortest round-trip decimal in its
    own type (:func:`shortest_text`: ``0.05`` is 5/100, a float32 0.1 is
    1/10), the way an engine's times are written to a CSV file."""
    if isinstance(x, str) or isinstance(x, (Fraction, Decimal)) or (
        isinstance(x, numbers.Integral) and not isinstance(x, bool)
    ):
        return exact_text(name, x)
    if isinstance(x, bool):
        raise TypeError(f"{name}: expected a number, got a bool")
    if isinstance(x, numbers.Real):
        f = float(x)
        if not math.isfinite(f):
            raise _invalid(name, x, "must be a finite number")
        return shortest_text(x)
    raise TypeError(f"{name}: expected a number, got {type(x).__name__}")


def mu_text(name: str, x: Any, allow_float: bool = False) -> str:
    """A friction coefficient: ``"inf"`` (rolling), a number >= 0 (static =
    kinetic), ``"S,K"`` or a pair ``(S, K)`` (static S >= kinetic K)."""
    if isinstance(x, (tuple, list)):
        if len(x) != 2:
            raise _invalid(name, x, "a pair (static, kinetic) has two numbers")
        return ",".join(exact_text(name, v, allow_float) for v in x)
    if isinstance(x, (float, Decimal)) and not isinstance(x, bool):
        if isinstance(x, float) and math.isinf(x) or isinstance(x, Decimal) and x.is_infinite():
            if x > 0:
                return "inf"  # rolling, as float("inf")
            raise _invalid(name, x, "must be >= 0, or inf (rolling)")
    return exact_text(name, x, allow_float)
