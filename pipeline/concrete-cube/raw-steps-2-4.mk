# Included by pipeline/concrete-cube/study.mk (its variables CC_*), in the flowchart's order.
# ==== Lab raw data (issue 7): steps 2-4 from raw files =========================
# The synthetic raw set in lab-data/concrete-cube/raw (source: synthetic, made by
# its generate.sh from the truth beside each file) run through the raw-data
# tools: porosity from the micro-CT stack and the face images (step 2), times of
# flight picked on the UPV waveforms (step 3), E_st, sigma_max and the crosshead
# multiplier from the load-frame records (step 4). Outputs: results/concrete-cube/raw-*.
#   make concrete-cube-raw            the results
#   make concrete-cube-raw-summary    and the comparison with the paper's values they were made from

CC_RAW := $(CC_LAB)/raw

# Step 2: micro-CT stack (pores dark, one Otsu threshold for the stack, specimen ROI).
$(CC_OUT)/raw-porosity-ct.json $(CC_OUT)/raw-porosity-ct-slices.csv $(CC_OUT)/raw-porosity-ct-overlay.png \
    $(CC_OUT)/raw-porosity-ct-profile.png &: $(CC_RAW)/ct-stack.tif $(CC_RAW)/ct-truth.toml $(BIN)/mw-porosity
	@mkdir -p $(@D)
	$(BIN)/mw-porosity --kind ct $(CC_RAW)/ct-stack.tif --roi 6,6,96,96 --from $(CC_RAW)/ct-truth.toml \
	  --csv $(CC_OUT)/raw-porosity-ct-slices.csv --overlay $(CC_OUT)/raw-porosity-ct-overlay.png \
	  --overlay-max-images 9 --profile-plot $(CC_OUT)/raw-porosity-ct-profile.png \
	  --out $(CC_OUT)/raw-porosity-ct.json > /dev/null

# Step 2: microscope images of the faces (plaster-filled pores bright, Otsu per image).
CC_RAW_FACES := $(CC_RAW)/face-1.png $(CC_RAW)/face-2.png $(CC_RAW)/face-3.png
$(CC_OUT)/raw-porosity-faces.json $(CC_OUT)/raw-porosity-faces.csv $(CC_OUT)/raw-porosity-faces-overlay.png &: \
    $(CC_RAW_FACES) $(BIN)/mw-porosity
	@mkdir -p $(@D)
	$(BIN)/mw-porosity --kind face $(CC_RAW_FACES) --csv $(CC_OUT)/raw-porosity-faces.csv \
	  --overlay $(CC_OUT)/raw-porosity-faces-overlay.png --out $(CC_OUT)/raw-porosity-faces.json > /dev/null

# Step 3: t_p and t_s picked on the P and S waveforms (AIC, low-pass at 4x the
# transducer frequencies, the 2 us transducer delay of upv-truth.toml subtracted).
$(CC_OUT)/raw-upv.json $(CC_OUT)/raw-upv-fig7.png &: $(CC_RAW)/upv-p.csv $(CC_RAW)/upv-s.csv \
    $(CC_RAW)/upv-truth.toml $(CC_OUT)/density.json $(BIN)/mw-upv
	$(BIN)/mw-upv --from $(CC_OUT)/density.json --from $(CC_RAW)/upv-truth.toml \
	  --p-wave $(CC_RAW)/upv-p.csv --s-wave $(CC_RAW)/upv-s.csv --lowpass-kHz 216 --s-lowpass-kHz 160 \
	  --plot $(CC_OUT)/raw-upv-fig7.png --title 'Synthetic UPV records (lab-data/concrete-cube/raw)' \
	  --out $(CC_OUT)/raw-upv.json > /dev/null

# Step 4: cyclic test (EN 12390-13 method B) and test to failure of the 150 mm cube.
$(CC_OUT)/raw-compress.json $(CC_OUT)/raw-compress-cycles.csv $(CC_OUT)/raw-compress-cyclic.csv \
    $(CC_OUT)/raw-compress-failure.csv $(CC_OUT)/raw-compress-fig5.png &: \
    $(CC_RAW)/cyclic-test.csv $(CC_RAW)/failure-test.csv $(CC_RAW)/compression-truth.toml $(BIN)/mw-compress
	@mkdir -p $(@D)
	$(BIN)/mw-compress --cyclic $(CC_RAW)/cyclic-test.csv --failure $(CC_RAW)/failure-test.csv \
	  --from $(CC_RAW)/compression-truth.toml --cycles-csv $(CC_OUT)/raw-compress-cycles.csv \
	  --cyclic-curve $(CC_OUT)/raw-compress-cyclic.csv --failure-curve $(CC_OUT)/raw-compress-failure.csv \
	  --plot $(CC_OUT)/raw-compress-fig5.png --title 'Synthetic compression tests (lab-data/concrete-cube/raw)' \
	  --out $(CC_OUT)/raw-compress.json > /dev/null

# Beside the paper's values the synthetic set was made from.
$(CC_OUT)/raw-porosity-vs-paper.txt $(CC_OUT)/raw-porosity-ct-vs-paper.csv \
    $(CC_OUT)/raw-porosity-faces-vs-paper.csv &: $(CC_OUT)/raw-porosity-ct.json $(CC_OUT)/raw-porosity-faces.json \
    $(CC_LAB)/porosity.toml $(BIN)/mw-compare
	$(BIN)/mw-compare --ours $(CC_OUT)/raw-porosity-ct.json --paper $(CC_LAB)/porosity.toml \
	  --title "Step 2 from the synthetic micro-CT stack (truth: lab-data/concrete-cube/raw/ct-truth.toml)" \
	  --csv $(CC_OUT)/raw-porosity-ct-vs-paper.csv --text $(CC_OUT)/raw-porosity-ct-vs-paper.txt > /dev/null
	$(BIN)/mw-compare --ours $(CC_OUT)/raw-porosity-faces.json --paper $(CC_LAB)/porosity.toml \
	  --title "Step 2 from the synthetic face images (truth: lab-data/concrete-cube/raw/faces-truth.toml)" \
	  --csv $(CC_OUT)/raw-porosity-faces-vs-paper.csv --text $(CC_OUT)/raw-porosity-faces-vs-paper.txt > /dev/null
	cat $(CC_OUT)/raw-porosity-ct-vs-paper.txt $(CC_OUT)/raw-porosity-faces-vs-paper.txt > $(CC_OUT)/raw-porosity-vs-paper.txt

$(CC_OUT)/raw-upv-vs-paper.txt $(CC_OUT)/raw-upv-vs-paper.csv &: $(CC_OUT)/raw-upv.json $(CC_LAB)/upv.toml $(BIN)/mw-compare
	$(BIN)/mw-compare --ours $(CC_OUT)/raw-upv.json --paper $(CC_LAB)/upv.toml \
	  --title "Step 3 from the synthetic UPV waveforms: picked times of flight" \
	  --csv $(CC_OUT)/raw-upv-vs-paper.csv --text $(CC_OUT)/raw-upv-vs-paper.txt > /dev/null

$(CC_OUT)/raw-compress-vs-paper.txt $(CC_OUT)/raw-compress-vs-paper.csv &: $(CC_OUT)/raw-compress.json $(CC_LAB)/static-test.toml $(BIN)/mw-compare
	$(BIN)/mw-compare --ours $(CC_OUT)/raw-compress.json --paper $(CC_LAB)/static-test.toml \
	  --title "Step 4 from the synthetic load-frame records (truth: lab-data/concrete-cube/raw/compression-truth.toml)" \
	  --csv $(CC_OUT)/raw-compress-vs-paper.csv --text $(CC_OUT)/raw-compress-vs-paper.txt > /dev/null

CC_RAW_RESULTS := $(CC_OUT)/raw-porosity-ct.json $(CC_OUT)/raw-porosity-faces.json $(CC_OUT)/raw-upv.json \
                  $(CC_OUT)/raw-compress.json $(CC_OUT)/raw-porosity-vs-paper.txt $(CC_OUT)/raw-upv-vs-paper.txt \
                  $(CC_OUT)/raw-compress-vs-paper.txt

.PHONY: concrete-cube-raw concrete-cube-raw-summary
concrete-cube-raw: $(CC_RAW_RESULTS)

concrete-cube-raw-summary: concrete-cube-raw
	@echo
	@echo "== Concrete cube from raw lab data (synthetic set, results/concrete-cube/raw-*) =="
	@cat $(CC_OUT)/raw-porosity-vs-paper.txt
	@echo
	@cat $(CC_OUT)/raw-upv-vs-paper.txt
	@echo
	@cat $(CC_OUT)/raw-compress-vs-paper.txt
