# mesowave - the one entry point.
#
#   make reproduce   install what is missing, build, run the studies on lab-data/
#   make test        install what is missing, build, run every test (CTest summary at the end)
#   make bench       benchmarks (bench/), results in docs/benchmarks.md
#   make clean       remove build/, results/ and the provenance database
#
# Every tool run by the pipeline records itself in $(MESOWAVE_DB).

SHELL := /bin/bash
.DELETE_ON_ERROR:

BUILD ?= build
BIN := $(BUILD)/bin
JOBS ?= $(shell nproc)
CMAKE_BUILD_TYPE ?= Release
export MESOWAVE_DB ?= $(CURDIR)/db/provenance.sqlite

.PHONY: all help deps build test reproduce pipeline bench clean

all: build

help:
	@sed -n '2,10p' Makefile | sed 's/^# \{0,1\}//'

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
# the results' timestamps with the tools as they are now.
reproduce: build
	@$(MAKE) --no-print-directory pipeline

include pipeline/concrete-cube/study.mk
include pipeline/steel-rod/study.mk
include pipeline/report.mk

pipeline: concrete-cube-summary concrete-cube-raw-summary steel-rod-summary report/index.html
	@echo; echo "report: $(CURDIR)/report/index.html"

bench: build
	bench/run

clean:
	rm -rf $(BUILD) results report db/provenance.sqlite db/provenance.sqlite-wal db/provenance.sqlite-shm
