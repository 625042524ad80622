# Concrete-cube study (the concrete paper's flowchart, Fig. 2), as make rules:
# lab-data/concrete-cube -> $(RESULTS)/concrete-cube. Included by the top Makefile,
# which defines BIN (the tools), RESULTS (results or results-quick), QUICK and
# exports MESOWAVE_DB (the provenance database).
#
# Blocks, in the flowchart's order: steps 1 and 3 (density, UPV dynamic moduli,
# static-modulus conversions, Table 1); steps 2-4 from raw lab data; step 5 (the
# DEM packing); step 6 (calibration and Table 2); the wave test at
# 100-500 kHz with its continuum reference, PCC (Table 3), figures and speed
# against error.

# Study prefix: CC (make variables CC_*, functions cc_*; scripts/new-study renames them).
PIPELINE_GOALS += concrete-cube-summary concrete-cube-raw-summary concrete-cube-calibration-summary \
                  concrete-cube-waves-summary

CC_LAB := lab-data/concrete-cube
CC_OUT := $(RESULTS)/concrete-cube
CC_NOTES := pipeline/concrete-cube

# The --from contract (app/tool.hpp): every entry of a --from file fills an option,
# or the file declares it foreign, or the reader names it in --from-ignore. A tool's
# JSON carries its inputs and side results for the reader beside the value the next
# step takes; these lists are those entries, per reader (a renamed entry is then an
# error, not a value left silently at its default).
CC_DENSITY_UNTAKEN := --from-ignore shape,mass_g,side_mm,mass_resolution_g,length_resolution_mm,volume_m3,u_density_kg_m3
CC_UPV_UNTAKEN_BY_FEM := --from-ignore G_d_GPa,method,nu_d_source,path_mm,t_p_us,t_s_us,v_p_m_s,v_s_m_s
CC_UPV_UNTAKEN_BY_ESTATIC := $(CC_UPV_UNTAKEN_BY_FEM),nu_d
CC_CALIBRATION_UNTAKEN := --from-ignore E_glob_GPa,nu_glob,sigma_dem_MPa,E_st_target_GPa,nu_st_target,sigma_max_target_MPa \
  --from-ignore E_error_pct,nu_error,sigma_error_pct,calibrated_by_trial,trial_count,trials_wall_s

# Step 1: density of the 150 mm cube.
$(CC_OUT)/density.json: $(CC_LAB)/specimen.toml $(BIN)/mw-specimen
	@mkdir -p $(@D)
	$(BIN)/mw-specimen --from $(CC_LAB)/specimen.toml --out $@ > /dev/null

# Step 3, dynamic route: v_p, v_s, nu_d (Eq. 10), E_d (Eq. 9).
$(CC_OUT)/upv.json: $(CC_LAB)/upv.toml $(CC_OUT)/density.json $(BIN)/mw-upv
	$(BIN)/mw-upv --from $(CC_OUT)/density.json $(CC_DENSITY_UNTAKEN) --from $(CC_LAB)/upv.toml --out $@ > /dev/null

# Step 3: Table 1 from the E_d computed exactly from the paper's inputs...
$(CC_OUT)/table1.csv $(CC_OUT)/table1.json &: $(CC_OUT)/upv.json $(CC_LAB)/static-test.toml $(BIN)/mw-estatic
	$(BIN)/mw-estatic --from $(CC_OUT)/upv.json $(CC_UPV_UNTAKEN_BY_ESTATIC) --from $(CC_LAB)/static-test.toml \
	  --table $(CC_OUT)/table1.csv --out $(CC_OUT)/table1.json > /dev/null

# ...and from the rounded E_d = 36.68 GPa the paper printed and used.
$(CC_OUT)/table1-printed-Ed.csv $(CC_OUT)/table1-printed-Ed.json &: $(CC_OUT)/density.json \
    $(CC_LAB)/paper/printed-results.toml $(CC_LAB)/static-test.toml $(BIN)/mw-estatic
	$(BIN)/mw-estatic --from $(CC_OUT)/density.json $(CC_DENSITY_UNTAKEN) --from $(CC_LAB)/paper/printed-results.toml \
	  --from $(CC_LAB)/static-test.toml \
	  --table $(CC_OUT)/table1-printed-Ed.csv --out $(CC_OUT)/table1-printed-Ed.json > /dev/null

# Beside the paper's printed values.
$(CC_OUT)/density-vs-paper.txt $(CC_OUT)/density-vs-paper.csv &: $(CC_OUT)/density.json $(CC_LAB)/paper/printed-results.toml $(BIN)/mw-compare
	$(BIN)/mw-compare --ours $(CC_OUT)/density.json --paper $(CC_LAB)/paper/printed-results.toml \
	  --title "Step 1: density (the mass is derived from the printed density, so this checks the arithmetic)" \
	  --csv $(CC_OUT)/density-vs-paper.csv --text $(CC_OUT)/density-vs-paper.txt > /dev/null

$(CC_OUT)/upv-vs-paper.txt $(CC_OUT)/upv-vs-paper.csv &: $(CC_OUT)/upv.json $(CC_LAB)/paper/printed-results.toml $(BIN)/mw-compare
	$(BIN)/mw-compare --ours $(CC_OUT)/upv.json --paper $(CC_LAB)/paper/printed-results.toml \
	  --title "Step 3: dynamic moduli from t_p, t_s, path and density (Eqs. 9-10) vs the paper" \
	  --csv $(CC_OUT)/upv-vs-paper.csv --text $(CC_OUT)/upv-vs-paper.txt > /dev/null

$(CC_OUT)/table1-vs-paper.txt $(CC_OUT)/table1-vs-paper.csv &: $(CC_OUT)/table1.csv $(CC_LAB)/paper/table1.csv $(BIN)/mw-compare
	$(BIN)/mw-compare --ours $(CC_OUT)/table1.csv --paper $(CC_LAB)/paper/table1.csv --key method \
	  --title "Table 1 from the exact E_d (36.671 GPa) vs the paper's Table 1" \
	  --csv $(CC_OUT)/table1-vs-paper.csv --text $(CC_OUT)/table1-vs-paper.txt > /dev/null

$(CC_OUT)/table1-printed-Ed-vs-paper.txt $(CC_OUT)/table1-printed-Ed-vs-paper.csv &: $(CC_OUT)/table1-printed-Ed.csv $(CC_LAB)/paper/table1.csv $(BIN)/mw-compare
	$(BIN)/mw-compare --ours $(CC_OUT)/table1-printed-Ed.csv --paper $(CC_LAB)/paper/table1.csv --key method \
	  --title "Table 1 from the paper's printed E_d (36.68 GPa) vs the paper's Table 1" \
	  --csv $(CC_OUT)/table1-printed-Ed-vs-paper.csv --text $(CC_OUT)/table1-printed-Ed-vs-paper.txt > /dev/null

CC_RESULTS := $(CC_OUT)/density.json $(CC_OUT)/upv.json $(CC_OUT)/table1.csv $(CC_OUT)/table1-printed-Ed.csv \
              $(CC_OUT)/density-vs-paper.txt $(CC_OUT)/upv-vs-paper.txt $(CC_OUT)/table1-vs-paper.txt $(CC_OUT)/table1-printed-Ed-vs-paper.txt

.PHONY: concrete-cube concrete-cube-summary
concrete-cube: $(CC_RESULTS)

# Printing what is already made runs no tool: a second `make reproduce` shows
# the same tables and re-runs nothing.
concrete-cube-summary: concrete-cube
	@echo
	@echo "== Concrete cube: steps 1 and 3 (results/concrete-cube) =="
	@cat $(CC_OUT)/density-vs-paper.txt
	@echo
	@cat $(CC_OUT)/upv-vs-paper.txt
	@echo
	@cat $(CC_OUT)/table1-vs-paper.txt
	@echo
	@cat $(CC_OUT)/table1-printed-Ed-vs-paper.txt
	@echo
	@cat $(CC_NOTES)/table1-note.txt

# ==== Lab raw data (issue 7): steps 2-4 from raw files =========================
# The synthetic raw set in lab-data/concrete-cube/raw (source: synthetic, made by
# its generate.sh from the truth beside each file) run through the raw-data
# tools: porosity from the micro-CT stack and the face images (step 2), times of
# flight picked on the UPV waveforms (step 3), E_st, sigma_max and the crosshead
# multiplier from the load-frame records (step 4). Outputs: results/concrete-cube/raw-*.
#   make concrete-cube-raw            the results
#   make concrete-cube-raw-summary    and the comparison with the paper's values they were made from

CC_RAW := $(CC_LAB)/raw

# Step 2: micro-CT stack (pores dark, one Otsu threshold for the stack, specimen ROI).
$(CC_OUT)/raw-porosity-ct.json $(CC_OUT)/raw-porosity-ct-slices.csv $(CC_OUT)/raw-porosity-ct-overlay.png \
    $(CC_OUT)/raw-porosity-ct-profile.png &: $(CC_RAW)/ct-stack.tif $(CC_RAW)/ct-truth.toml $(BIN)/mw-porosity
	@mkdir -p $(@D)
	$(BIN)/mw-porosity --kind ct $(CC_RAW)/ct-stack.tif --roi 6,6,96,96 --from $(CC_RAW)/ct-truth.toml \
	  --csv $(CC_OUT)/raw-porosity-ct-slices.csv --overlay $(CC_OUT)/raw-porosity-ct-overlay.png \
	  --overlay-max-images 9 --profile-plot $(CC_OUT)/raw-porosity-ct-profile.png \
	  --out $(CC_OUT)/raw-porosity-ct.json > /dev/null

# Step 2: microscope images of the faces (plaster-filled pores bright, Otsu per image).
CC_RAW_FACES := $(CC_RAW)/face-1.png $(CC_RAW)/face-2.png $(CC_RAW)/face-3.png
$(CC_OUT)/raw-porosity-faces.json $(CC_OUT)/raw-porosity-faces.csv $(CC_OUT)/raw-porosity-faces-overlay.png &: \
    $(CC_RAW_FACES) $(BIN)/mw-porosity
	@mkdir -p $(@D)
	$(BIN)/mw-porosity --kind face $(CC_RAW_FACES) --csv $(CC_OUT)/raw-porosity-faces.csv \
	  --overlay $(CC_OUT)/raw-porosity-faces-overlay.png --out $(CC_OUT)/raw-porosity-faces.json > /dev/null

# Step 3: t_p and t_s picked on the P and S waveforms (AIC, low-pass at 4x the
# transducer frequencies, the 2 us transducer delay of upv-truth.toml subtracted).
$(CC_OUT)/raw-upv.json $(CC_OUT)/raw-upv-fig7.png &: $(CC_RAW)/upv-p.csv $(CC_RAW)/upv-s.csv \
    $(CC_RAW)/upv-truth.toml $(CC_OUT)/density.json $(BIN)/mw-upv
	$(BIN)/mw-upv --from $(CC_OUT)/density.json $(CC_DENSITY_UNTAKEN) --from $(CC_RAW)/upv-truth.toml \
	  --p-wave $(CC_RAW)/upv-p.csv --s-wave $(CC_RAW)/upv-s.csv --lowpass-kHz 216 --s-lowpass-kHz 160 \
	  --plot $(CC_OUT)/raw-upv-fig7.png --title 'Synthetic UPV records (lab-data/concrete-cube/raw)' \
	  --out $(CC_OUT)/raw-upv.json > /dev/null

# Step 4: cyclic test (EN 12390-13 method B) and test to failure of the 150 mm cube.
$(CC_OUT)/raw-compress.json $(CC_OUT)/raw-compress-cycles.csv $(CC_OUT)/raw-compress-cyclic.csv \
    $(CC_OUT)/raw-compress-failure.csv $(CC_OUT)/raw-compress-fig5.png &: \
    $(CC_RAW)/cyclic-test.csv $(CC_RAW)/failure-test.csv $(CC_RAW)/compression-truth.toml $(BIN)/mw-compress
	@mkdir -p $(@D)
	$(BIN)/mw-compress --cyclic $(CC_RAW)/cyclic-test.csv --failure $(CC_RAW)/failure-test.csv \
	  --from $(CC_RAW)/compression-truth.toml --cycles-csv $(CC_OUT)/raw-compress-cycles.csv \
	  --cyclic-curve $(CC_OUT)/raw-compress-cyclic.csv --failure-curve $(CC_OUT)/raw-compress-failure.csv \
	  --plot $(CC_OUT)/raw-compress-fig5.png --title 'Synthetic compression tests (lab-data/concrete-cube/raw)' \
	  --out $(CC_OUT)/raw-compress.json > /dev/null

# Beside the paper's values the synthetic set was made from.
$(CC_OUT)/raw-porosity-vs-paper.txt $(CC_OUT)/raw-porosity-ct-vs-paper.csv \
    $(CC_OUT)/raw-porosity-faces-vs-paper.csv &: $(CC_OUT)/raw-porosity-ct.json $(CC_OUT)/raw-porosity-faces.json \
    $(CC_LAB)/porosity.toml $(BIN)/mw-compare
	$(BIN)/mw-compare --ours $(CC_OUT)/raw-porosity-ct.json --paper $(CC_LAB)/porosity.toml \
	  --title "Step 2 from the synthetic micro-CT stack (truth: lab-data/concrete-cube/raw/ct-truth.toml)" \
	  --csv $(CC_OUT)/raw-porosity-ct-vs-paper.csv --text $(CC_OUT)/raw-porosity-ct-vs-paper.txt > /dev/null
	$(BIN)/mw-compare --ours $(CC_OUT)/raw-porosity-faces.json --paper $(CC_LAB)/porosity.toml \
	  --title "Step 2 from the synthetic face images (truth: lab-data/concrete-cube/raw/faces-truth.toml)" \
	  --csv $(CC_OUT)/raw-porosity-faces-vs-paper.csv --text $(CC_OUT)/raw-porosity-faces-vs-paper.txt > /dev/null
	cat $(CC_OUT)/raw-porosity-ct-vs-paper.txt $(CC_OUT)/raw-porosity-faces-vs-paper.txt > $(CC_OUT)/raw-porosity-vs-paper.txt

$(CC_OUT)/raw-upv-vs-paper.txt $(CC_OUT)/raw-upv-vs-paper.csv &: $(CC_OUT)/raw-upv.json $(CC_LAB)/upv.toml $(BIN)/mw-compare
	$(BIN)/mw-compare --ours $(CC_OUT)/raw-upv.json --paper $(CC_LAB)/upv.toml \
	  --title "Step 3 from the synthetic UPV waveforms: picked times of flight" \
	  --csv $(CC_OUT)/raw-upv-vs-paper.csv --text $(CC_OUT)/raw-upv-vs-paper.txt > /dev/null

$(CC_OUT)/raw-compress-vs-paper.txt $(CC_OUT)/raw-compress-vs-paper.csv &: $(CC_OUT)/raw-compress.json $(CC_LAB)/static-test.toml $(BIN)/mw-compare
	$(BIN)/mw-compare --ours $(CC_OUT)/raw-compress.json --paper $(CC_LAB)/static-test.toml \
	  --title "Step 4 from the synthetic load-frame records (truth: lab-data/concrete-cube/raw/compression-truth.toml)" \
	  --csv $(CC_OUT)/raw-compress-vs-paper.csv --text $(CC_OUT)/raw-compress-vs-paper.txt > /dev/null

CC_RAW_RESULTS := $(CC_OUT)/raw-porosity-ct.json $(CC_OUT)/raw-porosity-faces.json $(CC_OUT)/raw-upv.json \
                  $(CC_OUT)/raw-compress.json $(CC_OUT)/raw-porosity-vs-paper.txt $(CC_OUT)/raw-upv-vs-paper.txt \
                  $(CC_OUT)/raw-compress-vs-paper.txt

.PHONY: concrete-cube-raw concrete-cube-raw-summary
concrete-cube-raw: $(CC_RAW_RESULTS)

concrete-cube-raw-summary: concrete-cube-raw
	@echo
	@echo "== Concrete cube from raw lab data (synthetic set, results/concrete-cube/raw-*) =="
	@cat $(CC_OUT)/raw-porosity-vs-paper.txt
	@echo
	@cat $(CC_OUT)/raw-upv-vs-paper.txt
	@echo
	@cat $(CC_OUT)/raw-compress-vs-paper.txt

# ==== Step 5: the DEM model's packing (Section 3.3) ============================
# The 50 mm cube of porosity.toml at p = 7 %, d = 1.6-2.0 mm and C_f = 1.1
# (dem-packing.toml), particle density from step 1 so that the model weighs what
# the specimen weighs; beside the paper's "40,000 elements, almost 250,000
# contacts". The quick tree packs a 20 mm cube of the same material.

ifeq ($(QUICK),1)
CC_SIDE_MM := 20
CC_PACK_SIZE := --cube-side-mm $(CC_SIDE_MM)
else
CC_SIDE_MM :=
CC_PACK_SIZE :=
endif

$(CC_OUT)/packing.h5 $(CC_OUT)/packing.json &: $(CC_LAB)/porosity.toml $(CC_LAB)/dem-packing.toml \
    $(CC_OUT)/density.json $(BIN)/mw-pack
	$(BIN)/mw-pack box --from $(CC_LAB)/porosity.toml --from $(CC_LAB)/dem-packing.toml --from $(CC_OUT)/density.json \
	  $(CC_DENSITY_UNTAKEN) $(CC_PACK_SIZE) --quiet --packing $(CC_OUT)/packing.h5 --out $(CC_OUT)/packing.json > /dev/null

$(CC_OUT)/packing-vs-paper.txt $(CC_OUT)/packing-vs-paper.csv &: $(CC_OUT)/packing.json \
    $(CC_LAB)/paper/dem-model.toml $(BIN)/mw-compare
	$(BIN)/mw-compare --ours $(CC_OUT)/packing.json --paper $(CC_LAB)/paper/dem-model.toml \
	  --title "Step 5: the packing (spheres; bonds = pairs within C_f (r_i + r_j)) vs the paper's round numbers" \
	  --csv $(CC_OUT)/packing-vs-paper.csv --text $(CC_OUT)/packing-vs-paper.txt > /dev/null

# ==== Step 6: calibration (E_dem, nu_dem, T, C, friction) =====================
# The virtual compression test of the step-5 packing (scenes/cube-compression.toml:
# frictionless walls, the upper one at 25 mm/s with the inertial number checked
# below 1e-4, extensometers at mid-height) and mw-calibrate cube, which varies
# E_dem, nu_dem and T = C (friction angle 18 deg, given) from the paper's values
# (the scene's material) until E_glob, nu_glob and the peak stress meet the static
# tests (static-test.toml) within 1 % on E, 0.01 on nu and 2 % on strength
# (docs/calibration.md). Every trial is a recorded mw-dem run; calibration.json
# is the material of the wave runs (CC_MATERIAL, read by `mw-dem --from`).
#
# Table 2 sets four rows side by side: the static tests, the paper's calibrated
# Yade model, the paper's parameters on mesowave's packing (one more compression
# run: why mesowave calibrates its own), and mesowave's calibration.
CC_COMPRESSION_SCENE := $(CC_NOTES)/scenes/cube-compression.toml
CC_CALIBRATION_TRIALS := $(CC_OUT)/calibration

$(CC_OUT)/calibration.json $(CC_OUT)/calibration-trials.csv $(CC_OUT)/calibration-trajectory.png \
    $(CC_OUT)/calibration-stress-strain.png &: $(CC_COMPRESSION_SCENE) $(CC_OUT)/packing.h5 \
    $(CC_LAB)/static-test.toml $(BIN)/mw-calibrate $(BIN)/mw-dem
	rm -rf $(CC_CALIBRATION_TRIALS)
	$(BIN)/mw-calibrate --from $(CC_LAB)/static-test.toml cube --scene $(CC_COMPRESSION_SCENE) \
	  --packing $(CC_OUT)/packing.h5 --work-dir $(CC_CALIBRATION_TRIALS) --trials $(CC_OUT)/calibration-trials.csv \
	  --plot-trajectory $(CC_OUT)/calibration-trajectory.png --plot-curves $(CC_OUT)/calibration-stress-strain.png \
	  --out $(CC_OUT)/calibration.json > /dev/null

$(CC_OUT)/compression-paper-parameters.json $(CC_OUT)/compression-paper-parameters.csv \
    $(CC_OUT)/compression-paper-parameters.h5 &: $(CC_COMPRESSION_SCENE) $(CC_OUT)/packing.h5 \
    $(CC_LAB)/dem-calibration-paper.toml $(BIN)/mw-dem
	$(BIN)/mw-dem --from $(CC_LAB)/dem-calibration-paper.toml run $(CC_COMPRESSION_SCENE) --packing $(CC_OUT)/packing.h5 \
	  --quiet --signals $(CC_OUT)/compression-paper-parameters.h5 --curves $(CC_OUT)/compression-paper-parameters.csv \
	  --summary $(CC_OUT)/compression-paper-parameters.json > /dev/null

# One quantity, three names: calibration.json's (E_glob_GPa), mw-dem's summary
# (test.E_glob_GPa, test.peak_stress_MPa) and the lab-data entries' ([E_glob], unit GPa).
$(CC_OUT)/table2.csv: $(CC_LAB)/paper/table2-experiment.toml $(CC_LAB)/paper/table2-dem.toml \
    $(CC_OUT)/compression-paper-parameters.json $(CC_OUT)/calibration.json $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name model \
	  --row "experiment (static tests; paper Table 2)=$(CC_LAB)/paper/table2-experiment.toml" \
	  --row "paper: Yade with its calibration (Table 2)=$(CC_LAB)/paper/table2-dem.toml" \
	  --row "mesowave with the paper's parameters=$(CC_OUT)/compression-paper-parameters.json" \
	  --row "mesowave calibrated (calibration.json)=$(CC_OUT)/calibration.json" \
	  --column "E_glob_GPa=E_glob_GPa|test.E_glob_GPa|E_glob" --column "nu_glob=nu_glob|test.nu_glob" \
	  --column "sigma_dem_MPa=sigma_dem_MPa|test.peak_stress_MPa|sigma_dem" --significant-digits 4 --csv $@ > /dev/null

$(CC_OUT)/table2-vs-paper.txt $(CC_OUT)/table2-vs-paper.csv &: $(CC_OUT)/calibration.json \
    $(CC_LAB)/paper/table2-dem.toml $(BIN)/mw-compare
	$(BIN)/mw-compare --ours $(CC_OUT)/calibration.json --paper $(CC_LAB)/paper/table2-dem.toml \
	  --title "Step 6, Table 2: mesowave's calibrated model against the paper's calibrated Yade model" \
	  --csv $(CC_OUT)/table2-vs-paper.csv --text $(CC_OUT)/table2-vs-paper.txt > /dev/null

CC_MATERIAL := $(CC_OUT)/calibration.json
CC_CALIBRATION_RESULTS := $(CC_OUT)/calibration.json $(CC_OUT)/calibration-trajectory.png \
  $(CC_OUT)/calibration-stress-strain.png $(CC_OUT)/table2.csv $(CC_OUT)/table2-vs-paper.txt

.PHONY: concrete-cube-calibration concrete-cube-calibration-summary
concrete-cube-calibration: $(CC_CALIBRATION_RESULTS)

concrete-cube-calibration-summary: concrete-cube-calibration
	@echo
	@echo "== Concrete cube, step 6: calibration ($(CC_OUT)/calibration.json; trials: $(CC_OUT)/calibration-trials.csv) =="
	@$(CC_PRINT_CSV) $(CC_OUT)/calibration-trials.csv
	@echo
	@echo "Table 2:"
	@$(CC_PRINT_CSV) $(CC_OUT)/table2.csv
	@echo
	@cat $(CC_OUT)/table2-vs-paper.txt

# ==== Waves: 100-500 kHz, sensors B-G (Sections 4.1-4.3) =====================
# DEM: the scene cube-wave.toml (linearised bonded network, 1.5 ms at 50 ns) on
# the step-5 packing with the CC_MATERIAL parameters, one run per frequency.
# Continuum reference: mw-fem box with the dynamic moduli of step 3 (E_d, nu_d,
# rho from mw-upv), the same actuator A and sensors B-G (sensors.toml, scaled to
# the cube; fem-transducers.py), the same burst. No measured cube signals ship,
# so Table 3 here is DEM against this continuum reference; files dropped into
# lab-data/concrete-cube/measured/ (docs/formats.md) are compared with the DEM too.
#
# Two FEM runs per frequency (docs/benchmarks.md, "Concrete cube: the continuum
# reference"): the FEM's phase error grows with the distance travelled, so no
# affordable mesh is converged over the whole 1.5 ms (hundreds of wavelengths);
# over the first 50 us (the direct waves and their first reflections) a mesh of
# h = 156.25 mm / f[kHz] (1.5625 mm at 100 kHz, 0.3125 mm at 500 kHz: a fixed
# number of elements per wavelength) is, at a cost of seconds to minutes.
#   fem-early-FkHz  55 us, h(f): the converged reference of the first packets;
#   fem-FkHz        the whole record at 2 mm (<= 200 kHz) or 1 mm, for the signal
#                   and spectrum figures and the PCC over the record, as the
#                   paper's Table 3 - not a converged reference after the first
#                   packets (said so in the report).

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
# The force of the scene's actuator A (amplitude_N): the FEM gets the same burst.
CC_FORCE_N := 0.01
CC_TRANSDUCERS = $$($(CC_NOTES)/fem-transducers.py $(CC_LAB)/sensors.toml $(CC_LAB)/porosity.toml $(CC_SIDE_MM))
CC_FEM_INPUTS := $(CC_OUT)/upv.json $(CC_LAB)/sensors.toml $(CC_LAB)/porosity.toml $(CC_NOTES)/fem-transducers.py \
  $(BIN)/mw-fem

$(CC_OUT)/dem-%kHz.h5 $(CC_OUT)/dem-%kHz.json: $(CC_SCENE) $(CC_OUT)/packing.h5 $(CC_MATERIAL) $(BIN)/mw-dem
	$(BIN)/mw-dem --from $(CC_MATERIAL) $(CC_CALIBRATION_UNTAKEN) run $(CC_SCENE) --packing $(CC_OUT)/packing.h5 --frequency-kHz $* $(CC_RECORD) \
	  --quiet --signals $(CC_OUT)/dem-$*kHz.h5 --summary $(CC_OUT)/dem-$*kHz.json > /dev/null

$(CC_OUT)/fem-%kHz.h5 $(CC_OUT)/fem-%kHz.json: $(CC_FEM_INPUTS)
	$(BIN)/mw-fem --from $(CC_OUT)/upv.json $(CC_UPV_UNTAKEN_BY_FEM) box $(CC_TRANSDUCERS) --mesh-mm $(call cc_fem_mesh,$*) \
	  --force-N $(CC_FORCE_N) --frequency-kHz $* $(CC_RECORD) \
	  --quiet --signals $(CC_OUT)/fem-$*kHz.h5 --out $(CC_OUT)/fem-$*kHz.json > /dev/null

$(CC_OUT)/fem-early-%kHz.h5 $(CC_OUT)/fem-early-%kHz.json: $(CC_FEM_INPUTS)
	$(BIN)/mw-fem --from $(CC_OUT)/upv.json $(CC_UPV_UNTAKEN_BY_FEM) box $(CC_TRANSDUCERS) --mesh-mm $(call cc_fem_early_mesh,$*) \
	  --force-N $(CC_FORCE_N) --frequency-kHz $* $(CC_EARLY_RECORD) \
	  --quiet --signals $(CC_OUT)/fem-early-$*kHz.h5 --out $(CC_OUT)/fem-early-$*kHz.json > /dev/null

# PCC of DEM against FEM per sensor, the DEM record interpolated onto the FEM's
# 0.1 us samples: over the first 50 us against the converged early reference, with
# the first packets' signals and envelopes (the paper's Fig. 14); over the whole
# record, with the signals (Figs. 12-13) and spectra (Fig. 15). The envelopes are
# computed zero-padded to twice the record (--pad double), so that the end of a
# record does not wrap onto its start.
$(CC_OUT)/pcc-early-%kHz.csv $(CC_OUT)/pcc-early-%kHz.json $(CC_OUT)/signals-early-%kHz.png \
    $(CC_OUT)/envelopes-early-%kHz.png: $(CC_OUT)/fem-early-%kHz.h5 $(CC_OUT)/dem-%kHz.h5 $(BIN)/mw-pcc
	$(BIN)/mw-pcc --a $(CC_OUT)/fem-early-$*kHz.h5 --b $(CC_OUT)/dem-$*kHz.h5 --resample linear --pad double \
	  --window-end-us $(CC_EARLY_US) --csv $(CC_OUT)/pcc-early-$*kHz.csv --out $(CC_OUT)/pcc-early-$*kHz.json \
	  --labels FEM,DEM --title "Concrete cube, $* kHz burst, first $(CC_EARLY_US) us: DEM against the continuum reference (FEM)" \
	  --plot-window-us 0,$(CC_EARLY_US) --plot-signals $(CC_OUT)/signals-early-$*kHz.png \
	  --plot-envelopes $(CC_OUT)/envelopes-early-$*kHz.png > /dev/null

$(CC_OUT)/pcc-%kHz.csv $(CC_OUT)/pcc-%kHz.json $(CC_OUT)/spectra-%kHz.csv $(CC_OUT)/signals-%kHz.png \
    $(CC_OUT)/spectra-%kHz.png: $(CC_OUT)/fem-%kHz.h5 $(CC_OUT)/dem-%kHz.h5 $(BIN)/mw-pcc
	$(BIN)/mw-pcc --a $(CC_OUT)/fem-$*kHz.h5 --b $(CC_OUT)/dem-$*kHz.h5 --resample linear --pad double \
	  --csv $(CC_OUT)/pcc-$*kHz.csv --out $(CC_OUT)/pcc-$*kHz.json \
	  --spectra $(CC_OUT)/spectra-$*kHz.csv --max-frequency-kHz $$(( 2 * $* )) \
	  --labels FEM,DEM --title "Concrete cube, $* kHz burst, whole record: DEM against the continuum reference (FEM)" \
	  --plot-signals $(CC_OUT)/signals-$*kHz.png --plot-spectra $(CC_OUT)/spectra-$*kHz.png > /dev/null

# Measured signals (a lab's own): lab-data/concrete-cube/measured/<F>kHz.h5 or .csv,
# signals named B-G, t = 0 at the start of the burst. Each is compared with the DEM
# run at its frequency (the DEM interpolated onto the measured samples).
CC_MEASURED := $(sort $(wildcard $(CC_MEASURED_DIR)/*kHz.h5 $(CC_MEASURED_DIR)/*kHz.csv))
cc_measured_f = $(patsubst %kHz,%,$(basename $(notdir $1)))
CC_MEASURED_FREQS := $(foreach m,$(CC_MEASURED),$(call cc_measured_f,$m))
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
cc_rows = $(foreach f,$(CC_FREQS),--row $f=$(CC_OUT)/pcc-$1$(f)kHz.csv)
CC_SENSORS := B C D E F G
ifneq ($(CC_MEASURED),)
$(CC_OUT)/table3-measured.csv: $(foreach f,$(CC_MEASURED_FREQS),$(CC_OUT)/pcc-measured-$(f)kHz.csv) $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name f_kHz $(foreach f,$(CC_MEASURED_FREQS),--row $f=$(CC_OUT)/pcc-measured-$(f)kHz.csv) \
	  --where sensor=mean --column pcc_signal --column pcc_envelope --csv $@ > /dev/null
CC_TABLE3_MEASURED := $(CC_OUT)/table3-measured.csv
CC_JOIN_MEASURED := --join $(CC_TABLE3_MEASURED):measured_vs_dem_pcc_signals=pcc_signal,measured_vs_dem_pcc_envelopes=pcc_envelope
CC_MEASURED_Y := --y "measured_vs_dem_pcc_signals=measured vs DEM, signals"
endif
# The measured folder itself: a file dropped in or taken out re-makes Table 3.
# The whole-record table first, then the first-packets columns joined to it.
$(CC_OUT)/table3-early.csv: $(foreach f,$(CC_FREQS),$(CC_OUT)/pcc-early-$(f)kHz.csv) $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name f_kHz $(call cc_rows,early-) --where sensor=mean \
	  --column pcc_signal --column pcc_envelope --csv $@ > /dev/null

$(CC_OUT)/table3.csv: $(foreach f,$(CC_FREQS),$(CC_OUT)/pcc-$(f)kHz.csv) $(CC_OUT)/table3-early.csv \
    $(CC_LAB)/paper/table3.csv $(CC_TABLE3_MEASURED) $(wildcard $(CC_MEASURED_DIR)) $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name f_kHz $(call cc_rows,) --where sensor=mean \
	  --column dem_vs_fem_pcc_signals=pcc_signal --column dem_vs_fem_pcc_envelopes=pcc_envelope \
	  --join $(CC_OUT)/table3-early.csv:dem_vs_fem_first_$(CC_EARLY_US)us_pcc_signals=pcc_signal,dem_vs_fem_first_$(CC_EARLY_US)us_pcc_envelopes=pcc_envelope \
	  --join $(CC_LAB)/paper/table3.csv:paper_experiment_vs_dem_pcc=pcc_mean $(CC_JOIN_MEASURED) --csv $@ > /dev/null

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
	  --y-range -0.2,1 --x-label "burst centre frequency [kHz]" --y-label "mean PCC over sensors B-G" \
	  --key below --title "Concrete cube: Table 3 (mean PCC over the sensors)" --out $@ > /dev/null

$(CC_OUT)/pcc-sensors.png: $(CC_OUT)/pcc-sensors.csv $(BIN)/mw-table
	$(BIN)/mw-table plot $< --x f_kHz $(foreach s,$(CC_SENSORS),--y "$s_signal=$s") --y-range -0.5,1 \
	  --x-label "burst centre frequency [kHz]" --y-label "PCC of DEM against FEM, first $(CC_EARLY_US) us, signals" \
	  --key below --title "Concrete cube: PCC per sensor, first $(CC_EARLY_US) us" --out $@ > /dev/null

# ==== Speed against error (the cube) ===========================================
# One frequency, a shorter record: the linearised network against the full
# contact law, dt 50 against 25 ns, one against two threads. Each run is compared
# with the most exact one (full law, 25 ns) by the mean PCC over sensors B-G;
# its cost is the wall time of the run on this machine.
CC_SPEED_F := 250
ifeq ($(QUICK),1)
CC_SPEED_RECORD := --duration-ms 0.1
else
CC_SPEED_RECORD := --duration-ms 0.3
endif
CC_SPEED_REFERENCE := full-25ns-1t
CC_SPEED_RUNS := linear-50ns-1t linear-50ns-2t linear-25ns-1t full-50ns-1t $(CC_SPEED_REFERENCE)
cc_speed_word = $(word $2,$(subst -, ,$1))

$(CC_OUT)/speed-%.h5 $(CC_OUT)/speed-%.json: $(CC_SCENE) $(CC_OUT)/packing.h5 $(CC_MATERIAL) $(BIN)/mw-dem
	$(BIN)/mw-dem --from $(CC_MATERIAL) $(CC_CALIBRATION_UNTAKEN) run $(CC_SCENE) --packing $(CC_OUT)/packing.h5 --frequency-kHz $(CC_SPEED_F) \
	  $(CC_SPEED_RECORD) --model $(call cc_speed_word,$*,1) --dt-ns $(patsubst %ns,%,$(call cc_speed_word,$*,2)) \
	  --threads $(patsubst %t,%,$(call cc_speed_word,$*,3)) --quiet \
	  --signals $(CC_OUT)/speed-$*.h5 --summary $(CC_OUT)/speed-$*.json > /dev/null

# (The JSON has the PCC to full precision: the runs agree to 4 digits and more.)
$(CC_OUT)/speed-pcc-%.json: $(CC_OUT)/speed-%.h5 $(CC_OUT)/speed-$(CC_SPEED_REFERENCE).h5 $(BIN)/mw-pcc
	$(BIN)/mw-pcc --a $(CC_OUT)/speed-$*.h5 --b $(CC_OUT)/speed-$(CC_SPEED_REFERENCE).h5 --resample linear --pad double \
	  --out $@ > /dev/null

$(CC_OUT)/speed.csv: $(foreach r,$(CC_SPEED_RUNS),$(CC_OUT)/speed-$r.json $(CC_OUT)/speed-pcc-$r.json) $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name run \
	  $(foreach r,$(CC_SPEED_RUNS),--row $r=$(CC_OUT)/speed-pcc-$r.json,$(CC_OUT)/speed-$r.json) \
	  --column model --column dt_s --column threads --column steps --column wall_s --column steps_per_s \
	  --column pcc_vs_reference=mean_pcc_signal --column pcc_envelope_vs_reference=mean_pcc_envelope \
	  --column peak_force_ratio --csv $@ > /dev/null

# The error axis: 1 - PCC against the reference on a log scale (the reference itself, 0, is off it).
$(CC_OUT)/speed-error.png: $(CC_OUT)/speed.csv $(BIN)/mw-table
	$(BIN)/mw-table plot $< --x wall_s --y pcc_vs_reference --label-column run --log-x --log-y --one-minus \
	  --x-label "wall time of the run on this machine [s]" \
	  --y-label "1 - mean PCC over B-G against $(CC_SPEED_REFERENCE)" \
	  --title "Concrete cube, $(CC_SPEED_F) kHz: speed against error (model, time step, threads)" --out $@ > /dev/null

CC_WAVE_RESULTS := $(CC_OUT)/packing-vs-paper.txt $(CC_OUT)/table3.csv $(CC_OUT)/table3.png \
  $(CC_OUT)/pcc-sensors.csv $(CC_OUT)/pcc-sensors.png $(CC_OUT)/speed.csv $(CC_OUT)/speed-error.png \
  $(foreach f,$(CC_FREQS),$(CC_OUT)/dem-$(f)kHz.h5 $(CC_OUT)/fem-$(f)kHz.h5 $(CC_OUT)/fem-early-$(f)kHz.h5 \
    $(CC_OUT)/pcc-$(f)kHz.csv $(CC_OUT)/pcc-early-$(f)kHz.csv) \
  $(foreach f,$(CC_FIGURE_FREQS),$(CC_OUT)/signals-$(f)kHz.png $(CC_OUT)/signals-early-$(f)kHz.png \
    $(CC_OUT)/envelopes-early-$(f)kHz.png $(CC_OUT)/spectra-$(f)kHz.png) \
  $(foreach r,$(CC_SPEED_RUNS),$(CC_OUT)/speed-$r.h5)
# Every run's files stay (make would otherwise delete what only pattern rules need).
.SECONDARY: $(CC_WAVE_RESULTS) $(foreach f,$(CC_FREQS) $(CC_MEASURED_FREQS),$(CC_OUT)/dem-$(f)kHz.json \
  $(CC_OUT)/fem-$(f)kHz.json $(CC_OUT)/fem-early-$(f)kHz.json $(CC_OUT)/pcc-$(f)kHz.json \
  $(CC_OUT)/pcc-early-$(f)kHz.json $(CC_OUT)/spectra-$(f)kHz.csv $(CC_OUT)/signals-$(f)kHz.png \
  $(CC_OUT)/signals-early-$(f)kHz.png $(CC_OUT)/envelopes-early-$(f)kHz.png $(CC_OUT)/spectra-$(f)kHz.png) \
  $(foreach r,$(CC_SPEED_RUNS),$(CC_OUT)/speed-$r.json $(CC_OUT)/speed-pcc-$r.json)

# A CSV file as aligned columns (the tables here have no quoted fields).
CC_PRINT_CSV := awk -F, '{ for (i = 1; i <= NF; i++) { c[NR, i] = $$i; if (length($$i) > w[i]) w[i] = length($$i) } \
  if (NF > n) n = NF } END { for (r = 1; r <= NR; r++) { for (i = 1; i <= n; i++) printf "%-*s  ", w[i], c[r, i]; print "" } }'

.PHONY: concrete-cube-waves concrete-cube-waves-summary
concrete-cube-waves: $(CC_WAVE_RESULTS)

concrete-cube-waves-summary: concrete-cube-waves
	@echo
	@echo "== Concrete cube: packing and waves ($(CC_OUT)) =="
	@cat $(CC_OUT)/packing-vs-paper.txt
	@echo
	@echo "Table 3: mean PCC over sensors B-G. mesowave: DEM against the continuum reference (mw-fem box);"
	@echo "paper: experiment against DEM (no measured cube signals ship$(if $(CC_MEASURED),; measured: $(CC_MEASURED_DIR)))."
	@$(CC_PRINT_CSV) $(CC_OUT)/table3.csv
	@echo
	@echo "Speed against error ($(CC_SPEED_F) kHz; PCC against $(CC_SPEED_REFERENCE)):"
	@$(CC_PRINT_CSV) $(CC_OUT)/speed.csv
