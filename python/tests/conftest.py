import os
import pathlib

import pytest

#: The repository root (the golden data live there; the installed package
#: does not need it, these tests do).
ROOT = pathlib.Path(__file__).resolve().parents[2]
GOLDEN = ROOT / "golden"


@pytest.fixture
def golden_dir():
    if not (GOLDEN / "data").is_dir():
        pytest.skip("needs the repository's golden/ directory")
    return GOLDEN
