# Chaser: `make demo` runs the main job and writes its 3D replay (demo-out/view.html), `make test`
# builds and runs every test, `make bench` the benchmarks, `make sanitize` every test under ASan and
# UBSan (`make sanitize-fast` CI's subset), `make fuzz` the loaders' fuzzers (docs/reliability.md),
# `make servicing` COMRADE's synchronisation, its Table 5 and the reach (with their replays), `make
# docs` the generated tables of README.md and docs/ (scripts/doc_tables.py).
# Each target installs missing system packages first (scripts/install-deps).
BUILD ?= build
JOBS ?= $(shell nproc)
MAKEFLAGS += --no-print-directory
PYTHON ?= /usr/bin/python3
DEMO_OUT ?= demo-out

FMEA_OUT ?= fmea-out
SERVICING_OUT ?= servicing-out
SANITIZE_BUILD ?= build-sanitize
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 600
FUZZ_TARGETS ?= scenario overrides invsim

SANITIZE_FAST_TESTS ?= test_core test_model test_plant test_earth test_multibody test_io test_flight test_flight_arm test_fdi test_fdi_design

.PHONY: all deps configure build test demo fmea servicing docs bench sanitize sanitize-fast fuzz clean

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
	@./$(BUILD)/cli/chaser view $(DEMO_OUT) --out $(DEMO_OUT)/view.html

# Zhou 2018's failure-mode analysis and reconfiguration study, with the search and per-mode plots.
fmea: build
	@./$(BUILD)/cli/chaser fmea scenarios/manual_rvd.yaml --out $(FMEA_OUT) --optimize --history
	@$(PYTHON) python/plot_invsim.py $(FMEA_OUT)

# COMRADE 2018's synchronisation (docs/servicing.md): one flight and its plots, then Table 5 by
# Monte Carlo, 100 runs per spin case and ASSIST's approach (~35 s on 2 cores), and its scatter;
# the capture: one flight (reach, grasp, rigidisation, stabilisation) and its plots, then Tables 5
# (reach) and 6, 100 runs per law (~6 min), Table 8, 20 runs per spin case (~10 min), the same
# runs' phase verdicts (comrade-mission, resumed: no run flown again), Table 7 from one capture
# (~7 min), an escape commanded during the grasp with its plots (~40 s), and ASSIST berthed by the
# arm with its plots (~10 s).
servicing: build
	@./$(BUILD)/cli/chaser run scenarios/comrade_sync.yaml --out $(SERVICING_OUT)/flight
	@$(PYTHON) python/plot_servicing.py $(SERVICING_OUT)/flight
	@./$(BUILD)/cli/chaser view $(SERVICING_OUT)/flight
	@./$(BUILD)/cli/chaser campaign scenarios/comrade_sync.yaml --preset comrade-table5 \
	  --also scenarios/comrade_assist.yaml --out $(SERVICING_OUT)/table5
	@$(PYTHON) python/plot_table5.py $(SERVICING_OUT)/table5
	@./$(BUILD)/cli/chaser run scenarios/comrade_capture.yaml --out $(SERVICING_OUT)/reach
	@$(PYTHON) python/plot_reach.py $(SERVICING_OUT)/reach
	@./$(BUILD)/cli/chaser view $(SERVICING_OUT)/reach
	@./$(BUILD)/cli/chaser campaign scenarios/comrade_capture.yaml --preset comrade-reach \
	  --out $(SERVICING_OUT)/reach-campaign
	@./$(BUILD)/cli/chaser campaign scenarios/comrade_capture.yaml --preset comrade-stabilise \
	  --out $(SERVICING_OUT)/stabilise-campaign
	@./$(BUILD)/cli/chaser campaign scenarios/comrade_capture.yaml --preset comrade-mission --resume \
	  --out $(SERVICING_OUT)/stabilise-campaign
	@./$(BUILD)/cli/chaser campaign scenarios/comrade_capture.yaml --preset comrade-rigidise \
	  --out $(SERVICING_OUT)/rigidise-campaign
	@./$(BUILD)/cli/chaser run scenarios/comrade_capture.yaml --set 'capture.escape={command_s: 2870}' \
	  --set duration_s=3900 --out $(SERVICING_OUT)/escape
	@$(PYTHON) python/plot_reach.py $(SERVICING_OUT)/escape
	@./$(BUILD)/cli/chaser run scenarios/comrade_berth.yaml --out $(SERVICING_OUT)/berth
	@$(PYTHON) python/plot_reach.py $(SERVICING_OUT)/berth

# Every generated results table in README.md and docs/ rewritten from its command's output
# (scripts/doc_tables.py; the Fonod 2015 and COMRADE campaigns take ~25 minutes on 2 cores).
docs: build
	@CHASER_CLI=./$(BUILD)/cli/chaser $(PYTHON) scripts/doc_tables.py --write

bench: build
	@./$(BUILD)/bench/chaser_bench

# Every test built with AddressSanitizer and UndefinedBehaviorSanitizer (cmake/sanitizers.cmake).
sanitize: deps
	@cmake -S . -B $(SANITIZE_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCHASER_SANITIZE=address,undefined \
	  -DCHASER_BUILD_BENCH=OFF >/dev/null
	@cmake --build $(SANITIZE_BUILD) -j$(JOBS)
	@cd $(SANITIZE_BUILD) && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest --output-on-failure -j$(JOBS)

# The suites of core, model, plant (multibody included), io and flight (fdi and arm included) under both sanitizers: what CI runs
# after make test (.ci/run), since the whole suite's sanitizer build takes too long there.
sanitize-fast: deps
	@cmake -S . -B $(SANITIZE_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCHASER_SANITIZE=address,undefined \
	  -DCHASER_BUILD_BENCH=OFF >/dev/null
	@cmake --build $(SANITIZE_BUILD) -j$(JOBS) --target $(SANITIZE_FAST_TESTS)
	@cd $(SANITIZE_BUILD) && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest --output-on-failure -j$(JOBS) -R '^($(subst $(eval) ,|,$(SANITIZE_FAST_TESTS)))$$'

# libFuzzer on the scenario loaders and the --set parser, FUZZ_SECONDS per target, one worker.
fuzz:
	@bash scripts/install-deps fuzz
	@cmake -S . -B $(FUZZ_BUILD) -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
	  -DCHASER_FUZZ=ON -DCHASER_BUILD_TESTS=OFF -DCHASER_BUILD_BENCH=OFF >/dev/null
	@cmake --build $(FUZZ_BUILD) -j$(JOBS) --target $(addprefix chaser_fuzz_,$(FUZZ_TARGETS))
	@bash fuzz/run.sh $(FUZZ_BUILD) $(FUZZ_SECONDS) $(FUZZ_TARGETS)

clean:
	rm -rf $(BUILD) $(SANITIZE_BUILD) $(FUZZ_BUILD) $(DEMO_OUT) $(FMEA_OUT)
