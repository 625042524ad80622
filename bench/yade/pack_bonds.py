# Counts, in Yade, the bonds a packing gets at the detection factor C_f:
# loads a Yade text packing (mw-pack --export-yade), lets Yade's collider and
# Ig2_Sphere_Sphere_ScGeom find every pair with |x_i - x_j| <= C_f (r_i + r_j)
# in one step, and prints the count - to check mw-pack's "bonds" against Yade
# on the very same spheres.
#
#   yade -n -x bench/yade/pack_bonds.py cube.txt 1.1
import sys
from yade import ymport

path = sys.argv[1]
cf = float(sys.argv[2]) if len(sys.argv) > 2 else 1.1
O.bodies.append(ymport.textExt(path, format='x_y_z_r'))
O.engines = [
    ForceResetter(),
    InsertionSortCollider([Bo1_Sphere_Aabb(aabbEnlargeFactor=cf)]),
    InteractionLoop([Ig2_Sphere_Sphere_ScGeom(interactionDetectionFactor=cf)],
                    [Ip2_FrictMat_FrictMat_FrictPhys()],
                    [Law2_ScGeom_FrictPhys_CundallStrack(neverErase=True)]),  # keep gap pairs
    NewtonIntegrator(damping=0),
]
O.dt = 1e-12
O.step()
spheres = len(O.bodies)
bonds = sum(1 for i in O.interactions if i.isReal)
print(f"yade: spheres {spheres} bonds {bonds} coordination {2.0 * bonds / spheres:.4f} (C_f = {cf})")
