#!/bin/bash
# mw-upv's S picks on the DEM's 1/3-scale records: AIC after P (the current chain) and the matched filter
cd "$(dirname "$0")/../../../spick-runs"   # run from anywhere; the records in spick-runs/ (dem-runs.sh)
B=../build/bin; D=../results/concrete-cube/density.json
REC="--noise-window-us 0,1 --amplitude-column R [m/s]"
W="--s-wavelet-burst-kHz 120,2 --s-wavelet-derivative"
for c in static dynamic; do
  $B/mw-upv --path-mm 50 --p-wave p-$c.csv --picker threshold --locate-relative 0.02 --noise-window-us 0,1 --amplitude-column 'R [m/s]' --out tp-$c.json > /dev/null
  $B/mw-upv --from tp-$c.json --from $D --s-wave s-$c.csv --picker aic --noise-window-us 0,1 --amplitude-column 'R [m/s]' --out aic-$c.json > /dev/null
  $B/mw-upv --from tp-$c.json --from $D --s-wave s-$c.csv --picker aic --noise-window-us 0,1 --amplitude-column 'R [m/s]' $W --plot xcorr-$c.png --title "1/3-scale DEM cube, calibration '$c': S record, matched filter (xcorr) after P" --out xcorr-$c.json > /dev/null
  for seed in 1 2 3 4 5 6 7 8 9 10; do
    N="--picker aic --add-noise-snr-dB 40 --add-noise-seed $seed"
    $B/mw-upv --path-mm 50 --p-wave p-$c.csv $N --noise-window-us 0,1 --amplitude-column 'R [m/s]' --out tp-noisy-$c-$seed.json > /dev/null
    $B/mw-upv --from tp-noisy-$c-$seed.json --from $D --s-wave s-$c.csv $N --noise-window-us 0,1 --amplitude-column 'R [m/s]' --out aic-noisy-$c-$seed.json > /dev/null
    $B/mw-upv --from tp-noisy-$c-$seed.json --from $D --s-wave s-$c.csv $N --noise-window-us 0,1 --amplitude-column 'R [m/s]' $W --out xcorr-noisy-$c-$seed.json > /dev/null
  done
done
python3 - <<'PY'
import json, statistics as st
ref = {'static': 21.23, 'dynamic': 18.37}
for c in ['static', 'dynamic']:
    a = json.load(open('aic-%s.json' % c)); x = json.load(open('xcorr-%s.json' % c))
    print(c, 'noise-free: t_p %.3f  AIC t_s %.3f  xcorr t_s %.3f (coef %.3f, stated bias %s us)  continuum %.2f' % (
        x['t_p_us'], a['t_s_us'], x['t_s_us'], x['t_s_pick_xcorr_coefficient'], x.get('t_s_pick_bias_us'), ref[c]))
    import os
    ok = [s for s in range(1, 11) if os.path.exists('aic-noisy-%s-%d.json' % (c, s)) and os.path.exists('xcorr-noisy-%s-%d.json' % (c, s))]
    print(c, '40 dB: seeds picked', ok, '(the others refused by the 1 us noise window check)')
    A = [json.load(open('aic-noisy-%s-%d.json' % (c, s)))['t_s_us'] for s in ok]
    X = [json.load(open('xcorr-noisy-%s-%d.json' % (c, s))) for s in ok]
    xs = [j['t_s_us'] for j in X]
    print(c, '40 dB: AIC t_s median %.3f [%.3f..%.3f]  xcorr median %.3f [%.3f..%.3f]  seed1 xcorr %.3f stated bias %.3f us, warnings %s' % (
        st.median(A), min(A), max(A), st.median(xs), min(xs), max(xs), xs[0], X[0]['t_s_pick_bias_us'], sum(len(j['warnings']) for j in X)))
    print('   xcorr - continuum: noise-free %+.3f us (%+.3f periods), 40 dB median %+.3f us; AIC noise-free %+.3f us' % (
        x['t_s_us'] - ref[c], (x['t_s_us'] - ref[c]) * 0.12, st.median(xs) - ref[c], a['t_s_us'] - ref[c]))
    print('   v_s xcorr %.0f m/s, nu_d %.4f, E_d %.2f GPa (noise-free)' % (x['v_s_m_s'], x['nu_d'], x['E_d_GPa']))
PY
