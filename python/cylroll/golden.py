"""The curated golden cases (``golden/cases/*.toml`` of the repository, built
into the package).

>>> import cylroll
>>> "mujoco_main" in cylroll.golden.names()
True
>>> cylroll.golden.case("mujoco_main") == cylroll.Model(theta0="1/10")
True
"""

from __future__ import annotations

from typing import List

from . import _cylroll
from ._model import Model

__all__ = ["names", "case", "description", "toml", "steps"]


def _name(name: object) -> None:
    if not isinstance(name, str):
        raise TypeError(f"name: expected a golden case name (str), got {type(name).__name__}")


def names() -> List[str]:
    """The names of the golden cases, sorted."""
    return list(_cylroll.golden_names())


def case(name: str) -> Model:
    """The model of the golden case ``name`` (with its friction laws, if any).
    Raises :class:`cylroll.InvalidParameterError` for an unknown name."""
    _name(name)
    _, pairs, _, _ = _cylroll.golden_case(name)
    return Model._from_pairs(dict(pairs))


def description(name: str) -> str:
    """The one-line description of the case."""
    _name(name)
    return _cylroll.golden_case(name)[2]


def steps(name: str) -> int:
    """Intervals of the case's time grid in the golden data (t_i = i t_end / steps)."""
    return _cylroll.golden_case(name)[3]


def toml(name: str) -> str:
    """The case file's text."""
    return _cylroll.golden_case(name)[0]
