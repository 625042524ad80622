# Steel-rod study (rod paper, Knak et al. 2022): DEM chains at d = 0.95R, 1.03R, 1.05R,
# 1.15R (rod Table 1) against the continuum reference (mw-fem, the paper's Abaqus role) and
# Pochhammer-Chree theory: PCC of each DEM model against the FEM per frequency (Table 1's
# last column), group velocities by the paper's peak-to-peak (echo) method and their RSS to
# theory (Table 2), the dispersion figure (Figure 9), speed against error. Included by the
# top Makefile, which defines BIN, RESULTS and QUICK and exports MESOWAVE_DB.
#
#   make steel-rod-summary        everything below, $(RESULTS)/steel-rod/summary.md at the end
#
# The rod - its diameter, length and steel (rod paper Section 4.1), the actuator and sensor on its
# ends, the burst - is lab-data/steel-rod/experiment.toml, read by every rod tool (--experiment):
# mw-pack line (R = D / 2, L, the rod's mass), mw-fem rod, mw-calibrate rod (the target E) and
# mw-dispersion (Pochhammer-Chree, the FEM echo's round trip 2 L). No value of it is typed here.
#
# The quick tree (QUICK=1) runs the same rules on a shorter rod (SR_LENGTH_MM: --length-mm; the
# sensor stays on the far end), three frequencies and 0.6 ms FEM records (SR_DURATION_MS:
# --duration-ms; long enough for the echo: it arrives after 3 L / c, about 300 us) - the two
# overrides of the experiment. The DEM chains keep the experiment's 1.5 ms record (their scenes
# take it; they cost milliseconds): 0.95R spreads its echo over longer than 0.6 ms.

# Study prefix: SR (make variables SR_*, functions sr_*; scripts/new-study renames them).
PIPELINE_GOALS += steel-rod-summary steel-rod-calibration

SR_OUT := $(RESULTS)/steel-rod
sr_comma := ,
sr_empty :=
sr_space := $(sr_empty) $(sr_empty)
sr_list = $(subst $(sr_space),$(sr_comma),$(strip $1))           # "a b" -> "a,b"
SR_SCENES := pipeline/steel-rod/scenes
SR_PAPER := lab-data/steel-rod/paper
SR_EXPERIMENT := lab-data/steel-rod/experiment.toml
# Rod paper Section 4.2 (the bursts); the records (Section 4.3) are the experiment's.
ifeq ($(QUICK),1)
SR_LENGTH_MM := 500
SR_FREQS := 50 100 150
SR_DURATION_MS := 0.6
else
SR_FREQS := 50 60 70 80 90 100 110 120 130 140 150
endif
SR_ROD := --experiment $(SR_EXPERIMENT)
# The quick tree's rod length; the FEM's far-end sensor sees the echo after the round trip 2 L
# (mw-dispersion's default with --experiment: the experiment's rod).
SR_LENGTH := $(if $(SR_LENGTH_MM),--length-mm $(SR_LENGTH_MM))
# The quick tree's FEM record; the full tree's is the experiment's [record] (1.5 ms).
SR_DURATION := $(if $(SR_DURATION_MS),--duration-ms $(SR_DURATION_MS))
SR_ROUND_TRIP := $(if $(SR_LENGTH_MM),--distance-mm $(shell echo $$((2 * $(SR_LENGTH_MM)))))
# The band of Table 2's RSS: the sweep's ends (Section 4.2: 50-150 kHz in both trees).
SR_BAND_KHZ := $(firstword $(SR_FREQS)),$(lastword $(SR_FREQS))
# The FEM reference as the paper's Abaqus model (Section 4.3.1): Rayleigh mass-proportional damping
# alpha = SR_ALPHA_PER_S, beta = 0; the burst as a concentrated force at the centre of one end
# (--patch-radius-mm 0: a point force, not the experiment's 2 x 2 mm plate).
SR_ALPHA_PER_S := 2000
# The four chains of Table 1, and 0.95R with the contact modulus that reproduces its E_DEM.
SR_MODELS := 0.95R 1.03R 1.05R 1.15R 0.95R-EDEM
# The FEM reference: axisymmetric rings (validated against the 3D hexahedra, docs/models.md);
# SR_FEM_MODEL=3d runs the paper's 3D mesh instead (about 50x the cost).
SR_FEM_MODEL ?= axisymmetric
SR_FEM_MESH ?= 1
# Further meshes for speed against error (same model).
ifeq ($(QUICK),1)
SR_SPEED_MESHES ?= 2
else
SR_SPEED_MESHES ?= 2 0.5
endif

sr_base = $(firstword $(subst -, ,$1))
sr_scene = $(SR_SCENES)/rod-wave$(if $(filter 1.03R,$1),,-$1).toml

# DEM packings: one line of spheres of R = D / 2, n = ceil(L / d), particle density from the rod's mass.
$(SR_OUT)/packing-%R.h5: $(SR_EXPERIMENT) $(BIN)/mw-pack
	@mkdir -p $(@D)
	$(BIN)/mw-pack line $(SR_ROD) $(SR_LENGTH) --spacing-R $* --packing $@ --out $(SR_OUT)/packing-$*R.json > /dev/null

# DEM runs: the experiment's force burst on the first sphere, the acceleration of the last, its
# record (the scene takes them from the experiment), on this tree's packing.
define SR_DEM_RUN
$(SR_OUT)/dem-$1-$2kHz.h5: $(call sr_scene,$1) $(SR_OUT)/packing-$(call sr_base,$1).h5 $(BIN)/mw-dem
	$(BIN)/mw-dem run $(call sr_scene,$1) --packing $(SR_OUT)/packing-$(call sr_base,$1).h5 --frequency-kHz $2 \
	  --quiet --signals $$@ --summary $(SR_OUT)/dem-$1-$2kHz.json > /dev/null
endef
$(foreach m,$(SR_MODELS),$(foreach f,$(SR_FREQS),$(eval $(call SR_DEM_RUN,$m,$f))))

# FEM runs: the experiment's rod, a point force at the centre of one end, far-end sensor S, the
# experiment's record (the quick tree's shorter one); every frequency of a mesh from ONE run (the
# linear step's impulse response convolved with each burst, Rayleigh damping included, equal to a
# direct run to round-off: fem/superposition.hpp, docs/benchmarks.md "One run, every frequency").
# Each fem-Hmm-FkHz.json reports that one run (its wall_s is the cost of all the frequencies).
define SR_FEM_RUN
$(foreach f,$(SR_FREQS),$(SR_OUT)/fem-$1mm-$(f)kHz.h5 $(SR_OUT)/fem-$1mm-$(f)kHz.json) &: $(SR_EXPERIMENT) $(BIN)/mw-fem
	@mkdir -p $(SR_OUT)
	$(BIN)/mw-fem rod $(SR_ROD) $(SR_LENGTH) --patch-radius-mm 0 --model $(SR_FEM_MODEL) --mesh-mm $1 \
	  --frequencies-kHz $(call sr_list,$(SR_FREQS)) --alpha-damping $(SR_ALPHA_PER_S) $(SR_DURATION) --quiet \
	  --signals-pattern '$(SR_OUT)/fem-$1mm-{f}kHz.h5' --out-pattern '$(SR_OUT)/fem-$1mm-{f}kHz.json' > /dev/null

endef
$(foreach h,$(SR_FEM_MESH) $(SR_SPEED_MESHES),$(eval $(call SR_FEM_RUN,$h)))

# PCC of each DEM model against the FEM, per frequency (signals and envelopes, sensor S; the
# DEM record interpolated onto the FEM's 0.1 us samples).
define SR_PCC
$(SR_OUT)/pcc-$1-$2kHz.csv: $(SR_OUT)/fem-$(SR_FEM_MESH)mm-$2kHz.h5 $(SR_OUT)/dem-$1-$2kHz.h5 $(BIN)/mw-pcc
	$(BIN)/mw-pcc --a $(SR_OUT)/fem-$(SR_FEM_MESH)mm-$2kHz.h5 --b $(SR_OUT)/dem-$1-$2kHz.h5 --sensors S \
	  --resample linear --csv $$@ > /dev/null
endef
$(foreach m,$(SR_MODELS),$(foreach f,$(SR_FREQS),$(eval $(call SR_PCC,$m,$f))))

# Group velocity by the echo at the far end (round trip 2 (n - 1) d for a chain, 2 L for the
# FEM) and its RSS to Pochhammer-Chree over SR_BAND_KHZ (Table 2).
define SR_MEASURE_DEM
$(SR_OUT)/measure-$1.csv: $(foreach f,$(SR_FREQS),$(SR_OUT)/dem-$1-$(f)kHz.h5) $(SR_OUT)/packing-$(call sr_base,$1).h5 $(SR_EXPERIMENT) $(BIN)/mw-dispersion
	$(BIN)/mw-dispersion measure $(foreach f,$(SR_FREQS),--run $(f)=$(SR_OUT)/dem-$1-$(f)kHz.h5) --method echo \
	  --distance-mm $$$$(jq '2 * (.spheres - 1) * .spacing_mm' $(SR_OUT)/packing-$(call sr_base,$1).json) --label $1 \
	  $(SR_ROD) --band-kHz $(SR_BAND_KHZ) --csv $$@ --out $(SR_OUT)/measure-$1.json > /dev/null
endef
$(foreach m,$(SR_MODELS),$(eval $(call SR_MEASURE_DEM,$m)))

define SR_MEASURE_FEM
$(SR_OUT)/measure-fem-$1mm.csv: $(foreach f,$(SR_FREQS),$(SR_OUT)/fem-$1mm-$(f)kHz.h5) $(SR_EXPERIMENT) $(BIN)/mw-dispersion
	$(BIN)/mw-dispersion measure $(foreach f,$(SR_FREQS),--run $(SR_OUT)/fem-$1mm-$(f)kHz.h5) --method echo \
	  $(SR_ROUND_TRIP) --label FEM-$1mm $(SR_ROD) --band-kHz $(SR_BAND_KHZ) \
	  --csv $$@ --out $(SR_OUT)/measure-fem-$1mm.json > /dev/null
endef
$(foreach h,$(SR_FEM_MESH) $(SR_SPEED_MESHES),$(eval $(call SR_MEASURE_FEM,$h)))

include pipeline/steel-rod/summary.mk
include pipeline/steel-rod/calibration.mk

# The schedule (top Makefile, "The order of the runs"): the rod needs nothing of the cube's chain.
PIPELINE_BESIDE += $(SR_OUT)/summary.md $(SR_OUT)/calibration-table.txt
