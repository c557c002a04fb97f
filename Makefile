# dhlab — two commands do everything, on a machine with nothing but Python 3.10+:
#   make lab    set up .venv (package + Jupyter kernel) and open the course in JupyterLab
#   make test   set up .venv and run the whole test suite (pytest + nbval over notebooks/)
# Other targets: make test-browser (real-browser tier), make test-nbgrader (nbgrader accepts the
# PUMA source notebook), make bench (benchmarks), make notebooks (re-execute them), make clean.

PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
READY  := $(VENV)/.ready-$(shell cat pyproject.toml constraints.txt | cksum | cut -d' ' -f1)
# pytest-xdist runs the notebooks two at a time; --dist loadfile keeps one notebook on one worker
XDIST  ?= -n 2 --dist loadfile

.PHONY: setup lab test test-browser test-nbgrader bench notebooks clean

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

lab: $(READY)
	$(BIN)/jupyter lab --ServerApp.root_dir=notebooks $(if $(filter 0,$(shell id -u)),--allow-root)

test: $(READY)
	$(BIN)/python -m pytest $(XDIST)

test-browser: $(READY)
	bash tests/browser/setup.sh
	$(BIN)/python -m pytest tests/browser --browser -p no:xdist

# nbgrader is installed only for this tier (students and our grader do not need it)
test-nbgrader: $(READY)
	$(BIN)/python -m pip install --quiet -c constraints.txt nbgrader
	PATH="$(CURDIR)/$(BIN):$$PATH" $(BIN)/python -m pytest tests/test_grading_nbgrader.py -p no:xdist

bench: $(READY)
	$(if $(RTB),$(BIN)/python -m pip install --quiet roboticstoolbox-python)
	$(BIN)/python benchmarks/run_all.py

# Re-execute every notebook in place (finite timeout), so stored outputs match the code;
# the student version of the PUMA assignment is generated from its source, not executed.
notebooks: $(READY)
	$(BIN)/python -m dhlab.execute $(filter-out notebooks/08_puma_assignment.ipynb,$(wildcard notebooks/*.ipynb)) notebooks/source/*.ipynb
	$(BIN)/python -m dhlab.grading.generate

clean:
	rm -rf $(VENV) .pytest_cache build *.egg-info
