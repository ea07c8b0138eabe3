"""Assertions for test suites (pytest, unittest): hold an engine's table to the
oracle.

.. code-block:: python

    from cylroll.testing import assert_matches_oracle

    def test_rolling_phase():
        table = run_my_engine(dt=1e-4)          # {"t": ..., "theta": ..., ...}
        assert_matches_oracle(table, case="mujoco_main", rtol=1e-3, atol=1e-6)
"""

from __future__ import annotations

from typing import Any, Union

from ._check import CheckReport, check
from ._model import Model

__all__ = ["assert_matches_oracle"]


def assert_matches_oracle(
    candidate: Any,
    case: Union[str, Model] = "mujoco_main",
    *,
    rtol: float = 1e-8,
    atol: float = 1e-10,
    digits: int = 20,
) -> CheckReport:
    """Asserts that ``candidate`` matches the oracle within ``atol + rtol·|oracle|``
    everywhere (see :func:`cylroll.check` for the arguments).

    Raises ``AssertionError`` whose message is the check's table (per-column
    maximum errors and where, the first failing row); returns the
    :class:`cylroll.CheckReport` when it passes.
    """
    __tracebackhide__ = True  # pytest: show the caller's line
    report = check(candidate, case, rtol=rtol, atol=atol, digits=digits)
    if not report.passed:
        raise AssertionError("the candidate does not match the oracle:\n" + report.text)
    return report
