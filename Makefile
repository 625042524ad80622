# mesowave - the one entry point.
#
#   make reproduce        install what is missing, build, run every study on lab-data/ (results/, report/)
#   make reproduce-quick  the same rules on small models and short records (results-quick/, report-quick/)
#   make new-study NAME=my-cube FROM=concrete-cube   a lab's own specimen: lab-data/ and pipeline/ folders
#   make test             install what is missing, build, run every test (CTest summary at the end)
#   make bench            benchmarks (bench/), results in docs/benchmarks.md
#   make clean            remove build/, both result trees, reports and provenance databases
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

.PHONY: all help deps build test reproduce reproduce-quick pipeline bench clean

all: build

help:
	@sed -n '2,12p' Makefile | sed 's/^# \{0,1\}//'

deps:
	@scripts/install-deps

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=$(CMAKE_BUILD_TYPE)

build: deps
	@$(MAKE) --no-print-directory $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# The pipeline runs in a second make, after the build, so that make compares
# the results' timestamps with the tools as they are now. The wall time of the
# pipeline (without the build) is printed at the end.
PRINT_WALL_TIME = awk -v s=$$start -v e=$$(date +%s.%N) -v l="$$(cut -d' ' -f1-3 /proc/loadavg)" -v n=$$(nproc) \
  'BEGIN { printf "pipeline wall time: %.1f s (load average now %s, %d cores)\n", e - s, l, n }'
reproduce: build
	@start=$$(date +%s.%N); $(MAKE) --no-print-directory pipeline && \
	  $(PRINT_WALL_TIME)

reproduce-quick: build
	@start=$$(date +%s.%N); $(MAKE) --no-print-directory pipeline QUICK=1 MESOWAVE_DB=$(QUICK_DB) && \
	  $(PRINT_WALL_TIME)

# A study is a folder pipeline/<study>/: its study.mk (the rules; it adds the goals that print
# its tables to PIPELINE_GOALS) and its report.toml (its sections of the report), with its
# inputs in lab-data/<study>/. Studies are found here, in folder order, so a new one
# (`make new-study`) runs in make reproduce and shows in the report without an edit here.
STUDIES := $(patsubst pipeline/%/study.mk,%,$(sort $(wildcard pipeline/*/study.mk)))
PIPELINE_GOALS :=
include $(foreach study,$(STUDIES),pipeline/$(study)/study.mk)
include pipeline/report.mk

pipeline: $(PIPELINE_GOALS) $(REPORT_DIR)/index.html
	@echo; echo "report: $(CURDIR)/$(REPORT_DIR)/index.html"

# A lab's own specimen as a new study, copied from an existing one with every lab-data value
# marked to be replaced (scripts/new-study --help):  make new-study NAME=my-cube FROM=concrete-cube
.PHONY: new-study
new-study:
	@scripts/new-study "$(NAME)" "$(FROM)"

bench: build
	bench/run

clean:
	rm -rf $(BUILD) results report results-quick report-quick
	rm -f db/provenance.sqlite db/provenance.sqlite-wal db/provenance.sqlite-shm \
	  db/provenance-quick.sqlite db/provenance-quick.sqlite-wal db/provenance-quick.sqlite-shm
