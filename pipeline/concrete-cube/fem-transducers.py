#!/usr/bin/env python3
"""The wave test's transducers as mw-fem box options, from the one place they are written down.

    fem-transducers.py SENSORS_TOML POROSITY_TOML [SIDE_MM]

lab-data/concrete-cube/sensors.toml places the actuator A and the sensors B-G on the
cube of porosity.toml (cube_side, 50 mm); the DEM scene (scenes/cube-wave.toml) carries
the same positions as fractions of the packing (a test checks it). This prints

    --size-mm S --source-mm X,Y,Z --patch-radius-mm R --sensor B=X,Y,Z/normal ...

for a cube of side SIDE_MM (default: cube_side), every position scaled by SIDE_MM /
cube_side, so that the quick pipeline's small cube keeps the geometry. A's square patch
(patch_mm, the 3 x 3 mm PZT) becomes the disc of the same area, the traction patch mw-fem
applies; the sensors record the acceleration normal to their face, as in the scene.
"""
import math
import sys
import tomllib


def fail(message):
    print(f"error: {message}", file=sys.stderr)
    sys.exit(1)


def main(argv):
    if len(argv) not in (3, 4):
        fail("usage: fem-transducers.py SENSORS_TOML POROSITY_TOML [SIDE_MM]")
    with open(argv[1], "rb") as f:
        transducers = tomllib.load(f)
    with open(argv[2], "rb") as f:
        cube = tomllib.load(f)["cube_side"]
    if cube.get("unit") != "mm":
        fail(f"{argv[2]}: cube_side must be in mm, not '{cube.get('unit')}'")
    reference = float(cube["value"])
    side = float(argv[3]) if len(argv) == 4 else reference
    if not (side > 0 and math.isfinite(side)):
        fail(f"side ({argv[3]} mm) must be a positive number")
    scale = side / reference

    def point(name, entry):
        centre = entry["centre_mm"]
        if len(centre) != 3 or any(not 0 <= c <= reference for c in centre):
            fail(f"{argv[1]}: {name}.centre_mm {centre} must be 3 coordinates in [0, {reference:g}] mm")
        return ",".join(f"{c * scale:.12g}" for c in centre)

    actuators = [n for n, e in transducers.items() if e.get("role") == "actuator"]
    sensors = [n for n, e in transducers.items() if e.get("role") == "sensor"]
    if len(actuators) != 1 or not sensors:
        fail(f"{argv[1]}: need one actuator and at least one sensor (found {len(actuators)} and {len(sensors)})")
    a = transducers[actuators[0]]
    px, py = a["patch_mm"]
    options = [f"--size-mm {side:.12g}", f"--source-mm {point(actuators[0], a)}",
               f"--patch-radius-mm {math.sqrt(px * py / math.pi):.6g}"]
    options += [f"--sensor {n}={point(n, transducers[n])}/normal" for n in sorted(sensors)]
    print(" ".join(options))


if __name__ == "__main__":
    main(sys.argv)
