# Included by pipeline/concrete-cube/study.mk (its variables CC_*), in the flowchart's order.
# ==== Speed against error (the cube) ===========================================
# One frequency, a shorter record: the linearised network against the full
# contact law, dt 50 against 25 ns, one against two threads. Each run is compared
# with the most exact one (full law, 25 ns) by the mean PCC over sensors B-G, the
# mean |shift| of the arrivals (first crossing of 2 % of each record's peak) and the
# mean |ratio - 1| of the peaks; its cost is the wall time of the run on this
# machine. The table's last column marks the Pareto front of wall time against PCC
# (the cheapest run for its accuracy).
# 0.1 ms: 25 periods, eight P transits of the 50 mm cube. The full-scale campaign measured these
# errors on 0.1 ms records (bench/speed_error_cube.sh; docs/benchmarks.md, "The campaign at full
# scale"); 0.3 ms cost the pipeline about 220 s more of CPU (299 s against 82 s on 2026-12-05).
CC_SPEED_F := 250
CC_SPEED_RECORD := --duration-ms 0.1
CC_SPEED_REFERENCE := full-25ns-1t
CC_SPEED_RUNS := linear-50ns-1t linear-50ns-2t linear-25ns-1t full-50ns-1t $(CC_SPEED_REFERENCE)
cc_speed_word = $(word $2,$(subst -, ,$1))

$(CC_OUT)/speed-%.h5 $(CC_OUT)/speed-%.json: $(CC_SCENE) $(CC_OUT)/packing.h5 $(CC_MATERIAL) $(BIN)/mw-dem
	$(BIN)/mw-dem --from $(CC_MATERIAL) run $(CC_SCENE) --packing $(CC_OUT)/packing.h5 --frequency-kHz $(CC_SPEED_F) \
	  $(CC_SPEED_RECORD) --model $(call cc_speed_word,$*,1) --dt-ns $(patsubst %ns,%,$(call cc_speed_word,$*,2)) \
	  --threads $(patsubst %t,%,$(call cc_speed_word,$*,3)) --quiet \
	  --signals $(CC_OUT)/speed-$*.h5 --summary $(CC_OUT)/speed-$*.json > /dev/null

# (The JSON has the PCC to full precision: the runs agree to 4 digits and more.)
$(CC_OUT)/speed-pcc-%.json: $(CC_OUT)/speed-%.h5 $(CC_OUT)/speed-$(CC_SPEED_REFERENCE).h5 $(BIN)/mw-pcc
	$(BIN)/mw-pcc --a $(CC_OUT)/speed-$*.h5 --b $(CC_OUT)/speed-$(CC_SPEED_REFERENCE).h5 --resample linear --pad double \
	  --arrival-relative 0.02 --out $@ > /dev/null

$(CC_OUT)/speed.csv: $(foreach r,$(CC_SPEED_RUNS),$(CC_OUT)/speed-$r.json $(CC_OUT)/speed-pcc-$r.json) $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name run \
	  $(foreach r,$(CC_SPEED_RUNS),--row $r=$(CC_OUT)/speed-pcc-$r.json,$(CC_OUT)/speed-$r.json) \
	  --column model --column dt_s --column threads --column steps --column wall_s --column steps_per_s \
	  --column pcc_vs_reference=mean_pcc_signal --column pcc_envelope_vs_reference=mean_pcc_envelope \
	  --column arrival_error_us=mean_abs_arrival_shift_us --column peak_amplitude_error=mean_abs_peak_error \
	  --column peak_force_ratio --pareto min:wall_s,max:pcc_vs_reference --csv $@ > /dev/null

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
# Every run's files stay (make would otherwise delete what only pattern rules need). The DEM and
# FEM records come from explicit rules, so they are never intermediate, and are left out: make 4.3
# puts off a missing .SECONDARY target until a later pass over the graph, which started the FEM
# references last in the schedule (top Makefile, "The order of the runs").
.SECONDARY: $(filter-out $(CC_OUT)/dem-% $(CC_OUT)/fem-%,$(CC_WAVE_RESULTS)) $(foreach f,$(CC_FREQS) $(CC_MEASURED_FREQS),$(CC_OUT)/pcc-$(f)kHz.json \
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
	@echo "DEM: every frequency from one superposed run with the viscous equivalent of Eq. (7), zeta = alpha_d / pi"
	@echo "(direct runs of the two laws: 1 - PCC 3e-4 to 2.5e-3, docs/benchmarks.md; the run: $(CC_OUT)/dem-waves.json)."
	@$(CC_PRINT_CSV) $(CC_OUT)/table3.csv
	@echo
	@echo "Speed against error ($(CC_SPEED_F) kHz; PCC against $(CC_SPEED_REFERENCE)):"
	@$(CC_PRINT_CSV) $(CC_OUT)/speed.csv
