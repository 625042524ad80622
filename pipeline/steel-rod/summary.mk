# Included by pipeline/steel-rod/study.mk (its variables SR_*): the tables beside the paper's,
# the paper's findings checked on them, Figure 9, speed against error, and summary.md. Every
# table is an mw-table run whose inputs are the files its numbers come from (as the concrete
# cube's Table 3); summarize.sh only puts the tables' Markdown and the findings between its
# headings.
#
#   make steel-rod-summary        $(SR_OUT)/summary.md, printed

sr_per_f = $(foreach f,$(SR_FREQS),$(SR_OUT)/$1-$(f)kHz.$2)      # one file per frequency
SR_FEM_LABEL := FEM $(SR_FEM_MESH) mm
SR_MEASURED := $(foreach m,$(SR_MODELS),$(SR_OUT)/measure-$m.csv) $(SR_OUT)/measure-fem-$(SR_FEM_MESH)mm.csv
SR_PCCS := $(foreach m,$(SR_MODELS),$(call sr_per_f,pcc-$m,csv))
# The FEM record in ms, as its first run reports it (steps x dt): the experiment's, or the quick
# tree's --duration-ms. A shell expansion for recipes, with the run as a prerequisite.
# (its report is a side file of the run's rule, whose target is the signal file: rules depend on that)
SR_FEM_FIRST_RUN := $(SR_OUT)/fem-$(SR_FEM_MESH)mm-$(firstword $(SR_FREQS))kHz.h5
SR_FEM_FIRST := $(SR_FEM_FIRST_RUN:.h5=.json)
sr_record_ms = $$(jq '.steps * .dt_us / 1000' $(SR_FEM_FIRST))

# Per model and frequency: PCC of sensor S against the FEM (signals and envelopes).
$(SR_OUT)/pcc.csv: $(SR_PCCS) $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name model,f_kHz \
	  $(foreach m,$(SR_MODELS),$(foreach f,$(SR_FREQS),--row $m,$f=$(SR_OUT)/pcc-$m-$(f)kHz.csv)) \
	  --where sensor=S --column pcc_signal --column pcc_envelope --csv $@ > /dev/null

# Table 1's last column: the mean PCC over the frequencies, beside the paper's.
$(SR_OUT)/table1.csv: $(SR_PCCS) $(SR_PAPER)/table1.csv $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name model $(foreach m,$(SR_MODELS),--row $m=$(call sr_list,$(call sr_per_f,pcc-$m,csv))) \
	  --where sensor=S --column 'pcc_vs_fem_signal=mean(pcc_signal)' --column 'pcc_vs_fem_envelope=mean(pcc_envelope)' \
	  --decimals pcc_vs_fem_signal=3 --decimals pcc_vs_fem_envelope=3 \
	  --join $(SR_PAPER)/table1.csv:paper_pcc_vs_fem=PCC_vs_FEM --csv $@ > /dev/null

# Table 2: RSS of the group velocity against Pochhammer-Chree over 50-150 kHz, beside the paper's.
$(SR_OUT)/table2.csv: $(SR_MEASURED) $(SR_PAPER)/table2.csv $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name model --row '$(SR_FEM_LABEL)=$(SR_OUT)/measure-fem-$(SR_FEM_MESH)mm.json' \
	  $(foreach m,$(SR_MODELS),--row $m=$(SR_OUT)/measure-$m.json) --column rss_m2_s2 --column rms_m_s \
	  --round rss_m2_s2=0 --round rms_m_s=1 --join $(SR_PAPER)/table2.csv:paper_rss_m2_s2=RSS_m2_s2 \
	  --join-as '$(SR_FEM_LABEL)=FEM' --csv $@ > /dev/null

# Group velocity by the echo method per frequency: theory, the FEM, every chain (Figure 9's points).
$(SR_OUT)/velocity.csv: $(SR_MEASURED) $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name f_kHz $(foreach f,$(SR_FREQS),--row $f=$(SR_OUT)/measure-fem-$(SR_FEM_MESH)mm.csv) \
	  --where 'f_kHz={f_kHz}' --column theory=theory_c_group_m_s --column '$(SR_FEM_LABEL)=c_group_m_s' \
	  $(foreach m,$(SR_MODELS),--join $(SR_OUT)/measure-$m.csv:$m=c_group_m_s) --csv $@ > /dev/null

# Speed against error: the median wall time of one run (the FEM's record simulated) against the RSS.
# A DEM chain runs once per frequency; the FEM's one run per mesh gives every frequency, so its
# wall_s is the cost of the whole sweep (fem-Hmm-FkHz.json all report that run).
$(SR_OUT)/speed.csv: $(SR_MEASURED) $(foreach h,$(SR_SPEED_MESHES),$(SR_OUT)/measure-fem-$(h)mm.csv) $(BIN)/mw-table
	$(BIN)/mw-table gather --key-name model \
	  $(foreach h,$(SR_FEM_MESH) $(SR_SPEED_MESHES),--row 'FEM $h mm=$(call sr_list,$(call sr_per_f,fem-$(h)mm,json) $(SR_OUT)/measure-fem-$(h)mm.json)') \
	  $(foreach m,$(SR_MODELS),--row 'DEM $m=$(call sr_list,$(call sr_per_f,dem-$m,json) $(SR_OUT)/measure-$m.json)') \
	  --column 'wall_s=median(wall_s)' --column rss_m2_s2 --csv $@ > /dev/null

# The paper's findings, checked on these tables.
$(SR_OUT)/findings.md: $(SR_OUT)/velocity.csv $(SR_OUT)/table1.csv $(SR_OUT)/table2.csv $(BIN)/mw-table
	$(BIN)/mw-table findings --velocity $(SR_OUT)/velocity.csv --table1 $(SR_OUT)/table1.csv \
	  --table2 $(SR_OUT)/table2.csv --fem-column '$(SR_FEM_LABEL)' --out $@ > /dev/null

# The tables as Markdown, for summary.md.
$(SR_OUT)/table1.md: $(SR_OUT)/table1.csv $(BIN)/mw-table
	$(BIN)/mw-table markdown $< --header 'pcc_vs_fem_signal=PCC signals' --header 'pcc_vs_fem_envelope=PCC envelopes' \
	  --header paper_pcc_vs_fem=paper --out $@ > /dev/null
$(SR_OUT)/table2.md: $(SR_OUT)/table2.csv $(BIN)/mw-table
	$(BIN)/mw-table markdown $< --header rss_m2_s2=RSS --header 'rms_m_s=rms [m/s]' --header paper_rss_m2_s2=paper \
	  --out $@ > /dev/null
$(SR_OUT)/velocity.md: $(SR_OUT)/velocity.csv $(BIN)/mw-table
	$(BIN)/mw-table markdown $< --header 'f_kHz=f [kHz]' \
	  --decimals theory=0 --decimals '$(SR_FEM_LABEL)=0' $(foreach m,$(SR_MODELS),--decimals $m=0) --out $@ > /dev/null
$(SR_OUT)/speed.md: $(SR_OUT)/speed.csv $(BIN)/mw-table
	$(BIN)/mw-table markdown $< --header 'wall_s=wall of one run [s] (DEM: one frequency; FEM: every frequency)' --header 'rss_m2_s2=RSS [m^2/s^2]' \
	  --significant wall_s=3 --decimals rss_m2_s2=0 --out $@ > /dev/null

# Figure 9: theory, the FEM and the DEM chains' measured group velocities.
$(SR_OUT)/figure9.png: $(SR_MEASURED) $(SR_EXPERIMENT) $(BIN)/mw-dispersion
	$(BIN)/mw-dispersion theory $(SR_ROD) --f-max-kHz 200 --df-kHz 1 --modes 1 \
	  --overlay '$(SR_FEM_LABEL)=$(SR_OUT)/measure-fem-$(SR_FEM_MESH)mm.csv' \
	  $(foreach m,$(SR_MODELS),--overlay 'DEM $m=$(SR_OUT)/measure-$m.csv') \
	  --plot-f-range-kHz 45,155 --plot-key outside,right,top --plot $@ > /dev/null

# Speed against error: one point per model (its own marker and legend entry), as the cube's.
$(SR_OUT)/speed-error.png: $(SR_OUT)/speed.csv $(SR_FEM_FIRST_RUN) $(BIN)/mw-table
	$(BIN)/mw-table plot $< --x wall_s --y rss_m2_s2 --label-column model --log-x --log-y \
	  --x-label "wall time of one $(sr_record_ms) ms run, one thread [s] (DEM: one frequency; FEM: all $(words $(SR_FREQS)))" \
	  --y-label 'RSS of the group velocity, $(subst $(sr_comma),-,$(SR_BAND_KHZ)) kHz [m^2/s^2]' \
	  --title 'Steel rod: speed against error (DEM chains, mw-fem axisymmetric; this machine)' --out $@ > /dev/null

SR_SUMMARY_PARTS := $(foreach t,table1 table2 velocity speed,$(SR_OUT)/$t.md) $(SR_OUT)/findings.md
# The rod's length is the packings' (the experiment's, or the quick tree's override).
$(SR_OUT)/summary.md: $(SR_SUMMARY_PARTS) $(SR_OUT)/pcc.csv $(SR_OUT)/figure9.png $(SR_OUT)/speed-error.png \
    $(SR_OUT)/packing-1.03R.h5 $(SR_FEM_FIRST_RUN) pipeline/steel-rod/summarize.sh
	pipeline/steel-rod/summarize.sh $(SR_OUT) $(SR_FEM_MESH) $(words $(SR_FREQS)) $(sr_record_ms) $(SR_ALPHA_PER_S) \
	  $$(jq .length_mm $(SR_OUT)/packing-1.03R.json) $(subst $(sr_comma),-,$(SR_BAND_KHZ)) > $@

.PHONY: steel-rod-summary
steel-rod-summary: $(SR_OUT)/summary.md
	@cat $<
