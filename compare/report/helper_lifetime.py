"""The plotting helpers end with the groundtruth process that started them.

compare/subprocess.cpp starts each helper with GROUNDTRUTH_PARENT_PID naming its parent, as it
starts workers (compare/worker.hpp end_with_parent): the helper asks the kernel to kill it when
that parent dies (prctl PR_SET_PDEATHSIG), so a run killed outright (SIGKILL, the memory killer)
leaves no helper drawing for nobody, and exits at once when the parent is already gone. Without
the variable (a helper run by hand) nothing changes.
"""
import ctypes
import os
import signal

PR_SET_PDEATHSIG = 1


def end_with_parent():
    parent = os.environ.get("GROUNDTRUTH_PARENT_PID")
    if not parent:
        return
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(PR_SET_PDEATHSIG, signal.SIGKILL)
    except (OSError, AttributeError):
        return  # not Linux: the parent's clean-up ends the helper's process group instead
    if str(os.getppid()) != parent:
        os._exit(128 + signal.SIGKILL)
