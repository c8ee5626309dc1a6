#!/usr/bin/env python3
"""campaigns/verification/body_spin.py reads a body's spin from a run: an elastic disk (plane
strain, r = 1 mm) set spinning as a rigid body, v = omega0 (-(Y - Yc), X - Xc) with omega0 = 2000
rad/s, and translating at (3, -4) m/s, in free flight for 2 us. At t = 0 the velocity field is an
exact rigid motion, so L_z / I_z is omega0 to round-off (1e-9 relative) and the centre's speed 5
m/s; free flight keeps the centre's velocity (momentum is conserved to round-off: 1e-9) and the
centre moves by v t (1e-9 m); the spin changes by what the transfers lose of a rigid rotation
(within 2 %). A body the run does not have is an error naming the objects.

  body_spin_test.py MPM"""
import csv
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
SCRIPT = os.path.join(ROOT, "campaigns", "verification", "body_spin.py")
BASE = os.path.join(ROOT, "data", "scenes", "verification", "elastic_base.json")

OMEGA, VX, VY, XC, YC, R, T = 2000.0, 3.0, -4.0, 0.004, 0.004, 0.001, 2.0e-6


def main():
    mpm = sys.argv[1]
    work = tempfile.mkdtemp(prefix="body_spin_")
    scene = {
        "extends": BASE,
        "objects": {"disk": {"material": "elastic_al",
                             "geometry": {"type": "cylinder", "bottom": [XC, YC, -0.001],
                                          "top": [XC, YC, 0.001], "radius": R},
                             "velocity": [f"{VX} - {OMEGA}*(Y - {YC})",
                                          f"{VY} + {OMEGA}*(X - {XC})", 0.0],
                             "particles_per_cell": [2, 2]}},
        "grid": {"geometry": "plane_strain", "lower": [0.0, 0.0], "upper": [0.008, 0.008],
                 "cells": [32, 32], "boundary": {"x-": "free", "x+": "free", "y-": "free",
                                                 "y+": "free"}},
        "time": {"max_time": T},
        "output": {"snapshots": True, "fields": ["velocity", "mass", "object"],
                   "interval": T / 2},
    }
    path = os.path.join(work, "spin.json")
    with open(path, "w") as f:
        json.dump(scene, f)
    run = os.path.join(work, "run")
    subprocess.run([mpm, "run", path, "--out", run, "--threads", "1"], check=True,
                   stdout=subprocess.DEVNULL)
    table = os.path.join(work, "spin.csv")
    subprocess.run([sys.executable, SCRIPT, run, "--object", "disk", "--radius", str(R), "--csv",
                    table], check=True, stdout=subprocess.DEVNULL)
    with open(table) as f:
        rows = [[float(x) for x in row] for row in list(csv.reader(f))[1:]]
    first, last = rows[0], rows[-1]
    speed = (VX * VX + VY * VY) ** 0.5
    failures = []

    def check(what, value, expected, tolerance):
        if not abs(value - expected) <= tolerance:
            failures.append(f"{what}: {value!r}, expected {expected!r} within {tolerance!r}")

    check("omega at t = 0 [rad/s]", first[5], OMEGA, 1e-9 * OMEGA)
    check("omega r / speed at t = 0", first[6], OMEGA * R / speed, 1e-9)
    check("speed at t = 0 [m/s]", first[4], speed, 1e-9 * speed)
    check("speed at the end [m/s]", last[4], speed, 1e-9 * speed)
    check("x_c at the end [m]", last[1], first[1] + VX * last[0], 1e-9)
    check("y_c at the end [m]", last[2], first[2] + VY * last[0], 1e-9)
    check("omega at the end [rad/s]", last[5], OMEGA, 0.02 * OMEGA)
    missing = subprocess.run([sys.executable, SCRIPT, run, "--object", "ball"],
                             capture_output=True, text=True)
    if missing.returncode == 0 or "no object 'ball'" not in missing.stderr \
            or "disk" not in missing.stderr:
        failures.append(f"an unknown object: exit {missing.returncode}, {missing.stderr!r}")
    print(f"omega {first[5]!r} -> {last[5]!r} rad/s, speed {first[4]!r} -> {last[4]!r} m/s")
    if failures:
        print("\n".join(failures))
        sys.exit(1)


if __name__ == "__main__":
    main()
