"""The maintainers' tools: run from the top of the repository, never installed with ``dhlab``.

    python -m tools.edition extract|build|check [notebooks...]   # the Spanish edition (make edition)
    python -m tools.i18n_catalog extract|update|compile|check     # the package's message catalogs
    python -m tools.execute notebooks/*.ipynb                     # re-execute notebooks (make notebooks)
    python -m tools.student_copy                                  # the student's own copy (make lab)

* :mod:`tools.edition` (with :mod:`tools.edition_catalog`, :mod:`tools.edition_text` and
  :mod:`tools.edition_home`): ``notebooks/es/`` built from the English notebooks and one catalog per
  notebook (``tools/locale/es/notebooks/<stem>.po``), the course home ``notebooks/index.ipynb``;
* :mod:`tools.i18n_catalog`: ``dhlab/locale/`` (the package's own messages, which it ships);
* :mod:`tools.execute`: stored outputs exactly what the code computes;
* :mod:`tools.student_copy`: ``my-notebooks/``, where a student works (``make lab``).

No file here (nor anywhere in the repository, which students clone) holds the assignment's solutions:
``dhlab-assign solutions OUT.ipynb`` computes them (:mod:`dhlab.assignment.solution`); ``make notebooks``
computes the solved notebook into a temporary folder, executes it, and makes the student notebook from it.

They reach into the repository (``notebooks/``, ``tools/locale/``) on purpose: that is where they work.
The package ``dhlab`` never imports them.
"""
