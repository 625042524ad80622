# Shock-concrete study (the shock paper: Larcher and Stempniewski, "Simulation of shock wave loaded
# concrete with discrete cracks", Universitaet Karlsruhe (TH); ../shared/seeds/004_*): the EFG solver
# mw-efg on the paper's Section 4.1 and 4.2 tests. Included by the top Makefile, which defines BIN,
# RESULTS and QUICK and exports MESOWAVE_DB.
#
#   make shock-concrete-summary     everything below, the tables printed
#
# - three-point bending (Section 4.1, Fig. 10): the Koermeling-Reinhardt beam of
#   lab-data/shock-concrete/three-point-bending.toml, both cohesive laws, the complete curves on the
#   ligament interface (docs/efg.md section 3): peak load, deflection at the peak, the work of
#   fracture against G_f x ligament area, the load-deflection figure;
# - the linear strip (the explicit solver's check): the peak's speed against c_p = sqrt(M / rho),
#   the stencil's dispersion, the history against the closed form, three node spacings;
# - shock steepening (Section 4.2, Fig. 11): the smooth law p = M s (1 + beta s), then the paper's
#   Y-function (without Eq. (27), as the paper's test; and with it), against the method of
#   characteristics: where and when the shock forms, its speed against a fine 1D bar of the same law
#   (shock_speed_over_bar; the fixed-level jump condition beside it is not the continuum's speed where
#   the speed is timed: docs/efg.md "Shock viscosity"), the stress profiles at several times, three
#   node spacings.
# - the shock strips and the slab run WITH the explicit solver's bulk viscosity, LS-DYNA's defaults
#   C_0 = 1.5, C_1 = 0.06 (the lead's decision, docs/efg.md "Shock viscosity": the shock speed then
#   converges to the continuum's; `mw-efg`'s own default stays off, the paper's model); the field
#   projection stays off (none).
# - the blasted slab (Section 4.3, Fig. 12): `mw-efg blast`, a line charge on a 400 x 100 mm plain
#   concrete slab in plane strain (lab-data/shock-concrete/blast-slab.toml), every part of the paper's
#   list at once; the crack pattern over the compacted zone and the crater (efg/crater.hpp), and a
#   node-spacing series (crack count and length, compacted depth, crater depth, width and area, wall time).
#
# Sizes (QUICK=0; the runs' own wall times on the 2-core development machine at load 9-11, one run
# after the other; docs/efg.md, "The shock-concrete study"): the beams on the 5 mm grid (1932 nodes,
# 23-26 s a law for the complete curve; the 2.5 mm grid would take about 10 min a law), the linear
# strips at 10, 5 and 2.5 mm (13 s in all), the shock strips at 2, 1 and 0.5 mm (116 s in all, 100 s
# of it the two 0.5 mm runs). The quick tree: the 10 mm beam (about 1.5 s a law), strips at 20 and
# 10 mm, shock strips at 4 and 2 mm - about 4 s of tool time. The slab runs at the resolved step (--dt-us 0.25)
# with the crack spacing and radius limits as lengths (30 mm, 15 mm: lab-data/shock-concrete/blast-slab.toml;
# docs/efg.md "The crater, and the slab against node spacing"): one thread, with the viscosity, load 12: 0.7 s
# at 20 mm, 3 s at 15 mm, 10 s at 10 mm, 10 s at 7.5 mm, 45 s at 5 mm (the cost follows the crack changes: with
# a 2 h spacing the 7.5 mm run took 136 s, the 5 mm one 40 min); the quick tree runs 20 and 15 mm (its figure
# 15 mm), the full one 15, 10, 7.5 and 5 mm (its figure 7.5 mm, with the ParaView snapshots).

# Study prefix: SC (make variables SC_*, functions sc_*; scripts/new-study renames them).
PIPELINE_GOALS += shock-concrete-summary

SC_OUT := $(RESULTS)/shock-concrete
SC_LAB := lab-data/shock-concrete
SC_NOTES := pipeline/shock-concrete
SC_BEAM := $(SC_LAB)/three-point-bending.toml
SC_BAR := $(SC_LAB)/shock-steepening.toml
SC_SMOOTH := $(SC_LAB)/shock-steepening-smooth.toml
SC_HUGONIOT := $(SC_LAB)/hugoniot.toml
SC_LAWS := exponential bilinear
# the shock strips' and the slab's bulk viscosity (see the header)
SC_VISCOSITY := --viscosity-quadratic 1.5 --viscosity-linear 0.06

ifeq ($(QUICK),1)
SC_BEAM_MM := 10
SC_BEAM_STEPS := --steps 40 --step-ratio 1.1
SC_LINEAR_SPACINGS := 20 10
SC_LINEAR_MM := 10
SC_SHOCK_SPACINGS := 4 2
SC_SHOCK_MM := 2
SC_SLAB_MM := 15
SC_SLAB_SPACINGS := 20 15
else
SC_BEAM_MM := 5
SC_BEAM_STEPS := --steps 60 --step-ratio 1.07
SC_LINEAR_SPACINGS := 10 5 2.5
SC_LINEAR_MM := 5
SC_SHOCK_SPACINGS := 2 1 0.5
SC_SHOCK_MM := 1
SC_SLAB_MM := 7.5
SC_SLAB_SPACINGS := 15 10 7.5 5
endif

# --- Three-point bending: the complete curve (ligament interface) to 1e-4 of the peak, the Q4 FEM
# of the same notched beam for the elastic stiffness (--fem-refinement 1: the grid's own cells).
define SC_BENDING
$(SC_OUT)/bending-$1.json $(SC_OUT)/curve-$1.csv $(SC_OUT)/crack-$1.csv &: $(SC_BEAM) $(BIN)/mw-efg
	@mkdir -p $$(@D)
	$(BIN)/mw-efg bending --from $(SC_BEAM) --law $1 --spacing-mm $(SC_BEAM_MM) --ligament-interface $(SC_BEAM_STEPS) \
	  --max-deflection-mm 12 --stop-load-fraction 1e-4 --fem-refinement 1 --curve $(SC_OUT)/curve-$1.csv \
	  --crack-path $(SC_OUT)/crack-$1.csv --out $(SC_OUT)/bending-$1.json > /dev/null
endef
$(foreach l,$(SC_LAWS),$(eval $(call SC_BENDING,$l)))

$(SC_OUT)/bending.csv: $(foreach l,$(SC_LAWS),$(SC_OUT)/bending-$l.json) $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name law $(foreach l,$(SC_LAWS),--row $l=$(SC_OUT)/bending-$l.json) \
	  --column spacing_mm=discretisation.spacing_mm --column nodes=cost.nodes --column peak_load_N \
	  --column deflection_at_peak_mm --column work_of_fracture_Nmm --column G_f_times_ligament_Nmm \
	  --column work_of_fracture_ratio --column dissipated_Nmm --column stiffness_N_per_mm=elastic_stiffness.efg_N_per_mm \
	  --column fem_stiffness_N_per_mm=elastic_stiffness.fem_notched_N_per_mm --column completed \
	  --column newton_iterations=cost.newton_iterations --column wall_s=cost.wall_s \
	  --round peak_load_N=1 --round deflection_at_peak_mm=3 --round work_of_fracture_Nmm=1 --round G_f_times_ligament_Nmm=1 \
	  --round work_of_fracture_ratio=4 --round dissipated_Nmm=1 --round stiffness_N_per_mm=0 --round fem_stiffness_N_per_mm=0 \
	  --round wall_s=3 --csv $@ > /dev/null

# Both laws' curves on one log deflection axis (the peak lies near 0.1 mm, the tail reaches 12 mm).
$(SC_OUT)/load-deflection.png: $(foreach l,$(SC_LAWS),$(SC_OUT)/curve-$l.csv) $(BIN)/mw-table
	$(BIN)/mw-table plot $(SC_OUT)/curve-exponential.csv --x deflection_mm --y load_N=exponential \
	  --overlay $(SC_OUT)/curve-bilinear.csv:load_N=bilinear --style lines --log-x \
	  --x-label 'deflection at mid-span [mm]' --y-label 'load [N]' --key 'inside top right' \
	  --title 'Three-point bending, ligament interface, $(SC_BEAM_MM) mm grid (cf. the paper'"'"'s Fig. 10)' --out $@ > /dev/null

# --- The linear strip (rollers: uniaxial strain), the bar's material: a 40/40 us triangle over 1 m
# (the peak's speed between 200 and 800 mm) and a 10/10 us one over 0.5 m (k h up to 0.85 at 5 mm:
# the dispersion shows), per node spacing; and a 20 kHz 3-cycle Hann burst over 0.8 m with mw-fem's
# explicit solver on the same bar (--fem-reference: one row of hexahedra of the same spacing, u_y =
# u_z held), v_x at 300 mm against the closed form (the set-up of tests/efg/wave_strip_test.cpp).
define SC_LINEAR
$(SC_OUT)/strip-long-$1mm.json $(SC_OUT)/strip-long-$1mm.csv &: $(SC_BAR) $(BIN)/mw-efg
	@mkdir -p $$(@D)
	$(BIN)/mw-efg wave --from $(SC_BAR) --law linear --length-mm 1000 --spacing-mm $1 --rise-us 40 --fall-us 40 \
	  --sensor-mm 200 --sensor-mm 800 --history $(SC_OUT)/strip-long-$1mm.csv --out $(SC_OUT)/strip-long-$1mm.json > /dev/null
$(SC_OUT)/strip-hann-$1mm.json $(SC_OUT)/strip-hann-$1mm.csv &: $(SC_BAR) $(BIN)/mw-efg
	@mkdir -p $$(@D)
	$(BIN)/mw-efg wave --from $(SC_BAR) --law linear --pulse hann --frequency-kHz 20 --cycles 3 --length-mm 800 \
	  --spacing-mm $1 --sensor-mm 300 --duration-us 250 --fem-reference --history $(SC_OUT)/strip-hann-$1mm.csv \
	  --out $(SC_OUT)/strip-hann-$1mm.json > /dev/null
$(SC_OUT)/strip-short-$1mm.json $(SC_OUT)/strip-short-$1mm.csv &: $(SC_BAR) $(BIN)/mw-efg
	@mkdir -p $$(@D)
	$(BIN)/mw-efg wave --from $(SC_BAR) --law linear --length-mm 500 --spacing-mm $1 --rise-us 10 --fall-us 10 \
	  --sensor-mm 100 --sensor-mm 400 --history $(SC_OUT)/strip-short-$1mm.csv --out $(SC_OUT)/strip-short-$1mm.json > /dev/null
endef
$(foreach h,$(SC_LINEAR_SPACINGS),$(eval $(call SC_LINEAR,$h)))

$(SC_OUT)/strip-linear.csv: $(foreach h,$(SC_LINEAR_SPACINGS),$(SC_OUT)/strip-long-$(h)mm.json $(SC_OUT)/strip-short-$(h)mm.json) $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name pulse,spacing_mm \
	  $(foreach p,long short,$(foreach h,$(SC_LINEAR_SPACINGS),--row $(if $(filter long,$p),40-40us,10-10us),$h=$(SC_OUT)/strip-$p-$(h)mm.json)) \
	  --column nodes --column steps --column dt_us --column stable_dt_us --column c_p_m_s --column peak_speed_m_s \
	  --column peak_speed_error --column speed_kh_pi_8=stencil_dispersion_by_kh.kh_pi_8.phase_speed_over_c_p \
	  --column speed_kh_pi_4=stencil_dispersion_by_kh.kh_pi_4.phase_speed_over_c_p \
	  --column speed_kh_pi_4_with_step=stencil_dispersion_by_kh.kh_pi_4.with_time_step --column energy_drift --column wall_s \
	  --round dt_us=3 --round stable_dt_us=3 --round c_p_m_s=1 --round peak_speed_m_s=1 --round peak_speed_error=4 \
	  --round speed_kh_pi_8=4 --round speed_kh_pi_4=4 --round speed_kh_pi_4_with_step=4 --round wall_s=3 --csv $@ > /dev/null

$(SC_OUT)/strip-fem.csv: $(foreach h,$(SC_LINEAR_SPACINGS),$(SC_OUT)/strip-hann-$(h)mm.json) $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name spacing_mm $(foreach h,$(SC_LINEAR_SPACINGS),--row $h=$(SC_OUT)/strip-hann-$(h)mm.json) \
	  --column efg_rms_error=fem_reference.sensors.x0.efg_rms_error --column fem_rms_error=fem_reference.sensors.x0.fem_rms_error \
	  --column efg_fem_rms_difference=fem_reference.sensors.x0.efg_fem_rms_difference --column efg_nodes=nodes \
	  --column efg_dt_us=dt_us --column efg_wall_s=wall_s --column fem_elements=fem_reference.elements \
	  --column fem_dt_us=fem_reference.dt_us --column fem_wall_s=fem_reference.wall_s \
	  --round efg_rms_error=4 --round fem_rms_error=4 --round efg_fem_rms_difference=4 --round efg_dt_us=3 --round fem_dt_us=3 \
	  --round efg_wall_s=3 --round fem_wall_s=3 --csv $@ > /dev/null

$(SC_OUT)/strip-hann.png: $(SC_OUT)/strip-hann-$(SC_LINEAR_MM)mm.csv $(BIN)/mw-table
	$(BIN)/mw-table plot $< --x t_us --y 'x0_v_x_m_s=EFG' --y 'x0_v_x_fem_m_s=mw-fem' --y 'x0_v_x_continuum_m_s=closed form' \
	  --style lines --x-label 't [us]' --y-label 'v x at 300 mm [m/s]' --key 'inside top right' \
	  --title 'Linear bar, $(SC_LINEAR_MM) mm: a 20 kHz 3-cycle burst, EFG and mw-fem against the closed form' --out $@ > /dev/null

define SC_LINEAR_FIGURE
$(SC_OUT)/strip-$1.png: $(SC_OUT)/strip-$1-$(SC_LINEAR_MM)mm.csv $(BIN)/mw-table
	$(BIN)/mw-table plot $$< --x t_us --y 'x0_sigma_xx_MPa=EFG at $2 mm' --y 'x0_sigma_xx_continuum_MPa=continuum at $2 mm' \
	  --y 'x1_sigma_xx_MPa=EFG at $3 mm' --y 'x1_sigma_xx_continuum_MPa=continuum at $3 mm' --style lines \
	  --x-label 't [us]' --y-label 'stress sigma xx [MPa]' --key 'inside bottom right' \
	  --title 'Linear strip, $(SC_LINEAR_MM) mm: $4 triangle, EFG against the closed form -p(t - x / c_p)' --out $$@ > /dev/null
endef
$(eval $(call SC_LINEAR_FIGURE,long,200,800,40/40 us))
$(eval $(call SC_LINEAR_FIGURE,short,100,400,10/10 us))

# --- Shock steepening: a 400 x 12 mm strip (the tests' is 300 mm long: tests/efg/shock_steepening_test.cpp),
# the sensors at 10-300 mm (the last two past where the smooth law's levels meet, 212 mm, for the
# shock speed), 110 us for the smooth law (its shock, at about 3850 m/s, passes 300 mm at about 90 us
# and meets the free end x = 400 mm at about 115 us; past that the 0.5 mm strip's reflected shock blows
# up the undamped run) and 140 us for the Y-function (its shock, at about 2600 m/s, passes 300 mm at
# about 130 us; the elastic precursor's reflection is back at 300 mm only at 164 us), the step
# re-read every step (a 2 mm strip stiffens faster than every 10th step catches); the bar, material
# and pulse from lab-data. quadratic: the smooth law; hugoniot: the Y-function without Eq. (27) (the
# paper's Section 4.2 test); hugoniot-unloading: with it (lab-data's unloading = 1).
SC_SENSORS := $(foreach x,10 30 50 100 150 200 250 300,--sensor-mm $x)
SC_PROFILE_TIMES := $(foreach t,20 40 60 80 100,--profile-us $t)
sc_duration_quadratic := 110
sc_duration_hugoniot := 140
sc_duration_hugoniot-unloading := 140
sc_inputs_quadratic := $(SC_BAR) $(SC_SMOOTH)
sc_args_quadratic := --law quadratic --from $(SC_BAR) --from $(SC_SMOOTH)
sc_inputs_hugoniot := $(SC_BAR) $(SC_HUGONIOT)
sc_args_hugoniot := --law hugoniot --from $(SC_BAR) --from $(SC_HUGONIOT) --unloading 0
sc_inputs_hugoniot-unloading := $(SC_BAR) $(SC_HUGONIOT)
sc_args_hugoniot-unloading := --law hugoniot --from $(SC_BAR) --from $(SC_HUGONIOT)
# The runs: each law at the study's spacing SC_SHOCK_MM (shock-LAW.json, its profiles and fronts:
# the figures' and the report's), the two stiffening laws at the other spacings too (shock-LAW-Hmm.json).
SC_SHOCK_OTHER_MM := $(filter-out $(SC_SHOCK_MM),$(SC_SHOCK_SPACINGS))
SC_SHOCK_LAWS := quadratic hugoniot hugoniot-unloading

define SC_SHOCK
$(SC_OUT)/shock-$1$3.json $(SC_OUT)/profiles-$1$3.csv $(SC_OUT)/fronts-$1$3.csv &: $(sc_inputs_$1) $(BIN)/mw-efg
	@mkdir -p $$(@D)
	$(BIN)/mw-efg wave $(sc_args_$1) --length-mm 400 --width-mm 12 --spacing-mm $2 --duration-us $(sc_duration_$1) --stiffness-check 1 $(SC_VISCOSITY) \
	  $(SC_SENSORS) --profiles $(SC_OUT)/profiles-$1$3.csv $(SC_PROFILE_TIMES) --fronts $(SC_OUT)/fronts-$1$3.csv \
	  --out $(SC_OUT)/shock-$1$3.json > /dev/null
endef
$(foreach l,$(SC_SHOCK_LAWS),$(eval $(call SC_SHOCK,$l,$(SC_SHOCK_MM),)))
$(foreach h,$(SC_SHOCK_OTHER_MM),$(eval $(call SC_SHOCK,quadratic,$h,-$(h)mm))$(eval $(call SC_SHOCK,hugoniot,$h,-$(h)mm)))

# One row per run: law and spacing, the main runs first.
SC_SHOCK_ROWS := $(foreach l,$(SC_SHOCK_LAWS),$l,$(SC_SHOCK_MM)=$(SC_OUT)/shock-$l.json) \
  $(foreach h,$(SC_SHOCK_OTHER_MM),quadratic,$h=$(SC_OUT)/shock-quadratic-$(h)mm.json hugoniot,$h=$(SC_OUT)/shock-hugoniot-$(h)mm.json)
$(SC_OUT)/shock.csv: $(foreach r,$(SC_SHOCK_ROWS),$(lastword $(subst =, ,$r))) $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name law,spacing_mm $(addprefix --row ,$(SC_SHOCK_ROWS)) \
	  --column formation_distance_mm=characteristics.formation_distance_mm --column formation_time_us=characteristics.formation_time_us \
	  --column p_lo_MPa=characteristics.p_lo_MPa --column p_hi_MPa=characteristics.p_hi_MPa \
	  --column meet_distance_mm=characteristics.meet_distance_mm \
	  --column measured_meet_distance_mm=characteristics.measured_meet_distance_mm \
	  --column meet_time_us=characteristics.meet_time_us --column measured_meet_time_us=characteristics.measured_meet_time_us \
	  --column jump_speed_m_s=characteristics.jump_speed_m_s --column shock_speed_m_s=characteristics.shock_speed_m_s \
	  --column bar_speed_m_s=characteristics.bar_1d_speed_m_s --column shock_speed_over_bar=characteristics.shock_speed_over_bar \
	  --column shock_speed_over_fixed_level_jump=characteristics.shock_speed_over_jump --column max_modulus_scale --column steps \
	  --column energy_drift --column wall_s \
	  --round formation_distance_mm=2 --round formation_time_us=2 --round p_lo_MPa=1 --round p_hi_MPa=1 \
	  --round meet_distance_mm=1 --round measured_meet_distance_mm=1 --round meet_time_us=2 --round measured_meet_time_us=2 \
	  --round jump_speed_m_s=1 --round shock_speed_m_s=1 --round bar_speed_m_s=1 --round shock_speed_over_bar=4 --round shock_speed_over_fixed_level_jump=4 --round max_modulus_scale=3 \
	  --round wall_s=3 --csv $@ > /dev/null

define SC_PROFILE_FIGURE
$(SC_OUT)/profiles-$1.png: $(SC_OUT)/profiles-$1.csv $(BIN)/mw-table
	$(BIN)/mw-table plot $(SC_OUT)/profiles-$1.csv --x x_mm \
	  $(foreach t,20 40 60 80 100,--y 'p_MPa_at_$(t)us=t = $t us') --style lines --x-label 'x [mm]' \
	  --y-label 'compression, -sigma xx on the centre line [MPa]' --key 'inside top right' \
	  --title '$2, $(SC_SHOCK_MM) mm strip: the front steepens (cf. the paper'"'"'s Fig. 11)' \
	  --out $$@ > /dev/null
endef
$(eval $(call SC_PROFILE_FIGURE,quadratic,Smooth law p = M s (1 + beta s)))
$(eval $(call SC_PROFILE_FIGURE,hugoniot,Y-function without Eq. (27)))

# --- The blasted slab: 60 us (the wave crosses the 100 mm thickness in 33 us and returns as tension
# from the free bottom), one thread (the runs' wall times are a column). The study's spacing gets the
# crack and energy CSVs, the figure and the ParaView series; the others only their summaries.
SC_SLAB := $(SC_LAB)/blast-slab.toml
# the resolved step: 0.25 us holds the 17 us pulse in 70 steps (docs/efg.md, "The slab's time step, its spacing and its cost")
SC_SLAB_ARGS := --from $(SC_SLAB) --from $(SC_HUGONIOT) --duration-us 60 --dt-us 0.25 --threads 1 $(SC_VISCOSITY)
$(SC_OUT)/slab.json $(SC_OUT)/slab-cracks.csv $(SC_OUT)/slab-energy.csv $(SC_OUT)/slab.png &: $(SC_SLAB) $(SC_HUGONIOT) $(BIN)/mw-efg
	@mkdir -p $(@D)
	$(BIN)/mw-efg blast $(SC_SLAB_ARGS) --spacing-mm $(SC_SLAB_MM) --cracks $(SC_OUT)/slab-cracks.csv \
	  --energy $(SC_OUT)/slab-energy.csv --plot $(SC_OUT)/slab.png --snapshots $(SC_OUT)/slab-vtk --snapshot-stride 2 --out $(SC_OUT)/slab.json > /dev/null
define SC_SLAB_RUN
$(SC_OUT)/slab-$1mm.json: $(SC_SLAB) $(SC_HUGONIOT) $(BIN)/mw-efg
	@mkdir -p $$(@D)
	$(BIN)/mw-efg blast $(SC_SLAB_ARGS) --spacing-mm $1 --out $$@ > /dev/null
endef
$(foreach h,$(SC_SLAB_SPACINGS),$(eval $(call SC_SLAB_RUN,$h)))

$(SC_OUT)/slab-spacing.csv: $(foreach h,$(SC_SLAB_SPACINGS),$(SC_OUT)/slab-$(h)mm.json) $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name spacing_mm $(foreach h,$(SC_SLAB_SPACINGS),--row $h=$(SC_OUT)/slab-$(h)mm.json) \
	  --column nodes --column gauss_points --column crack_count --column longest_crack_mm --column total_crack_length_mm \
	  --column max_crack_speed_m_s --column refused_changes --column compacted_depth_mm=compacted.depth_mm \
	  --column compacted_width_mm=compacted.width_mm --column compacted_joined_depth_mm=compacted.joined_depth_mm \
	  --column compacted_points=compacted.points \
	  --column max_compression_eps_v=compacted.max_compression_eps_v \
	  --column crater_depth_mm=crater.depth_mm --column crater_width_mm=crater.width_mm --column crater_area_cm2=crater.area_cm2 \
	  --column crater_fragments=crater.fragments --column spall_fragments=crater.spall_fragments --column open_segments=crater.open_segments \
	  --column balance_over_W_ext=energy.balance_over_W_ext --column energy_jump_J=energy.energy_jump_J \
	  --column external_work_J=energy.external_work_J --column viscous_work_J=energy.viscous_J --column run_drift=energy.run_drift --column steps \
	  --column wall_s=cost.wall_s \
	  --round longest_crack_mm=1 --round total_crack_length_mm=1 --round max_crack_speed_m_s=1 --round compacted_depth_mm=1 --round compacted_joined_depth_mm=1 \
	  --round compacted_width_mm=1 --round crater_depth_mm=1 --round crater_width_mm=1 --round crater_area_cm2=2 --round max_compression_eps_v=4 --round balance_over_W_ext=3 --round energy_jump_J=0 \
	  --round external_work_J=0 --round viscous_work_J=0 --round wall_s=2 --csv $@ > /dev/null

SC_TABLES := bending strip-linear strip-fem shock slab-spacing
SC_FIGURES := load-deflection.png strip-long.png strip-short.png strip-hann.png profiles-quadratic.png profiles-hugoniot.png slab.png

.PHONY: shock-concrete shock-concrete-summary
shock-concrete: $(foreach t,$(SC_TABLES),$(SC_OUT)/$t.csv) $(addprefix $(SC_OUT)/,$(SC_FIGURES)) \
    $(SC_OUT)/fronts-quadratic.csv $(SC_OUT)/fronts-hugoniot.csv $(SC_OUT)/slab.json
# The schedule (top Makefile, "The order of the runs"): nothing here needs the cube's chain.
PIPELINE_BESIDE += shock-concrete

# Printing what is already made runs no tool.
shock-concrete-summary: shock-concrete
	@echo
	@echo "== Shock concrete: three-point bending, linear strip, shock steepening, blasted slab ($(SC_OUT)) =="
	@$(foreach t,$(SC_TABLES),echo; echo "$t:"; grep -v '^#' $(SC_OUT)/$t.csv | column -s, -t;)
