# The two commands a new user needs (see README.md):
#   make demo   set everything up, render the default material charts to out/
#   make test   set everything up, run the whole test suite
.PHONY: setup demo test bench clean

PY := .venv/bin/python

setup:
	@bash scripts/setup.sh

demo: setup
	@$(PY) -m pbrlab demo --out out

test: setup
	@$(PY) -m pytest -n auto -p no:cacheprovider $(PYTEST_ARGS)

bench: setup
	@$(PY) -m pbrlab bench --out docs/bench

clean:
	rm -rf out test-output site .venv
