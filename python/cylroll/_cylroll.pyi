"""Type stubs of the native module cylroll._cylroll (PyO3). Use the public API of
``cylroll`` instead: these functions take the model as key/value text and return plain
tuples; the Python modules turn them into classes."""

from typing import Dict, List, Optional, Tuple, Union

#: (name, text, digits, err, err_text)
_Value = Tuple[str, str, int, float, str]
#: (kind, contact, mode, t, theta)
_Event = Tuple[str, Optional[str], Optional[str], _Value, _Value]

MODEL_KEYS: List[str]
FRICTION_KEYS: List[str]
TRAJECTORY_COLUMNS: List[str]
FRICTION_COLUMNS: List[str]
FORCE_KEYS: List[str]
FRICTION_FORCE_KEYS: List[str]
MAX_DIGITS: int
LIBRARY_VERSION: str

def validate(
    pairs: Dict[str, str],
) -> Tuple[List[Tuple[str, str]], Optional[Tuple[str, str]]]: ...
def read_toml(path: str) -> Dict[str, str]: ...
def golden_names() -> List[str]: ...
def golden_case(name: str) -> Tuple[str, Dict[str, str], str, int]: ...
def separation(
    pairs: Dict[str, str], digits: int, mu: Optional[str] = None
) -> Dict[str, Union[List[_Value], List[str], str, List[_Event]]]: ...
def time(pairs: Dict[str, str], digits: int, theta: str) -> Tuple[_Value, Optional[str]]: ...
def forces(
    pairs: Dict[str, str], digits: int, theta: str
) -> Tuple[List[_Value], Optional[str]]: ...
def trajectory(
    pairs: Dict[str, str], digits: int, times: List[str]
) -> Tuple[List[str], List[List[_Value]], Optional[List[str]]]: ...
def check(
    csv: str,
    source: str,
    case_name: str,
    pairs: Optional[Dict[str, str]],
    rtol: float,
    atol: float,
    digits: int,
) -> Dict[str, object]: ...
def enclose(
    pairs: Dict[str, str], digits: int, what: str, theta: Optional[str] = ...
) -> List[Tuple[str, str, int, str, str]]: ...
