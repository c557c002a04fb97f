"""The public names of the package stay what they say, whatever was imported before."""
import importlib

import dhlab


def test_panel_functions_are_not_shadowed_by_their_modules():
    for module in ("dhlab.teach", "dhlab.spaces", "dhlab.stepthrough", "dhlab.view"):
        importlib.import_module(module)
    assert callable(dhlab.teach) and callable(dhlab.spaces)
    assert callable(dhlab.stepthrough) and callable(dhlab.stepthrough_link) and callable(dhlab.robot_view)


def test_everything_in_all_exists():
    missing = [name for name in dhlab.__all__ if not hasattr(dhlab, name)]
    assert not missing
