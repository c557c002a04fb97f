"""What the tests share (helpers, not tests): the seed cases' data (seeddata), the lecture decks' rules
(deck_rules), the notebooks' marks for nbval (nbmarks), the kernels' private sockets (kernelsockets),
the grader run from a copy of the package (grader), a released notebook solved as a student would
(solved_notebooks), a student's answers and their ground truth (written_answers), two robots that
move alike (robot_motion), the texts a figure really draws (drawn_text), and the browser tiers'
switch and Chromium (browser_tiers).

``tests/`` is on ``sys.path`` (pytest puts the folder of the top ``conftest.py`` there), so a test
imports ``from support.seeddata import load_cases``.
"""
