"""These notebooks are test submissions for the grader (tests/grading/test_grading_runner.py), some of
them hostile (they hang, exhaust memory, kill processes): never collect them as notebooks (nbval)."""
collect_ignore_glob = ["*.ipynb", "make_submissions.py"]
