"""``cylroll.check``: hold another program's table against the oracle.

The scoring is the command line's (``cylroll check``), done by the same Rust
core: per-column tolerances, a verdict per phase of the reference, per event
(when the candidate has a ``mode`` column) and per branch where the motion is
not unique. The report's attribute names are the keys of
``cylroll check --format json``.
"""

from __future__ import annotations

import csv
import decimal
import fractions
import io
import json
import numbers
import os
from decimal import Decimal, localcontext
from fractions import Fraction
from typing import Any, Dict, List, Mapping, NamedTuple, Optional, Tuple, Union

import numpy as np

from . import _cylroll
from ._exact import _invalid, exact_text, shortest_text
from ._model import Model, _count, _digits

__all__ = ["check", "CheckReport", "ColumnStats", "PhaseStats", "FirstFailure", "Phase",
           "EventVerdict", "BranchReport"]

#: Columns that are not numbers: compared as text (the phase of each row).
_TEXT = ("mode",)


def _num(x: Any) -> Any:
    """A JSON number, or the string ``inf``/``nan`` the report uses for a
    non-finite one, as a float; ``"-"`` (no finite ratio: the ``mode``
    column, a value off a zero limit) as None."""
    if x == "-":
        return None
    if isinstance(x, str):
        return float(x)
    return x


class PhaseStats(NamedTuple):
    """One column's statistics over one phase of the reference."""

    #: largest |candidate − oracle| in the phase
    max_abs: float
    #: the time where it occurs
    max_abs_t: str
    #: largest |err| / limit in the phase (None where there is no finite
    #: ratio: ``mode``, whose failures are rows in another mode, or a value
    #: off a zero limit)
    worst_err_over_limit: Optional[float]
    #: rows out of tolerance (``mode``: rows in another mode)
    failures: int
    #: values whose verdict the oracle's error bound leaves open
    undecided: int
    #: no failure and nothing undecided in the phase
    passed: bool


class ColumnStats(NamedTuple):
    """Per-column statistics of a check (the keys of the JSON report)."""

    #: column name
    column: str
    #: the relative tolerance applied (None for ``mode``)
    rtol: Optional[float]
    #: the absolute tolerance applied, in the column's own units (None for ``mode``)
    atol: Optional[float]
    #: the column's natural scale (the default atol is ``atol`` times it)
    scale: Optional[float]
    #: whether ``tol=`` set this column's tolerance
    tol_set: bool
    #: largest |candidate − oracle|
    max_abs: float
    #: the time where it occurs (as the candidate wrote it)
    max_abs_t: str
    #: largest |candidate − oracle| / |oracle|; ``None`` when every oracle
    #: value of the column is 0 (a relative error is undefined there)
    max_rel: Optional[float]
    #: the time where it occurs
    max_rel_t: str
    #: largest |candidate − oracle| / (atol + rtol·|oracle|): above 1 fails
    #: (None where there is no finite ratio: ``mode``, or a value off a
    #: zero limit)
    worst_err_over_limit: Optional[float]
    #: which term of that limit was the larger where it occurs: ``"atol"``
    #: (an oracle value near 0), ``"rtol"``, or ``"mode"``
    worst_bound: str
    #: rows out of tolerance
    failures: int
    #: values whose verdict the oracle's error bound leaves open
    undecided: int
    #: per phase of :attr:`CheckReport.phases`, in order
    phases: List[PhaseStats]

    @property
    def name(self) -> str:
        """The column name (an alias of :attr:`column`)."""
        return self.column


class FirstFailure(NamedTuple):
    """The first value out of tolerance (in row order, then column order)."""

    #: 1-based data row of the candidate
    row: int
    #: its time
    t: str
    #: the column
    column: str
    #: the candidate's value as written
    candidate: str
    #: the oracle's value (verified digits; for ``mode`` the reference's mode)
    oracle: str
    #: the limit atol + rtol·|oracle| it exceeded
    limit: float
    #: which term of the limit was the larger: ``"atol"``, ``"rtol"`` or ``"mode"``
    bound: str


class Phase(NamedTuple):
    """A phase of the reference on the candidate's rows: consecutive rows the
    reference puts in one mode."""

    #: 1-based number
    phase: int
    #: the reference's mode (``stick/stick``, ``stick/slip+``, ``flight``, …)
    mode: str
    #: time of its first row
    t_first: str
    #: time of its last row
    t_last: str
    #: its rows
    rows: int
    #: 1-based candidate row of its first row
    row_first: int
    #: and of its last
    row_last: int
    #: every column certainly within tolerance there
    passed: bool
    #: ``pass``, ``fail`` or ``undecided``
    verdict: str


class EventVerdict(NamedTuple):
    """The verdict on one event of the reference, or on a change of mode of
    the candidate the reference does not have (``kind`` ``spurious``)."""

    #: ``slip_onset``, ``stick``, ``separation``, ``impact``, …, ``spurious``
    kind: str
    #: ``floor`` or ``contact``, where the event concerns one
    contact: Optional[str]
    #: the mode entered (``-`` at the end of the model)
    mode: str
    #: the reference's ``{"t", "theta"}`` (verified digits), None for ``spurious``
    reference: Optional[Dict[str, str]]
    #: the candidate's transition matched with it: ``{"from", "to", "rows",
    #: "t", "theta"}`` (its last row in the old mode and first in the new)
    candidate: Optional[Dict[str, Any]]
    #: the error in θ: the oracle's θ at the nearer end of the candidate's
    #: bracket minus the event's (0 when the event lies inside it)
    error: Optional[float]
    #: the verdict; None where the event is not judged
    passed: Optional[bool]
    #: why, in words
    why: str


class BranchReport(NamedTuple):
    """The branch judged against where the motion is not unique."""

    #: ``auto``, ``stay``, ``part`` or ``part-at θ``
    requested: str
    #: the branch followed (``stay``, ``part``, ``part-at θ``)
    followed: str
    #: why, in words (under ``auto``: where the candidate parted)
    why: str
    #: False when the candidate parted where the rigid-body motion may not
    lawful: bool
    #: ``{"theta_indeterminate", "theta_s"}``: where parting is lawful (None
    #: where the motion is unique)
    window: Optional[Dict[str, str]]
    #: where the candidate parted (``found_by``, ``rows``, ``t``, ``theta``),
    #: when ``auto`` looked for it and found it
    parting: Optional[Dict[str, Any]]


def _first(d: Optional[Mapping[str, Any]]) -> Optional[FirstFailure]:
    if d is None:
        return None
    return FirstFailure(row=d["row"], t=d["t"], column=d["column"], candidate=d["candidate"],
                        oracle=d["oracle"], limit=_num(d["limit"]), bound=d["bound"])


def _column(c: Mapping[str, Any]) -> ColumnStats:
    phases = [PhaseStats(max_abs=_num(p["max_abs"]), max_abs_t=p["max_abs_t"],
                         worst_err_over_limit=_num(p["worst_err_over_limit"]),
                         failures=p["failures"], undecided=p["undecided"], passed=p["passed"])
              for p in c["phases"]]
    return ColumnStats(
        column=c["column"], rtol=c["rtol"], atol=_num(c["atol"]), scale=_num(c["scale"]),
        tol_set=c["tol_set"], max_abs=_num(c["max_abs"]), max_abs_t=c["max_abs_t"],
        max_rel=None if c["max_rel"] is None else _num(c["max_rel"]), max_rel_t=c["max_rel_t"],
        worst_err_over_limit=_num(c["worst_err_over_limit"]), worst_bound=c["worst_bound"],
        failures=c["failures"], undecided=c["undecided"], phases=phases)


class CheckReport:
    """The verdict of :func:`check`; the attributes are the keys of
    ``cylroll check --format json`` (numbers as numbers).

    ``passed`` (every value certainly within tolerance, every judged event
    within ``event_tol``, the branch lawful), ``verdict`` (``"pass"``,
    ``"fail"``, or ``"undecided"``: nothing fails but a value lies within
    the oracle's error bound of its limit), ``columns`` (a
    :class:`ColumnStats` per judged column, in the candidate's order, without
    ``t``), ``phases`` (:class:`Phase`), ``events`` (:class:`EventVerdict`),
    ``branch`` (:class:`BranchReport`), ``first_failure`` and
    ``first_undecided`` (:class:`FirstFailure` or ``None``), ``case``,
    ``rows``, ``rows_after_end`` and ``first_after_end`` (rows after the end
    of the model, left out), ``end``, ``rtol``, ``atol``, ``event_tol``,
    ``oracle_digits``, ``notes`` (remarks on the judgement, as the command
    line's ``NOTE:`` lines); ``report`` is the whole JSON object as a dict.
    ``str(report)`` is the command line's table.
    """

    def __init__(self, d: Mapping[str, Any]) -> None:
        r = json.loads(d["report"])
        self.report: Dict[str, Any] = r
        self.case: str = r["case"]
        self.passed: bool = bool(d["passed"])
        self.verdict: str = d["verdict"]
        self.rows: int = r["rows"]
        self.rows_after_end: int = r["rows_after_end"]
        self.first_after_end: Optional[Dict[str, Any]] = r["first_after_end"]
        self.notes: List[str] = list(r.get("notes", []))
        self.end: Optional[Dict[str, str]] = r["end"]
        self.rtol: float = r["rtol"]
        self.atol: float = r["atol"]
        self.event_tol: float = r["event_tol"]
        self.oracle_digits: int = r["oracle_digits"]
        b = r["branch"]
        self.branch = BranchReport(requested=b["requested"], followed=b["followed"],
                                   why=b["why"], lawful=b["lawful"], window=b["window"],
                                   parting=b["parting"])
        self.phases: List[Phase] = [Phase(**p) for p in r["phases"]]
        self.columns: List[ColumnStats] = [_column(c) for c in r["columns"]]
        self.events_judged: bool = r["events_judged"]
        self.events: List[EventVerdict] = [
            EventVerdict(kind=e["kind"], contact=e["contact"], mode=e["mode"],
                         reference=e["reference"], candidate=e["candidate"],
                         error=None if e["error"] is None else _num(e["error"]),
                         passed=e["passed"], why=e["why"])
            for e in r["events"]]
        self.transitions: int = r["transitions"]
        self.first_failure: Optional[FirstFailure] = _first(r["first_failure"])
        self.first_undecided: Optional[FirstFailure] = _first(r["first_undecided"])
        self.text: str = d["text"]

    @property
    def digits(self) -> int:
        """The oracle's significant digits (an alias of :attr:`oracle_digits`)."""
        return self.oracle_digits

    def column(self, name: str) -> ColumnStats:
        """The statistics of one column."""
        for c in self.columns:
            if c.column == name:
                return c
        raise KeyError(f"no column {name!r} was judged; judged: "
                       f"{', '.join(c.column for c in self.columns)}")

    def event(self, kind: str, contact: Optional[str] = None) -> Optional[EventVerdict]:
        """The first event verdict of that kind (and contact), or None."""
        for e in self.events:
            if e.kind == kind and (contact is None or e.contact == contact):
                return e
        return None

    def to_dict(self) -> Dict[str, Any]:
        """The JSON report as a dict (numbers as numbers)."""
        return dict(self.report)

    def __str__(self) -> str:
        return self.text.rstrip("\n")

    def __repr__(self) -> str:
        return self.__str__()


def _cell(name: str, x: Any) -> str:
    if isinstance(x, str):
        return x.strip()
    if isinstance(x, (bool, np.bool_)):
        raise TypeError(f"column {name}: a bool is not a number")
    if isinstance(x, (int, np.integer)):
        return str(int(x))
    # exact numbers are judged as they are, not through a float64
    if isinstance(x, decimal.Decimal):
        return str(x)
    if isinstance(x, fractions.Fraction):
        return _fraction_text(name, x)
    if x is None or isinstance(x, (complex, np.complexfloating)) or not isinstance(
        x, (float, np.floating, numbers.Real)
    ):
        raise TypeError(f"expected a real number or its text, got {type(x).__name__}")
    # the shortest decimal that reads back as the same float in its own
    # type (a float32 0.1 is 0.1; inf and nan are refused by the core, with
    # the row named)
    return shortest_text(x)


def _fraction_text(name: str, x: fractions.Fraction) -> str:
    """The exact decimal of a Fraction whose denominator is 2^a 5^b; any
    other is refused (it has no decimal, and a rounding would be judged)."""
    d = x.denominator
    a = b = 0
    while d % 2 == 0:
        d //= 2
        a += 1
    while d % 5 == 0:
        d //= 5
        b += 1
    if d != 1:
        raise ValueError(
            f"{x} has no exact decimal: give it as a decimal string or a "
            f"Decimal (the candidate is judged as written, not rounded)"
        )
    k = max(a, b)
    # x·10^k is an integer: its digits with the point k places from the right
    n = x.numerator * 10**k // x.denominator
    sign = "-" if n < 0 else ""
    digits = str(abs(n)).rjust(k + 1, "0")
    return f"{sign}{digits[:-k]}.{digits[-k:]}" if k else f"{sign}{digits}"


def _from_mapping(cand: Any) -> Tuple[List[str], List[List[str]]]:
    names = [str(k) for k in cand.keys()]
    cols = []
    for k, name in zip(cand.keys(), names):
        col = cand[k]
        arr = col.to_numpy() if hasattr(col, "to_numpy") else np.asarray(col)
        if arr.ndim == 0:
            arr = arr.reshape(1)
        if arr.ndim != 1:
            # a DataFrame with two columns of one name gives a 2-d selection
            why = (f"the name stands for {arr.shape[1]} columns"
                   if arr.ndim == 2 and hasattr(col, "columns") else
                   f"expected a 1-d array, got shape {arr.shape}")
            raise _invalid("candidate", f"column {name}", why)
        if any(c in name for c in ',"\r\n'):
            raise _invalid("candidate", name, "a column name may not hold a comma, a quote or a "
                           "line break")
        # numpy scalars of a float type other than float64 keep their type
        # (tolist() would widen float32 to the float64 it is, not the
        # decimal it prints as)
        items = list(arr) if arr.dtype.kind == "f" and arr.dtype != np.float64 else arr.tolist()
        cells = []
        for i, x in enumerate(items):
            try:
                c = str(x).strip() if name in _TEXT else _cell(name, x)
            except (TypeError, ValueError) as e:
                raise _invalid("candidate", f"row {i + 1}, column {name}: {x!r}", str(e)) from None
            if any(ch in c for ch in ',"\r\n'):
                raise _invalid("candidate", f"row {i + 1}, column {name}: {c!r}",
                               "a cell may not hold a comma, a quote or a line break")
            cells.append(c)
        cols.append(cells)
    n = {len(c) for c in cols}
    if len(n) > 1:
        lens = ", ".join(f"{k}: {len(c)}" for k, c in zip(names, cols))
        raise _invalid("candidate", lens, "the columns must have the same length")
    return names, [list(r) for r in zip(*cols)]


def _csv_text(names: List[str], rows: List[List[str]]) -> str:
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(names)
    w.writerows(rows)
    return buf.getvalue()


def _tol_text(name: str, x: Any) -> str:
    """A tolerance as the decimal text the library reads (as the command
    line's): a float as its shortest repr, an int, ``Decimal`` or text as
    given, a ``Fraction`` to 17 significant digits (so that 1e-400 stays
    itself, refused, and is not read as 0)."""
    if isinstance(x, bool):
        raise TypeError(f"{name}: expected a number, got bool")
    if isinstance(x, str):
        return x
    if isinstance(x, Decimal):
        return str(x)
    if isinstance(x, numbers.Integral):
        return str(int(x))
    if isinstance(x, Fraction):
        if x < 0:
            return "-" + _tol_text(name, -x)
        with localcontext() as c:
            c.prec = 17
            return str(Decimal(x.numerator) / Decimal(x.denominator))
    if isinstance(x, numbers.Real):
        return repr(float(x))
    raise TypeError(f"{name}: expected a number, got {type(x).__name__}")


def _tols(tol: Optional[Mapping[str, Any]]) -> List[Tuple[str, str, Optional[str]]]:
    if tol is not None and not hasattr(tol, "items"):
        raise TypeError(f"tol: expected a mapping of column -> rtol or (rtol, atol), got {type(tol).__name__}")
    out = []
    for column, v in (tol or {}).items():
        name = f"tol[{column!r}]"
        if isinstance(v, (tuple, list)):
            if len(v) != 2:
                raise ValueError(f"{name}: expected rtol or (rtol, atol), got {v!r}")
            out.append((str(column), _tol_text(name, v[0]),
                        None if v[1] is None else _tol_text(name, v[1])))
        else:
            out.append((str(column), _tol_text(name, v), None))
    return out


def check(
    candidate: Union[str, "os.PathLike[str]", Mapping[str, Any], Any],
    case: Union[str, Model] = "mujoco_main",
    *,
    rtol: float = 1e-8,
    atol: float = 1e-10,
    tol: Optional[Mapping[str, Union[float, Tuple[float, Optional[float]]]]] = None,
    branch: str = "auto",
    part_at: Optional[Union[str, float]] = None,
    event_tol: Optional[float] = None,
    digits: int = 20,
    past_end: str = "report",
    max_rows: Optional[int] = None,
    schema: Optional[int] = None,
) -> CheckReport:
    """Judges another program's table against the oracle: the command line's
    ``cylroll check``, by the same scoring core.

    ``candidate``: a mapping of column name -> 1-d array (a ``dict`` of
    NumPy arrays, a pandas ``DataFrame``) or the path of a CSV file with a
    header row. Columns are matched by name: any subset of the oracle's
    (``t, theta, theta_dot, theta_ddot, phi1, phi2, x1, x2, y2, x1_dot,
    phi1_dot, x2_dot, y2_dot, phi2_dot, F1, N1, F21, N12, s1, s12, work``);
    ``t`` is required, the rows in time order; a ``mode`` column
    (``"stick/stick"``, ``"flight"``, …) is compared with the reference's
    mode of each row, and its changes are judged as events. The oracle is
    evaluated at the candidate's own times (no interpolation); a float time
    is read as the decimal it prints as.

    ``case``: a golden case by name (``cylroll.golden.names()``) or a
    :class:`Model`.

    A value fails when \\|candidate − oracle\\| > atol + rtol·\\|oracle\\|
    (numpy's ``isclose`` rule), the oracle at ``digits`` significant digits;
    ``atol`` is in units of each column's natural scale (time sqrt(r/g),
    lengths r, velocities sqrt(g r), forces (m1 + m2) g, work m2 g r).
    ``tol={"theta": 1e-3, "N12": (1e-2, 1e-4)}`` sets a column's rtol, and
    its atol in the column's own units. An rtol finer than ``digits`` can
    judge (below 10^(2 − digits)) is refused; a value within the oracle's
    error bound of its limit is *undecided* (``verdict``), never judged on
    unverified digits.

    ``branch``: where the motion is not unique (between the branch point θ*
    and θs), ``"auto"`` judges the candidate against the branch it took (it
    parted at θ*: ``part``; at θs: ``stay``; inside: parting at its own
    angle; before θ*: not lawful, a failure), or ``"stay"`` / ``"part"``;
    ``part_at`` an angle. ``event_tol``: the tolerance of an event in radians
    of θ (default 1e-3). ``past_end``: rows after the end of the model (the
    first impact) are left out and reported (``"report"``) or refused
    (``"refuse"``). ``max_rows``: the largest number of data rows accepted
    (default 1 000 000, at most 10^8; the candidate is read in chunks).
    ``schema``: ``1`` judges a candidate written in the first golden schema
    (φ2 of a rolling contact in the paper's gauge, r1 θ0/r2 below today's),
    as ``cylroll check --schema 1``; by default ``2``.

    Tolerances (``rtol``, ``atol``, ``tol``'s values, ``event_tol``) are
    numbers or their text: 0, or finite from 1e-300 on (a smaller one would
    be judged as 0 or as a subnormal of a few bits, and is refused).

    Returns a :class:`CheckReport`; raises :class:`InvalidParameterError`
    (a ``ValueError``) for a malformed candidate, naming the row, and
    :class:`VerificationError` as the oracle can.
    """
    if isinstance(case, Model):
        case_name, pairs = "model", case.to_dict()
    elif isinstance(case, str):
        case_name, pairs = case, None
    else:
        raise TypeError(f"case: expected a golden case name or a Model, got {type(case).__name__}")
    if isinstance(candidate, (str, os.PathLike)):
        text, path, source = None, os.fspath(candidate), os.fspath(candidate)
    elif hasattr(candidate, "keys"):
        names, rows = _from_mapping(candidate)
        text, path, source = _csv_text(names, rows), None, "candidate"
    else:
        raise TypeError("candidate: expected a CSV path, a dict of arrays or a DataFrame, "
                        f"got {type(candidate).__name__}")
    if not isinstance(branch, str):
        raise TypeError(f"branch: expected 'auto', 'stay' or 'part', got {type(branch).__name__}")
    if part_at is not None and not isinstance(part_at, str):
        # exactly, as the Model's methods read an angle (a float as the
        # decimal it prints as)
        if isinstance(part_at, (float, np.floating)):
            part_at = _cell("part_at", part_at)
        else:
            part_at = exact_text("part_at", part_at, False)
    rows = None if max_rows is None else _count("max_rows", max_rows, _cylroll.MAX_ROWS)
    d = _cylroll.check(text, path, source, case_name, pairs, _tol_text("rtol", rtol),
                       _tol_text("atol", atol), _tols(tol), branch, part_at,
                       None if event_tol is None else _tol_text("event_tol", event_tol),
                       _digits(digits), str(past_end), rows,
                       None if schema is None else _count("schema", schema, 2))
    return CheckReport(d)
