# Concrete cube, flowchart steps 1 and 3 from the printed values: density, UPV moduli, Table 1.
# Included by study.mk (its variables CC_*).

# Step 1: density of the 150 mm cube.
$(CC_OUT)/density.json: $(CC_LAB)/specimen.toml $(BIN)/mw-specimen
	@mkdir -p $(@D)
	$(BIN)/mw-specimen --from $(CC_LAB)/specimen.toml --out $@ > /dev/null

# Step 3, dynamic route: v_p, v_s, nu_d (Eq. 10), E_d (Eq. 9).
$(CC_OUT)/upv.json: $(CC_LAB)/upv.toml $(CC_OUT)/density.json $(BIN)/mw-upv
	$(BIN)/mw-upv --from $(CC_OUT)/density.json --from $(CC_LAB)/upv.toml --out $@ > /dev/null

# Step 3: Table 1 from the E_d computed exactly from the paper's inputs...
$(CC_OUT)/table1.csv $(CC_OUT)/table1.json &: $(CC_OUT)/upv.json $(CC_LAB)/static-test.toml $(BIN)/mw-estatic
	$(BIN)/mw-estatic --from $(CC_OUT)/upv.json --from $(CC_LAB)/static-test.toml \
	  --table $(CC_OUT)/table1.csv --out $(CC_OUT)/table1.json > /dev/null

# ...and from the rounded E_d = 36.68 GPa the paper printed and used.
$(CC_OUT)/table1-printed-Ed.csv $(CC_OUT)/table1-printed-Ed.json &: $(CC_OUT)/density.json \
    $(CC_LAB)/paper/printed-results.toml $(CC_LAB)/static-test.toml $(BIN)/mw-estatic
	$(BIN)/mw-estatic --from $(CC_OUT)/density.json --from $(CC_LAB)/paper/printed-results.toml \
	  --from $(CC_LAB)/static-test.toml \
	  --table $(CC_OUT)/table1-printed-Ed.csv --out $(CC_OUT)/table1-printed-Ed.json > /dev/null

# Beside the paper's printed values.
$(CC_OUT)/density-vs-paper.txt $(CC_OUT)/density-vs-paper.csv &: $(CC_OUT)/density.json $(CC_LAB)/paper/printed-results.toml $(BIN)/mw-compare
	$(BIN)/mw-compare --ours $(CC_OUT)/density.json --paper $(CC_LAB)/paper/printed-results.toml \
	  --title "Step 1: density (the mass is derived from the printed density, so this checks the arithmetic)" \
	  --csv $(CC_OUT)/density-vs-paper.csv --text $(CC_OUT)/density-vs-paper.txt > /dev/null

$(CC_OUT)/upv-vs-paper.txt $(CC_OUT)/upv-vs-paper.csv &: $(CC_OUT)/upv.json $(CC_LAB)/paper/printed-results.toml $(BIN)/mw-compare
	$(BIN)/mw-compare --ours $(CC_OUT)/upv.json --paper $(CC_LAB)/paper/printed-results.toml \
	  --title "Step 3: dynamic moduli from t_p, t_s, path and density (Eqs. 9-10) vs the paper" \
	  --csv $(CC_OUT)/upv-vs-paper.csv --text $(CC_OUT)/upv-vs-paper.txt > /dev/null

$(CC_OUT)/table1-vs-paper.txt $(CC_OUT)/table1-vs-paper.csv &: $(CC_OUT)/table1.csv $(CC_LAB)/paper/table1.csv $(BIN)/mw-compare
	$(BIN)/mw-compare --ours $(CC_OUT)/table1.csv --paper $(CC_LAB)/paper/table1.csv --key method \
	  --title "Table 1 from the exact E_d (36.671 GPa) vs the paper's Table 1" \
	  --csv $(CC_OUT)/table1-vs-paper.csv --text $(CC_OUT)/table1-vs-paper.txt > /dev/null

$(CC_OUT)/table1-printed-Ed-vs-paper.txt $(CC_OUT)/table1-printed-Ed-vs-paper.csv &: $(CC_OUT)/table1-printed-Ed.csv $(CC_LAB)/paper/table1.csv $(BIN)/mw-compare
	$(BIN)/mw-compare --ours $(CC_OUT)/table1-printed-Ed.csv --paper $(CC_LAB)/paper/table1.csv --key method \
	  --title "Table 1 from the paper's printed E_d (36.68 GPa) vs the paper's Table 1" \
	  --csv $(CC_OUT)/table1-printed-Ed-vs-paper.csv --text $(CC_OUT)/table1-printed-Ed-vs-paper.txt > /dev/null

CC_RESULTS := $(CC_OUT)/density.json $(CC_OUT)/upv.json $(CC_OUT)/table1.csv $(CC_OUT)/table1-printed-Ed.csv \
              $(CC_OUT)/density-vs-paper.txt $(CC_OUT)/upv-vs-paper.txt $(CC_OUT)/table1-vs-paper.txt $(CC_OUT)/table1-printed-Ed-vs-paper.txt

.PHONY: concrete-cube concrete-cube-summary
concrete-cube: $(CC_RESULTS)

# Printing what is already made runs no tool: a second `make reproduce` shows
# the same tables and re-runs nothing.
concrete-cube-summary: concrete-cube
	@echo
	@echo "== Concrete cube: steps 1 and 3 (results/concrete-cube) =="
	@cat $(CC_OUT)/density-vs-paper.txt
	@echo
	@cat $(CC_OUT)/upv-vs-paper.txt
	@echo
	@cat $(CC_OUT)/table1-vs-paper.txt
	@echo
	@cat $(CC_OUT)/table1-printed-Ed-vs-paper.txt
	@echo
	@cat $(CC_NOTES)/table1-note.txt
