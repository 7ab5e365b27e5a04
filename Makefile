# Chaser: `make demo` runs the main job, `make test` builds and runs every test, `make bench` the
# benchmarks. Each target installs missing system packages first (scripts/install-deps).
BUILD ?= build
JOBS ?= $(shell nproc)
MAKEFLAGS += --no-print-directory
PYTHON ?= /usr/bin/python3
DEMO_OUT ?= demo-out

FMEA_OUT ?= fmea-out

.PHONY: all deps configure build test demo fmea bench clean

all: build

deps:
	@bash scripts/install-deps

configure: deps
	@cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null

build: configure
	@cmake --build $(BUILD) -j$(JOBS)

test: build
	@cd $(BUILD) && ctest --output-on-failure -j$(JOBS)

demo: build
	@./$(BUILD)/cli/chaser run scenarios/msr_terminal.yaml --out $(DEMO_OUT) \
	  --set 'faults=[{thruster: T8, kind: stuck_open, onset_s: 1000}]'
	@$(PYTHON) python/plot_run.py $(DEMO_OUT)
	@$(PYTHON) python/plot_fdi.py $(DEMO_OUT)

# Zhou 2018's failure-mode analysis and reconfiguration study, with the search and per-mode plots.
fmea: build
	@./$(BUILD)/cli/chaser fmea scenarios/manual_rvd.yaml --out $(FMEA_OUT) --optimize --history
	@$(PYTHON) python/plot_invsim.py $(FMEA_OUT)

bench: build
	@./$(BUILD)/bench/chaser_bench

clean:
	rm -rf $(BUILD) $(DEMO_OUT) $(FMEA_OUT)
