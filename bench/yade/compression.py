# Yade 2023.02a (Debian `yade`) version of mw-dem's virtual compression test
# (pipeline/concrete-cube/scenes/cube-compression.toml), to cross-check the
# elastic part - E_glob and nu_glob - on the very same spheres.
#
#   yade -n -x bench/yade/compression.py SPHERES.txt SCENE.toml SCENE_INFO.json OUT.json \
#        --stop-at-MPa 25 --modulus-levels-MPa 5 20 [--strengths] [--curves OUT.csv]
#
# SPHERES.txt: the packing as Yade textExt (mw-pack --export-yade), in packing
#   order, so body id = packing index.
# SCENE.toml: the scene; read for what `mw-dem info` does not print: the walls'
#   ramp_us, the sensors' sample_interval_ns and the [test] table (which
#   sensors are loads, axial and lateral extensometers).
# SCENE_INFO.json: `mw-dem info SCENE --packing P [--unbreakable-bonds]`
#   (material, dt, each wall's inward normal and velocity, each extensometer's
#   two pads as packing indices).
# OUT.json: the curves, E_glob, nu_glob, peak, wall time.
#
# Bonds as in wave.py: the stock Yade law computes F_n = k_n (penetrationDepth -
# unp) with unp = 0 at bond creation, so this script creates the C_f bonds in
# one step with every sphere held, sets each bond's unp to its initial
# penetrationDepth (Eq. 1), sets the adhesions, and resets the detection
# factors to 1. The adhesions are 1e30 R^2 (unbreakable, what mw-dem's
# --unbreakable-bonds runs) unless --strengths asks for the scene's T R^2, C R^2.
#
# The test, with mw-dem's definitions (tools/mesowave/dem/rigid_wall.*,
# extensometer.*, uniaxial_test.*):
# - walls: utils.wall of a frictionless (friction angle 0), non-cohesive
#   CohFrictMat with the spheres' Young's modulus, so the Wall-Sphere
#   CohFrictPhys has kn = E_dem r (Ip2 with both radii r) and no shear force;
#   placed on the bounding box, min(z - r) and max(z + r), touching the
#   outermost sphere; the moving one follows mw-dem's travel(t) (half-cosine
#   ramp to the velocity, velocity_ramp.hpp) exactly: its velocity in step n is
#   (travel(t_{n+1}) - travel(t_n)) / dt, which Yade's NewtonIntegrator applies
#   to the fixed body;
# - the wall force of step n (positions x_n) and the strains after step n
#   (x_{n+1} - x_0) are sampled together every sample interval, as mw-dem's
#   ActuatorForceSensor and Extensometer do;
# - stress = mean of the walls' forces / bounding-box area across the axis;
#   strain of an extensometer (mean_b u.e - mean_a u.e) / L0, L0 the pads'
#   mean-centre distance along e at step 0; axial = minus the mean of the axial
#   ones (compression positive), lateral = the mean of the lateral ones;
# - E_glob = (sigma_a - sigma_b) / (eps(sigma_a) - eps(sigma_b)) at the first
#   crossings of the levels up to the peak (linear interpolation between
#   samples), nu_glob = (eps_l(sigma_a) - eps_l(sigma_b)) / (same); also the
#   least-squares slopes over the samples between the crossings;
# - the run stops at the first sample whose stress reaches --stop-at-MPa.
import argparse
import json
import math
import time
import tomllib

from yade import ymport, utils

parser = argparse.ArgumentParser(prog="compression.py")
parser.add_argument("spheres")
parser.add_argument("scene")
parser.add_argument("info")
parser.add_argument("out")
parser.add_argument("--stop-at-MPa", type=float, required=True)
parser.add_argument("--modulus-levels-MPa", type=float, nargs=2, required=True)
parser.add_argument("--strengths", action="store_true", help="the scene's T, C instead of unbreakable bonds")
parser.add_argument("--curves", help="CSV: t_s, stress_MPa, axial_strain, lateral_strain")
parser.add_argument("--max-steps", type=int, default=None, help="default: the scene's duration")
args = parser.parse_args()

info = json.load(open(args.info))
scene = tomllib.load(open(args.scene, "rb"))
m = info["material"]
test = scene["test"]
if test["kind"] != "compression":
    raise SystemExit("error: [test] kind is %s; this script runs a compression test" % test["kind"])
sensors = {s["name"]: s for s in scene["sensor"]}
placed = {s["name"]: s for s in info["sensor_points"]}
walls = [a for a in info["actuator_loads"] if a["kind"] == "wall"]
ramps = {a["name"]: a.get("ramp_us", 0.0) * 1e-6 for a in scene["actuator"]}
names = test["load"] + test["axial"] + test["lateral"]
intervals = {sensors[n].get("sample_interval_ns") for n in names}
if len(intervals) != 1 or None in intervals:
    raise SystemExit("error: the test's sensors must share one sample_interval_ns")
dt = info["dt_s"]
every = round(intervals.pop() * 1e-9 / dt)

huge = 1e30
strength_T = m["T_Pa"] if args.strengths and m["T_Pa"] is not None else huge
strength_C = m["C_Pa"] if args.strengths and m["C_Pa"] is not None else huge
mat = O.materials.append(CohFrictMat(
    young=m["E_dem_Pa"], poisson=m["nu_dem"], frictionAngle=m["friction_angle_rad"], density=m["density_kg_m3"],
    isCohesive=True, normalCohesion=huge, shearCohesion=huge, momentRotationLaw=False, fragile=True))
wall_mat = O.materials.append(CohFrictMat(
    young=m["E_dem_Pa"], poisson=m["nu_dem"], frictionAngle=0.0, density=m["density_kg_m3"], isCohesive=False))
ids = O.bodies.append(ymport.textExt(args.spheres, format="x_y_z_r", material=mat))
assert ids == list(range(len(ids))), "the spheres must be the first bodies, in packing order"
assert len(ids) == info["spheres"], "the text file and the scene have different sphere counts"

factor = m["bond_factor"]
sphere_bounds = Bo1_Sphere_Aabb(aabbEnlargeFactor=factor)
collider = InsertionSortCollider([sphere_bounds, Bo1_Wall_Aabb()])
ig2 = Ig2_Sphere_Sphere_ScGeom6D(interactionDetectionFactor=factor)
O.engines = [
    ForceResetter(),
    collider,
    InteractionLoop([ig2, Ig2_Wall_Sphere_ScGeom()], [Ip2_CohFrictMat_CohFrictMat_CohFrictPhys(setCohesionNow=True)],
                    # sphere-sphere (ScGeom6D): the cohesive law; wall-sphere (ScGeom): k_n u, friction angle 0
                    [Law2_ScGeom6D_CohFrictPhys_CohesionMoment(), Law2_ScGeom_FrictPhys_CundallStrack()]),
    PyRunner(iterPeriod=1, command="move_walls()"),
    NewtonIntegrator(damping=m["damping"]),
    PyRunner(iterPeriod=1, command="record()"),
]
O.dt = dt

# Step 0: bonds, with nothing moving and no wall yet.
for b in O.bodies:
    b.state.blockedDOFs = "xyzXYZ"
running = False  # move_walls and record (below) wait for the bonds; a PyRunner skips the first step anyway
O.step()
bonds = 0
for i in O.interactions:
    i.phys.unp = i.geom.penetrationDepth  # Eq. (1): F_n = K_n (u - u_0)
    r = min(O.bodies[i.id1].shape.radius, O.bodies[i.id2].shape.radius)
    i.phys.normalAdhesion = strength_T * r * r  # Eq. (6)
    i.phys.shearAdhesion = strength_C * r * r
    bonds += 1
sphere_bounds.aabbEnlargeFactor = 1.0
ig2.interactionDetectionFactor = 1.0
for b in O.bodies:
    b.state.blockedDOFs = ""
    b.state.vel = Vector3(0, 0, 0)
    b.state.angVel = Vector3(0, 0, 0)

pos0 = [Vector3(O.bodies[k].state.pos) for k in ids]
radius = [O.bodies[k].shape.radius for k in ids]
lower = [min(pos0[k][d] - radius[k] for k in ids) for d in range(3)]
upper = [max(pos0[k][d] + radius[k] for k in ids) for d in range(3)]


def travel(w, t):
    """mw-dem's VelocityRamp::travel_m: half-cosine ramp to the velocity, then constant."""
    s = t - w["delay_s"]
    V, ramp = w["velocity_m_s"], w["ramp_s"]
    if s <= 0:
        return 0.0
    if s >= ramp:
        return V * (s - 0.5 * ramp)
    k = math.pi / ramp
    return 0.5 * V * (s - math.sin(k * s) / k)


# Walls on the bounding box; sense: only the side the spheres are on interacts.
for w in walls:
    e = w["direction"]
    w["axis"] = max(range(3), key=lambda d: abs(e[d]))
    w["inward"] = 1.0 if e[w["axis"]] > 0 else -1.0
    w["ramp_s"] = ramps[w["name"]]
    w["plane0"] = lower[w["axis"]] if w["inward"] > 0 else upper[w["axis"]]
    w["id"] = O.bodies.append(utils.wall(w["plane0"], axis=w["axis"], sense=int(w["inward"]), material=wall_mat))

axis = walls[0]["axis"]
p, q = (axis + 1) % 3, (axis + 2) % 3
area = (upper[p] - lower[p]) * (upper[q] - lower[q])


def mean_centre(group):
    c = Vector3(0, 0, 0)
    for k in group:
        c += pos0[k]
    return c / len(group)


gauges = {}
for n in test["axial"] + test["lateral"]:
    s = placed[n]
    e = Vector3(*s["component"])
    gauges[n] = (s["spheres"], s["spheres_b"], e, (mean_centre(s["spheres_b"]) - mean_centre(s["spheres"])).dot(e))


def broken_bonds():
    """Bonds broken so far: in tension Yade erases them, in shear it keeps them with cohesionBroken."""
    return bonds - sum(1 for i in O.interactions if isinstance(i.geom, ScGeom6D) and not i.phys.cohesionBroken)


def strain(n):
    a, b, e, L0 = gauges[n]
    ua = sum((O.bodies[k].state.pos - pos0[k]).dot(e) for k in a) / len(a)
    ub = sum((O.bodies[k].state.pos - pos0[k]).dot(e) for k in b) / len(b)
    return (ub - ua) / L0


iter0 = O.iter
stop_at = args.stop_at_MPa * 1e6
curves = {"t_s": [], "stress_Pa": [], "axial_strain": [], "lateral_strain": [], "forces_N": [], "broken_bonds": []}
stop_reason = None


def move_walls():
    # Wall position in step n is plane0 + inward travel(t_n), as RigidWall::plane_at.
    if not running:
        return
    n = O.iter - iter0
    for w in walls:
        step = travel(w, (n + 1) * dt) - travel(w, n * dt)
        v = Vector3(0, 0, 0)
        v[w["axis"]] = w["inward"] * step / dt
        O.bodies[w["id"]].state.vel = v


def record():
    global stop_reason
    if not running:
        return
    n = O.iter - iter0
    if n % every != 0:
        return
    # Force of the spheres on wall w along its outward normal = the wall's push on the specimen.
    forces = {w["name"]: -w["inward"] * O.forces.f(w["id"])[w["axis"]] for w in walls}
    load = sum(forces[sensors[name]["actuator"]] for name in test["load"]) / len(test["load"])
    stress = load / area
    curves["t_s"].append(n * dt)
    curves["stress_Pa"].append(stress)
    curves["axial_strain"].append(-sum(strain(g) for g in test["axial"]) / len(test["axial"]))
    curves["lateral_strain"].append(sum(strain(g) for g in test["lateral"]) / len(test["lateral"]))
    curves["forces_N"].append([forces[sensors[name]["actuator"]] for name in test["load"]])
    if args.strengths:  # bonds that broke so far (tension or Mohr-Coulomb), as mw-dem's broken-bond counter
        curves["broken_bonds"].append(broken_bonds())
    if stress >= stop_at:
        stop_reason = "the stress reached %.2f MPa (stop at %.2f MPa)" % (stress / 1e6, stop_at / 1e6)
        O.pause()


max_steps = args.max_steps if args.max_steps else info["steps"]
running = True
start = time.time()
O.run(max_steps, True)
wall_s = time.time() - start
steps = O.iter - iter0

# The analysis, as analyse_uniaxial_test.
sig, eps, lat, t = curves["stress_Pa"], curves["axial_strain"], curves["lateral_strain"], curves["t_s"]
peak = max(range(len(sig)), key=lambda i: sig[i])


def first_crossing(level):
    for i in range(peak + 1):
        if sig[i] < level:
            continue
        if i == 0:
            return 0.0
        return i - 1 + (level - sig[i - 1]) / (sig[i] - sig[i - 1])
    raise SystemExit("error: the stress reached only %.3f MPa, below %.3f MPa" % (sig[peak] / 1e6, level / 1e6))


def at(v, x):
    i = int(math.floor(x))
    if i + 1 >= len(v):
        return v[-1]
    w = x - i
    return (1 - w) * v[i] + w * v[i + 1]


def slope(x, y, begin, end):
    n = end - begin
    mx, my = sum(x[begin:end]) / n, sum(y[begin:end]) / n
    sxx = sum((x[i] - mx) ** 2 for i in range(begin, end))
    sxy = sum((x[i] - mx) * (y[i] - my) for i in range(begin, end))
    return sxy / sxx


sigma_b, sigma_a = (level * 1e6 for level in args.modulus_levels_MPa)
ib, ia = first_crossing(sigma_b), first_crossing(sigma_a)
eps_b, eps_a = at(eps, ib), at(eps, ia)
E = (sigma_a - sigma_b) / (eps_a - eps_b)
nu = (at(lat, ia) - at(lat, ib)) / (eps_a - eps_b)
begin, end = math.ceil(ib), math.floor(ia) + 1
E_fit = slope(eps, sig, begin, end)
nu_fit = slope(eps, lat, begin, end)
rate = (eps_a - eps_b) / (at(t, ia) - at(t, ib))
d_mean = 2 * sum(radius) / len(radius)
inertial = max(rate * d_mean * math.sqrt(m["density_kg_m3"] / sig[i]) for i in range(begin, peak + 1) if sig[i] > 0)

# Pairs whose bond broke and that touch again: stock Yade erased the bond and
# made a fresh contact with unp = 0, which pushes with k_n times the whole
# overlap (docs/models.md, "Deliberate differences"); mw-dem keeps u_0.
sphere_ids = set(ids)
recontacts = [i for i in O.interactions
              if i.id1 in sphere_ids and i.id2 in sphere_ids and i.phys.cohesionBroken and i.geom.penetrationDepth > 0]
import yade.config
result = {
    "yade_version": yade.config.version, "threads": O.numThreads, "spheres": len(ids), "bonds": bonds,
    "bonds_broken_end": broken_bonds(),
    "adhesions": "scene T, C" if args.strengths else "1e30 R^2 (unbreakable)",
    "fresh_contacts_end": len(recontacts),
    "fresh_contact_max_force_N": max((i.phys.normalForce.norm() for i in recontacts), default=0.0),
    "dt_s": dt, "sample_interval_steps": every, "steps": steps, "wall_s": wall_s, "s_per_step": wall_s / steps,
    "stop_reason": stop_reason, "area_mm2": area * 1e6,
    "gauge_lengths_mm": {n: g[3] * 1e3 for n, g in gauges.items()},
    "walls": [{"name": w["name"], "plane0_mm": w["plane0"] * 1e3, "velocity_m_s": w["velocity_m_s"], "ramp_s": w["ramp_s"]}
              for w in walls],
    "peak_stress_MPa": sig[peak] / 1e6, "modulus_levels_MPa": list(args.modulus_levels_MPa),
    "eps_b": eps_b, "eps_a": eps_a, "E_secant_GPa": E / 1e9, "nu_secant": nu,
    "E_fit_GPa": E_fit / 1e9, "nu_fit": nu_fit, "fit_points": end - begin,
    "strain_rate_1_s": rate, "inertial_number_max": inertial,
    "curves": curves,
}
json.dump(result, open(args.out, "w"))
if args.curves:
    with open(args.curves, "w") as f:
        f.write("t_s,stress_MPa,axial_strain,lateral_strain\n")
        for i in range(len(t)):
            f.write("%.17g,%.17g,%.17g,%.17g\n" % (t[i], sig[i] / 1e6, eps[i], lat[i]))
print("yade: %d spheres, %d bonds, %d steps in %.1f s (%d threads): E_glob %.4f GPa, nu_glob %.5f (secant %g-%g MPa), "
      "peak %.3f MPa; %s" % (len(ids), bonds, steps, wall_s, O.numThreads, E / 1e9, nu, sigma_b / 1e6, sigma_a / 1e6,
                             sig[peak] / 1e6, stop_reason))
