# Included by pipeline/concrete-cube/study.mk (its variables CC_*), in the flowchart's order.
# ==== Waves: 100-500 kHz, sensors B-G (Sections 4.1-4.3) =====================
# DEM: the scene cube-wave.toml (linearised bonded network, 1.5 ms at 50 ns) on
# the step-5 packing with the CC_MATERIAL parameters, every frequency from ONE
# superposed run (docs/models.md, "One run, every frequency"), with the linear
# viscous damping of the same loss as the paper's local damping (Eq. 7).
# Continuum reference: mw-fem box with the dynamic moduli of step 3 (E_d, nu_d,
# rho from mw-upv) on the same experiment (experiment.toml: actuator A, sensors
# B-G, the burst and the record; scaled to the quick tree's cube by --size-mm). No measured cube signals ship,
# so Table 3 here is DEM against this continuum reference; files dropped into
# lab-data/concrete-cube/measured/ (docs/formats.md) are compared with the DEM too.
#
# Two FEM references per frequency (docs/benchmarks.md, "Concrete cube: the continuum
# reference"): the FEM's phase error grows with the distance travelled, so no
# affordable mesh is converged over the whole 1.5 ms (hundreds of wavelengths);
# over the first 50 us (the direct waves and their first reflections) a mesh of
# h = 156.25 mm / f[kHz] (1.5625 mm at 100 kHz, 0.3125 mm at 500 kHz: a fixed
# number of elements per wavelength, ~17 per S wavelength) is.
#   fem-early-FkHz  55 us, the converged reference of the first packets;
#   fem-FkHz        the whole record at 2 mm (<= 200 kHz) or 1 mm, for the signal
#                   and spectrum figures and the PCC over the record, as the
#                   paper's Table 3 - not a converged reference after the first
#                   packets (said so in the report).
# One mw-fem run per mesh gives every frequency of it (--frequencies-kHz,
# fem/superposition.hpp: the linear step's unit-impulse response convolved with
# each burst, equal to a direct run to round-off; docs/benchmarks.md, "One run,
# every frequency"): the whole records from one run per mesh (2 instead of 9), and
# the early references all from one run on the finest mesh, h(highest frequency):
# at least as converged as h(f) for every f (a finer mesh changes them only by the
# coarser mesh's discretisation error, measured there), and the cheapest choice -
# every group that holds the highest frequency costs that mesh's run, which is 38 %
# of the nine meshes' (the cost goes as h^-4 = f^4).

CC_SCENE := $(CC_NOTES)/scenes/cube-wave.toml
CC_MEASURED_DIR ?= $(CC_LAB)/measured
CC_EARLY_US := 50
CC_EARLY_RECORD := --duration-ms 0.055
cc_fem_early_mesh = $(shell awk 'BEGIN { printf "%.6g", 156.25 / $1 }')
ifeq ($(QUICK),1)
CC_FREQS := 100 300 500
CC_RECORD := --duration-ms 0.3
cc_fem_mesh = 1
else
CC_FREQS := 100 150 200 250 300 350 400 450 500
CC_RECORD :=
cc_fem_mesh = $(if $(filter 100 150 200,$1),2,1)
endif
CC_FIGURE_FREQS := 100 300 500
# The wave test as the lab sets it up, for both solvers (the scene references it too).
CC_EXPERIMENT := $(CC_LAB)/experiment.toml
CC_FEM_EXPERIMENT := --experiment $(CC_EXPERIMENT) $(if $(CC_SIDE_MM),--size-mm $(CC_SIDE_MM))
CC_FEM_INPUTS := $(CC_OUT)/upv.json $(CC_EXPERIMENT) $(BIN)/mw-fem

# Measured signals (a lab's own): lab-data/concrete-cube/measured/<F>kHz.h5 or .csv,
# signals named B-G, t = 0 at the start of the burst; each is compared with the DEM
# record at its frequency (below), so the DEM run makes those frequencies too.
CC_MEASURED := $(sort $(wildcard $(CC_MEASURED_DIR)/*kHz.h5 $(CC_MEASURED_DIR)/*kHz.csv))
cc_measured_f = $(patsubst %kHz,%,$(basename $(notdir $1)))
CC_MEASURED_FREQS := $(foreach m,$(CC_MEASURED),$(call cc_measured_f,$m))

# The DEM records, dem-FkHz.h5 / .json for every frequency, from one mw-dem run: one
# unit-impulse run of the linearised network, each burst's signals its convolution
# with the response. The paper's local damping F (1 - alpha_d sgn(F v)) (Eq. 7) is
# not additive, so the runs use its linear equivalent (--damping-law viscous):
# mass-proportional damping c = 4 alpha_d f_c at each burst's centre frequency f_c,
# zeta = alpha_d / pi, the same amplitude loss per cycle as Eq. (7) on one
# oscillator. Against direct runs with Eq. (7) it differs by 1 - PCC = 3e-4 to
# 2.5e-3 (docs/benchmarks.md, "One run, every frequency"); against direct viscous
# runs the superposition is exact to 1 - PCC <= 1.2e-6. Where the bound on the
# peak bond force / strength does not prove the linear model valid (it depends on
# the calibrated material and the packing) the run checks that frequency with a
# direct run (--check-unproven), which measures the peak; each record says which
# (superposition.validity, superposition.checks). dem-waves.json: the run's summary.
CC_DEM_FREQS := $(sort $(CC_FREQS) $(CC_MEASURED_FREQS))
cc_comma := ,
cc_empty :=
cc_space := $(cc_empty) $(cc_empty)
# The rule is a function of the folder ($1) and the material ($2), so that cube-150.mk makes the
# same records with its second calibration.
cc_dem_records = $(foreach f,$(CC_DEM_FREQS),$1/dem-$(f)kHz.h5 $1/dem-$(f)kHz.json)
define CC_DEM_WAVES
$(call cc_dem_records,$1) $1/dem-waves.json &: $(CC_SCENE) $(CC_EXPERIMENT) $(CC_OUT)/packing.h5 $2 $(BIN)/mw-dem
	@mkdir -p $1
	$(BIN)/mw-dem --from $2 run $(CC_SCENE) --packing $(CC_OUT)/packing.h5 --damping-law viscous \
	  --frequencies-kHz $(subst $(cc_space),$(cc_comma),$(CC_DEM_FREQS)) --check-unproven $(CC_RECORD) --quiet \
	  --signals-pattern '$1/dem-{f}kHz.h5' --summary-pattern '$1/dem-{f}kHz.json' \
	  --summary $1/dem-waves.json > /dev/null
endef
CC_DEM_RECORDS := $(call cc_dem_records,$(CC_OUT))
$(eval $(call CC_DEM_WAVES,$(CC_OUT),$(CC_MATERIAL)))

# One superposed mw-fem run: $1 the files' prefix, $2 the mesh [mm], $3 its frequencies, $4 the record options.
define CC_FEM_RUN
$(foreach f,$3,$(CC_OUT)/$1-$(f)kHz.h5 $(CC_OUT)/$1-$(f)kHz.json) &: $(CC_FEM_INPUTS)
	$(BIN)/mw-fem --from $(CC_OUT)/upv.json box $(CC_FEM_EXPERIMENT) --mesh-mm $2 \
	  --frequencies-kHz $(subst $(cc_space),$(cc_comma),$(strip $3)) $4 --quiet \
	  --signals-pattern '$(CC_OUT)/$1-{f}kHz.h5' --out-pattern '$(CC_OUT)/$1-{f}kHz.json' > /dev/null

endef
# The whole records: the frequencies of each mesh cc_fem_mesh gives, one run per mesh.
CC_FEM_MESHES := $(sort $(foreach f,$(CC_FREQS),$(call cc_fem_mesh,$f)))
cc_fem_group = $(foreach f,$(CC_FREQS),$(if $(filter $1,$(call cc_fem_mesh,$f)),$f))
$(foreach m,$(CC_FEM_MESHES),$(eval $(call CC_FEM_RUN,fem,$m,$(call cc_fem_group,$m),$(CC_RECORD))))
# The early references: one run on the mesh of the highest frequency.
CC_FEM_EARLY_MESH := $(call cc_fem_early_mesh,$(lastword $(shell printf '%s\n' $(CC_FREQS) | sort -g)))
$(eval $(call CC_FEM_RUN,fem-early,$(CC_FEM_EARLY_MESH),$(CC_FREQS),$(CC_EARLY_RECORD)))

# PCC of DEM against FEM per sensor, the DEM record interpolated onto the FEM's
# 0.1 us samples: over the first 50 us against the converged early reference, with
# the first packets' signals and envelopes (the paper's Fig. 14); over the whole
# record, with the signals (Figs. 12-13) and spectra (Fig. 15). The envelopes are
# computed zero-padded to twice the record (--pad double), so that the end of a
# record does not wrap onto its start.
# The rules are a function of the folder of the DEM records, which gets the PCC files and
# Table 3 ($1), and a label for the figures' titles ($2, none here), so that cube-150.mk compares
# its second calibration's records with the same references.
define CC_WAVE_PCC
$1/pcc-early-%kHz.csv $1/pcc-early-%kHz.json $1/signals-early-%kHz.png \
    $1/envelopes-early-%kHz.png: $(CC_OUT)/fem-early-%kHz.h5 $1/dem-%kHz.h5 $(BIN)/mw-pcc
	$(BIN)/mw-pcc --a $(CC_OUT)/fem-early-$$*kHz.h5 --b $1/dem-$$*kHz.h5 --resample linear --pad double \
	  --window-end-us $(CC_EARLY_US) --csv $1/pcc-early-$$*kHz.csv --out $1/pcc-early-$$*kHz.json \
	  --labels FEM,DEM --title "Concrete cube$(if $2, ($2)), $$* kHz burst, first $(CC_EARLY_US) us: DEM against the continuum reference (FEM)" \
	  --plot-window-us 0,$(CC_EARLY_US) --plot-signals $1/signals-early-$$*kHz.png \
	  --plot-envelopes $1/envelopes-early-$$*kHz.png > /dev/null

$1/pcc-%kHz.csv $1/pcc-%kHz.json $1/spectra-%kHz.csv $1/signals-%kHz.png \
    $1/spectra-%kHz.png: $(CC_OUT)/fem-%kHz.h5 $1/dem-%kHz.h5 $(BIN)/mw-pcc
	$(BIN)/mw-pcc --a $(CC_OUT)/fem-$$*kHz.h5 --b $1/dem-$$*kHz.h5 --resample linear --pad double \
	  --csv $1/pcc-$$*kHz.csv --out $1/pcc-$$*kHz.json \
	  --spectra $1/spectra-$$*kHz.csv --max-frequency-kHz $$$$(( 2 * $$* )) \
	  --labels FEM,DEM --title "Concrete cube$(if $2, ($2)), $$* kHz burst, whole record: DEM against the continuum reference (FEM)" \
	  --plot-signals $1/signals-$$*kHz.png --plot-spectra $1/spectra-$$*kHz.png > /dev/null

endef
$(eval $(call CC_WAVE_PCC,$(CC_OUT),))

# Each measured file against the DEM record at its frequency (the DEM interpolated
# onto the measured samples).
define CC_MEASURED_PCC
$(CC_OUT)/pcc-measured-$(call cc_measured_f,$1)kHz.csv: $1 $(CC_OUT)/dem-$(call cc_measured_f,$1)kHz.h5 $(BIN)/mw-pcc
	$(BIN)/mw-pcc --a $1 --b $(CC_OUT)/dem-$(call cc_measured_f,$1)kHz.h5 --resample linear --pad double --csv $$@ \
	  --labels measured,DEM --title "Concrete cube, $(call cc_measured_f,$1) kHz: DEM against the measured signals ($1)" \
	  --plot-signals $(CC_OUT)/signals-measured-$(call cc_measured_f,$1)kHz.png > /dev/null
endef
$(foreach m,$(CC_MEASURED),$(eval $(call CC_MEASURED_PCC,$m)))

# Table 3: the mean PCC over sensors per frequency, beside the paper's (which is
# experiment against DEM), the measured comparison where there is one; the PCC of
# every sensor; both as figures.
cc_rows = $(foreach f,$(CC_FREQS),--row $f=$(or $2,$(CC_OUT))/pcc-$1$(f)kHz.csv)
CC_SENSORS := B C D E F G
ifneq ($(CC_MEASURED),)
$(CC_OUT)/table3-measured.csv: $(foreach f,$(CC_MEASURED_FREQS),$(CC_OUT)/pcc-measured-$(f)kHz.csv) $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name f_kHz $(foreach f,$(CC_MEASURED_FREQS),--row $f=$(CC_OUT)/pcc-measured-$(f)kHz.csv) \
	  --where sensor=mean --column pcc_signal --column pcc_envelope --csv $@ > /dev/null
CC_TABLE3_MEASURED := $(CC_OUT)/table3-measured.csv
CC_JOIN_MEASURED := --join $(CC_TABLE3_MEASURED):measured_vs_dem_pcc_signals=pcc_signal,measured_vs_dem_pcc_envelopes=pcc_envelope
CC_MEASURED_Y := --y "measured_vs_dem_pcc_signals=measured vs DEM, signals"
endif
# The first-packets table, then the whole-record one with the first-packets columns joined to it.
# $1 the folder (as CC_WAVE_PCC's), $2 and $3 the names of variables that hold more prerequisites
# and more options of the whole table (the measured comparison).
define CC_TABLE3
$1/table3-early.csv: $(foreach f,$(CC_FREQS),$1/pcc-early-$(f)kHz.csv) $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name f_kHz $(call cc_rows,early-,$1) --where sensor=mean \
	  --column pcc_signal --column pcc_envelope --csv $$@ > /dev/null

$1/table3.csv: $(foreach f,$(CC_FREQS),$1/pcc-$(f)kHz.csv) $1/table3-early.csv \
    $(CC_LAB)/paper/table3.csv $($2) $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name f_kHz $(call cc_rows,,$1) --where sensor=mean \
	  --column dem_vs_fem_pcc_signals=pcc_signal --column dem_vs_fem_pcc_envelopes=pcc_envelope \
	  --join $1/table3-early.csv:dem_vs_fem_first_$(CC_EARLY_US)us_pcc_signals=pcc_signal,dem_vs_fem_first_$(CC_EARLY_US)us_pcc_envelopes=pcc_envelope \
	  --join $(CC_LAB)/paper/table3.csv:paper_experiment_vs_dem_pcc=pcc_mean $($3) --csv $$@ > /dev/null

endef
# The measured folder itself: a file dropped in or taken out re-makes Table 3.
CC_TABLE3_MEASURED_INPUTS := $(CC_TABLE3_MEASURED) $(wildcard $(CC_MEASURED_DIR))
$(eval $(call CC_TABLE3,$(CC_OUT),CC_TABLE3_MEASURED_INPUTS,CC_JOIN_MEASURED))

$(CC_OUT)/pcc-sensors.csv: $(foreach f,$(CC_FREQS),$(CC_OUT)/pcc-early-$(f)kHz.csv) $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name f_kHz $(call cc_rows,early-) \
	  $(foreach s,$(CC_SENSORS),--column $s_signal=pcc_signal@sensor=$s) \
	  $(foreach s,$(CC_SENSORS),--column $s_envelope=pcc_envelope@sensor=$s) --csv $@ > /dev/null

$(CC_OUT)/table3.png: $(CC_OUT)/table3.csv $(BIN)/mw-table
	$(BIN)/mw-table plot $< --x f_kHz --y "dem_vs_fem_first_$(CC_EARLY_US)us_pcc_signals=DEM vs FEM, first $(CC_EARLY_US) us, signals" \
	  --y "dem_vs_fem_first_$(CC_EARLY_US)us_pcc_envelopes=DEM vs FEM, first $(CC_EARLY_US) us, envelopes" \
	  --y "dem_vs_fem_pcc_signals=DEM vs FEM, whole record, signals" \
	  --y "dem_vs_fem_pcc_envelopes=DEM vs FEM, whole record, envelopes" --y "paper_experiment_vs_dem_pcc=paper: experiment vs DEM" \
	  $(CC_MEASURED_Y) \
	  --y-range -0.3,1 --x-label "burst centre frequency [kHz]" --y-label "mean PCC over sensors B-G" \
	  --key below --title "Concrete cube: Table 3 (mean PCC over the sensors)" --out $@ > /dev/null

$(CC_OUT)/pcc-sensors.png: $(CC_OUT)/pcc-sensors.csv $(BIN)/mw-table
	$(BIN)/mw-table plot $< --x f_kHz $(foreach s,$(CC_SENSORS),--y "$s_signal=$s") --y-range -0.5,1 \
	  --x-label "burst centre frequency [kHz]" --y-label "PCC of DEM against FEM, first $(CC_EARLY_US) us, signals" \
	  --key below --title "Concrete cube: PCC per sensor, first $(CC_EARLY_US) us" --out $@ > /dev/null
