#!/usr/bin/env python3
"""A graded grid against the uniform grids it sits between (issue 56, item 4): the Taylor rod H8
(House et al. 1995) with a refined box at its impact end, beside the uniform base grid and the
uniform grid at the box's fine cell size everywhere. Lf and Dm are measured as taylor.py measures
them (largest particle x; twice the largest radius within 0.5 mm of the anvil), each plus the
seeding's offset read from the run's own first snapshot (the outermost seeded particle's distance
inside the rod: on a graded grid it depends on the cell a face lies in). The runs go to RUNS
(default build/graded_taylor/<geometry>); OUT/graded.csv gets the table:

  run, cells, particles, steps, particle_steps, Lf [m], Dm [m], dLf vs fine [-], dDm vs fine [-]

  campaigns/taylor/graded_taylor.py OUT [--geometry axisymmetric|3d] [--box-x 0.005]
                                        [--factor 2] [--growth 1.3] [--threads 2]
                                        [--mpm build/bin/mpm] [--runs RUNS]

The axisymmetric case takes about 15 s on 2 threads, the 3D quarter a few minutes.
"""
import argparse
import csv
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from impact import results  # noqa: E402

REPO = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
L0, R0 = 0.01519, 0.5 * 0.007595  # H8's rod [m] (data/scenes/taylor/h8_quarter.json)
ANVIL_LAYER = 0.0005  # [m], as taylor.py


def measure(run_dir, geometry):
    """(Lf, Dm) of a finished run, with the seeding's offsets of its first snapshot."""
    snaps = results.snapshots(run_dir)
    first, last = results.read_points(snaps[0][1]), results.read_points(snaps[-1][1])
    x0, x = first["points"], last["points"]

    def radius(p):
        return p[:, 1] if geometry == "axisymmetric" else (p[:, 1] ** 2 + p[:, 2] ** 2) ** 0.5

    axial = L0 - x0[:, 0].max()
    radial = R0 - radius(x0)[x0[:, 0] < ANVIL_LAYER].max()
    near = x[:, 0] < ANVIL_LAYER
    return x[:, 0].max() + axial, 2.0 * (radius(x)[near].max() + radial)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("out")
    ap.add_argument("--geometry", choices=("axisymmetric", "3d"), default="axisymmetric")
    ap.add_argument("--box-x", type=float, default=0.005, help="the box's upper x [m]")
    ap.add_argument("--factor", type=float, default=2.0)
    ap.add_argument("--growth", type=float, default=1.3)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--mpm", default=os.path.join(REPO, "build", "bin", "mpm"))
    ap.add_argument("--runs", help="where the runs go (default build/graded_taylor/GEOMETRY)")
    a = ap.parse_args()
    runs_dir = a.runs or os.path.join(REPO, "build", "graded_taylor", a.geometry)
    scene = os.path.join(REPO, "data", "scenes", "taylor",
                         "h8_axisymmetric.json" if a.geometry == "axisymmetric" else
                         "h8_quarter.json")
    base = [25, 14] if a.geometry == "axisymmetric" else [25, 14, 14]
    fine = [round(c * a.factor) for c in base]
    upper = [a.box_x] + [0.00886] * (len(base) - 1)  # the whole radius: the mushroom grows there
    runs = {"base": {"grid": {"cells": base}},
            "fine": {"grid": {"cells": fine}},
            "graded": {"grid": {"refine": {"lower": [0.0] * len(base), "upper": upper,
                                           "factor": a.factor, "growth": a.growth}}}}
    os.makedirs(a.out, exist_ok=True)
    rows = {}
    for name, patch in runs.items():
        run_dir = os.path.join(runs_dir, name)
        results.Launcher(a.mpm).run("run", scene, out=run_dir, options=["--overwrite"],
                                    threads=a.threads, sets=[patch])
        with open(os.path.join(run_dir, "summary.json")) as f:
            s = json.load(f)
        Lf, Dm = measure(run_dir, a.geometry)
        rows[name] = {"run": name, "cells": "x".join(str(c) for c in s["grid"]["cells"][:len(base)]),
                      "particles": s["particles"], "steps": s["steps"],
                      "particle_steps": s["particles"] * s["steps"], "Lf [m]": Lf, "Dm [m]": Dm}
    for r in rows.values():
        r["dLf vs fine [-]"] = r["Lf [m]"] / rows["fine"]["Lf [m]"] - 1.0
        r["dDm vs fine [-]"] = r["Dm [m]"] / rows["fine"]["Dm [m]"] - 1.0
    with open(os.path.join(a.out, "graded.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows["base"].keys()))
        w.writeheader()
        w.writerows(rows.values())
    for r in rows.values():
        print(f"{r['run']:7s} {r['cells']:>9s} {r['particles']:8d} particles {r['steps']:6d} steps "
              f"{r['particle_steps']:.3g} p-steps  Lf {r['Lf [m]'] * 1e3:.4f} mm "
              f"({r['dLf vs fine [-]']:+.2%})  Dm {r['Dm [m]'] * 1e3:.4f} mm "
              f"({r['dDm vs fine [-]']:+.2%})")


if __name__ == "__main__":
    main()
