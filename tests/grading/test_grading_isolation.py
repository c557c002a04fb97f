"""Two graders at once (two classes graded in two terminals, two CI jobs on one machine) never
share a kernel user, so neither kills the other's kernels (dhlab.grading.run.isolation.claim)."""
import os
import pwd
import shutil
import subprocess
import time

import pytest

from dhlab.grading.run import isolation

pytestmark = pytest.mark.skipif(os.geteuid() != 0, reason="kernels run as their own users only when the grader is root")


def _alive(proc) -> bool:
    return proc.poll() is None


def test_two_graders_hold_different_users_and_leave_each_other_alone():
    first = isolation.setup(2, "user")
    try:
        names = [u[0] for u in first.users]
        assert len(set(names)) == 2 and all(n.startswith(isolation.USER_PREFIX) for n in names)
        # a kernel of the first grader, running as its first user
        user = first.users[0]
        kernel = subprocess.Popen(["sleep", "60"], user=user[1], group=user[2], extra_groups=[])
        second = isolation.setup(2, "user")           # its clean slate kills only its own users' processes
        try:
            assert not {u[0] for u in second.users} & set(names), "two graders share a user"
            time.sleep(0.2)
            assert _alive(kernel), "the second grader killed the first grader's kernel"
        finally:
            second.close()
            shutil.rmtree(second.base, ignore_errors=True)
        first.cleanup(user, first.workdir(user), "")  # the first grader ends its own kernel
        kernel.wait(timeout=10)
    finally:
        first.close()
        shutil.rmtree(first.base, ignore_errors=True)


def test_a_user_is_held_until_its_grader_closes():
    name = "dhlab-test-lock-only"                     # a lock no grader takes: nothing else can interfere
    fd = isolation.claim(name)
    assert fd is not None
    assert isolation.claim(name) is None              # held: another grader cannot take it
    os.close(fd)                                      # what Isolation.close() does (and the end of the process)
    again = isolation.claim(name)
    assert again is not None
    os.close(again)


def test_close_gives_the_users_back():
    iso = isolation.setup(1, "user")
    fds = list(iso.locks)
    assert fds and all(os.fstat(fd) for fd in fds)
    iso.close()
    shutil.rmtree(iso.base, ignore_errors=True)
    for fd in fds:
        with pytest.raises(OSError):
            os.fstat(fd)
    assert pwd.getpwnam(iso.users[0][0]).pw_uid != 0


def test_without_any_user_root_still_drops_to_a_bare_uid(monkeypatch):
    """No grading user can be created and there is no 'nobody' (a bare container): root can
    still become uid 65534, so the kernel never runs as root (Gradescope runs as root)."""
    real = pwd.getpwnam

    def getpwnam(name):
        if name == "nobody":
            raise KeyError(name)
        return real(name)

    def no_users(iso, jobs):
        raise OSError("useradd: cannot lock /etc/passwd")

    monkeypatch.setattr(pwd, "getpwnam", getpwnam)
    monkeypatch.setattr(isolation, "_claim_users", no_users)
    iso = isolation.setup(1)
    try:
        uid = isolation.NOBODY_UID
        assert iso.users == [(f"uid-{uid}", uid, uid)] and iso.jobs == 1
        assert iso.mode == "user" and f"uid {uid}" in iso.why, iso.why
    finally:
        iso.close()
        shutil.rmtree(iso.base, ignore_errors=True)
