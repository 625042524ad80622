# Rod paper Table 1 (issue 5): per spacing, the particle density from the rod's
# mass (mw-pack line) and the contact modulus E_dem from the quasi-static tension
# test of the chain (mw-calibrate rod), started from the paper's K_n column read
# as E_dem (lab-data/steel-rod/paper/table1.csv), so that the first trial is the
# paper's model and the last one gives the rod's E (Section 4.1; mw-calibrate rod reads
# it from lab-data/steel-rod/experiment.toml, SR_EXPERIMENT).
# Included by pipeline/steel-rod/study.mk.
#   make steel-rod-calibration     results/steel-rod/calibration-table.{csv,txt}

SR_TENSION := pipeline/steel-rod/scenes/rod-tension.toml
SR_CAL_MODELS := 0.95R 1.03R 1.05R 1.15R
sr_paper_Ec_GPa = $(shell awk -F, -v m=$1 '!/^\#/ && $$1 == m { print $$4 / 1e9 }' $(SR_PAPER)/table1.csv)

define SR_CALIBRATE
$(SR_OUT)/calibration-$1.json: $(SR_TENSION) $(SR_OUT)/packing-$1.h5 $(SR_PAPER)/table1.csv $(SR_EXPERIMENT) $(BIN)/mw-calibrate $(BIN)/mw-dem
	$(BIN)/mw-calibrate rod --scene $(SR_TENSION) --packing $(SR_OUT)/packing-$1.h5 $(SR_ROD) \
	  --start-E-dem-GPa $$(call sr_paper_Ec_GPa,$1) --work-dir $(SR_OUT)/calibration-$1 --out $$@ > /dev/null
endef
$(foreach m,$(SR_CAL_MODELS),$(eval $(call SR_CALIBRATE,$m)))

# Sphere count, rho_p and E_DEM (the tension test at the paper's K_n) beside Table 1; and the
# contact modulus that gives the rod's E (mw-calibrate rod): mesowave's Table 1, gathered.
$(SR_OUT)/calibration-ours.csv: $(foreach m,$(SR_CAL_MODELS),$(SR_OUT)/calibration-$m.json) $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name model $(foreach m,$(SR_CAL_MODELS),--row $m=$(SR_OUT)/calibration-$m.json) \
	  --column spheres --column rho_p_kg_m3 --column E_DEM_GPa=E_DEM_at_start_GPa --column E_dem_calibrated_GPa=E_dem_GPa \
	  --column Kn_calibrated_N_m=Kn_N_m --column E_DEM_calibrated_GPa=E_DEM_GPa --round rho_p_kg_m3=2 \
	  --round E_DEM_GPa=3 --round E_dem_calibrated_GPa=2 --round Kn_calibrated_N_m=-6 --round E_DEM_calibrated_GPa=3 \
	  --csv $@ > /dev/null

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
