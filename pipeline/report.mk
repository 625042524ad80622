# The report: $(REPORT_DIR)/index.html from pipeline/report.toml (its title and opening text)
# and each study's pipeline/<study>/report.toml (its sections, in the order of STUDIES), with
# provenance from $(MESOWAVE_DB). Its prerequisites are read from the specs, so a file is
# listed once. The quick tree's report reads the same specs with their files in $(RESULTS)/
# (copies made by sed, so the two cannot drift apart).
REPORT_SPECS := pipeline/report.toml $(wildcard $(foreach study,$(STUDIES),pipeline/$(study)/report.toml))
REPORT_ITEMS := $(patsubst results/%,$(RESULTS)/%,\
  $(shell sed -n 's/^\(table\|figure\|note\) = "\(.*\)"/\2/p' $(REPORT_SPECS)))

ifeq ($(QUICK),1)
REPORT_TREE_SPECS := $(patsubst pipeline/%,$(RESULTS)/%,$(REPORT_SPECS))
$(RESULTS)/report.toml: pipeline/report.toml
	@mkdir -p $(@D)
	sed -e '0,/^title = "\(.*\)"/s//title = "\1 - quick look (small models, short records: make reproduce-quick)"/' $< > $@
$(RESULTS)/%/report.toml: pipeline/%/report.toml
	@mkdir -p $(@D)
	sed -e 's#^\(table\|figure\|note\) = "results/#\1 = "$(RESULTS)/#' $< > $@
else
REPORT_TREE_SPECS := $(REPORT_SPECS)
endif

$(REPORT_DIR)/index.html: $(REPORT_TREE_SPECS) $(REPORT_ITEMS) $(BIN)/mw-report
	$(BIN)/mw-report $(addprefix --spec ,$(REPORT_TREE_SPECS)) --out-dir $(REPORT_DIR)

.PHONY: report
report: $(REPORT_DIR)/index.html

# Renders the page in headless Chromium: every figure decoded, every table there.
.PHONY: check-report
check-report: $(REPORT_DIR)/index.html
	@scripts/check-report $(REPORT_DIR)/index.html \
	  $$(cat $(REPORT_SPECS) | grep -c '^table = ') $$(cat $(REPORT_SPECS) | grep -c '^figure = ')
