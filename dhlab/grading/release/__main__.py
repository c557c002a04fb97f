"""``python -m dhlab.grading.release …`` is ``dhlab-assign …``."""
import sys

from .notebooks import main

if __name__ == "__main__":        # not when a tool imports every module (the doctests)
    sys.exit(main())
