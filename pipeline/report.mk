# The report: $(REPORT_DIR)/index.html from the files named in pipeline/report.toml,
# with provenance from $(MESOWAVE_DB). Its prerequisites are read from the spec,
# so a file is listed once. The quick tree's report reads the same spec with its
# files in $(RESULTS)/ (a copy made by sed, so the two cannot drift apart).
REPORT_SPEC := pipeline/report.toml
REPORT_ITEMS := $(patsubst results/%,$(RESULTS)/%,\
  $(shell sed -n 's/^\(table\|figure\|note\) = "\(.*\)"/\2/p' $(REPORT_SPEC)))

ifeq ($(QUICK),1)
REPORT_TREE_SPEC := $(RESULTS)/report.toml
$(REPORT_TREE_SPEC): $(REPORT_SPEC)
	@mkdir -p $(@D)
	sed -e 's#^\(table\|figure\|note\) = "results/#\1 = "$(RESULTS)/#' \
	  -e '0,/^title = "\(.*\)"/s//title = "\1 - quick look (small models, short records: make reproduce-quick)"/' $< > $@
else
REPORT_TREE_SPEC := $(REPORT_SPEC)
endif

$(REPORT_DIR)/index.html: $(REPORT_TREE_SPEC) $(REPORT_ITEMS) $(BIN)/mw-report
	$(BIN)/mw-report --spec $(REPORT_TREE_SPEC) --out-dir $(REPORT_DIR)

.PHONY: report
report: $(REPORT_DIR)/index.html

# Renders the page in headless Chromium: every figure decoded, every table there.
.PHONY: check-report
check-report: $(REPORT_DIR)/index.html
	@scripts/check-report $(REPORT_DIR)/index.html \
	  $$(grep -c '^table = ' $(REPORT_SPEC)) $$(grep -c '^figure = ' $(REPORT_SPEC))
