"""The worked examples in dhlab's docstrings run and print what they claim."""
import doctest
import importlib
import pkgutil

import pytest

import dhlab

# every module, subpackages included (dhlab.views.camera, dhlab.grading.release.notebooks, ...)
MODULES = sorted(m.name for m in pkgutil.walk_packages(dhlab.__path__, "dhlab."))


@pytest.mark.parametrize("name", ["dhlab"] + MODULES)
def test_docstring_examples(name):
    module = importlib.import_module(name)
    result = doctest.testmod(module, optionflags=doctest.NORMALIZE_WHITESPACE)
    assert result.failed == 0, f"{result.failed} docstring example(s) failed in {name}"
