"""cylroll: a reference oracle for a cylinder rolling on a rolling cylinder.

Every number is computed to a requested number of significant digits and
returned with only the digits that were verified (two working precisions and
the method's own error estimate; see the repository's README, "Precision and
what is verified").

>>> import cylroll
>>> sep = cylroll.Model().separation()       # identical solid cylinders from rest at the top
>>> sep.theta_s.text                          # π/3
'1.04719755119659774615421446109'
>>> m = cylroll.Model(theta0="1/10", mu_floor="0.3", mu_contact="0.3")
>>> [e.kind for e in m.separation(digits=12).events]
['slip_onset', 'separation', 'impact']
>>> [e.kind for e in cylroll.Model(theta0="1/10").separation(digits=12).events]
['indeterminate', 'separation', 'impact']

The pieces:

- :class:`Model` — exact parameters and the questions :meth:`Model.separation`,
  :meth:`Model.time`, :meth:`Model.forces`, :meth:`Model.trajectory`;
- :class:`Value`, :class:`Separation`, :class:`Event`, :class:`Forces`,
  :class:`Trajectory` — the answers (exact decimal text, NumPy arrays);
- :func:`check` / :func:`cylroll.testing.assert_conforms` — judge another
  program's table (per column, phase, event and branch; the scoring of
  ``cylroll check``);
- :mod:`cylroll.golden` — the curated cases by name;
- the exceptions :class:`InvalidParameterError` and :class:`NotPhysicalError`
  (both ``ValueError``), :class:`VerificationError`, :class:`InputFileError`,
  :class:`InternalError`, all :class:`CylrollError`.

Computations release the GIL and run on a worker thread; Ctrl-C
(``KeyboardInterrupt``) returns at once and stops the computation at its next
rung or integration step.
"""

from . import _cylroll
from ._check import (BranchReport, CheckReport, ColumnStats, EventVerdict, FirstFailure, Phase,
                     PhaseStats, check)
from ._errors import (CylrollError, InputFileError, InternalError, InvalidParameterError,
                      NotPhysicalError, VerificationError)
from ._model import FRICTION_KEYS, MAX_DIGITS, MODEL_KEYS, Model
from ._results import Enclosure, Event, Forces, Separation, Trajectory, Value
from . import golden, testing

__version__ = "0.1.0"

#: The columns of a trajectory, in order, for every contact law (the
#: ``mode`` of each row is apart: :attr:`Trajectory.modes`).
COLUMNS = tuple(_cylroll.COLUMNS)
#: The keys of :meth:`Model.forces` for every contact law.
FORCE_KEYS = tuple(_cylroll.FORCE_KEYS)

__all__ = [
    "Model", "Value", "Separation", "Event", "Forces", "Trajectory", "Enclosure",
    "check", "CheckReport", "ColumnStats", "PhaseStats", "FirstFailure", "Phase",
    "EventVerdict", "BranchReport",
    "CylrollError", "InvalidParameterError", "NotPhysicalError", "VerificationError",
    "InputFileError", "InternalError",
    "golden", "testing",
    "MODEL_KEYS", "FRICTION_KEYS", "COLUMNS", "FORCE_KEYS", "MAX_DIGITS",
]
