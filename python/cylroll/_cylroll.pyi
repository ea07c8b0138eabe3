"""Type stubs of the native module cylroll._cylroll (PyO3). Use the public API of
``cylroll`` instead: these functions take the model as key/value text and return plain
tuples; the Python modules turn them into classes."""

from typing import Dict, List, Optional, Tuple

#: (name, text, digits, err, err_text)
_Value = Tuple[str, str, int, float, str]
#: (kind, contact, mode, t, theta)
_Event = Tuple[str, Optional[str], Optional[str], _Value, _Value]

MODEL_KEYS: List[str]
FRICTION_KEYS: List[str]
COLUMNS: List[str]
FORCE_KEYS: List[str]
MAX_DIGITS: int
MAX_ROWS: int
LIBRARY_VERSION: str

#: an answer: values, notes, events, start_mode, end, impact_surface, branch, mode,
#: routes (trajectory also columns, rows, modes)
_Answer = Dict[str, object]

def validate(pairs: Dict[str, str]) -> List[Tuple[str, str]]: ...
def read_toml(path: str) -> Dict[str, str]: ...
def golden_names() -> List[str]: ...
def golden_case(name: str) -> Tuple[str, Dict[str, str], str, int]: ...
def separation(
    pairs: Dict[str, str], digits: int, branch: str = ..., part_at: Optional[str] = ...
) -> _Answer: ...
def time(
    pairs: Dict[str, str], digits: int, theta: str, branch: str = ..., part_at: Optional[str] = ...
) -> _Answer: ...
def forces(
    pairs: Dict[str, str], digits: int, theta: str, branch: str = ..., part_at: Optional[str] = ...
) -> _Answer: ...
def trajectory(
    pairs: Dict[str, str],
    digits: int,
    times: List[str],
    branch: str = ...,
    part_at: Optional[str] = ...,
    columns: Optional[str] = ...,
) -> _Answer: ...
def check(
    csv: Optional[str],
    path: Optional[str],
    source: str,
    case_name: str,
    pairs: Optional[Dict[str, str]],
    rtol: str,
    atol: str,
    tols: List[Tuple[str, str, Optional[str]]],
    branch: str,
    part_at: Optional[str],
    event_tol: Optional[str],
    digits: int,
    past_end: str,
    max_rows: Optional[int],
    schema: Optional[int] = ...,
) -> Dict[str, object]: ...
def enclose(
    pairs: Dict[str, str], digits: int, what: str, theta: Optional[str] = ...
) -> List[Tuple[str, str, int, str, str]]: ...
