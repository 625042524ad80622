# mesowave - the one entry point.
#
#   make reproduce        install what is missing, build, run every study on lab-data/ (results/, report/),
#                         PIPELINE_JOBS runs at once (default: the cores; a -j given wins)
#   make reproduce-quick  the same rules on small models and short records (results-quick/, report-quick/)
#   make new-study NAME=my-cube FROM=concrete-cube   a lab's own specimen: lab-data/ and pipeline/ folders
#   make test             install what is missing, build, run every test (CTest summary at the end)
#   make test-sanitize    the same suite built with ASan and UBSan (build-sanitize/)
#   make fuzz             libFuzzer campaign on every parser of user files (build-fuzz/, docs/fuzzing.md)
#   make bench            benchmarks (bench/), results in docs/benchmarks.md
#   make clean            remove build/, both result trees, reports and provenance databases
#   make reproduce LAUNCH=slurm [-j N] [LAUNCH_CPUS=4] [LAUNCH_FLAGS='-p long']
#                         every tool run of the pipeline as a Slurm job step (docs/slurm.md)
#   make check-slurm      reproduce-quick on a one-node Slurm cluster on localhost against the plain run
#
# Every tool run by the pipeline records itself in $(MESOWAVE_DB): db/provenance.sqlite for the
# full tree, db/provenance-quick.sqlite for the quick one.

SHELL := /bin/bash
.DELETE_ON_ERROR:

BUILD ?= build
BIN := $(BUILD)/bin
JOBS ?= $(shell nproc)
CMAKE_BUILD_TYPE ?= Release

# Two pipeline trees made by the same rules: the full-size studies (QUICK=0) and a first look
# on small models and short records (QUICK=1, `make reproduce-quick`; for tests too). The
# studies choose their sizes from QUICK; each tree has its own results, report and database.
QUICK ?= 0
ifeq ($(QUICK),1)
RESULTS := results-quick
REPORT_DIR := report-quick
else
RESULTS := results
REPORT_DIR := report
endif
QUICK_DB := $(CURDIR)/db/provenance-quick.sqlite
export MESOWAVE_DB ?= $(if $(filter 1,$(QUICK)),$(QUICK_DB),$(CURDIR)/db/provenance.sqlite)

# LAUNCH=slurm: make's shell is scripts/slurm-shell, which runs every recipe line that starts a
# tool ($(BIN)/mw-...) as a Slurm job step (srun: a job of its own, or a step of the allocation
# make runs in) with LAUNCH_CPUS cores (OMP_NUM_THREADS the same) and LAUNCH_FLAGS added to srun
# (partition, time limit, account); other lines run here. The tree must be on storage the nodes
# share. Each step records into a database of its own, merged into $(MESOWAVE_DB) on this host
# after it (mw-prov merge): SQLite is never opened from two hosts at once (docs/slurm.md).
LAUNCH ?=
LAUNCH_CPUS ?= 1
LAUNCH_FLAGS ?=
ifeq ($(LAUNCH),slurm)
SHELL := $(CURDIR)/scripts/slurm-shell
export MESOWAVE_LAUNCH_BIN := $(BIN)
export MESOWAVE_LAUNCH_CPUS := $(LAUNCH_CPUS)
export MESOWAVE_LAUNCH_FLAGS := $(LAUNCH_FLAGS)
else ifneq ($(LAUNCH),)
$(error LAUNCH=$(LAUNCH): the one launcher is slurm (LAUNCH=slurm), or leave LAUNCH unset to run the tools here)
endif

.PHONY: all help deps build test test-sanitize fuzz reproduce reproduce-quick pipeline bench clean check-slurm

all: build

help:
	@sed -n '2,18p' Makefile | sed 's/^# \{0,1\}//'

deps:
	@scripts/install-deps

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=$(CMAKE_BUILD_TYPE)

build: deps
	@$(MAKE) --no-print-directory $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

# The suite's Slurm test starts a one-node cluster (tests/pipeline/slurm_test.cpp): its packages.
test: build
	@scripts/install-deps slurm
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# The whole suite with AddressSanitizer and UndefinedBehaviorSanitizer: the
# library, the tools the CLI and pipeline tests run, the tests and the fuzz
# corpora's replays. Any report fails its test (-fno-sanitize-recover; leaks
# too). Several times slower than `make test`.
SANITIZE_BUILD ?= build-sanitize
test-sanitize: deps
	cmake -S . -B $(SANITIZE_BUILD) -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=$(SANITIZE_OPT)" \
	  "-DCMAKE_C_FLAGS_RELEASE=$(SANITIZE_OPT)" -DMESOWAVE_SANITIZE=ON -DMESOWAVE_BUILD_BENCH=OFF
	cmake --build $(SANITIZE_BUILD) -j $(JOBS)
	cd $(SANITIZE_BUILD) && ASAN_OPTIONS=$(SANITIZE_ASAN_OPTIONS) UBSAN_OPTIONS=print_stacktrace=1 \
	  ctest --output-on-failure -j $(JOBS)
SANITIZE_ASAN_OPTIONS ?= detect_stack_use_after_return=1:strict_string_checks=1
# -O1: the usual optimisation for sanitizer runs (quick to build, exact reports).
SANITIZE_OPT ?= -O1 -DNDEBUG

# The libFuzzer campaign (docs/fuzzing.md): every target of tests/fuzz for
# FUZZ_SECONDS each, one after the other, seeded from tests/fuzz/corpus/<target>/.
# New inputs go to build-fuzz/corpus/<target>/, crashes to build-fuzz/crashes/<target>/;
# the run fails if any target crashed. FUZZ_TARGETS picks some
# (make fuzz FUZZ_TARGETS="scene_toml image" FUZZ_SECONDS=60).
FUZZ_BUILD ?= build-fuzz
FUZZ_SECONDS ?= 300
FUZZ_TARGETS ?= $(basename $(notdir $(filter-out tests/fuzz/replay_main.cpp,$(wildcard tests/fuzz/*.cpp))))
FUZZ_FLAGS ?= -timeout=10 -rss_limit_mb=2048
# libFuzzer's advice: little optimisation (quicker to build, clearer reports),
# line tables for the stack traces, assertions on.
FUZZ_OPT ?= -O1 -gline-tables-only
fuzz:
	@scripts/install-deps fuzz
	cmake -S . -B $(FUZZ_BUILD) -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
	  -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=$(FUZZ_OPT)" "-DCMAKE_C_FLAGS_RELWITHDEBINFO=$(FUZZ_OPT)" \
	  -DMESOWAVE_FUZZ=ON -DMESOWAVE_BUILD_TESTS=OFF -DMESOWAVE_BUILD_BENCH=OFF
	cmake --build $(FUZZ_BUILD) -j $(JOBS) --target fuzz_targets
	@crashed=; for t in $(FUZZ_TARGETS); do \
	  mkdir -p $(FUZZ_BUILD)/corpus/$$t $(FUZZ_BUILD)/crashes/$$t; \
	  echo "fuzz: $$t for $(FUZZ_SECONDS) s"; \
	  LSAN_OPTIONS=suppressions=$(CURDIR)/tests/fuzz/lsan.supp $(FUZZ_BUILD)/tests/fuzz/fuzz_$$t $(FUZZ_FLAGS) -max_total_time=$(FUZZ_SECONDS) -print_final_stats=1 \
	    -artifact_prefix=$(FUZZ_BUILD)/crashes/$$t/ $(FUZZ_BUILD)/corpus/$$t tests/fuzz/corpus/$$t \
	    > $(FUZZ_BUILD)/$$t.log 2>&1 || crashed="$$crashed $$t"; \
	  grep -E '^(stat::number_of_executed_units|stat::new_units_added)' $(FUZZ_BUILD)/$$t.log | tr '\n' ' '; echo; \
	done; \
	if [ -n "$$crashed" ]; then echo "fuzz: crashes in$$crashed (inputs in $(FUZZ_BUILD)/crashes/, logs $(FUZZ_BUILD)/*.log)"; exit 1; fi; \
	echo "fuzz: no crash"

# The pipeline runs in a second make, after the build, so that make compares
# the results' timestamps with the tools as they are now. The wall time of the
# pipeline (without the build) is printed at the end.
PRINT_WALL_TIME = awk -v s=$$start -v e=$$(date +%s.%N) -v l="$$(cut -d' ' -f1-3 /proc/loadavg)" -v n=$$(nproc) \
  'BEGIN { printf "pipeline wall time: %.1f s (load average now %s, %d cores)\n", e - s, l, n }'
# The schedule: PIPELINE_JOBS tool runs at once (default: the machine's cores), each taking the
# threads the thread policy gives it (core/threads.hpp: the cores less the other runnable threads
# at its start - one each while two run on 2 cores, two for a run that starts alone). Measured on
# 2 cores against one run at a time on two threads (docs/benchmarks.md, "The schedule on 2 cores").
# A -j the user gives (make -j1 reproduce) wins; the outputs are the same bits either way.
PIPELINE_JOBS ?= $(shell nproc)
pipeline_schedule = $(if $(filter -j%,$(MAKEFLAGS)),,-j$(PIPELINE_JOBS)) --output-sync=target
reproduce: build
	@start=$$(date +%s.%N); $(MAKE) --no-print-directory $(pipeline_schedule) pipeline-scheduled && \
	  $(PRINT_WALL_TIME)

reproduce-quick: build
	@start=$$(date +%s.%N); $(MAKE) --no-print-directory $(pipeline_schedule) pipeline-scheduled QUICK=1 MESOWAVE_DB=$(QUICK_DB) && \
	  $(PRINT_WALL_TIME)

# The order of the runs. GNU make starts targets in the order it walks the graph, and one that
# becomes ready waits until the walk comes round again - in the whole pipeline, until every other
# ready run has started (on 2026-12-05 the cube's calibration, the longest chain's second link,
# started 2.5 minutes after its packing). So the studies name (in their study.mk):
#   PIPELINE_CHAIN   the end of their longest chain of dependent runs (the cube: packing ->
#                    calibration -> DEM waves); it runs in a make of its own, which starts each
#                    link as soon as the one before ends;
#   PIPELINE_BESIDE  what needs nothing of the chain; it runs beside it, in the job slots the chain
#                    leaves (both makes share them: -j stays the number of runs at once);
#   PIPELINE_FIRST   the inputs both read (made first, before either starts).
# No target may be in (or under) both PIPELINE_CHAIN and PIPELINE_BESIDE: two makes would make it
# at once (scripts/check-pipeline checks that their dry runs share no tool run). A last pass, make
# pipeline, makes what needs both (PCC, tables, the report) and anything a study did not name; so a
# study that names nothing gets the same results, only later.
PIPELINE_FIRST :=
PIPELINE_CHAIN :=
PIPELINE_BESIDE :=
# (Its rules follow the studies' includes below, which fill these lists.)

# A study is a folder pipeline/<study>/: its study.mk (the rules; it adds the goals that print
# its tables to PIPELINE_GOALS) and its report.toml (its sections of the report), with its
# inputs in lab-data/<study>/. Studies are found here, in folder order, so a new one
# (`make new-study`) runs in make reproduce and shows in the report without an edit here.
STUDIES := $(patsubst pipeline/%/study.mk,%,$(sort $(wildcard pipeline/*/study.mk)))
PIPELINE_GOALS :=
include $(foreach study,$(STUDIES),pipeline/$(study)/study.mk)
include pipeline/report.mk

# The schedule's rules (above: "The order of the runs").
# (The empty recipes keep make from listing what is up to date.)
.PHONY: pipeline-scheduled pipeline-first pipeline-chain-beside pipeline-chain pipeline-chain-goals pipeline-beside-goals
pipeline-scheduled:
	+@$(MAKE) --no-print-directory pipeline-first
	+@$(MAKE) --no-print-directory pipeline-chain-beside
	+@$(MAKE) --no-print-directory pipeline
pipeline-first: $(PIPELINE_FIRST) ; @:
pipeline-chain-beside: pipeline-chain pipeline-beside-goals ; @:
pipeline-chain:
	+@$(MAKE) --no-print-directory pipeline-chain-goals
pipeline-chain-goals: $(PIPELINE_CHAIN) ; @:
pipeline-beside-goals: $(PIPELINE_BESIDE) ; @:

pipeline: $(PIPELINE_GOALS) $(REPORT_DIR)/index.html
	@echo; echo "report: $(CURDIR)/$(REPORT_DIR)/index.html"
	$(if $(filter slurm,$(LAUNCH)),@scripts/slurm-shell --summary)

# `make reproduce-quick LAUNCH=slurm` on a one-node Slurm cluster started on localhost, against
# the same pipeline run plainly, each in a copy of this tree: outputs equal, provenance whole
# (scripts/check-slurm; the suite's test runs a part of it). Needs root.
check-slurm: build
	@scripts/install-deps slurm
	scripts/check-slurm --build $(BUILD) -j $(JOBS)

# A lab's own specimen as a new study, copied from an existing one with every lab-data value
# marked to be replaced (scripts/new-study --help):  make new-study NAME=my-cube FROM=concrete-cube
.PHONY: new-study
new-study:
	@scripts/new-study "$(NAME)" "$(FROM)"

bench: build
	bench/run

clean:
	rm -rf $(BUILD) $(SANITIZE_BUILD) $(FUZZ_BUILD) results report results-quick report-quick
	rm -f db/provenance.sqlite db/provenance.sqlite-wal db/provenance.sqlite-shm \
	  db/provenance-quick.sqlite db/provenance-quick.sqlite-wal db/provenance-quick.sqlite-shm
	rm -rf db/provenance.jobs db/provenance-quick.jobs
