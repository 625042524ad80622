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

include pipeline/concrete-cube/steps-1-3.mk
include pipeline/concrete-cube/raw-steps-2-4.mk
include pipeline/concrete-cube/step-5-packing.mk
include pipeline/concrete-cube/step-6-calibration.mk
include pipeline/concrete-cube/waves.mk
include pipeline/concrete-cube/speed.mk
