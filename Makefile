# The two commands a new user needs (see README.md):
#   make demo   set everything up, render the default material charts to out/
#   make test   set everything up, run the whole test suite (about 10 minutes on a quiet 2-core machine)
#   make check  set everything up, run the quick subset: every layer, the slow modules left out (tests/slow_modules.py)
.PHONY: setup demo test check bench clean

PY := .venv/bin/python

setup:
	@bash scripts/setup.sh

demo: setup
	@$(PY) -m pbrlab demo --out out

test: setup
	@$(PY) -m pytest -n auto -p no:cacheprovider $(PYTEST_ARGS)

check: setup
	@$(PY) -m pytest -n auto -p no:cacheprovider -m "not slow" $(PYTEST_ARGS)

bench: setup
	@$(PY) -m pbrlab bench --out docs/bench

clean:
	rm -rf out test-output site .venv
