#!/usr/bin/env python3
"""The rate study's table (run-small.sh): side | seed | rate [mm/s] | peak [MPa] | against 2.5 mm/s |
E_glob [GPa] | nu_glob | steps | wall [s] | broken bonds at peak | inertial number (max)."""
import json,glob,re,sys
rows={}
for f in sorted(glob.glob('results/rate-study/*mm/s*-v*.json')):
    m=re.search(r'/(\d+)mm/s(\d+)-v([\d.]+)\.json',f); side,seed,v=m.group(1),int(m.group(2)),float(m.group(3))
    d=json.load(open(f)); t=d['test']
    rows[(side,seed,v)]=(t['peak_stress_MPa'],t['E_glob_GPa'],t['nu_glob'],d['steps'],d['wall_s'],t['broken_bonds_at_peak'],t['inertial_number_max'])
for k in sorted(rows):
    side,seed,v=k; p=rows[k]; ref=rows.get((side,seed,2.5))
    dev='%+.2f %%'%(100*(p[0]/ref[0]-1)) if ref else ''
    print(f"{side} mm | {seed} | {v:g} | {p[0]:.2f} | {dev} | {p[1]:.3f} | {p[2]:.4f} | {p[3]:,} | {p[4]:.0f} | {p[5]} | {p[6]:.1e}")
