# Yade 2023.02a (Debian `yade`) version of an mw-dem wave scene, for timing and
# for cross-checking mesowave's signals on the very same spheres.
#
#   yade -n -x bench/yade/wave.py SPHERES.txt SCENE_INFO.json OUT.json [STEPS] [THREADS]
#
# SPHERES.txt: the packing as Yade textExt (mw-pack --export-yade), in packing
#   order, so body id = packing index.
# SCENE_INFO.json: `mw-dem info SCENE` output (material, dt, the spheres under
#   each actuator and sensor as packing indices).
# OUT.json: wall time per step and each sensor's velocity samples v_{n+1/2}
#   (the leapfrog velocity after step n, mesowave's velocity signal).
#
# Bonds: eq1_bonds.py (stock Yade 2023.02a does not subtract the initial
# overlap; the shared step 0 makes its bonds match Eq. (1)).
import json
import math
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(sys.argv[0])))  # eq1_bonds.py beside this script
from eq1_bonds import make_eq1_bonds
from yade import ymport

spheres_file, info_file, out_file = sys.argv[1], sys.argv[2], sys.argv[3]
steps = int(sys.argv[4]) if len(sys.argv) > 4 else None
threads = int(sys.argv[5]) if len(sys.argv) > 5 else None
info = json.load(open(info_file))
m = info["material"]

# Bonds are made in one step with cohesion too large to break anything; the
# scene's strengths (Eq. 6) are set on every bond afterwards.
huge = 1e30
strength_T = m["T_Pa"] if m["T_Pa"] is not None else huge
strength_C = m["C_Pa"] if m["C_Pa"] is not None else huge
mat = O.materials.append(CohFrictMat(
    young=m["E_dem_Pa"], poisson=m["nu_dem"], frictionAngle=m["friction_angle_rad"], density=m["density_kg_m3"],
    isCohesive=True, normalCohesion=huge, shearCohesion=huge, momentRotationLaw=False, fragile=True))
ids = O.bodies.append(ymport.textExt(spheres_file, format="x_y_z_r", material=mat))
assert ids == list(range(len(ids))), "the spheres must be the first bodies, in packing order"
assert len(ids) == info["spheres"], "the text file and the scene have different sphere counts"

factor = m["bond_factor"]
collider = InsertionSortCollider([Bo1_Sphere_Aabb(aabbEnlargeFactor=factor)])
ig2 = Ig2_Sphere_Sphere_ScGeom6D(interactionDetectionFactor=factor)
actuator = PyRunner(iterPeriod=1, command="apply_loads()")
O.engines = [
    ForceResetter(),
    collider,
    InteractionLoop([ig2], [Ip2_CohFrictMat_CohFrictMat_CohFrictPhys(setCohesionNow=True)],
                    [Law2_ScGeom6D_CohFrictPhys_CohesionMoment()]),
    actuator,
    NewtonIntegrator(damping=m["damping"]),
    PyRunner(iterPeriod=1, command="record()"),
]
O.dt = info["dt_s"]

recording = False
def apply_loads():
    if not recording:
        return
    t = O.time - t0
    for a in info["actuator_loads"]:
        f, n = a["frequency_hz"], a["cycles"]
        if t < 0 or t > n / f:
            continue
        phase = 2 * math.pi * f * t
        share = a["amplitude_N"] * math.sin(phase) * 0.5 * (1 - math.cos(phase / n)) / len(a["spheres"])
        F = Vector3(*a["direction"]) * share
        for k in a["spheres"]:
            O.forces.addF(k, F)
samples = {s["name"]: [] for s in info["sensor_points"]}
def record():
    if not recording:
        return
    for s in info["sensor_points"]:
        v = Vector3(0, 0, 0)
        for k in s["spheres"]:
            v += O.bodies[k].state.vel
        samples[s["name"]].append((v / len(s["spheres"])).dot(Vector3(*s["component"])))
# Step 0: the bonds of Eq. (1), with nothing moving (eq1_bonds.py).
bonds = make_eq1_bonds(strength_T, strength_C, collider.boundDispatcher.functors[0], ig2)

if threads and O.numThreads != threads:
    print("yade: warning: %d threads requested, running on %d (start yade with -j%d)" % (threads, O.numThreads, threads))
t0 = O.time
recording = True
n = steps if steps else info["steps"]
start = time.time()
O.run(n, True)
wall = time.time() - start
import yade.config
json.dump({"yade_version": yade.config.version, "threads": O.numThreads, "spheres": len(ids), "bonds": bonds, "steps": n,
           "wall_s": wall, "s_per_step": wall / n, "dt_s": O.dt, "samples": samples}, open(out_file, "w"))
print("yade: %d spheres, %d bonds, %d steps in %.1f s (%.4f s/step, %d threads)" % (len(ids), bonds, n, wall, wall / n, O.numThreads))
