# Included by pipeline/concrete-cube/study.mk (its variables CC_*); not part of make reproduce
# (its goals are not in PIPELINE_GOALS: about an hour on two cores). docs/cube-150.md.
# ==== The lab's 150 mm cube against its own UPV test (issue 18, item 1) =========
#   make cube-150          the packing, the dynamic calibration, four wave runs, the picks, the tables
#
# The lab measured t_p = 35.0 us and t_s = 55.1 us on 150 mm cubes (upv.toml), the only wave data
# of this concrete; the paper modelled a 50 mm cube. Here:
#  1. the 150 mm cube packed as step 5 packs the 50 mm one (mw-pack --cube-side-mm 150);
#  2. two calibrations of the 50 mm cube (step 6): the pipeline's (CC_CALIBRATION_TARGETS, by
#     default the static tests: the paper's method) and one to the dynamic moduli E_d, nu_d of
#     step 3 (the `dynamic` choice of step-6-calibration.mk, run beside it);
#  3. the UPV test on the 150 mm DEM cube with each calibration: the P transducers' run
#     (scenes/upv150-p.toml: 54 kHz normal burst) and the S transducers' (upv150-s.toml: 40 kHz
#     tangential burst), the receiver's record picked by mw-upv as a lab record (below), and the
#     picks beside the measured ones.
# Every tool run is recorded in $(MESOWAVE_DB); the runs' wall time and peak memory are there
# (mw-prov runs), their spheres, bonds and steps in the summaries gathered in upv150-cost.csv.

C150_OUT := $(CC_OUT)/cube-150
C150_SIDE_MM := 150
C150_CHOICE_STATIC := $(CC_CALIBRATION_TARGETS)
C150_CHOICE_DYNAMIC := dynamic
C150_MATERIAL.$(C150_CHOICE_DYNAMIC) := $(C150_OUT)/calibration-dynamic.json
C150_MATERIAL.$(C150_CHOICE_STATIC) := $(CC_MATERIAL)
C150_CHOICES := $(sort $(C150_CHOICE_STATIC) $(C150_CHOICE_DYNAMIC))
# How mw-upv picks the DEM's records (docs/cube-150.md, "Picking a noise-free record"). The DEM
# record has no pre-trigger: its first 3 us, before any motion can reach the far face at one bond
# a step, are the noise window (all zeros). Without noise, Maeda's AIC finds the lattice's
# numerical precursor (1e-6 of the peak, long before the wave), so the P onset is the first
# crossing of 2 % of the peak (threshold picker, as a pulse analyser's); the S onset is mw-upv's
# S chain after that t_p (AIC up to the S envelope's peak, from 1.3 t_p), where the P wave's
# coda sets the AIC's noise.
C150_RECORD := --noise-window-us 0,3 --amplitude-column 'R [m/s]'
C150_P_PICK := --picker threshold --locate-relative 0.02 $(C150_RECORD)
C150_S_PICK := --picker aic $(C150_RECORD)

$(C150_OUT)/packing.h5 $(C150_OUT)/packing.json &: $(CC_LAB)/porosity.toml $(CC_LAB)/dem-packing.toml \
    $(CC_OUT)/density.json $(BIN)/mw-pack
	@mkdir -p $(@D)
	$(BIN)/mw-pack box --from $(CC_LAB)/porosity.toml --from $(CC_LAB)/dem-packing.toml --from $(CC_OUT)/density.json \
	  --cube-side-mm $(C150_SIDE_MM) --quiet --packing $(C150_OUT)/packing.h5 --out $(C150_OUT)/packing.json > /dev/null

# The calibration to E_d and nu_d on the pipeline's 50 mm packing (the pipeline's own calibration
# is this one when CC_CALIBRATION_TARGETS=dynamic; then the rule is not used).
$(C150_OUT)/calibration-dynamic.json $(C150_OUT)/calibration-dynamic-trials.csv $(C150_OUT)/calibration-dynamic-targets.csv \
    $(C150_OUT)/calibration-dynamic-trajectory.png $(C150_OUT)/calibration-dynamic-stress-strain.png &: \
    $(CC_COMPRESSION_SCENE) $(CC_OUT)/packing.h5 $(CC_CALIBRATION_TARGET_FILES.dynamic) $(BIN)/mw-calibrate $(BIN)/mw-dem
	@mkdir -p $(@D)
	$(call cc_calibrate,dynamic,$(C150_OUT)/calibration-dynamic-trials,$(C150_OUT)/calibration-dynamic)

# One wave run per transducer pair and calibration: upv-p-<choice>.h5/.csv/.json, upv-s-<choice>.*
define C150_RUNS
$(C150_OUT)/upv-$2-$1.h5 $(C150_OUT)/upv-$2-$1.csv $(C150_OUT)/upv-$2-$1.json &: $(CC_NOTES)/scenes/upv150-$2.toml \
    $(CC_LAB)/upv-experiment-$2.toml $(C150_OUT)/packing.h5 $(C150_MATERIAL.$1) $(BIN)/mw-dem
	$(BIN)/mw-dem --from $(C150_MATERIAL.$1) run $(CC_NOTES)/scenes/upv150-$2.toml --packing $(C150_OUT)/packing.h5 \
	  --quiet --signals $(C150_OUT)/upv-$2-$1.h5 --signals-csv $(C150_OUT)/upv-$2-$1.csv \
	  --summary $(C150_OUT)/upv-$2-$1.json > /dev/null
endef
define C150_PICKS
$(C150_OUT)/upv-tp-$1.json $(C150_OUT)/upv-p-$1.png &: $(C150_OUT)/upv-p-$1.csv $(BIN)/mw-upv
	$(BIN)/mw-upv --path-mm $(C150_SIDE_MM) --p-wave $(C150_OUT)/upv-p-$1.csv $(C150_P_PICK) \
	  --plot $(C150_OUT)/upv-p-$1.png --title "150 mm DEM cube, calibration '$1': P transducers (54 kHz), the pick" \
	  --out $(C150_OUT)/upv-tp-$1.json > /dev/null
$(C150_OUT)/upv-picks-$1.json $(C150_OUT)/upv-s-$1.png &: $(C150_OUT)/upv-tp-$1.json $(C150_OUT)/upv-s-$1.csv \
    $(CC_OUT)/density.json $(BIN)/mw-upv
	$(BIN)/mw-upv --from $(C150_OUT)/upv-tp-$1.json --from $(CC_OUT)/density.json --s-wave $(C150_OUT)/upv-s-$1.csv \
	  $(C150_S_PICK) --plot $(C150_OUT)/upv-s-$1.png \
	  --title "150 mm DEM cube, calibration '$1': S transducers (40 kHz), the pick" --out $(C150_OUT)/upv-picks-$1.json > /dev/null
endef
$(foreach c,$(C150_CHOICES),$(foreach k,p s,$(eval $(call C150_RUNS,$c,$k)))$(eval $(call C150_PICKS,$c)))

# The picks beside the lab's (upv.toml: t_p, t_s; upv.json: v_p, v_s, E_d, nu_d of step 3).
$(C150_OUT)/upv150.csv: $(CC_LAB)/upv.toml $(CC_OUT)/upv.json $(foreach c,$(C150_CHOICES),$(C150_OUT)/upv-picks-$c.json \
    $(C150_MATERIAL.$c)) $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name record --row "measured (upv.toml; step 3)=$(CC_LAB)/upv.toml,$(CC_OUT)/upv.json" \
	  $(foreach c,$(C150_CHOICES),--row "DEM calibrated to $c=$(C150_OUT)/upv-picks-$c.json,$(C150_MATERIAL.$c)") \
	  --column "t_p_us=t_p_us|t_p" --column "t_s_us=t_s_us|t_s" --column v_p_m_s --column v_s_m_s --column E_d_GPa \
	  --column nu_d --column "E_glob_GPa=E_glob_GPa|E_d_GPa" --column "nu_glob=nu_glob|nu_d" \
	  --significant-digits 4 --csv $@ > /dev/null

# What each wave run cost (wall time and peak memory of every run: mw-prov runs --tool mw-dem).
$(C150_OUT)/upv150-cost.csv: $(foreach c,$(C150_CHOICES),$(foreach k,p s,$(C150_OUT)/upv-$k-$c.json)) $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name run \
	  $(foreach c,$(C150_CHOICES),$(foreach k,p s,--row "$k, $c=$(C150_OUT)/upv-$k-$c.json")) \
	  --column model --column spheres --column bonds --column threads --column steps --column setup_s --column wall_s \
	  --column steps_per_s --column memory_estimate_MiB --column peak_force_ratio --significant-digits 4 --csv $@ > /dev/null

$(C150_OUT)/packing150.csv: $(C150_OUT)/packing.json $(CC_OUT)/packing.json $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name packing --row "150 mm cube=$(C150_OUT)/packing.json" \
	  --row "50 mm cube (step 5)=$(CC_OUT)/packing.json" --column spheres --column bonds --column coordination \
	  --column porosity_pct --column particle_density_kg_m3 --column relaxation_iterations --column threads \
	  --column wall_time_s --significant-digits 5 --csv $@ > /dev/null

C150_RESULTS := $(C150_OUT)/packing150.csv $(C150_OUT)/upv150.csv $(C150_OUT)/upv150-cost.csv \
  $(foreach c,$(C150_CHOICES),$(C150_OUT)/upv-p-$c.png $(C150_OUT)/upv-s-$c.png)

.PHONY: cube-150
cube-150: $(C150_RESULTS)
	@echo
	@echo "== The 150 mm cube ($(C150_OUT)): packing (wall time and peak memory: mw-prov runs --tool mw-pack) =="
	@$(CC_PRINT_CSV) $(C150_OUT)/packing150.csv
	@echo
	@echo "== UPV on the 150 mm DEM cube against the lab's (P 54 kHz, S 40 kHz, 150 mm path) =="
	@$(CC_PRINT_CSV) $(C150_OUT)/upv150.csv
	@echo
	@echo "== The wave runs' cost (wall time and peak memory: mw-prov runs --tool mw-dem) =="
	@$(CC_PRINT_CSV) $(C150_OUT)/upv150-cost.csv
