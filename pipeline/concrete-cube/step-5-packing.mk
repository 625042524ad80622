# Included by pipeline/concrete-cube/study.mk (its variables CC_*), in the flowchart's order.
# ==== Step 5: the DEM model's packing (Section 3.3) ============================
# The 50 mm cube of porosity.toml at p = 7 %, d = 1.6-2.0 mm and C_f = 1.1
# (dem-packing.toml), particle density from step 1 so that the model weighs what
# the specimen weighs; beside the paper's "40,000 elements, almost 250,000
# contacts". The quick tree packs a 20 mm cube of the same material.

ifeq ($(QUICK),1)
CC_SIDE_MM := 20
CC_PACK_SIZE := --cube-side-mm $(CC_SIDE_MM)
else
CC_SIDE_MM :=
CC_PACK_SIZE :=
endif

$(CC_OUT)/packing.h5 $(CC_OUT)/packing.json &: $(CC_LAB)/porosity.toml $(CC_LAB)/dem-packing.toml \
    $(CC_OUT)/density.json $(BIN)/mw-pack
	$(BIN)/mw-pack box --from $(CC_LAB)/porosity.toml --from $(CC_LAB)/dem-packing.toml --from $(CC_OUT)/density.json \
	  $(CC_PACK_SIZE) --quiet --packing $(CC_OUT)/packing.h5 --out $(CC_OUT)/packing.json > /dev/null

$(CC_OUT)/packing-vs-paper.txt $(CC_OUT)/packing-vs-paper.csv &: $(CC_OUT)/packing.json \
    $(CC_LAB)/paper/dem-model.toml $(BIN)/mw-compare
	$(BIN)/mw-compare --ours $(CC_OUT)/packing.json --paper $(CC_LAB)/paper/dem-model.toml \
	  --title "Step 5: the packing (spheres; bonds = pairs within C_f (r_i + r_j)) vs the paper's round numbers" \
	  --csv $(CC_OUT)/packing-vs-paper.csv --text $(CC_OUT)/packing-vs-paper.txt > /dev/null
