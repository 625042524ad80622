# Concrete-cube study (the concrete paper's flowchart, Fig. 2), as make rules:
# lab-data/concrete-cube -> $(RESULTS)/concrete-cube. Included by the top Makefile,
# which defines BIN (the tools), RESULTS (results or results-quick), QUICK and
# exports MESOWAVE_DB (the provenance database).
#
# One file a block, in the flowchart's order (included at the end of this file):
#   steps-1-3.mk           steps 1 and 3: density, UPV dynamic moduli, static-modulus conversions, Table 1
#   raw-steps-2-4.mk       steps 2-4 from raw lab data (porosity, times of flight, compression records)
#   step-5-packing.mk      step 5: the DEM packing
#   step-6-calibration.mk  step 6: calibration and Table 2
#   waves.mk               the wave test at 100-500 kHz, its continuum reference, PCC (Table 3), figures
#   speed.mk               speed against error
#   cube-150.mk            the lab's 150 mm cube against its UPV test (make concrete-cube-150; not in make reproduce)

# Study prefix: CC (make variables CC_*, functions cc_*; scripts/new-study renames them).
PIPELINE_GOALS += concrete-cube-summary concrete-cube-raw-summary concrete-cube-calibration-summary \
                  concrete-cube-waves-summary

CC_LAB := lab-data/concrete-cube
CC_OUT := $(RESULTS)/concrete-cube
CC_NOTES := pipeline/concrete-cube

# The --from contract (docs/formats.md): every entry of a --from file fills an option of the
# reader, or the file declares it foreign. The tools' results declare all but their products
# (density.json: density_kg_m3; upv.json: E_d_GPa, density_kg_m3; calibration.json: the five
# calibrated values), so a renamed product is an error in the next step, never a default.

include pipeline/concrete-cube/steps-1-3.mk
include pipeline/concrete-cube/raw-steps-2-4.mk
include pipeline/concrete-cube/step-5-packing.mk
include pipeline/concrete-cube/step-6-calibration.mk
include pipeline/concrete-cube/waves.mk
include pipeline/concrete-cube/speed.mk
include pipeline/concrete-cube/cube-150.mk

# The schedule (top Makefile, "The order of the runs"): the chain packing -> calibration -> DEM
# waves (and the speed runs, which need the calibration) in a make of its own, the continuum
# references and the compression with the paper's parameters beside it; the packing and the
# step-3 moduli, which both sides read, first.
PIPELINE_FIRST += $(CC_OUT)/density.json $(CC_OUT)/upv.json $(CC_OUT)/packing.h5
PIPELINE_CHAIN += $(CC_DEM_RECORDS) $(foreach r,$(CC_SPEED_RUNS),$(CC_OUT)/speed-$r.h5)
PIPELINE_BESIDE += $(foreach f,$(CC_FREQS),$(CC_OUT)/fem-early-$(f)kHz.h5 $(CC_OUT)/fem-$(f)kHz.h5) \
  $(CC_OUT)/compression-paper-parameters.json
