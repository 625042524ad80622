#!/usr/bin/env bash
# Regenerates the synthetic raw lab data of this folder (source: synthetic).
# Every file is made by mw-synth from the ground truth written beside it
# (*-truth.toml); the same seeds give the same bytes.
#
#   lab-data/concrete-cube/raw/generate.sh [BIN]     (BIN defaults to build/bin)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
bin=${1:-$here/../../../build/bin}
cd "$here"

# Step 2: a micro-CT stack (32 slices, 50 um voxels, spherical voids, dark) and
# three microscope face images (10 um pixels, irregular plaster-filled voids,
# bright), both at a target pore fraction of 7 % (concrete paper, Section 3.1).
"$bin/mw-synth" ct --stack ct-stack.tif --truth ct-truth.toml --porosity-pct 7 --pore-shape sphere --seed 7
"$bin/mw-synth" faces --prefix face --count 3 --truth faces-truth.toml --porosity-pct 7 --pore-shape irregular --seed 11

# Steps 3-4: cyclic test (EN 12390-13 method B as in Section 3.2: 0.3 MPa/s to
# 16.7 MPa, 20 s holds, two 75 mm extensometers) and test to failure (0.6 MPa/s)
# of a 150 mm cube with E = 27.42 GPa, f_c = 66.0 MPa, crosshead multiplier 1/4.5.
"$bin/mw-synth" compression --cyclic cyclic-test.csv --failure failure-test.csv --truth compression-truth.toml \
  --E-GPa 27.42 --strength-MPa 66.0 --upper-stress-MPa 16.7 --lower-stress-MPa 0.5 \
  --cyclic-stress-rate-MPa-s 0.3 --failure-stress-rate-MPa-s 0.6 --hold-s 20 --side-mm 150 \
  --gauge-length-mm 75 --crosshead-multiplier 0.2222222222222222 --seed 3

# Step 3: UPV waveforms through the 150 mm cube (P 54 kHz, S 40 kHz transducers,
# Section 3.2) with t_p = 35 us, t_s = 55.1 us, a 2 us transducer + couplant
# delay, 6 dB attenuation and 20 dB SNR, sampled at 10 MHz with 50 us pre-trigger.
"$bin/mw-synth" upv --p-wave upv-p.csv --s-wave upv-s.csv --truth upv-truth.toml \
  --path-mm 150 --t-p-us 35 --t-s-us 55.1 --p-transducer-frequency-kHz 54 --s-transducer-frequency-kHz 40 \
  --delay-us 2 --attenuation-dB 6 --snr-dB 20 --pretrigger-us 50 --duration-us 250 --dt-us 0.1 --seed 5
