"""The notebook kernels' private sockets (used by tests/conftest.py for nbval).

Why the kernels use Unix sockets (the flaky "Kernel didn't respond in 60 seconds")
-------------------------------------------------------------------------------
nbval starts one Jupyter kernel per notebook. jupyter_client picks a kernel's five
TCP ports in the *test process* (bind to port 0, read the number, close the socket)
and the kernel binds them seconds later, once Python has started. Its cache of
ports handed out is per process, so under ``pytest -n 2`` two workers — and the
grading tests, which start sandbox kernels in other processes at the same time —
can be given the same free port. If the port taken twice is a kernel's IOPub port,
that kernel stays alive but its IOPub thread cannot bind, while our client listens
to the other kernel's IOPub: ``wait_for_ready`` never sees the message it waits for,
and after 60 s the whole notebook errors ("Kernel didn't respond in 60 seconds").
(Forcing one kernel's IOPub port onto another's reproduces exactly that message,
with the kernel alive; a shared shell or control port gives "Kernel died" instead.)

A kernel started here talks over Unix domain sockets in a folder of its own (the
``ipc`` transport of ZeroMQ): there are no ports to pick, so no two processes can
ever pick the same one, whatever else runs on the machine.
"""
import os
import shutil
import tempfile

from jupyter_client.manager import KernelManager
from jupyter_client.utils import run_sync


class PrivateSocketKernelManager(KernelManager):
    """A KernelManager whose kernel listens on Unix sockets in its own temporary folder."""

    def __init__(self, **kwargs):
        folder = tempfile.mkdtemp(prefix="dhlab-kernel-")
        kwargs.setdefault("transport", "ipc")
        kwargs.setdefault("ip", os.path.join(folder, "kernel"))   # sockets kernel-1 … kernel-5
        super().__init__(**kwargs)
        self._socket_folder = folder

    async def _async_cleanup_resources(self, restart: bool = False) -> None:
        await super()._async_cleanup_resources(restart=restart)       # (shutdown_kernel calls this one)
        if not restart:
            shutil.rmtree(self._socket_folder, ignore_errors=True)

    cleanup_resources = run_sync(_async_cleanup_resources)
