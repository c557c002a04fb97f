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


def test_notebook_kernels_use_private_unix_sockets():
    """The fix of the flaky "Kernel didn't respond in 60 seconds" (see tests/kernelsockets.py): nbval's
    kernels listen on Unix sockets in a folder of their own, so no TCP port is picked at all."""
    import os

    import nbval.kernel
    from kernelsockets import PrivateSocketKernelManager

    assert nbval.kernel.KernelManager is PrivateSocketKernelManager
    a, b = PrivateSocketKernelManager(), PrivateSocketKernelManager()
    try:
        assert a.transport == b.transport == "ipc"
        assert a.ip != b.ip and os.path.isdir(os.path.dirname(a.ip))
    finally:
        for km in (a, b):
            km.cleanup_resources()
    assert not os.path.exists(os.path.dirname(a.ip))


def test_unit_helpers_say_their_direction_and_old_names_still_work_with_a_message():
    import math

    import pytest

    assert math.isclose(dhlab.deg2rad(180), math.pi) and math.isclose(dhlab.rad2deg(math.pi), 180.0)
    assert repr(-dhlab.deg2rad(30)) == "deg2rad(-30)"
    with pytest.warns(FutureWarning, match=r"dhlab.deg\(\) is renamed dhlab.deg2rad\(\)"):
        assert dhlab.deg(90) == dhlab.deg2rad(90)
    with pytest.warns(FutureWarning, match=r"dhlab.rad\(\) is renamed dhlab.rad2deg\(\)"):
        assert dhlab.rad(math.pi / 2) == dhlab.rad2deg(math.pi / 2)
