# dhlab — two commands do everything, on a machine with nothing but Python 3.10+:
#   make lab    set up .venv (package + Jupyter kernel) and open the course home in JupyterLab, in the
#               student's own copy of the course, my-notebooks/ (made on the first run from notebooks/,
#               then only added to: the student's answers stay theirs, git ignores them, git pull never
#               conflicts; index.ipynb there: the English and the Spanish edition start there)
#   make test   set up .venv and run the whole test suite (pytest + nbval over notebooks/ and notebooks/es/,
#               the course; never my-notebooks/)
# Other targets: make lab-es (the same, JupyterLab's menus in Spanish), make edition (the Spanish
# notebooks: catalogs updated, stale notebooks rebuilt, everything checked), make test-browser
# (real-browser tier), make test-nbgrader (nbgrader accepts the PUMA source notebook), make bench
# (benchmarks), make notebooks (re-execute them, both editions), make docs (the docs site, docs/_build/html),
# make lint (ruff), make clean. The maintainers' tools
# these run live in tools/ (python -m tools.edition, tools.execute, tools.i18n_catalog), never installed.

PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
READY  := $(VENV)/.ready-$(shell cat pyproject.toml constraints.txt | cksum | cut -d' ' -f1)
# pytest-xdist runs the notebooks two at a time; --dist loadfile keeps one notebook on one worker
XDIST  ?= -n 2 --dist loadfile

.PHONY: setup lab lab-es edition test lint test-browser test-nbgrader bench notebooks clean

setup: $(READY)

$(READY):
	@$(PYTHON) -c 'import sys; sys.exit(0 if sys.version_info >= (3, 10) else "dhlab needs Python 3.10 or newer; this is " + sys.version.split()[0])'
	@$(PYTHON) -c 'import venv, ensurepip' 2>/dev/null || { echo "Python's venv module is missing: on Debian/Ubuntu run 'sudo apt install python3-venv', then try again."; exit 1; }
	rm -rf $(VENV)
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -c constraints.txt -e ".[lab,test]"
	$(BIN)/python -m ipykernel install --sys-prefix --name python3 --display-name "Python 3 (dhlab)" >/dev/null
	@# no news or update pop-ups over a projected lecture
	mkdir -p $(VENV)/share/jupyter/lab/settings
	echo '{"@jupyterlab/apputils-extension:notification": {"fetchNews": "false", "checkForUpdates": false}}' \
	  > $(VENV)/share/jupyter/lab/settings/overrides.json
	touch $@

# the student's own copy of the course, where JupyterLab opens (tools/student_copy.py): made from
# notebooks/ on the first run; later runs add the course's new notebooks and never change the student's
MY_NOTEBOOKS := my-notebooks
LAB_ARGS := --ServerApp.root_dir=$(MY_NOTEBOOKS) --LabApp.default_url=/lab/tree/index.ipynb $(if $(filter 0,$(shell id -u)),--allow-root)
LAB_ES   := $(VENV)/share/jupyter/lab/settings-es

lab: $(READY)
	$(BIN)/python -m tools.student_copy $(MY_NOTEBOOKS)
	$(BIN)/jupyter lab $(LAB_ARGS)

# JupyterLab's own menus in Spanish (the language pack jupyterlab-language-pack-es-ES, installed with
# the lab extras): the usual settings plus locale es_ES as the default; a language chosen in
# Settings > Language still wins, as for `make lab`.
lab-es: $(READY)
	mkdir -p $(LAB_ES)
	$(BIN)/python -c 'import json, sys; s = json.load(open(sys.argv[1])); s["@jupyterlab/translation-extension:plugin"] = {"locale": "es_ES"}; json.dump(s, open(sys.argv[2], "w"))' \
	  $(VENV)/share/jupyter/lab/settings/overrides.json $(LAB_ES)/overrides.json
	$(BIN)/python -m tools.student_copy $(MY_NOTEBOOKS)
	$(BIN)/jupyter lab $(LAB_ARGS) --LabApp.app_settings_dir=$(LAB_ES)

# The Spanish edition (notebooks/es/, from the English notebooks and tools/locale/es/notebooks/*.po):
# catalogs brought in step with the English (a changed cell becomes fuzzy), the notebooks whose
# catalog is complete rebuilt and executed if stale (and the assignment's Spanish text the package
# ships, dhlab/grading/template/), the course home rewritten, then every check.
edition: $(READY)
	$(BIN)/python -m tools.edition extract
	$(BIN)/python -m tools.edition build --if-stale
	$(BIN)/python -m tools.edition check

test: $(READY)
	$(BIN)/python -m pytest $(XDIST)

# ruff with the rules of pyproject.toml ([tool.ruff]): seconds; .ci/run runs it first
lint: $(READY)
	$(BIN)/python -m ruff check .

# Every notebook in JupyterLab + Chromium (inline and ipympl), the teach panel in Voilà, the
# key-to-pixels latency; screenshots and latency.json are left in tests/browser/results/.
test-browser: $(READY)
	bash tests/browser/setup.sh
	$(BIN)/python -m pytest tests/browser --browser -p no:xdist --durations=5

# The README's picture (notebooks/images/teach_ssrms.png), taken by the browser tier
.PHONY: screenshots
screenshots: $(READY)
	bash tests/browser/setup.sh
	DHLAB_UPDATE_SCREENSHOTS=1 $(BIN)/python -m pytest tests/browser/test_readme_picture.py --browser -p no:xdist -q

# nbgrader is installed only for this tier (students and our grader do not need it)
test-nbgrader: $(READY)
	$(BIN)/python -m pip install --quiet -c constraints.txt nbgrader
	PATH="$(CURDIR)/$(BIN):$$PATH" $(BIN)/python -m pytest tests/grading/test_grading_nbgrader.py -p no:xdist

bench: $(READY)
	$(if $(RTB),$(BIN)/python -m pip install --quiet roboticstoolbox-python)
	$(BIN)/python benchmarks/run_all.py

# Re-execute every notebook in place (finite timeout), so stored outputs match the code (the
# Spanish ones are rebuilt from the English and their catalogs, and executed);
# the PUMA assignment's solutions are in no file (students clone this repository): its solved
# notebook is computed from the student notebook (dhlab.assignment.solution) into a temporary
# folder, executed there, and the student notebook made from it again, written as
# notebooks/08_puma_assignment.ipynb and as the package's copy dhlab-assign starts from.
notebooks: $(READY)
	$(BIN)/python -m tools.execute $(filter-out notebooks/08_puma_assignment.ipynb notebooks/index.ipynb,$(wildcard notebooks/*.ipynb))
	solved=$$(mktemp -d) && nb=$$solved/08_puma_assignment.ipynb \
	  && $(BIN)/python -m dhlab.grading.release.generate --solved $$nb && $(BIN)/python -m tools.execute $$nb \
	  && $(BIN)/python -m dhlab.grading.release.generate $$nb; status=$$?; rm -rf $$solved; exit $$status
	$(BIN)/python -m tools.edition build

# (never my-notebooks/: the student's answers)
clean:
	rm -rf $(VENV) .pytest_cache build *.egg-info

# The browser edition (JupyterLite + a self-hosted Pyodide 0.27.7): `make lite` builds the static
# site build/lite/ (publish that folder on any web server, GitHub Pages included); its build tools
# live in their own venv, build/lite-venv. `make lite-serve` serves it on 127.0.0.1 (PORT=8000).
LITE_VENV  := build/lite-venv
LITE_READY := $(LITE_VENV)/.ready-$(shell cat lite/requirements.txt | cksum | cut -d' ' -f1)

.PHONY: lite lite-serve test-lite

$(LITE_READY):
	rm -rf $(LITE_VENV)
	$(PYTHON) -m venv $(LITE_VENV)
	$(LITE_VENV)/bin/python -m pip install --quiet --upgrade pip
	$(LITE_VENV)/bin/python -m pip install --quiet -r lite/requirements.txt
	touch $@

# the docs are built first so that the site carries them under docs/
lite: $(LITE_READY) docs
	$(LITE_VENV)/bin/python lite/build.py

lite-serve:
	@test -f build/lite/index.html || $(MAKE) lite
	$(PYTHON) lite/serve.py --port $(or $(PORT),8000)

# every notebook of the site in Chromium (Playwright); measurements in build/lite-measurements.json
test-lite: $(READY) lite
	bash tests/browser/setup.sh
	$(BIN)/python -m pytest tests/lite --lite -p no:xdist

# The docs site (docs/, MyST Markdown + Sphinx, API reference from the docstrings): docs/_build/html.
# Warnings are errors and every internal link and cross-reference must resolve (-W -n: Sphinx's own
# checks, offline, what CI runs). `make docs-linkcheck` also tries every external link: it needs
# the network (CI's machine reaches only PyPI, so CI runs the offline check only).
DOCS_BUILD := docs/_build
.PHONY: docs docs-linkcheck

docs: $(READY)
	$(BIN)/python -m sphinx -b html -E -W --keep-going -n -q docs $(DOCS_BUILD)/html
	@echo "built $(DOCS_BUILD)/html/index.html"

docs-linkcheck: $(READY)
	$(BIN)/python -m sphinx -b linkcheck -q docs $(DOCS_BUILD)/linkcheck
