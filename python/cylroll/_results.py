"""Result types: verified values, the separation answer with its events, the
forces at an angle, and trajectory tables."""

from __future__ import annotations

import math
from decimal import Decimal
from fractions import Fraction
from typing import (TYPE_CHECKING, Any, Dict, Iterator, List, Mapping, NamedTuple, Optional,
                    Sequence, Tuple)

import numpy as np

if TYPE_CHECKING:  # pragma: no cover
    import pandas

    from ._model import Model

#: A value as the native module returns it: (name, text, digits, err, err_text).
_Raw = Tuple[str, str, int, float, str]


class Value:
    """A verified number.

    ``text`` holds exactly the verified significant digits (``digits`` of
    them; a value printed as ``"0"`` has ``digits == 0``: it is zero to the
    accuracy asked for); ``err`` is the estimated bound on the absolute error
    of the value the digits were rounded from (``err_text`` the same, short).

    ``float(v)`` is the float nearest ``text``; ``v.decimal()`` the exact
    ``decimal.Decimal`` of ``text``. ``str(v)`` is ``text``.

    A friction ratio at an angle where its normal force is 0 to within its
    bound (at θs, ``|F21|/N12``) has no finite verified value: its ``text`` is
    ``">=X"``, ``is_lower_bound`` is true, ``lower_bound`` is X, and
    ``float(v)`` / ``v.decimal()`` raise ``ValueError`` saying so.

    ``notes``: for the answer of :meth:`Model.time`, the notes the command
    line prints with it (an angle past θs within the digits asked answered
    at θs, an angle on the branch followed past the branch point, …); empty
    for the values of other answers (their notes are the answer's own).
    """

    __slots__ = ("name", "text", "digits", "err", "err_text", "mode", "notes")

    name: str
    text: str
    digits: int
    err: float
    err_text: str
    mode: Optional[str]
    notes: List[str]

    def __init__(self, name: str, text: str, digits: int, err: float, err_text: str = "",
                 mode: Optional[str] = None, notes: Optional[List[str]] = None) -> None:
        self.notes = list(notes or [])
        self.name = name
        self.text = text
        self.digits = digits
        self.err = err
        self.err_text = err_text or f"{err:.1e}"
        #: with friction, for :meth:`Model.time`: the mode where the angle is reached
        self.mode = mode

    @classmethod
    def _from(cls, raw: _Raw, mode: Optional[str] = None,
              notes: Optional[List[str]] = None) -> "Value":
        return cls(raw[0], raw[1], raw[2], raw[3], raw[4], mode, notes)

    @property
    def is_lower_bound(self) -> bool:
        """Whether only a lower bound is known (``text`` is ``">=X"``)."""
        return self.text.startswith(">=")

    @property
    def lower_bound(self) -> Optional[float]:
        """X of a ``">=X"`` value, as the float at or below it (still a lower
        bound); ``None`` for a verified value."""
        if not self.is_lower_bound:
            return None
        x = self.text[2:]
        f = float(x)
        if Fraction(f) > Fraction(x):
            f = math.nextafter(f, -math.inf)
        return f

    def _check_finite(self) -> None:
        if self.is_lower_bound:
            raise ValueError(
                f"{self.name} has no finite verified value here, only the lower bound "
                f"{self.text} (its normal force is 0 to within its error bound)")

    def decimal(self) -> Decimal:
        """The verified digits as an exact ``decimal.Decimal``."""
        self._check_finite()
        return Decimal(self.text)

    def __float__(self) -> float:
        self._check_finite()
        return float(self.text)

    def __str__(self) -> str:
        return self.text

    def __repr__(self) -> str:
        extra = f", mode={self.mode!r}" if self.mode is not None else ""
        return (f"Value({self.name!r}, {self.text!r}, digits={self.digits}, "
                f"err={self.err_text}{extra})")

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Value):
            return NotImplemented
        return (self.name, self.text, self.digits) == (other.name, other.text, other.digits)

    def __hash__(self) -> int:
        return hash((self.name, self.text, self.digits))


def _table(values: Sequence[Value]) -> List[str]:
    w = max((len(v.name) for v in values), default=0)
    wt = max((len(v.text) for v in values), default=0)
    lines = []
    for v in values:
        if v.is_lower_bound:
            note = "a lower bound: the normal force is 0 to within its error bound"
        elif v.digits == 0:
            note = ("exactly 0" if v.err == 0 else
                    f"0 to within an absolute bound: |x| <= {v.err_text}")
        else:
            note = f"{v.digits} digits, |err| <= {v.err_text}"
        lines.append(f"  {v.name:<{w}} = {v.text:<{wt}}   [{note}]")
    return lines


class _Values(Mapping[str, Value]):
    """A mapping name -> :class:`Value` in the library's order; values are
    also attributes (``sep.theta_s``)."""

    _values: Dict[str, Value]
    model: "Model"
    digits: int

    def __getitem__(self, key: str) -> Value:
        return self._values[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self._values)

    def __len__(self) -> int:
        return len(self._values)

    def __getattr__(self, name: str) -> Value:
        if name.startswith("_"):
            raise AttributeError(name)
        try:
            return self._values[name]
        except KeyError:
            raise AttributeError(
                f"{type(self).__name__} has no value {name!r}; it has {', '.join(self._values)}"
            ) from None

    def to_dict(self) -> Dict[str, float]:
        """name -> float. Raises ``ValueError`` where a value is only a lower
        bound (the friction a contact needs at θs, ``">=X"``): there use
        :meth:`texts` or ``Value.lower_bound``."""
        return {k: float(v) for k, v in self._values.items()}

    def texts(self) -> Dict[str, str]:
        """name -> the verified digits as text."""
        return {k: v.text for k, v in self._values.items()}


class Event:
    """One event of a motion (every contact law).

    ``kind``: ``slip_onset``, ``stick``, ``slip_reversal``,
    ``indeterminate`` (a branch point: from here the cylinders may lawfully
    stay together or part), ``separation``, ``lift_off`` or ``impact``;
    ``contact``: ``"floor"``, ``"contact"`` or ``None``; ``mode``: the mode
    entered (``"stick/slip+"`` = floor sticking, contact slipping forwards;
    ``"flight"`` after separation; ``None`` at the end of the model); ``t``
    and ``theta``: verified :class:`Value` s; ``alternatives``: at a branch
    point every other continuation consistent there (``"part"``, and any other
    closed mode such as ``"stick/slip+"``), else empty.
    """

    __slots__ = ("kind", "contact", "mode", "t", "theta", "alternatives")

    def __init__(self, kind: str, contact: Optional[str], mode: Optional[str], t: Value,
                 theta: Value, alternatives: Sequence[str] = ()) -> None:
        self.kind = kind
        self.contact = contact
        self.mode = mode
        self.t = t
        self.theta = theta
        self.alternatives = list(alternatives)

    def __repr__(self) -> str:
        where = f" ({self.contact})" if self.contact else ""
        into = f" -> {self.mode}" if self.mode else ""
        return f"<Event {self.kind}{where} at t = {self.t.text}, theta = {self.theta.text}{into}>"


class _Motion:
    """What every answer about the motion carries: the events, the start
    mode, how the motion ended, the branch followed and the notes."""

    events: List[Event]
    start_mode: Optional[str]
    end: Optional[str]
    impact_surface: Optional[str]
    branch: str
    notes: List[str]

    def _motion(self, d: Dict[str, Any]) -> None:
        self.events = [Event(k, c, m, Value._from(t), Value._from(th), alt)
                       for (k, c, m, t, th, alt) in d.get("events", [])]
        self.start_mode = d.get("start_mode")
        self.end = d.get("end")
        self.impact_surface = d.get("impact_surface")
        self.branch = d.get("branch", "stay")
        self.notes = list(d.get("notes", []))

    def event(self, kind: str) -> Optional[Event]:
        """The first event of a kind (``"separation"``, ``"indeterminate"``,
        …), or ``None``."""
        return next((e for e in self.events if e.kind == kind), None)


class Separation(_Values, _Motion):
    """The answer of :meth:`Model.separation`.

    A mapping name -> :class:`Value` (``theta_s``, ``t_s``, ``work_s``,
    ``theta_indeterminate``, …, in the command line's order) with the values
    also as attributes; ``t_s`` is ``None`` for a start from rest exactly at
    the top. ``events`` (a list of :class:`Event`, the impact last),
    ``start_mode``, ``end`` (what ended the motion), ``impact_surface``,
    ``branch`` and ``notes``, for every contact law.
    """

    @classmethod
    def _build(cls, model: "Model", digits: int, d: Dict[str, Any]) -> "Separation":
        s = cls.__new__(cls)
        s.model = model
        s.digits = digits
        s._values = {raw[0]: Value._from(raw) for raw in d["values"]}
        s._motion(d)
        return s

    @property
    def theta_s(self) -> Optional[Value]:
        """θs: where the cylinders part (``None`` where the model ends before
        they part: cylinder 2 reaches the floor while still on cylinder 1, or
        cylinder 1 lifts off; :attr:`end` says which)."""
        return self._values.get("theta_s")

    @property
    def t_s(self) -> Optional[Value]:
        """The time to separation (``None``: infinite, a start from rest at the top)."""
        return self._values.get("t_s")

    @property
    def theta_indeterminate(self) -> Optional[Value]:
        """Where parting becomes lawful while the cylinders still press on
        each other (``None``: the motion is unique)."""
        return self._values.get("theta_indeterminate")

    @property
    def friction(self) -> bool:
        """Whether some contact has Coulomb friction."""
        return self.model.friction is not None

    def __str__(self) -> str:
        lines = [f"Separation ({self.digits} digits requested; every digit shown is verified)"]
        lines += _table(list(self._values.values()))
        if self.start_mode is not None:
            lines.append(f"  start mode: {self.start_mode}; branch: {self.branch}")
        for i, e in enumerate(self.events, 1):
            where = f" ({e.contact})" if e.contact else ""
            into = f" -> {e.mode}" if e.mode else ""
            lines.append(f"  event {i}: {e.kind}{where} at t = {e.t.text}, "
                         f"theta = {e.theta.text}{into}")
        lines += [f"  note: {n}" for n in self.notes]
        return "\n".join(lines)

    __repr__ = __str__


class Forces(_Values):
    """The answer of :meth:`Model.forces`: a mapping name -> :class:`Value`
    (``F1``, ``N1``, ``F21``, ``N12``, ``theta_dot``, ``theta_ddot``,
    ``mu_floor``, ``mu_contact``, ``s1``, ``s12``, ``work``; for the ideal
    models also the most friction each rolling contact needs over [θ0, θ]
    and where: ``mu_floor_max``, ``theta_mu_floor_max``, ``mu_contact_max``,
    ``theta_mu_contact_max``) and the mode there (``mode``), with the notes
    the command line prints (``notes``: an angle past θs within the digits
    asked answered at θs, an angle on the branch followed past the branch
    point, …)."""

    mode: Optional[str]
    notes: List[str]

    @classmethod
    def _build(cls, model: "Model", digits: int, vals: Sequence[_Raw],
               mode: Optional[str], notes: Optional[List[str]] = None) -> "Forces":
        f = cls.__new__(cls)
        f.model = model
        f.digits = digits
        f._values = {raw[0]: Value._from(raw) for raw in vals}
        f.mode = mode
        f.notes = list(notes or [])
        return f

    def __str__(self) -> str:
        lines = [f"Forces ({self.digits} digits requested; every digit shown is verified)"]
        lines += _table(list(self._values.values()))
        if self.mode is not None:
            lines.append(f"  mode: {self.mode}")
        lines += [f"  note: {n}" for n in self.notes]
        return "\n".join(lines)

    __repr__ = __str__


class Trajectory(_Motion):
    """The answer of :meth:`Model.trajectory`: a table, one row per time,
    the same for every contact law.

    ``columns``: the names (``t, theta, theta_dot, theta_ddot, phi1, phi2,
    x1, x2, y2, x1_dot, phi1_dot, x2_dot, y2_dot, phi2_dot, F1, N1, F21, N12,
    s1, s12, work``); ``rows``: lists of :class:`Value`; ``modes``: the mode
    of each row (``"stick/slip+"`` = floor sticking, contact slipping
    forwards; ``"flight"``); ``events`` up to the last time.

    ``traj.column("theta")`` (or ``traj["theta"]``) is a float64 NumPy array;
    ``traj.values("theta")`` the :class:`Value` s; ``traj.errors("theta")``
    the error bounds; ``traj.to_numpy()`` the whole table (rows × columns);
    ``traj.to_pandas()`` a DataFrame (needs pandas); ``traj.to_csv()`` the
    command line's CSV (verified digits as text).
    """

    columns: List[str]
    modes: List[str]
    model: "Model"
    digits: int

    @classmethod
    def _build(cls, model: "Model", digits: int, d: Dict[str, Any],
               csv_head: Optional[List[str]] = None) -> "Trajectory":
        t = cls.__new__(cls)
        t.model = model
        t.digits = digits
        # the CSV's columns where ``columns=`` chose them (``mode`` where asked)
        t._csv_head = csv_head
        t.columns = list(d["columns"])
        # by column: (texts, digits, error bounds, their short texts); a
        # row's Values are made only when asked (``rows``, ``values``)
        t._cols = list(d["cols"])
        t._rows = None
        t.modes = list(d["modes"])
        t._motion(d)
        return t

    def _index(self, name: str) -> int:
        try:
            return self.columns.index(name)
        except ValueError:
            raise KeyError(f"no column {name!r}; columns: {', '.join(self.columns)}") from None

    def _values(self, j: int) -> List[Value]:
        name = self.columns[j]
        texts, digits, errs, err_texts = self._cols[j]
        return [Value(name, a, b, c, e) for a, b, c, e in zip(texts, digits, errs, err_texts)]

    @property
    def rows(self) -> List[List[Value]]:
        """The table as lists of :class:`Value`, one per time (made on first
        use; ``column``, ``errors``, ``to_numpy`` and ``to_csv`` do not need
        them)."""
        if self._rows is None:
            cols = [self._values(j) for j in range(len(self.columns))]
            self._rows = [list(r) for r in zip(*cols)] if cols else [[] for _ in self.modes]
        return self._rows

    def __len__(self) -> int:
        return len(self.modes)

    def values(self, name: str) -> List[Value]:
        """The column ``name`` as :class:`Value` s."""
        return self._values(self._index(name))

    def column(self, name: str) -> np.ndarray:
        """The column ``name`` as a float64 array (each the float nearest the
        verified digits)."""
        return np.array(self._cols[self._index(name)][0], dtype=np.float64)

    def __getitem__(self, name: str) -> np.ndarray:
        return self.column(name)

    def errors(self, name: str) -> np.ndarray:
        """The error bounds of the column ``name`` (float64, rounded up)."""
        return np.array(self._cols[self._index(name)][2], dtype=np.float64)

    def to_numpy(self) -> np.ndarray:
        """The table as a float64 array of shape (rows, columns), columns in
        :attr:`columns` order (the modes are in :attr:`modes`)."""
        out = np.empty((len(self.modes), len(self.columns)), dtype=np.float64)
        for j, col in enumerate(self._cols):
            out[:, j] = np.array(col[0], dtype=np.float64)
        return out

    def to_dict(self) -> Dict[str, np.ndarray]:
        """name -> float64 array (``check`` takes this back)."""
        return {c: self.column(c) for c in self.columns}

    def to_pandas(self) -> "pandas.DataFrame":
        """A pandas DataFrame of float64 columns and the ``mode`` column.
        Raises ``ImportError`` when pandas is not installed."""
        try:
            import pandas as pd
        except ImportError as e:  # pragma: no cover - depends on the environment
            raise ImportError("Trajectory.to_pandas() needs pandas: pip install pandas") from e
        df = pd.DataFrame(self.to_numpy(), columns=self.columns)
        df["mode"] = self.modes
        return df

    def to_csv(self, path: Optional[str] = None) -> str:
        """The command line's CSV (header, then the verified digits as text,
        the ``mode`` column last; a table made with ``columns=`` has those
        columns alone, in their order, ``mode`` among them only where asked,
        as ``--columns`` prints them); written to ``path`` if given."""
        head = self._csv_head or list(self.columns) + ["mode"]
        lines = [",".join(head)]
        texts = [self.modes if h == "mode" else self._cols[self._index(h)][0] for h in head]
        for cells in zip(*texts):
            lines.append(",".join(cells))
        text = "\n".join(lines) + "\n"
        if path is not None:
            with open(path, "w") as f:
                f.write(text)
        return text

    def __str__(self) -> str:
        n = len(self.modes)
        head = (f"Trajectory: {n} row{'s' if n != 1 else ''} x {len(self.columns)} columns "
                f"({self.digits} digits requested; every digit shown is verified)")
        show = list(range(n)) if n <= 8 else [0, 1, 2, 3, None, n - 3, n - 2, n - 1]
        # t, θ, θ̇ and N12 where the table has them, else its first four columns
        # (a table made with ``columns=``)
        cols = [c for c in ("t", "theta", "theta_dot", "N12") if c in self.columns]
        if not cols:
            cols = list(self.columns[:4])
        lines = [head, "  " + "  ".join(f"{c:<18}" for c in cols) + "  mode"]
        for i in show:
            if i is None:
                lines.append("  ...")
                continue
            cells = [self._cols[self.columns.index(c)][0][i][:18] for c in cols]
            line = "  " + "  ".join(f"{c:<18}" for c in cells) + f"  {self.modes[i]}"
            lines.append(line)
        return "\n".join(lines)

    __repr__ = __str__


class Enclosure(NamedTuple):
    """A proved enclosure (:meth:`Model.enclose`): the true value lies in
    ``[mid − rad, mid + rad]`` (decimal strings, ``rad`` rounded up), and
    ``text`` holds the ``digits`` significant digits every point of it
    shares."""

    #: quantity name (``theta_s``, ``t_s``, ``t``, ``F1``, …)
    name: str
    #: the proved digits
    text: str
    #: how many significant digits are proved
    digits: int
    #: the midpoint, as a decimal string
    mid: str
    #: the radius, as a decimal string (rounded up)
    rad: str

    def interval(self) -> Tuple[Decimal, Decimal]:
        """``(mid − rad, mid + rad)`` as exact ``decimal.Decimal`` ends."""
        from decimal import localcontext

        with localcontext() as ctx:
            ctx.prec = len(self.mid) + 40
            m, r = Decimal(self.mid), Decimal(self.rad)
            return (m - r, m + r)

    def __contains__(self, x: object) -> bool:
        lo, hi = self.interval()
        return lo <= Decimal(str(x)) <= hi
