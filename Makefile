# trinormal: `make lab` opens the notebooks, `make test` checks everything.
# Each target sets up what it needs. uv is used from PATH, or bootstrapped into .tools/.

PYTHON ?= python3
export UV_PYTHON_DOWNLOADS := never
# No bytecode compiling when installing (it would compile every module of every group, most never
# imported): Python compiles what is imported, once, on first import, and keeps it. For that,
# PYTHONDONTWRITEBYTECODE (set on some machines) is not passed on: with it, every process (each
# pytest worker, the JupyterLab server, every kernel) would compile every module it imports from
# source, every time.
export UV_COMPILE_BYTECODE := 0
unexport PYTHONDONTWRITEBYTECODE
export NO_MKDOCS_2_WARNING := 1

SYSTEM_UV := $(shell command -v uv 2>/dev/null)
ifeq ($(SYSTEM_UV),)
UV := .tools/bin/uv
UV_DEP := .tools/bin/uv
else
UV := $(SYSTEM_UV)
UV_DEP :=
endif
RUN := $(UV) run --locked --no-sync

# The interpreter's real path. `python3` is often a shim (pyenv, asdf) whose path differs from the
# interpreter .venv was made with: handed the shim, uv removes and rebuilds .venv on every call.
PYTHON_EXE := $(shell $(PYTHON) -c 'import sys; print(sys.executable)' 2>/dev/null)
UV_PYTHON_ARG := $(if $(PYTHON_EXE),--python "$(PYTHON_EXE)")

# `uv sync`, skipped when a dry run says it would change nothing: an up-to-date .venv is left
# as it is.
SYNC := sh scripts/sync-env.sh $(UV)

# Each stage of `make test` runs under this wrapper, which adds its time to .cache/stage-times.tsv;
# `make test` prints the table at the end.
PY := $(if $(PYTHON_EXE),$(PYTHON_EXE),$(PYTHON))
TIMED = $(PY) scripts/stages.py run $@ --

.PHONY: env lab lab-env test test-stages types-and-site lint types unit notebooks nbval docs docs-build browser bench js clean

.tools/bin/uv:
	$(PYTHON) -m venv .tools
	.tools/bin/pip install --quiet --disable-pip-version-check uv

## env: create or refresh .venv/ (package editable, every group); a no-op when it is up to date
# Every group is a superset of what any other target installs, so exact syncing removes nothing
# another target put there.
env: $(UV_DEP)
	$(TIMED) $(SYNC) --locked --all-groups $(UV_PYTHON_ARG)

## lab: open JupyterLab on the notebooks (the main job)
# Installs only the lab group (the package, numpy, sympy, matplotlib, widgets, JupyterLab), not the
# docs, browser-test or benchmark tools; --inexact keeps those if `make env` installed them before.
# No news feed, no news question, no update check: the server fetches nothing (news_url, the
# update checker) and .jupyter/overrides.json answers "never" for the browser side.
# Root needs --allow-root.
LAB_FLAGS := --LabApp.news_url=None --LabApp.check_for_updates_class=jupyterlab.NeverCheckForUpdate \
	--LabApp.app_settings_dir="$(CURDIR)/.jupyter" \
	$(if $(filter 0,$(shell id -u)),--allow-root)

lab-env: $(UV_DEP)
	$(SYNC) --locked --inexact --no-default-groups --group lab $(UV_PYTHON_ARG)

# LAB_ARGS: more options for JupyterLab (`make lab LAB_ARGS="--port 8890 --no-browser"`).
lab: lab-env
	$(RUN) jupyter lab notebooks $(LAB_FLAGS) $(LAB_ARGS)

## test: lint, types, unit/property/doctests, the site and its browser tests, the notebooks (nbval)
# The notebooks are checked by nbval once, in the browser stage (tests/browser/test_wheel.py): copied
# out of the built wheel and run in a kernel of the fresh venv it is installed in. `make nbval` checks
# them in this environment.
# Prints each stage's time at the end, also when a stage fails.
test:
	@$(PY) scripts/stages.py reset
	@$(MAKE) --no-print-directory test-stages; status=$$?; $(PY) scripts/stages.py report; exit $$status

# mypy and the site's build each use one core: on two cores they run side by side
test-stages: env lint types-and-site unit
	$(BROWSER_TESTS)

types-and-site: env
	@$(MAKE) --no-print-directory -j2 types docs-build

lint: env
	$(TIMED) $(RUN) ruff check trinormal tests benchmarks docs scripts
	$(TIMED) $(RUN) ruff format --check trinormal tests benchmarks docs scripts

types: env
	$(TIMED) $(RUN) mypy

# In parallel on every core (pytest-xdist).
unit: env
	$(TIMED) $(RUN) pytest tests trinormal docs/hooks README.md --doctest-glob=README.md --ignore=tests/browser -q -n auto

## nbval: the notebooks' stored outputs, re-run here (make test runs nbval on the wheel's copies)
nbval: env
	$(TIMED) $(RUN) pytest --nbval --nbval-current-env --nbval-sanitize-with tests/nbval_sanitize.cfg notebooks -q

## notebooks: re-execute every notebook top to bottom from a clean kernel, storing outputs
notebooks: env
	$(RUN) jupyter nbconvert --to notebook --execute --inplace --NotebookClient.store_widget_state=False notebooks/*.ipynb

## docs: build the site and serve it on 127.0.0.1:8000
docs: env
	$(RUN) mkdocs serve -a 127.0.0.1:8000

docs-build: env
	$(TIMED) $(RUN) mkdocs build --strict

# The site docs-build made, never a second build. Two workers; the tests that use the one
# JupyterLab server (tests/browser/test_*lab*.py) all run on one of them (see its conftest.py).
BROWSER_TESTS = TRINORMAL_SITE_DIR="$(CURDIR)/site" $(PY) scripts/stages.py run browser -- $(RUN) pytest tests/browser -q -n 2 --dist loadgroup --durations=15

browser: env docs-build
	$(BROWSER_TESTS)

## bench: the performance figures, each against a peer measured in the same run
bench: env
	for f in benchmarks/bench_*.py; do $(RUN) python $$f || exit 1; done

## js: rebuild the 3D views (trinormal/explorer/static/: explorer.js, the widget, and site-modules/, the site's) from js/explorer/ and its lockfile
js:
	cd js/explorer && npm ci --no-audit --no-fund && node build.mjs

clean:
	rm -rf .venv .tools site .cache .pytest_cache .mypy_cache .ruff_cache
