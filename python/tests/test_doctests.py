"""The examples in the docstrings run and say what they show."""
import doctest

import pytest

import cylroll
import cylroll._model
import cylroll.golden


@pytest.mark.parametrize("module", [cylroll, cylroll._model, cylroll.golden])
def test_docstring_examples(module):
    result = doctest.testmod(module)
    assert result.failed == 0 and result.attempted > 0
