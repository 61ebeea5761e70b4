# The course's commands.  `make lab` and `make test` set up a fresh machine by themselves.
SHELL := /bin/bash
PYTHON ?= python3
VENV := .venv
BIN := $(CURDIR)/$(VENV)/bin
STAMP := $(VENV)/.installed
ARGS ?=
# Every command below sees the virtual environment first, so the notebooks' "python3" kernel
# (whose kernel.json runs `python`) is the environment's Python.
export PATH := $(BIN):$(PATH)
export PYTHONHASHSEED := 0

.PHONY: lab test outputs slides site bench venv clean

# JupyterLab settings the course ships (binder/overrides.json: the live deck wraps long code lines
# and outputs), installed where the environment's JupyterLab reads them.
LAB_OVERRIDES := $(VENV)/share/jupyter/lab/settings/overrides.json
$(LAB_OVERRIDES): binder/overrides.json $(STAMP)
	@mkdir -p $(dir $@) && cp binder/overrides.json $@

$(STAMP): pyproject.toml
	@bash scripts/make_venv.sh "$(PYTHON)" "$(VENV)"
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[lab,test,site]'
	@touch $(STAMP)

venv: $(STAMP) $(LAB_OVERRIDES)

## make lab: install everything into .venv and open JupyterLab on the course map.
lab: $(STAMP) $(LAB_OVERRIDES)
	$(BIN)/jupyter lab --ServerApp.root_dir="$(CURDIR)" $$([ "$$(id -u)" = 0 ] && echo --allow-root) $(ARGS) course/index.ipynb

## make test: unit, property, doctest, notebook (nbval under another SIMD dispatch: the portability
## check), widget-sweep and fuzz tests on two pytest-xdist workers, and beside them the browser tests
## (scripts/run_tests.py); prints each part's time and the total wall time, fails if either part fails.
test: $(STAMP) $(LAB_OVERRIDES)
	@bash scripts/setup_browser.sh
	@$(BIN)/python scripts/run_tests.py $(ARGS)

## make outputs: re-execute every notebook from a clean kernel and store its outputs (the nbval baseline).
outputs: $(STAMP)
	$(BIN)/python scripts/execute_notebooks.py course/*.ipynb

## make slides: an offline reveal.js deck per chapter in build/slides/.
slides: $(STAMP)
	$(BIN)/python scripts/build_slides.py

## make site: the whole course as a static website in build/site/html (Jupyter Book 1.x, from the
## stored outputs, offline). Launch buttons: SITE_REPO (default: origin), SITE_BRANCH (main), and
## SITE_HUB=https://your.hub adds a JupyterHub button (nbgitpuller).
site: $(STAMP)
	$(BIN)/python scripts/build_site.py --repo "$(SITE_REPO)" --branch "$(SITE_BRANCH)" --hub "$(SITE_HUB)"

## make bench: speed against reference libraries, printed as ratios.
bench: $(STAMP)
	$(BIN)/python -m benchmarks

clean:
	rm -rf build .pytest_cache tests/browser/screenshots
