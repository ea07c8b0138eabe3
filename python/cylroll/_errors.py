"""The exceptions of cylroll, one per kind of library error.

Every exception carries the library's one-line message (``str(exc)``), the
command line's exit code for it (``exc.exit_code``) and the numbers of the
error as attributes.

==========================  ====================================  =========
exception                   raised for                            exit code
==========================  ====================================  =========
``InvalidParameterError``   a parameter outside its range or      2
                            unparsable (also a ``ValueError``)
``NotPhysicalError``        a request with no finite or physical  2
                            answer (also a ``ValueError``)
``VerificationError``       the requested digits could not be     3
                            verified, or a friction event has no
                            unique continuation
``InputFileError``          an input file cannot be read          2
                            (also an ``OSError``)
``InternalError``           a bug in cylroll (a caught panic)     –
==========================  ====================================  =========
"""

from __future__ import annotations

from typing import Any, Dict, Sequence, Tuple

__all__ = [
    "CylrollError",
    "InvalidParameterError",
    "NotPhysicalError",
    "VerificationError",
    "InputFileError",
    "InternalError",
]


class CylrollError(Exception):
    """Base class of every cylroll error.

    Attributes: ``exit_code`` (the command line's exit status for this error),
    ``fields`` (the numbers of the error, as text).
    """

    exit_code: int = 1

    fields: Dict[str, str] = {}
    kind: str = ""

    def _set_fields(self, kind: str, fields: Dict[str, str]) -> None:
        self.kind = kind
        self.fields = dict(fields)
        for k, v in self.fields.items():
            setattr(self, k, v)


class InvalidParameterError(CylrollError, ValueError):
    """A parameter is outside its allowed range or cannot be parsed.

    Attributes ``name``, ``value`` and ``allowed`` (the allowed range in words).
    """

    exit_code = 2
    name: str
    value: str
    allowed: str


class NotPhysicalError(CylrollError, ValueError):
    """A request with no finite or physical answer (a time from rest exactly at
    the top, a start where the cylinders part at once, cylinders that never
    separate, …). Attribute ``what``."""

    exit_code = 2
    what: str


class VerificationError(CylrollError, ArithmeticError):
    """The numerical method could not verify the requested digits, or (with
    friction) an event where the rigid-body model has no unique continuation:
    the command line's exit code 3. The message says how far it got.

    Attributes ``quantity`` and, depending on the failure, ``requested``,
    ``reached``, ``detail`` or the interval ``lo``, ``hi`` searched."""

    exit_code = 3


class InputFileError(CylrollError, OSError):
    """An input file cannot be read (attributes ``path`` and ``what``)."""

    exit_code = 2


class InternalError(CylrollError, RuntimeError):
    """A bug in cylroll: the library panicked. Nothing was returned."""

    exit_code = 101


_KINDS = {
    "invalid_parameter": InvalidParameterError,
    "not_physical": NotPhysicalError,
    "not_converged": VerificationError,
    "no_sign_change": VerificationError,
    "io": InputFileError,
    "write": InputFileError,
}


def _from_library(
    kind: str, message: str, exit_code: int, fields: Sequence[Tuple[str, str]]
) -> CylrollError:
    """Builds the exception for a library error (called by the native module)."""
    cls: Any = _KINDS.get(kind, CylrollError)
    exc = cls(message)
    exc._set_fields(kind, dict(fields))
    if exc.exit_code != exit_code:
        exc.exit_code = exit_code
    return exc
