"""How the lessons print: a vector as ``(x, y, z)``, rounded, never ``-0`` (:func:`fmt`); an equation
``label = M`` in LaTeX (:func:`show`).

Every notebook prints positions and axes with :func:`fmt`, so that a stored output is stable from
one run to the next and the numbers in the text can be found in it. Notebooks 2-4 print fixed
decimals (``(0.500000, 0.000000, 1.000000)``: the columns line up); notebooks 5-7 drop the
trailing zeros (``(0.5, 0, 1)``: a frame's axes read at a glance). Each lesson module offers
``fmt`` with its notebook's style.

>>> fmt([0.5, -1e-9, 1])
'(0.500000, 0.000000, 1.000000)'
>>> fmt([12.0, -0.0, -3.5], 3, trim=True)
'(12, 0, -3.5)'
"""
from __future__ import annotations

from ...validation import as_float_array

__all__ = ["fmt", "show"]


def fmt(v, digits: int = 6, *, trim: bool = False) -> str:
    """The vector ``v`` (a list, an array, a sympy Matrix of numbers) as ``(x, y, …)`` with
    ``digits`` decimals and no ``-0``; ``trim=True`` drops the trailing zeros (and a bare ``.``)."""
    values = as_float_array(v, "v", finite=True).ravel()
    # round first, then add 0.0: that turns a rounded -0.0 (from -1e-9, say) into +0.0
    texts = [f"{round(float(x), digits) + 0.0:.{digits}f}" for x in values]
    if trim and digits > 0:                      # (with no decimals, "30" has no trailing zeros to drop)
        texts = [text.rstrip("0").rstrip(".") for text in texts]
    return "(" + ", ".join(texts) + ")"


def show(label: str, M) -> None:
    """Display ``label = M`` in LaTeX (``label`` is LaTeX, ``M`` a sympy matrix or expression)."""
    import sympy as sp  # lazy: only a notebook that shows an equation needs sympy
    from IPython.display import Math, display  # lazy: the notebook's own libraries, on first display

    display(Math(f"{label} = {sp.latex(M)}"))
