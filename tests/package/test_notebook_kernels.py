"""The notebooks' kernels as ``make test`` runs them under nbval: each on private Unix sockets
(tests/conftest.py installs tests/support/kernelsockets.py), never on a TCP port."""


def test_notebook_kernels_use_private_unix_sockets():
    """The fix of the flaky "Kernel didn't respond in 60 seconds" (see tests/support/kernelsockets.py): nbval's
    kernels listen on Unix sockets in a folder of their own, so no TCP port is picked at all."""
    import os

    import nbval.kernel

    from support.kernelsockets import PrivateSocketKernelManager

    assert nbval.kernel.KernelManager is PrivateSocketKernelManager
    a, b = PrivateSocketKernelManager(), PrivateSocketKernelManager()
    try:
        assert a.transport == b.transport == "ipc"
        assert a.ip != b.ip and os.path.isdir(os.path.dirname(a.ip))
    finally:
        for km in (a, b):
            km.cleanup_resources()
    assert not os.path.exists(os.path.dirname(a.ip))
