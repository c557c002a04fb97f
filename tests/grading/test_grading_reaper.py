"""dhlab.grading.run.reaper: a daemon started below the grader dies before the grader writes its result."""
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

from dhlab.grading.run import isolation

GRADER = r'''import os, sys, time
from dhlab.grading.run import reaper
assert reaper.become_subreaper()
mark = sys.argv[1]
if os.fork() == 0:                      # the "kernel": starts a daemon (double fork, setsid) and exits
    os.setsid()
    if os.fork() == 0:
        null = os.open(os.devnull, os.O_RDWR)
        for fd in (0, 1, 2):            # as daemons do: let go of the grader's pipes
            os.dup2(null, fd)
        for _ in range(400):
            open(mark, "w").write(f"{os.getpid()} {time.time()}")
            time.sleep(0.05)
    os._exit(0)
for _ in range(400):                    # until the daemon runs, orphaned (on a loaded machine: seconds)
    if os.path.exists(mark):
        break
    time.sleep(0.05)
below = reaper.descendants()
left = reaper.end_descendants() if sys.argv[2] == "end" else []
print(len(below), len(left), len(reaper.descendants()))
'''


def _grader(tmp_path, end: bool):
    mark = tmp_path / "alive"
    out = subprocess.run([sys.executable, "-c", GRADER, str(mark), "end" if end else "keep"], capture_output=True,
                         text=True, timeout=60, env=dict(os.environ, PYTHONPATH=str(Path(__file__).parents[2])))
    assert out.returncode == 0, out.stderr
    return mark, [int(x) for x in out.stdout.split()]


def _still_written(mark: Path) -> bool:
    first = mark.read_text()
    time.sleep(0.4)
    return mark.read_text() != first


def test_the_orphaned_daemon_stays_below_the_grader_and_dies(tmp_path):
    mark, (below, left, after) = _grader(tmp_path, end=True)
    assert below >= 1 and left >= 1 and after == 0
    assert mark.exists() and not _still_written(mark)


def test_without_ending_them_the_daemon_outlives_the_grader(tmp_path):
    """The test above can fail: without end_descendants the daemon keeps writing."""
    mark, (below, left, after) = _grader(tmp_path, end=False)
    try:
        assert below >= 1 and after >= 1 and _still_written(mark)
    finally:
        try:
            os.kill(int(mark.read_text().split()[0]), signal.SIGKILL)      # the daemon this test started
        except (OSError, ValueError):
            pass


def test_a_bare_uid_has_its_own_number_as_group():
    assert isolation._gid_of(isolation.NOBODY_UID + 4321) == isolation.NOBODY_UID + 4321
    assert isolation._gid_of(0) == 0
