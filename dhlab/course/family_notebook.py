"""Where a personal notebook's locked "Your robot" cell imported ``use_variant`` from.

Notebooks released before :mod:`dhlab.assignment` existed run
``from dhlab.course.family_notebook import use_variant``: this name keeps them working.
New releases import it from :mod:`dhlab.assignment`. (With :mod:`dhlab.course.assignment`,
the only imports from ``course/`` up into ``assignment/``.)
"""
from dhlab.assignment.notebook_cells import use_variant  # noqa: F401

__all__ = ["use_variant"]
