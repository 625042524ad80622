# Included by pipeline/concrete-cube/study.mk (its variables CC_*), in the flowchart's order.
# ==== Step 6: calibration (E_dem, nu_dem, T, C, friction) =====================
# The virtual compression test of the step-5 packing (scenes/cube-compression.toml:
# frictionless walls, the upper one at 25 mm/s with the inertial number checked
# below 1e-4, extensometers at mid-height) and mw-calibrate cube, which varies
# E_dem, nu_dem and T = C (friction angle 18 deg, given) from the paper's values
# (the scene's material) until E_glob, nu_glob and the peak stress meet the
# targets (CC_CALIBRATION_TARGETS below: the static tests, static-test.toml, or the lab's own step-4
# results, raw-compress.json; or the dynamic moduli, upv.json) within 1 % on E, 0.01 on nu and 2 % on strength
# (docs/calibration.md). Every trial is a recorded mw-dem run; calibration.json
# is the material of the wave runs (CC_MATERIAL, read by `mw-dem --from`).
#
# Table 2 sets four rows side by side: the static tests, the paper's calibrated
# Yade model, the paper's parameters on mesowave's packing (one more compression
# run: why mesowave calibrates its own), and mesowave's calibration.
CC_COMPRESSION_SCENE := $(CC_NOTES)/scenes/cube-compression.toml
CC_CALIBRATION_TRIALS := $(CC_OUT)/calibration

# The calibration's targets, chosen here and only here (docs/calibration.md, "Which targets"):
#   static-test  the paper's static tests: E_st_measured, nu_st and sigma_max of static-test.toml
#                (Section 3.2; Table 2's experiment row). The default.
#   raw-step-4   the lab's own step 4: E_st_measured_GPa and sigma_max_MPa of raw-compress.json
#                (mw-compress on the load-frame records, raw-steps-2-4.mk); nu_st stays static-test.toml's
#                (the paper takes nu_d; the records have no lateral strain). The last --from file wins.
#   dynamic      the dynamic moduli of step 3 (E_d_GPa and nu_d of upv.json, mw-upv on the UPV test;
#                mw-calibrate --E-d-GPa/--nu-d), so that the model carries waves at the measured pulse
#                velocities; the strength stays static-test.toml's sigma_max (docs/cube-150.md).
#   make reproduce-quick CC_CALIBRATION_TARGETS=raw-step-4
# calibration.json and calibration-targets.csv (the report, under Table 2) say which file, entry and
# SHA-256 each target came from.
CC_CALIBRATION_TARGETS := static-test
CC_CALIBRATION_TARGET_FILES.static-test := $(CC_LAB)/static-test.toml
CC_CALIBRATION_TARGET_FILES.raw-step-4 := $(CC_LAB)/static-test.toml $(CC_OUT)/raw-compress.json
CC_CALIBRATION_TARGET_FILES.dynamic := $(CC_LAB)/static-test.toml $(CC_OUT)/upv.json
# upv.json's density is a product for mw-estatic and mw-fem; the calibration takes the packing's.
CC_CALIBRATION_TARGET_FLAGS.dynamic := --from-ignore density_kg_m3
CC_CALIBRATION_TARGET_FILES := $(CC_CALIBRATION_TARGET_FILES.$(CC_CALIBRATION_TARGETS))
ifeq ($(strip $(CC_CALIBRATION_TARGET_FILES)),)
$(error CC_CALIBRATION_TARGETS = '$(CC_CALIBRATION_TARGETS)' is not a choice: static-test, raw-step-4 or dynamic)
endif

# The elastic trials' wall speed: the linearised network's only rate effect is inertia, so they load
# faster than the failure trials' 25 mm/s (the scene's; the strength depends on the rate) - as fast as
# keeps the inertial number below about 0.7 of the scene's quasi-static bound 1e-4: 100 mm/s on the
# 50 mm cube (6.2e-5; E_glob and nu_glob -1.4e-5 and -1.1e-5 against 25 mm/s, 3.7x fewer steps),
# 50 mm/s on the quick tree's 20 mm cube (6.9e-5: its strain rate is 2.5x the 50 mm cube's at one
# speed). docs/calibration.md, "The elastic trials' speed".
ifeq ($(QUICK),1)
CC_ELASTIC_VELOCITY_MM_S := 50
else
CC_ELASTIC_VELOCITY_MM_S := 100
endif

# mw-calibrate cube for one choice of targets: $1 the choice, $2 the trials' folder, $3 the output
# prefix ($3.json, $3-trials.csv, $3-targets.csv, $3-trajectory.png, $3-stress-strain.png). The
# pipeline's calibration is the chosen one; cube-150.mk runs a second choice beside it.
cc_calibrate = rm -rf $2 && $(BIN)/mw-calibrate $(addprefix --from ,$(CC_CALIBRATION_TARGET_FILES.$1)) \
  $(CC_CALIBRATION_TARGET_FLAGS.$1) cube --scene $(CC_COMPRESSION_SCENE) --packing $(CC_OUT)/packing.h5 --work-dir $2 \
  --elastic-velocity-mm-s $(CC_ELASTIC_VELOCITY_MM_S) \
  --trials $3-trials.csv --targets-csv $3-targets.csv --plot-trajectory $3-trajectory.png \
  --plot-curves $3-stress-strain.png --out $3.json > /dev/null

# The choice as a file, rewritten only when it changes: switching re-runs the calibration and
# what follows it, switching back re-runs it again, and a second make with the same choice runs nothing.
CC_CALIBRATION_CHOICE := $(CC_OUT)/calibration-targets.choice
$(CC_CALIBRATION_CHOICE): concrete-cube-calibration-choice-check
	@mkdir -p $(@D)
	@echo '$(CC_CALIBRATION_TARGETS): $(CC_CALIBRATION_TARGET_FILES)' | cmp -s - $@ || \
	  echo '$(CC_CALIBRATION_TARGETS): $(CC_CALIBRATION_TARGET_FILES)' > $@
# No recipe, no file: the choice file's recipe runs every time (it rewrites the file only on a change).
.PHONY: concrete-cube-calibration-choice-check
concrete-cube-calibration-choice-check:

$(CC_OUT)/calibration.json $(CC_OUT)/calibration-trials.csv $(CC_OUT)/calibration-targets.csv \
    $(CC_OUT)/calibration-trajectory.png $(CC_OUT)/calibration-stress-strain.png &: $(CC_COMPRESSION_SCENE) \
    $(CC_OUT)/packing.h5 $(CC_CALIBRATION_TARGET_FILES) $(CC_CALIBRATION_CHOICE) $(BIN)/mw-calibrate $(BIN)/mw-dem
	$(call cc_calibrate,$(CC_CALIBRATION_TARGETS),$(CC_CALIBRATION_TRIALS),$(CC_OUT)/calibration)

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
CC_CALIBRATION_RESULTS := $(CC_OUT)/calibration.json $(CC_OUT)/calibration-targets.csv $(CC_OUT)/calibration-trajectory.png \
  $(CC_OUT)/calibration-stress-strain.png $(CC_OUT)/table2.csv $(CC_OUT)/table2-vs-paper.txt

.PHONY: concrete-cube-calibration concrete-cube-calibration-summary
concrete-cube-calibration: $(CC_CALIBRATION_RESULTS)

concrete-cube-calibration-summary: concrete-cube-calibration
	@echo
	@echo "== Concrete cube, step 6: calibration ($(CC_OUT)/calibration.json; trials: $(CC_OUT)/calibration-trials.csv) =="
	@$(CC_PRINT_CSV) $(CC_OUT)/calibration-trials.csv
	@echo
	@echo "Targets (CC_CALIBRATION_TARGETS = $(CC_CALIBRATION_TARGETS)):"
	@$(CC_PRINT_CSV) $(CC_OUT)/calibration-targets.csv
	@echo
	@echo "Table 2:"
	@$(CC_PRINT_CSV) $(CC_OUT)/table2.csv
	@echo
	@cat $(CC_OUT)/table2-vs-paper.txt
