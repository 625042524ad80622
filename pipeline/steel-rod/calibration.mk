# Rod paper Table 1 (issue 5): per spacing, the particle density from the rod's
# mass (mw-pack line) and the contact modulus E_dem from the quasi-static tension
# test of the chain (mw-calibrate rod), started from the paper's K_n column read
# as E_dem (lab-data/steel-rod/paper/table1.csv), so that the first trial is the
# paper's model and the last one gives the rod's E = 208.72 GPa (Section 4.1).
# Included by pipeline/steel-rod/study.mk.
#   make steel-rod-calibration     results/steel-rod/calibration-table.{csv,txt}

SR_TENSION := pipeline/steel-rod/scenes/rod-tension.toml
SR_CAL_MODELS := 0.95R 1.03R 1.05R 1.15R
sr_paper_Ec_GPa = $(shell awk -F, -v m=$1 '!/^\#/ && $$1 == m { print $$4 / 1e9 }' $(SR_PAPER)/table1.csv)

define SR_CALIBRATE
$(SR_OUT)/calibration-$1.json: $(SR_TENSION) $(SR_OUT)/packing-$1.h5 $(SR_PAPER)/table1.csv $(BIN)/mw-calibrate $(BIN)/mw-dem
	$(BIN)/mw-calibrate rod --scene $(SR_TENSION) --packing $(SR_OUT)/packing-$1.h5 --E-GPa 208.72 \
	  --start-E-dem-GPa $$(call sr_paper_Ec_GPa,$1) --work-dir $(SR_OUT)/calibration-$1 --out $$@ > /dev/null
endef
$(foreach m,$(SR_CAL_MODELS),$(eval $(call SR_CALIBRATE,$m)))

# Sphere count, rho_p and E_DEM (the tension test at the paper's K_n) beside Table 1; and the
# contact modulus that gives the rod's E.
$(SR_OUT)/calibration-ours.csv: $(foreach m,$(SR_CAL_MODELS),$(SR_OUT)/calibration-$m.json)
	{ echo "# mesowave's Table 1: sphere count and rho_p of the chain (mw-pack line), E_DEM of the tension test at the paper's K_n (E_dem), and the E_dem that gives E = 208.72 GPa (mw-calibrate rod)"; \
	  echo "model,spheres,rho_p_kg_m3,E_DEM_GPa,E_dem_calibrated_GPa,Kn_calibrated_N_m,E_DEM_calibrated_GPa"; \
	  for m in $(SR_CAL_MODELS); do jq -r --arg m $$m 'def r(d): . * d | round / d; [$$m, .spheres, (.rho_p_kg_m3 | r(100)), (.E_DEM_at_start_GPa | r(1000)), (.E_dem_GPa | r(100)), (.Kn_N_m / 1e6 | round * 1e6), (.E_DEM_GPa | r(1000))] | @csv' \
	    $(SR_OUT)/calibration-$$m.json | tr -d '"'; done; } > $@

$(SR_OUT)/calibration-table.txt $(SR_OUT)/calibration-table.csv &: $(SR_OUT)/calibration-ours.csv $(SR_PAPER)/table1.csv $(BIN)/mw-compare
	$(BIN)/mw-compare --ours $(SR_OUT)/calibration-ours.csv --paper $(SR_PAPER)/table1.csv --key model \
	  --columns spheres rho_p_kg_m3 E_DEM_GPa \
	  --title "Rod Table 1: chains calibrated by mass and by the tension test (E_DEM at the paper's K_n read as E_dem)" \
	  --csv $(SR_OUT)/calibration-table.csv --text $(SR_OUT)/calibration-table.txt > /dev/null

.PHONY: steel-rod-calibration
steel-rod-calibration: $(SR_OUT)/calibration-table.txt
	@cat $<
	@echo
	@grep -v '^#' $(SR_OUT)/calibration-ours.csv | column -s, -t
	@echo
	@cat pipeline/steel-rod/calibration-note.txt
