# Step 0 of a mesowave scene in Yade 2023.02a, shared by our Yade scripts
# (wave.py, compression.py). The stock Yade law computes F_n = k_n
# (penetrationDepth - unp) with unp = 0 at bond creation, so a dense packing
# would start pre-stressed and gap bonds would break at once. To match Eq. (1),
# F_n = K_n (u - u_0): the C_f bonds are made in one step with every sphere
# held, each bond's unp set to its initial penetrationDepth and its adhesions
# to T R^2 and C R^2 (Eq. 6, R the smaller radius), the detection factors
# reset to 1, and the spheres freed at rest.
from yade.minieigenHP import Vector3
from yade.wrapper import Omega


def make_eq1_bonds(strength_T, strength_C, sphere_bounds, ig2):
    """Runs the bonding step; returns the number of bonds. `sphere_bounds` is the
    Bo1_Sphere_Aabb and `ig2` the Ig2_Sphere_Sphere_ScGeom6D that carry C_f."""
    O = Omega()
    for b in O.bodies:
        b.state.blockedDOFs = "xyzXYZ"
    O.step()
    bonds = 0
    for i in O.interactions:
        i.phys.unp = i.geom.penetrationDepth  # Eq. (1)
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
    return bonds
