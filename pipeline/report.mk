# The report: report/index.html from the files named in pipeline/report.toml,
# with provenance from $(MESOWAVE_DB). Its prerequisites are read from the spec,
# so a file is listed once.
REPORT_SPEC := pipeline/report.toml
REPORT_ITEMS := $(shell sed -n 's/^\(table\|figure\|note\) = "\(.*\)"/\2/p' $(REPORT_SPEC))

report/index.html: $(REPORT_SPEC) $(REPORT_ITEMS) $(BIN)/mw-report
	$(BIN)/mw-report --spec $(REPORT_SPEC) --out-dir report

.PHONY: report
report: report/index.html

# Renders the page in headless Chromium: every figure decoded, every table there.
.PHONY: check-report
check-report: report/index.html
	@scripts/check-report report/index.html \
	  $$(grep -c '^table = ' $(REPORT_SPEC)) $$(grep -c '^figure = ' $(REPORT_SPEC))
