"""``cylroll.check``: hold another program's table against the oracle."""

from __future__ import annotations

import csv
import io
import os
from typing import Any, List, Mapping, NamedTuple, Optional, Tuple, Union

import numpy as np

from . import _cylroll
from ._model import Model, _digits

__all__ = ["check", "CheckReport", "ColumnStats", "FirstFailure"]

#: Columns that are not numbers: compared as text (the phase of each row).
_TEXT = ("mode",)


class ColumnStats(NamedTuple):
    """Per-column statistics of a check."""

    #: column name
    name: str
    #: largest |candidate − oracle|
    max_abs: float
    #: the time where it occurs (as the candidate wrote it)
    max_abs_t: str
    #: largest |candidate − oracle| / |oracle|; ``None`` when every oracle
    #: value of the column is 0 (a relative error is undefined there)
    max_rel: Optional[float]
    #: the time where it occurs
    max_rel_t: str
    #: rows out of tolerance
    failures: int
    #: largest |candidate − oracle| / (atol + rtol·|oracle|): above 1 fails
    worst_ratio: float
    #: which term of that limit was the larger where it occurs: ``"atol"``
    #: (an oracle value near 0) or ``"rtol"``
    worst_bound: str


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
    #: the oracle's value (verified digits)
    oracle: str
    #: the limit atol + rtol·|oracle| it exceeded
    limit: float
    #: which term of the limit was the larger: ``"atol"`` or ``"rtol"``
    bound: str


class CheckReport:
    """The verdict of :func:`check`.

    ``passed``: every value within tolerance; ``columns``: a
    :class:`ColumnStats` per judged column (in the candidate's order, without
    ``t``); ``first_failure``: a :class:`FirstFailure` or ``None``; ``case``,
    ``rows``, ``rtol``, ``atol``, ``digits`` (of the oracle values compared
    against). ``str(report)`` is the command line's table.
    """

    def __init__(self, d: Mapping[str, Any]) -> None:
        self.case: str = d["case"]
        self.rtol: float = d["rtol"]
        self.atol: float = d["atol"]
        self.rows: int = d["rows"]
        self.digits: int = d["digits"]
        self.passed: bool = d["passed"]
        self.columns: List[ColumnStats] = [ColumnStats(*c) for c in d["columns"]]
        ff = d["first_failure"]
        self.first_failure: Optional[FirstFailure] = None if ff is None else FirstFailure(*ff)
        self.text: str = d["text"]

    def column(self, name: str) -> ColumnStats:
        """The statistics of one column."""
        for c in self.columns:
            if c.name == name:
                return c
        raise KeyError(f"no column {name!r} was judged; judged: "
                       f"{', '.join(c.name for c in self.columns)}")

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
    # the shortest decimal that reads back as the same float
    return repr(float(x))


def _from_mapping(cand: Any) -> Tuple[List[str], List[List[str]]]:
    names = [str(k) for k in cand.keys()]
    cols = []
    keep = []
    for k, name in zip(cand.keys(), names):
        col = cand[k]
        arr = col.to_numpy() if hasattr(col, "to_numpy") else np.asarray(col)
        if arr.ndim == 0:
            arr = arr.reshape(1)
        if arr.ndim != 1:
            raise ValueError(f"column {name}: expected a 1-d array, got shape {arr.shape}")
        keep.append(name)
        if name in _TEXT:
            cols.append([str(x).strip() for x in arr.tolist()])
        else:
            cols.append([_cell(name, x) for x in arr.tolist()])
    n = {len(c) for c in cols}
    if len(n) > 1:
        lens = ", ".join(f"{k}: {len(c)}" for k, c in zip(keep, cols))
        raise ValueError(f"the columns have different lengths ({lens})")
    rows = [list(r) for r in zip(*cols)]
    return keep, rows


def _from_csv(path: str) -> Tuple[List[str], List[List[str]]]:
    with open(path, newline="") as f:
        rows = [r for r in csv.reader(f) if any(c.strip() for c in r)]
    if not rows:
        return [], []
    head = [c.strip() for c in rows[0]]
    return head, [[r[i] if i < len(r) else "" for i in range(len(head))] for r in rows[1:]]


def check(
    candidate: Union[str, "os.PathLike[str]", Mapping[str, Any], Any],
    case: Union[str, Model] = "mujoco_main",
    *,
    rtol: float = 1e-8,
    atol: float = 1e-10,
    digits: int = 20,
) -> CheckReport:
    """Judges another program's table against the oracle.

    ``candidate``: a mapping of column name -> 1-d array (a ``dict`` of
    NumPy arrays, a pandas ``DataFrame``) or the path of a CSV file with a
    header row. Columns are matched by name: any subset of the oracle's
    (``t, theta, theta_dot, theta_ddot, phi1, phi2, x1, x2, y2, x1_dot,
    phi1_dot, x2_dot, y2_dot, phi2_dot, F1, N1, F21, N12, s1, s12, work``);
    ``t`` is required; a ``mode`` column (``"stick/stick"``, ``"flight"``,
    …) is compared with the oracle's phase of each row. The oracle is evaluated at the candidate's
    own times (no interpolation); a float time is read as the decimal it
    prints as.

    ``case``: a golden case by name (``cylroll.golden.names()``) or a
    :class:`Model`.

    A value fails when \\|candidate − oracle\\| > atol + rtol·\\|oracle\\|
    (numpy's ``isclose`` rule), the oracle at ``digits`` significant digits.
    Returns a :class:`CheckReport`; raises ``ValueError`` for a malformed
    candidate (an unknown column, no ``t``, a cell that is not a number) and
    :class:`VerificationError` as the oracle can.
    """
    if isinstance(candidate, (str, os.PathLike)):
        source = os.fspath(candidate)
        names, rows = _from_csv(source)
    elif hasattr(candidate, "keys"):
        source = "candidate"
        names, rows = _from_mapping(candidate)
    else:
        raise TypeError("candidate: expected a CSV path, a dict of arrays or a DataFrame, "
                        f"got {type(candidate).__name__}")
    buf = io.StringIO()
    buf.write(",".join(names) + "\n")
    for r in rows:
        buf.write(",".join(r) + "\n")
    if isinstance(case, Model):
        case_name, pairs = "model", case.to_dict()
    elif isinstance(case, str):
        case_name, pairs = case, None
    else:
        raise TypeError(f"case: expected a golden case name or a Model, got {type(case).__name__}")
    d = _cylroll.check(buf.getvalue(), source, case_name, pairs, float(rtol), float(atol),
                       _digits(digits))
    return CheckReport(d)
