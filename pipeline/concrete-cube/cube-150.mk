# Included by pipeline/concrete-cube/study.mk (its variables CC_*); not part of make reproduce
# (its goals are not in PIPELINE_GOALS: about an hour on two quiet cores). docs/cube-150.md. The
# target and the variables carry the study's name and prefix (CC_C150_*), so that a study copied by
# `make new-study` gets its own.
# ==== The lab's 150 mm cube against its own UPV test (issue 18, item 1) =========
#   make concrete-cube-150   the packing, the dynamic calibration, four wave runs, the picks, the tables,
#                            Table 3 with each calibration, the report (report/concrete-cube-150/)
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
# The quick tree (QUICK=1) runs the same rules on small cubes (below), so that a test
# (tests/pipeline/cube_150_test.cpp) makes the whole chain in a minute.

CC_C150_OUT := $(CC_OUT)/cube-150
# The sizes, named by the lab's test: 150 the lab's cube, packed here; 50 the same test at 1/3 scale on
# step 5's packing. Each size's cube side (= the transducers' path) [mm], its scenes (scenes/<name>-p.toml,
# -s.toml) and its packing (the 50 mm one's row in packing150.csv named for where it comes from).
CC_C150_SIZES := 150 50
CC_C150_SIDE_MM.150 := 150
CC_C150_SIDE_MM.50 := 50
CC_C150_SCENE.150 := upv150
CC_C150_SCENE.50 := upv50
CC_C150_PACKING.150 := $(CC_C150_OUT)/packing.h5
CC_C150_PACKING.50 := $(CC_OUT)/packing.h5
CC_C150_PACKING_ROW.50 := 50 mm cube (step 5)
# The bursts [kHz] (the experiment files' [burst]: lab-data/concrete-cube/upv-experiment-{p,s}*.toml),
# for the S pick's matched filter and the summary's headings.
CC_C150_BURST_KHZ.150.p := 54
CC_C150_BURST_KHZ.150.s := 40
CC_C150_BURST_KHZ.50.p := 162
CC_C150_BURST_KHZ.50.s := 120
CC_C150_CHOICE_STATIC := $(CC_CALIBRATION_TARGETS)
CC_C150_CHOICE_DYNAMIC := dynamic
CC_C150_MATERIAL.$(CC_C150_CHOICE_DYNAMIC) := $(CC_C150_OUT)/calibration-dynamic.json
CC_C150_MATERIAL.$(CC_C150_CHOICE_STATIC) := $(CC_MATERIAL)
CC_C150_CHOICES := $(sort $(CC_C150_CHOICE_STATIC) $(CC_C150_CHOICE_DYNAMIC))
# How mw-upv picks the DEM's records (docs/cube-150.md, "Picking a noise-free record"). The DEM
# record has no pre-trigger: its first 3 us (1 us on the 50 mm cube), before any motion can reach
# the far face at one bond (at most 2.2 mm) a step of 50 ns, are the noise window (all zeros).
# Without noise, Maeda's AIC finds the lattice's numerical precursor (1e-6 of the peak, long before the wave), so the P onset is the first
# crossing of 2 % of the peak (threshold picker, as a pulse analyser's); the S onset is mw-upv's
# S chain after that t_p (from 1.3 t_p to the S envelope's peak) with the matched filter below.
CC_C150_NOISE_US.150 := 0,3
CC_C150_NOISE_US.50 := 0,1
cc_c150_record = --noise-window-us $(CC_C150_NOISE_US.$1) --amplitude-column 'R [m/s]'
CC_C150_P_PICK := --picker threshold --locate-relative 0.02
CC_C150_S_PICK := --picker aic
# The S onset by the matched filter with the load's time derivative (the records are the receiver's
# velocity under a force burst: lab-data/concrete-cube/upv-experiment-s*.toml's [burst], 40 kHz x 2
# cycles, and x 3 the frequency at 1/3 scale). The AIC places the onset at the burst's first large
# half-cycle, which rides on the P wave's near field, 0.4 periods late (docs/upv-pickers.md, "The
# DEM's S records"); the matched filter is 0.13-0.42 us after the continuum's S time on the 50 mm cube.
cc_c150_s_wavelet = --s-wavelet-burst-kHz $(CC_C150_BURST_KHZ.$1.s),2 --s-wavelet-derivative
# The lab's own chain beside it: white noise added to the record at a stated SNR (mw-upv
# --add-noise-snr-dB: 20 log10(peak / noise RMS), seeded), then mw-upv's defaults, AIC for P and
# the AIC-after-P chain for S, as on a lab record. 40 dB: source assumed, the middle of the picker
# table (docs/upv-pickers.md: 20-60 dB; the synthetic lab records are at 20 dB, where the AIC
# refuses most records; real ones are cleaner), so the stated bias of each pick is the table's.
CC_C150_NOISE_SNR_DB := 40
CC_C150_NOISY_PICK := --picker aic --add-noise-snr-dB $(CC_C150_NOISE_SNR_DB) --add-noise-seed 1

# The quick tree: the chain's rules on small cubes, a test of the rules and of the tables' numbers, not
# a model of the lab's cube: the sizes are modelling choices for that test, not the paper's values.
# The lab's cube at 37.5 mm (1/4 scale) and the 1/3-scale test on a 30 mm cube of its own: step 5's
# quick cube (20 mm) is too small for mw-upv's noise window, 16 samples (0.8 us) before the far face
# first moves (there at 0.63 us; on the 30 mm cube at 0.98 us, on the 37.5 mm one at 1.18 us). Both
# run the 1/3-scale test's scenes: the DEM places the transducers at the experiment's fractions of the
# packing's extent but keeps their patches' size, and the lab's 44.31 mm patches would take a whole
# face of the 37.5 mm cube (where the matched filter found no S onset on the dynamic calibration's
# record); the 14.77 mm ones are 0.39 and 0.49 of the faces. The bursts and records scale with the
# side, so that every wavelength keeps its ratio to the path as in the lab's test (the experiment's
# frequencies x 50 / side, its records x side / 50) and the same pickers read the records.
ifeq ($(QUICK),1)
CC_C150_SIDE_MM.150 := 37.5
CC_C150_SIDE_MM.50 := 30
CC_C150_SCENE.150 := upv50
CC_C150_PACKING.50 := $(CC_C150_OUT)/packing-50.h5
CC_C150_PACKING_ROW.50 := $(CC_C150_SIDE_MM.50) mm cube
CC_C150_BURST_KHZ.150.p := 216
CC_C150_BURST_KHZ.150.s := 160
CC_C150_BURST_KHZ.50.p := 270
CC_C150_BURST_KHZ.50.s := 200
CC_C150_RECORD_MS.150.p := 0.02
CC_C150_RECORD_MS.150.s := 0.03
CC_C150_RECORD_MS.50.p := 0.016
CC_C150_RECORD_MS.50.s := 0.024
CC_C150_NOISE_US.150 := 0,1
CC_C150_NOISE_US.50 := 0,0.9
endif
# mw-dem's burst and record instead of the experiment file's where a record is set (the quick tree);
# $1 the size, $2 p or s.
cc_c150_dem_record = $(if $(CC_C150_RECORD_MS.$1.$2), --frequency-kHz $(CC_C150_BURST_KHZ.$1.$2) --duration-ms $(CC_C150_RECORD_MS.$1.$2))
cc_c150_packing_json = $(patsubst %.h5,%.json,$(CC_C150_PACKING.$1))

# A size's cube packed with step 5's inputs at its side: the lab's cube, and the quick tree's 1/3-scale
# cube (the full tree's is step 5's own packing). $1 the size.
define CC_C150_PACK
$(CC_C150_PACKING.$1) $(call cc_c150_packing_json,$1) &: $(CC_LAB)/porosity.toml $(CC_LAB)/dem-packing.toml \
    $(CC_OUT)/density.json $(BIN)/mw-pack
	@mkdir -p $$(@D)
	$(BIN)/mw-pack box --from $(CC_LAB)/porosity.toml --from $(CC_LAB)/dem-packing.toml --from $(CC_OUT)/density.json \
	  --cube-side-mm $(CC_C150_SIDE_MM.$1) --quiet --packing $(CC_C150_PACKING.$1) --out $(call cc_c150_packing_json,$1) > /dev/null
endef
$(eval $(call CC_C150_PACK,150))
ifeq ($(QUICK),1)
$(eval $(call CC_C150_PACK,50))
endif

# The calibration to E_d and nu_d on the pipeline's 50 mm packing (the pipeline's own calibration
# is this one when CC_CALIBRATION_TARGETS=dynamic; then the rule is not used).
$(CC_C150_OUT)/calibration-dynamic.json $(CC_C150_OUT)/calibration-dynamic-trials.csv $(CC_C150_OUT)/calibration-dynamic-targets.csv \
    $(CC_C150_OUT)/calibration-dynamic-trajectory.png $(CC_C150_OUT)/calibration-dynamic-stress-strain.png &: \
    $(CC_COMPRESSION_SCENE) $(CC_OUT)/packing.h5 $(CC_CALIBRATION_TARGET_FILES.dynamic) $(BIN)/mw-calibrate $(BIN)/mw-dem
	@mkdir -p $(@D)
	$(call cc_calibrate,dynamic,$(CC_C150_OUT)/calibration-dynamic-trials,$(CC_C150_OUT)/calibration-dynamic)

# One wave run per size, transducer pair and calibration: upv<size>-p-<choice>.h5/.csv/.json and
# upv<size>-s-<choice>.*; size 150 is the lab's cube, 50 the same test scaled by 1/3 on step 5's
# packing (scenes/upv50-*.toml: three times the frequency, the same wavelengths per path), a check
# at 1/30 of the cost. $1 the choice, $2 p or s, $3 the size.
define CC_C150_RUNS
$(CC_C150_OUT)/upv$3-$2-$1.h5 $(CC_C150_OUT)/upv$3-$2-$1.csv $(CC_C150_OUT)/upv$3-$2-$1.json &: \
    $(CC_NOTES)/scenes/$(CC_C150_SCENE.$3)-$2.toml $(CC_LAB)/upv-experiment-$2$(if $(filter upv50,$(CC_C150_SCENE.$3)),-50mm).toml \
    $(CC_C150_PACKING.$3) $(CC_C150_MATERIAL.$1) $(BIN)/mw-dem
	@mkdir -p $$(@D)
	$(BIN)/mw-dem --from $(CC_C150_MATERIAL.$1) run $(CC_NOTES)/scenes/$(CC_C150_SCENE.$3)-$2.toml --packing $(CC_C150_PACKING.$3)$(call cc_c150_dem_record,$3,$2) \
	  --quiet --signals $(CC_C150_OUT)/upv$3-$2-$1.h5 --signals-csv $(CC_C150_OUT)/upv$3-$2-$1.csv \
	  --summary $(CC_C150_OUT)/upv$3-$2-$1.json > /dev/null
endef
# The P pick first (threshold), then the S chain after it (the matched filter); the second run reads the first's t_p.
define CC_C150_PICKS
$(CC_C150_OUT)/upv$2-tp-$1.json $(CC_C150_OUT)/upv$2-p-$1.png &: $(CC_C150_OUT)/upv$2-p-$1.csv $(BIN)/mw-upv
	$(BIN)/mw-upv --path-mm $(CC_C150_SIDE_MM.$2) --p-wave $(CC_C150_OUT)/upv$2-p-$1.csv $(CC_C150_P_PICK) $(call cc_c150_record,$2) \
	  --plot $(CC_C150_OUT)/upv$2-p-$1.png --title "$(CC_C150_SIDE_MM.$2) mm DEM cube, calibration '$1': P transducers, the pick" \
	  --out $(CC_C150_OUT)/upv$2-tp-$1.json > /dev/null
$(CC_C150_OUT)/upv$2-picks-$1.json $(CC_C150_OUT)/upv$2-s-$1.png &: $(CC_C150_OUT)/upv$2-tp-$1.json $(CC_C150_OUT)/upv$2-s-$1.csv \
    $(CC_OUT)/density.json $(BIN)/mw-upv
	$(BIN)/mw-upv --from $(CC_C150_OUT)/upv$2-tp-$1.json --from $(CC_OUT)/density.json --s-wave $(CC_C150_OUT)/upv$2-s-$1.csv \
	  $(CC_C150_S_PICK) $(call cc_c150_s_wavelet,$2) $(call cc_c150_record,$2) --plot $(CC_C150_OUT)/upv$2-s-$1.png \
	  --title "$(CC_C150_SIDE_MM.$2) mm DEM cube, calibration '$1': S transducers, the matched filter's pick" --out $(CC_C150_OUT)/upv$2-picks-$1.json > /dev/null
$(CC_C150_OUT)/upv$2-tp-noisy-$1.json $(CC_C150_OUT)/upv$2-p-noisy-$1.png &: $(CC_C150_OUT)/upv$2-p-$1.csv $(BIN)/mw-upv
	$(BIN)/mw-upv --path-mm $(CC_C150_SIDE_MM.$2) --p-wave $(CC_C150_OUT)/upv$2-p-$1.csv $(CC_C150_NOISY_PICK) $(call cc_c150_record,$2) \
	  --plot $(CC_C150_OUT)/upv$2-p-noisy-$1.png \
	  --title "$(CC_C150_SIDE_MM.$2) mm DEM cube, calibration '$1': P record + noise at $(CC_C150_NOISE_SNR_DB) dB, AIC pick" \
	  --out $(CC_C150_OUT)/upv$2-tp-noisy-$1.json > /dev/null
$(CC_C150_OUT)/upv$2-picks-noisy-$1.json $(CC_C150_OUT)/upv$2-s-noisy-$1.png &: $(CC_C150_OUT)/upv$2-tp-noisy-$1.json \
    $(CC_C150_OUT)/upv$2-s-$1.csv $(CC_OUT)/density.json $(BIN)/mw-upv
	$(BIN)/mw-upv --from $(CC_C150_OUT)/upv$2-tp-noisy-$1.json --from $(CC_OUT)/density.json --s-wave $(CC_C150_OUT)/upv$2-s-$1.csv \
	  $(CC_C150_NOISY_PICK) $(call cc_c150_s_wavelet,$2) $(call cc_c150_record,$2) --plot $(CC_C150_OUT)/upv$2-s-noisy-$1.png \
	  --title "$(CC_C150_SIDE_MM.$2) mm DEM cube, calibration '$1': S record + noise at $(CC_C150_NOISE_SNR_DB) dB, matched filter after P" \
	  --out $(CC_C150_OUT)/upv$2-picks-noisy-$1.json > /dev/null
endef
$(foreach c,$(CC_C150_CHOICES),$(foreach z,$(CC_C150_SIZES),$(foreach k,p s,$(eval $(call CC_C150_RUNS,$c,$k,$z)))$(eval $(call CC_C150_PICKS,$c,$z))))

# The picks beside the lab's (upv.toml: t_p, t_s; upv.json: v_p, v_s, E_d, nu_d of step 3); the
# 50 mm rows' times are over 50 mm (x 3 for the 150 mm path), their velocities compare directly.
# E_glob_GPa, nu_glob: a DEM row's calibrated static moduli (its material file; mw-table looks for
# the first name in all of a row's files first, so never its picks' E_d), and in the measured row
# their measured counterparts, the compression tests' E_st and nu_st (static-test.toml, step 4).
$(CC_C150_OUT)/upv150.csv: $(CC_LAB)/upv.toml $(CC_OUT)/upv.json $(CC_LAB)/static-test.toml $(foreach c,$(CC_C150_CHOICES),$(foreach z,$(CC_C150_SIZES),\
    $(CC_C150_OUT)/upv$z-picks-$c.json $(CC_C150_OUT)/upv$z-picks-noisy-$c.json) $(CC_C150_MATERIAL.$c)) $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name record --row "measured (upv.toml; static-test.toml)=$(CC_LAB)/upv.toml,$(CC_OUT)/upv.json,$(CC_LAB)/static-test.toml" \
	  $(foreach c,$(CC_C150_CHOICES),$(foreach z,$(CC_C150_SIZES),--row "DEM $(CC_C150_SIDE_MM.$z) mm; calibrated to $c=$(CC_C150_MATERIAL.$c),$(CC_C150_OUT)/upv$z-picks-$c.json" \
	    --row "DEM $(CC_C150_SIDE_MM.$z) mm; calibrated to $c; + $(CC_C150_NOISE_SNR_DB) dB noise; AIC=$(CC_C150_MATERIAL.$c),$(CC_C150_OUT)/upv$z-picks-noisy-$c.json")) \
	  --column path_mm --column "t_p_us=t_p_us|t_p" --column "t_s_us=t_s_us|t_s" --column v_p_m_s --column v_s_m_s \
	  --column E_d_GPa --column nu_d --column "E_glob_GPa=E_glob_GPa|E_st_measured" --column "nu_glob=nu_glob|nu_st" \
	  --significant-digits 4 --csv $@ > /dev/null

# What each wave run cost (wall time and peak memory of every run: mw-prov runs --tool mw-dem).
$(CC_C150_OUT)/upv150-cost.csv: $(foreach c,$(CC_C150_CHOICES),$(foreach z,$(CC_C150_SIZES),$(foreach k,p s,$(CC_C150_OUT)/upv$z-$k-$c.json))) \
    $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name run \
	  $(foreach c,$(CC_C150_CHOICES),$(foreach z,$(CC_C150_SIZES),$(foreach k,p s,--row "$(CC_C150_SIDE_MM.$z) mm $k; $c=$(CC_C150_OUT)/upv$z-$k-$c.json"))) \
	  --column model --column spheres --column bonds --column threads --column steps --column setup_s --column wall_s \
	  --column steps_per_s --column memory_estimate_MiB --column peak_force_ratio --significant-digits 4 --csv $@ > /dev/null

$(CC_C150_OUT)/packing150.csv: $(foreach z,$(CC_C150_SIZES),$(call cc_c150_packing_json,$z)) $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name packing --row "$(CC_C150_SIDE_MM.150) mm cube=$(call cc_c150_packing_json,150)" \
	  --row "$(CC_C150_PACKING_ROW.50)=$(call cc_c150_packing_json,50)" --column spheres --column bonds --column coordination \
	  --column porosity_pct --column particle_density_kg_m3 --column relaxation_iterations --column threads \
	  --column wall_time_s --significant-digits 5 --csv $@ > /dev/null

# ==== Table 3 with each calibration ("what each does to Table 3?") ==========
# Table 3 compares the DEM's wave records (100-500 kHz, sensors B-G) with the continuum reference,
# which carries the dynamic moduli E_d, nu_d of step 3 (waves.mk). Calibrated to the static tests
# (E_glob 27.4 GPa against E_d 36.7 GPa), the DEM's waves travel at about sqrt(E_glob / E_d) = 0.86
# of the reference's speed. The same one-run, nine-frequency DEM with the material calibrated to
# E_d, nu_d gives its records in waves-dynamic/, compared with the same FEM references by the same
# rules (waves.mk's CC_DEM_WAVES, CC_WAVE_PCC, CC_TABLE3); table3-calibrations.csv puts the two
# Tables 3 side by side. When the pipeline's own calibration is the dynamic one, its records are those.
CC_C150_WAVES.$(CC_C150_CHOICE_DYNAMIC) := $(CC_C150_OUT)/waves-$(CC_C150_CHOICE_DYNAMIC)
CC_C150_WAVES.$(CC_C150_CHOICE_STATIC) := $(CC_OUT)
ifneq ($(CC_C150_WAVES.$(CC_C150_CHOICE_DYNAMIC)),$(CC_OUT))
$(eval $(call CC_DEM_WAVES,$(CC_C150_WAVES.$(CC_C150_CHOICE_DYNAMIC)),$(CC_C150_MATERIAL.$(CC_C150_CHOICE_DYNAMIC))))
$(eval $(call CC_WAVE_PCC,$(CC_C150_WAVES.$(CC_C150_CHOICE_DYNAMIC)),DEM calibrated to E_d and nu_d))
$(eval $(call CC_TABLE3,$(CC_C150_WAVES.$(CC_C150_CHOICE_DYNAMIC))))
endif
# Table 3's PCC columns (dem_vs_fem_*) of each calibration as <choice>_*, the pipeline's first.
CC_C150_TABLE3_CHOICES := $(CC_C150_CHOICE_STATIC) $(filter-out $(CC_C150_CHOICE_STATIC),$(CC_C150_CHOICE_DYNAMIC))
CC_C150_TABLE3_COLUMNS := dem_vs_fem_first_$(CC_EARLY_US)us_pcc_signals dem_vs_fem_first_$(CC_EARLY_US)us_pcc_envelopes \
  dem_vs_fem_pcc_signals dem_vs_fem_pcc_envelopes
cc_c150_table3_name = $(patsubst dem_vs_fem_%,$1_%,$2)
cc_c150_table3_join = $(subst $(cc_space),$(cc_comma),$(foreach k,$(CC_C150_TABLE3_COLUMNS),$(call cc_c150_table3_name,$1,$k)=$k))
$(CC_C150_OUT)/table3-calibrations.csv: $(foreach c,$(CC_C150_TABLE3_CHOICES),$(CC_C150_WAVES.$c)/table3.csv) $(BIN)/mw-table
	@mkdir -p $(@D)
	$(BIN)/mw-table gather --key-name f_kHz \
	  $(foreach f,$(CC_FREQS),--row $f=$(CC_C150_WAVES.$(firstword $(CC_C150_TABLE3_CHOICES)))/table3.csv) \
	  $(foreach k,$(CC_C150_TABLE3_COLUMNS),--column $(call cc_c150_table3_name,$(firstword $(CC_C150_TABLE3_CHOICES)),$k)=$k@f_kHz={f_kHz}) \
	  $(foreach c,$(wordlist 2,2,$(CC_C150_TABLE3_CHOICES)),--join $(CC_C150_WAVES.$c)/table3.csv:$(call cc_c150_table3_join,$c)) \
	  --csv $@ > /dev/null

$(CC_C150_OUT)/table3-calibrations.png: $(CC_C150_OUT)/table3-calibrations.csv $(BIN)/mw-table
	$(BIN)/mw-table plot $< --x f_kHz \
	  $(foreach c,$(CC_C150_TABLE3_CHOICES),--y "$c_first_$(CC_EARLY_US)us_pcc_signals=calibrated to $c: first $(CC_EARLY_US) us, signals" \
	    --y "$c_first_$(CC_EARLY_US)us_pcc_envelopes=calibrated to $c: first $(CC_EARLY_US) us, envelopes" \
	    --y "$c_pcc_signals=calibrated to $c: whole record, signals") \
	  --y-range -0.4,1 --x-label "burst centre frequency [kHz]" --y-label "mean PCC over sensors B-G, DEM against FEM" \
	  --key below --title "Concrete cube: Table 3 with each calibration (the FEM reference has E_d, nu_d)" --out $@ > /dev/null

# Its report, apart from make reproduce's: report/concrete-cube-150/index.html. The quick tree's reads
# the same spec with its files in $(RESULTS)/ (a copy made by sed, as pipeline/report.mk's).
CC_C150_REPORT_SOURCE := $(CC_NOTES)/report-150.toml
CC_C150_REPORT := $(REPORT_DIR)/concrete-cube-150/index.html
ifeq ($(QUICK),1)
CC_C150_REPORT_SPEC := $(CC_C150_OUT)/report-150.toml
$(CC_C150_REPORT_SPEC): $(CC_C150_REPORT_SOURCE)
	@mkdir -p $(@D)
	sed -e '0,/^title = "\(.*\)"/s//title = "\1 - quick look (small models, short records)"/' \
	  -e 's#^\(table\|figure\) = "results/#\1 = "$(RESULTS)/#' $< > $@
else
CC_C150_REPORT_SPEC := $(CC_C150_REPORT_SOURCE)
endif
$(CC_C150_REPORT): $(CC_C150_REPORT_SPEC) \
    $(patsubst results/%,$(RESULTS)/%,$(shell sed -n 's/^\(table\|figure\) = "\(.*\)"/\2/p' $(CC_C150_REPORT_SOURCE))) \
    $(BIN)/mw-report
	$(BIN)/mw-report --spec $(CC_C150_REPORT_SPEC) --out-dir $(@D) > /dev/null

CC_C150_RESULTS := $(CC_C150_OUT)/packing150.csv $(CC_C150_OUT)/upv150.csv $(CC_C150_OUT)/upv150-cost.csv \
  $(CC_C150_OUT)/table3-calibrations.csv $(CC_C150_OUT)/table3-calibrations.png $(CC_C150_REPORT) \
  $(foreach c,$(CC_C150_CHOICES),$(foreach z,$(CC_C150_SIZES),$(CC_C150_OUT)/upv$z-p-$c.png $(CC_C150_OUT)/upv$z-s-$c.png \
    $(CC_C150_OUT)/upv$z-p-noisy-$c.png $(CC_C150_OUT)/upv$z-s-noisy-$c.png))

.PHONY: concrete-cube-150
concrete-cube-150: $(CC_C150_RESULTS)
	@echo
	@echo "== The $(CC_C150_SIDE_MM.150) mm cube ($(CC_C150_OUT)): packing (wall time and peak memory: mw-prov runs --tool mw-pack) =="
	@$(CC_PRINT_CSV) $(CC_C150_OUT)/packing150.csv
	@echo
	@echo "== UPV on the $(CC_C150_SIDE_MM.150) mm DEM cube against the lab's (P $(CC_C150_BURST_KHZ.150.p) kHz, S $(CC_C150_BURST_KHZ.150.s) kHz, $(CC_C150_SIDE_MM.150) mm path) =="
	@$(CC_PRINT_CSV) $(CC_C150_OUT)/upv150.csv
	@echo
	@echo "== The wave runs' cost (wall time and peak memory: mw-prov runs --tool mw-dem) =="
	@$(CC_PRINT_CSV) $(CC_C150_OUT)/upv150-cost.csv
	@echo
	@echo "== Table 3 with each calibration: mean PCC of DEM against the continuum (E_d, nu_d) =="
	@$(CC_PRINT_CSV) $(CC_C150_OUT)/table3-calibrations.csv
	@echo
	@echo "report: $(CURDIR)/$(CC_C150_REPORT)"
