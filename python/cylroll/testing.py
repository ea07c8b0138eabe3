"""Assertions for test suites (pytest, unittest): hold an engine's table to the
oracle, with the scoring of ``cylroll check``.

.. code-block:: python

    from cylroll.testing import assert_conforms

    def test_my_engine():
        table = run_my_engine(dt=1e-4)          # {"t": ..., "theta": ..., "mode": ...}
        assert_conforms(table, "main_mu_0_3", rtol=1e-3, atol=1e-6)
"""

from __future__ import annotations

from typing import Any, Union

from ._check import CheckReport, check
from ._model import Model

__all__ = ["assert_conforms", "assert_matches_oracle"]


def assert_conforms(
    candidate: Any,
    case: Union[str, Model] = "mujoco_main",
    **kwargs: Any,
) -> CheckReport:
    """Asserts that ``candidate`` conforms to the reference: every value within
    its column's tolerance, every judged event within ``event_tol``, on a
    lawful branch (keyword arguments as :func:`cylroll.check`: ``rtol``,
    ``atol``, ``tol``, ``branch``, ``part_at``, ``event_tol``, ``digits``,
    ``past_end``).

    Raises ``AssertionError`` whose message is the check's table (per column,
    per phase and per event, the branch judged against, the first failing row);
    returns the :class:`cylroll.CheckReport` when it passes.
    """
    __tracebackhide__ = True  # pytest: show the caller's line
    report = check(candidate, case, **kwargs)
    if not report.passed:
        what = ("a verdict rests on digits the oracle did not verify"
                if report.verdict == "undecided" else "it does not conform")
        raise AssertionError(f"the candidate against {report.case}: {what}:\n" + report.text)
    return report


def assert_matches_oracle(
    candidate: Any,
    case: Union[str, Model] = "mujoco_main",
    *,
    rtol: float = 1e-8,
    atol: float = 1e-10,
    digits: int = 20,
    **kwargs: Any,
) -> CheckReport:
    """:func:`assert_conforms` under its earlier name (the same check)."""
    __tracebackhide__ = True
    return assert_conforms(candidate, case, rtol=rtol, atol=atol, digits=digits, **kwargs)
