"""The model: parameters, contact models, start and friction, all exact."""

from __future__ import annotations

import numbers
import os
import re
from fractions import Fraction
from typing import Any, Dict, Iterable, List, Optional, Tuple, Union

from . import _cylroll
from ._errors import InvalidParameterError
from ._exact import Number, _invalid, exact_text, mu_text, time_text
from ._results import Enclosure, Forces, Separation, Trajectory, Value

#: The model keys, in the library's order.
MODEL_KEYS: Tuple[str, ...] = tuple(_cylroll.MODEL_KEYS)
#: The friction keys.
FRICTION_KEYS: Tuple[str, ...] = tuple(_cylroll.FRICTION_KEYS)
#: Largest number of significant digits accepted.
MAX_DIGITS: int = _cylroll.MAX_DIGITS

Mu = Union[Number, Tuple[Number, Number], None]


def _count(name: str, x: Any, hi: int) -> int:
    """A count (digits, steps): an ``int`` or any integer type (numpy's
    included); a float, even 5.0, is refused as the wrong type."""
    if isinstance(x, bool) or not isinstance(x, numbers.Integral):
        raise TypeError(f"{name}: expected an int (or a numpy integer), got {type(x).__name__}")
    x = int(x)
    if not 1 <= x <= hi:
        raise _invalid(name, x, f"must be between 1 and {hi}")
    return x


def _digits(digits: Any) -> int:
    return _count("digits", digits, MAX_DIGITS)


class Model:
    """A cylinder (2) on a cylinder (1) on the floor, with exact parameters.

    Every number is read exactly: pass text (``"0.3"`` is 3/10, ``"1/3"``,
    ``"1e-3"``; angles may be ``"pi/6"``, ``"2*pi/3"``), an ``int``, a
    ``fractions.Fraction`` or a ``decimal.Decimal``. A ``float`` is refused
    (``TypeError``) unless ``allow_float=True``, and then it is taken as the
    binary number it is: ``0.1`` is 3602879701896397/36028797018963968, not
    1/10.

    The model is validated at once; bad input raises
    :class:`cylroll.InvalidParameterError` (a ``ValueError``) naming the
    parameter and its allowed range. A model is immutable; :meth:`replace`
    returns a changed copy.

    Parameters (the defaults are the paper's main case: identical solid
    cylinders, m = r = g = 1, k = 1/2, both contacts rolling, from rest at
    the top, θ0 = 0):

    floor
        ``"roll"`` (no slip: μ = ∞), ``"slip"`` (frictionless: μ = 0) or
        ``"fixed"`` (cylinder 1 held still).
    contact
        between the cylinders: ``"roll"`` or ``"slip"``.
    m1, m2, r1, r2
        masses and radii (> 0).
    k1, k2
        inertia factors, I = k m r² (>= 0; k > 1 is a bobbin).
    g
        gravity (> 0).
    theta0
        the line of centres at the start, clockwise from vertical, |θ0| < π/2.
    thetadot0
        its rate at the start (θ0·θ̇0 >= 0: the motion runs away from the top).
    omega0
        the common rolling rate fixing the conserved momenta: the value φ̇1
        takes whenever θ̇ = 0 (0 for a fixed floor).
    mu_floor, mu_contact
        Coulomb friction at the floor and between the cylinders: a number
        >= 0 (static = kinetic), ``"S,K"`` or a pair ``(S, K)`` (static S >=
        kinetic K), ``"inf"`` (exactly ``roll``) or 0 (exactly ``slip``).
        ``None`` (the default): the contact of ``floor`` / ``contact``. The
        ideal contacts are the limits of Coulomb friction: every model has
        the same answers (events, free flight, the first impact, columns).
    mu
        Coulomb friction at both contacts (the floor's unless it is
        ``"fixed"``); not together with ``mu_floor`` / ``mu_contact``.
    allow_float
        accept ``float`` parameters as their exact binary values.

    The questions: :meth:`separation`, :meth:`time`, :meth:`forces`,
    :meth:`trajectory`. Each takes ``digits`` (significant digits, 1 to
    2000, default 30) and returns values with only verified digits.

    >>> import cylroll
    >>> cylroll.Model().separation().theta_s.text     # π/3
    '1.04719755119659774615421446109'
    """

    __slots__ = ("_pairs", "_echo")

    def __init__(
        self,
        *,
        floor: str = "roll",
        contact: str = "roll",
        m1: Number = 1,
        m2: Number = 1,
        r1: Number = 1,
        r2: Number = 1,
        k1: Number = "1/2",
        k2: Number = "1/2",
        g: Number = 1,
        theta0: Number = 0,
        thetadot0: Number = 0,
        omega0: Number = 0,
        mu_floor: Mu = None,
        mu_contact: Mu = None,
        mu: Mu = None,
        allow_float: bool = False,
    ) -> None:
        _flag("allow_float", allow_float)
        if not isinstance(floor, str):
            raise TypeError("floor: expected 'roll', 'slip' or 'fixed'")
        if not isinstance(contact, str):
            raise TypeError("contact: expected 'roll' or 'slip'")
        nums = dict(m1=m1, m2=m2, r1=r1, r2=r2, k1=k1, k2=k2, g=g, theta0=theta0,
                    thetadot0=thetadot0, omega0=omega0)
        pairs: Dict[str, str] = {"floor": floor, "contact": contact}
        for k, v in nums.items():
            pairs[k] = exact_text(k, v, allow_float)
        if mu is not None:
            if mu_floor is not None or mu_contact is not None:
                raise TypeError("give mu, or mu_floor and mu_contact, not both")
            if floor.strip().lower() != "fixed":
                mu_floor = mu
            mu_contact = mu
        if mu_floor is not None:
            pairs["mu_floor"] = mu_text("mu_floor", mu_floor, allow_float)
        if mu_contact is not None:
            pairs["mu_contact"] = mu_text("mu_contact", mu_contact, allow_float)
        self._init(pairs)

    def _init(self, pairs: Dict[str, str]) -> None:
        echo = _cylroll.validate(pairs)
        object.__setattr__(self, "_pairs", dict(pairs))
        object.__setattr__(self, "_echo", dict(echo))

    @classmethod
    def _from_pairs(cls, pairs: Dict[str, str]) -> "Model":
        m = cls.__new__(cls)
        m._init(pairs)
        return m

    @classmethod
    def from_toml(cls, path: Union[str, "os.PathLike[str]"]) -> "Model":
        """A model from a ``--params`` TOML file: the keys of the constructor
        (``floor``, ``m1``, …, ``mu_floor``, ``mu_contact``), values as strings
        or integers (TOML floats are binary and refused; ``inf`` and ``nan``
        are read as the words). Missing keys take the defaults. A golden case
        file (``golden/cases/*.toml``) is one: its descriptive keys
        ``description`` and ``steps`` are accepted and ignored; any other key
        raises :class:`cylroll.InvalidParameterError` naming it and the file."""
        return cls._from_pairs(_cylroll.read_toml(os.fspath(path)))

    def __setattr__(self, name: str, value: Any) -> None:
        raise AttributeError("Model is immutable; use model.replace(...)")

    def replace(self, *, allow_float: bool = False, **changes: Any) -> "Model":
        """A copy with some parameters changed (the constructor's keywords;
        ``mu_floor=None`` removes a coefficient; ``mu`` sets both).

        A new law replaces its contact's friction: ``floor=`` drops the
        model's ``mu_floor`` and ``contact=`` its ``mu_contact``, unless the
        same call gives them (``mu`` gives both where the law takes one), so
        ``Model(mu="0.3").replace(floor="roll")``
        is a rolling floor under a Coulomb contact (the coefficient would
        otherwise remain that contact's law)."""
        _flag("allow_float", allow_float)
        for k, allowed in (("floor", "'roll', 'slip' or 'fixed'"), ("contact", "'roll' or 'slip'")):
            if k in changes and not isinstance(changes[k], str):
                raise TypeError(f"{k}: expected {allowed}, got {type(changes[k]).__name__}")
        pairs = dict(self._pairs)
        # (mu, below, gives both again where the law takes one: not a held floor)
        for law, coef in (("floor", "mu_floor"), ("contact", "mu_contact")):
            if law in changes and coef not in changes:
                pairs.pop(coef, None)
        if "mu" in changes:
            mu = changes.pop("mu")
            if "mu_floor" in changes or "mu_contact" in changes:
                raise TypeError("give mu, or mu_floor and mu_contact, not both")
            held = str(changes.get("floor", pairs.get("floor", "roll"))).strip().lower() == "fixed"
            if not held:
                changes["mu_floor"] = mu
            changes["mu_contact"] = mu
        for k, v in changes.items():
            if k in ("floor", "contact"):
                pairs[k] = v
            elif k in FRICTION_KEYS:
                if v is None:
                    pairs.pop(k, None)
                else:
                    pairs[k] = mu_text(k, v, allow_float)
            elif k in MODEL_KEYS:
                pairs[k] = exact_text(k, v, allow_float)
            else:
                raise TypeError(f"replace() got an unexpected keyword argument {k!r}")
        return Model._from_pairs(pairs)

    # --- what the model is

    @property
    def params(self) -> Dict[str, str]:
        """The model as exact text, in the library's order: the laws
        (``floor``, ``contact``: ``roll``, ``slip``, ``fixed`` or ``coulomb``;
        ``mu_floor``, ``mu_contact``: ``inf``, ``0``, μ or ``S,K``, ``none``
        for a held cylinder), then ``m1`` … ``omega0``: rationals in lowest
        terms, angles as multiples of π where given so."""
        return dict(self._echo)

    @property
    def laws(self) -> Dict[str, str]:
        """The law of each contact: ``{"floor": …, "contact": …, "mu_floor":
        …, "mu_contact": …}`` (the first four keys of :attr:`params`)."""
        return {k: self._echo[k] for k in ("floor", "contact", "mu_floor", "mu_contact")}

    @property
    def friction(self) -> Optional[Dict[str, str]]:
        """The coefficients ``{"mu_floor": …, "mu_contact": …}`` when some
        contact has Coulomb friction, else ``None`` (the ideal models, the
        limits μ = ∞ and μ = 0)."""
        if "coulomb" not in (self._echo["floor"], self._echo["contact"]):
            return None
        return {"mu_floor": self._echo["mu_floor"], "mu_contact": self._echo["mu_contact"]}

    def to_dict(self) -> Dict[str, str]:
        """The keys this model was built from (a ``--params`` file's keys)."""
        return dict(self._pairs)

    def __repr__(self) -> str:
        items = [f"{k}={v!r}" for k, v in self._echo.items()]
        return "Model(" + ", ".join(items) + ")"

    def _key(self) -> Tuple[Any, ...]:
        return tuple(self._echo.items())

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Model) and self._key() == other._key()

    def __hash__(self) -> int:
        return hash(self._key())

    def __reduce__(self) -> Any:
        return (Model._from_pairs, (dict(self._pairs),))

    # --- the questions

    def separation(self, digits: int = 30, *, branch: str = "stay",
                   part_at: Optional[Number] = None) -> Separation:
        """The motion to its end, for every contact law: the events
        (:attr:`Separation.events`: slip onsets, sticks, reversals, the
        branch point ``indeterminate``, ``separation``, the ``impact``), and
        ``theta_s``, ``t_s`` (None for a start from rest exactly at the top,
        where every time is infinite and θs is the limit θ0 → 0+),
        ``work_s`` (energy dissipated by friction up to separation),
        ``theta_indeterminate``, ``t_indeterminate`` (where parting becomes
        lawful while the cylinders still press on each other: from there the
        rigid-body motion is not unique), the first impact (``t_impact``,
        ``x1_impact``, … ``psi2_dot_impact``); for the ideal models on the
        ``stay`` branch also the closed forms' findings (``N1_min``,
        ``mu_floor_max``, ``theta_phi1dot_zero``, ``F21_at_s``, …).

        ``branch``: ``"stay"`` (the contact persists while it can; the limit
        of stiff compliant contact) or ``"part"`` (the cylinders part at the
        first instant they may, as velocity-level complementarity engines
        do); ``part_at``: part where θ reaches this angle (inside the window
        where parting is lawful).

        Raises :class:`InvalidParameterError`, :class:`NotPhysicalError`,
        :class:`VerificationError`.
        """
        d = _cylroll.separation(self._pairs, _digits(digits), *_branch(branch, part_at))
        return Separation._build(self, digits, d)

    def enclose(self, what: str = "separation", theta: Optional[Number] = None,
                digits: int = 30) -> List[Enclosure]:
        """Proved enclosures (the command line's ``--rigorous``).

        ``what="separation"``: ``theta_s`` and, when finite and enclosed,
        ``t_s``, and where the motion is not unique the branch point
        ``theta_indeterminate``, ``t_indeterminate``; ``what="time"`` with ``theta``: ``t``; ``what="forces"``
        with ``theta``: the forces, rates and needed friction that can be
        enclosed. With friction only ``what="separation"``, from a start where
        both contacts stick: where sticking ends, ``theta_slip_onset`` and
        ``t_slip_onset`` (or ``theta_s`` and ``t_s`` when the contact opens
        there); the phases after it are verified only. Each
        :class:`Enclosure` holds ``[mid ± rad]`` and the digits it proves
        (interval arithmetic with directed rounding; see the README,
        "Guarantees"). A quantity that cannot be enclosed is left out.

        Raises :class:`InvalidParameterError` for ``what`` other than these
        (with friction: other than ``"separation"``), :class:`NotPhysicalError`
        with friction when nothing can be enclosed (a start that slips at
        once).
        """
        if what in ("time", "forces") and theta is None:
            raise _invalid("theta", "(not given)",
                           f"enclose({what!r}) needs the angle to enclose it at")
        th = None if theta is None else time_text("theta", theta)
        rows = _cylroll.enclose(self._pairs, _digits(digits), what, th)
        return [Enclosure(*r) for r in rows]

    def time(self, theta: Number, digits: int = 30, *, branch: str = "stay",
             part_at: Optional[Number] = None) -> Value:
        """t(θ): the time from the start until θ first reaches ``theta``
        (an exact angle: ``"pi/4"``, ``"0.9"``, a Fraction, …; a float is read
        as the decimal it prints as). The angle must lie between θ0 and the
        separation (with friction: while the contacts hold).

        Raises :class:`InvalidParameterError` (an angle outside the motion),
        :class:`NotPhysicalError` (a start from rest exactly at the top:
        infinite), :class:`VerificationError`.
        """
        d = _cylroll.time(self._pairs, _digits(digits), time_text("theta", theta),
                          *_branch(branch, part_at))
        return Value._from(d["values"][0], d["mode"], d.get("notes"))

    def forces(self, theta: Number, digits: int = 30, *, branch: str = "stay",
               part_at: Optional[Number] = None) -> Forces:
        """The state where θ first reaches ``theta``: ``F1``, ``N1``, ``F21``,
        ``N12``, ``theta_dot``, ``theta_ddot``, ``mu_floor`` = \\|F1\\|/N1,
        ``mu_contact`` = \\|F21\\|/N12, ``s1``, ``s12`` (slip speeds) and
        ``work`` (energy dissipated), with the mode there
        (:attr:`Forces.mode`); for the ideal models also the most friction
        each rolling contact needs over [θ0, θ]."""
        d = _cylroll.forces(self._pairs, _digits(digits), time_text("theta", theta),
                            *_branch(branch, part_at))
        return Forces._build(self, digits, d["values"], d["mode"], d.get("notes"))

    def trajectory(
        self,
        times: Optional[Iterable[Number]] = None,
        digits: int = 30,
        *,
        t_end: Optional[Number] = None,
        steps: Optional[int] = None,
        branch: str = "stay",
        part_at: Optional[Number] = None,
        columns: Optional[Iterable[str]] = None,
    ) -> Trajectory:
        """The motion at the given times (ascending, >= 0), through every
        phase up to the first impact, for every contact law: one row per
        time with the columns ``t, theta, theta_dot, theta_ddot, phi1, phi2,
        x1, x2, y2, x1_dot, phi1_dot, x2_dot, y2_dot, phi2_dot, F1, N1, F21,
        N12, s1, s12, work`` and a mode per row (``"stick/slip+"``,
        ``"flight"``), and the events up to the last time.

        ``times`` may be exact numbers or floats (a float is read as the
        decimal it prints as: ``np.linspace(0, 5, 101)`` gives 0.05, 0.1, …
        exactly), or give ``t_end`` and ``steps`` for the exact grid
        t_i = i·t_end/steps, i = 0 … steps.

        ``columns`` (names among those above, e.g. ``["t", "theta"]``) keeps
        only those columns, in that order, with the digits the full table
        gives them; ``["t", "theta"]`` or ``["theta"]`` computes θ alone (no
        force), several times faster with friction. The modes are always
        given.

        Raises :class:`InvalidParameterError` (a time after the first impact,
        a negative time),
        :class:`NotPhysicalError` (a start from rest exactly at the top),
        :class:`VerificationError`.
        """
        if times is None:
            if t_end is None or steps is None:
                raise TypeError("trajectory() needs times, or t_end and steps")
            steps = _count("steps", steps, 100_000)
            # a time like every other: a float is read as the decimal it prints as
            te = time_text("t_end", t_end)
            if _to_fraction(te) <= 0:
                raise _invalid("t_end", te, "must be > 0")
            texts = [_grid_point(te, i, steps) for i in range(steps + 1)]
        else:
            if t_end is not None or steps is not None:
                raise TypeError("give times, or t_end and steps, not both")
            if isinstance(times, (str, bytes)):
                raise TypeError("times: expected a sequence of numbers, got a string")
            try:
                it = iter(times)
            except TypeError:
                raise TypeError(
                    f"times: expected a sequence of numbers (e.g. [0.5]), got "
                    f"{type(times).__name__}") from None
            texts = [time_text("times", t) for t in it]
        cols = None
        if columns is not None:
            if isinstance(columns, (str, bytes)):
                raise TypeError("columns: expected a sequence of column names, e.g. ['t', 'theta']")
            names = list(columns)
            if not names or not all(isinstance(c, str) for c in names):
                raise _invalid("columns", repr(names), "must be a non-empty sequence of column names")
            cols = ",".join(names)
        try:
            d = _cylroll.trajectory(self._pairs, _digits(digits), texts,
                                    *_branch(branch, part_at), cols)
        except InvalidParameterError as e:
            if times is not None or e.name != "times":
                raise
            # a time of the grid, not one given: named by t_end and its step
            k = texts.index(e.value) if e.value in texts else None
            at = f"the grid's time {e.value}" + (f" (step {k} of {steps})" if k is not None else "")
            raise _invalid("t_end", te, f"{at} {e.allowed}") from None
        # the CSV's header as --columns prints it (the names trimmed, as the
        # core reads them)
        head = None if cols is None else [c.strip() for c in cols.split(",")]
        return Trajectory._build(self, digits, d, head)


def _flag(name: str, x: Any) -> None:
    """A keyword that takes True or False (``allow_float="yes"`` was taken as true)."""
    if not isinstance(x, bool):
        raise TypeError(f"{name}: expected True or False, got {type(x).__name__}")


def _branch(branch: str, part_at: Optional[Number]) -> Tuple[str, Optional[str]]:
    if not isinstance(branch, str):
        raise TypeError("branch: expected 'stay' or 'part'")
    return branch, None if part_at is None else time_text("part_at", part_at)


def _grid_point(t_end: str, i: int, steps: int) -> str:
    """i·t_end/steps as exact text (a terminating decimal where it is one, so
    that the time column echoes it exactly)."""
    q = _to_fraction(t_end) * Fraction(i, steps)
    d = q.denominator
    for p in (2, 5):
        while d % p == 0:
            d //= p
    if d == 1:
        # terminating: write it out as a decimal
        n, den = q.numerator, q.denominator
        k = 0
        while den != 1 and 10**k % den != 0:
            k += 1
        scaled = n * (10**k // den)
        s = str(abs(scaled)).rjust(k + 1, "0")
        txt = s[:-k] + "." + s[-k:] if k else s
        return ("-" if scaled < 0 else "") + txt
    return f"{q.numerator}/{q.denominator}"


# the exponent of a decimal; beyond ±100000 the library refuses it (Fraction
# would build 10**exponent, however large, before anything else)
_EXPONENT = re.compile(r"e[+-]?0*(\d+)")


def _to_fraction(text: str) -> Fraction:
    t = text.strip().lower()
    if "pi" in t:
        raise _invalid("t_end", text, "expected an exact number such as 0.25, 1/3 or 1e-3")
    for m in _EXPONENT.finditer(t):
        if len(m.group(1)) > 6 or int(m.group(1)) > 100_000:
            raise _invalid("t_end", text, "the exponent must be within ±100000")
    try:
        if "/" in t:
            a, b = t.split("/", 1)
            return Fraction(a) / Fraction(b)
        return Fraction(t)
    except (ValueError, ZeroDivisionError):
        raise _invalid("t_end", text, "expected an exact number such as 0.25, 1/3 or 1e-3") from None
