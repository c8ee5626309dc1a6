#!/usr/bin/env python3
"""The manufactured solutions of campaigns/verification/manufactured_solutions.py: first its own
--check (every body force sympy derives against central differences of u and P in numpy at
random points, 1e-6 relative), then the scene keys it prints as the solver reads them: every printed expression (muParser syntax: ^, ln, pi) is accepted by
`mpm check` on the grid of its field (a 3D box, a plane-strain box, an axisymmetric rod on the
axis), and a run of 1e-6 s with them ends with finite books. The material here is the elastic
verification aluminium, not yet the neo-Hookean law the fields are written for: this checks the
expressions, not the solution.

  manufactured_expressions_test.py MPM WORK_DIR
"""
import json
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
SCRIPT = os.path.join(ROOT, "campaigns", "verification", "manufactured_solutions.py")
BASE = os.path.join(ROOT, "data", "scenes", "verification", "elastic_base.json")

GRIDS = {
    "axis_aligned": ({"lower": [0, 0, 0], "upper": [0.04, 0.04, 0.04], "cells": [8, 8, 8]},
                     {"type": "box", "lower": [0.01, 0.01, 0.01], "upper": [0.03, 0.03, 0.03]}),
    "plane_strain": ({"geometry": "plane_strain", "lower": [0, 0], "upper": [0.04, 0.04],
                      "cells": [8, 8]},
                     {"type": "box", "lower": [0.01, 0.01, -0.5], "upper": [0.03, 0.03, 0.5]}),
    "axisymmetric": ({"geometry": "axisymmetric", "lower": [0, 0], "upper": [0.04, 0.02],
                      "cells": [8, 4], "boundary": {"x+": "free", "y+": "free"}},
                     {"type": "cylinder", "bottom": [0.01, 0, 0], "top": [0.03, 0, 0],
                      "radius": 0.01}),
}


def main(mpm, work):
    os.makedirs(work, exist_ok=True)
    sys.path.insert(0, os.path.dirname(SCRIPT))
    import manufactured_solutions as derived  # noqa: E402 (sympy: python3-sympy)
    assert derived.check() == 0, "a derived body force differs from central differences"
    fields = [derived.scene_keys(f) for f in derived.FIELDS]
    assert [f["field"] for f in fields] == list(GRIDS), fields
    for f in fields:
        grid, geometry = GRIDS[f["field"]]
        per_axis = [2, 2, 2] if f["field"] == "axis_aligned" else [2, 2]
        scene = {"extends": BASE,
                 "constants": {"A": 1e-5, "L": 0.04, "c": 3000.0, "mu": 26e9,
                               "lambda_": 51e9, "rho0": 2700.0},
                 "grid": grid,
                 "time": {"max_time": 1e-6},
                 "output": {"snapshots": False, "exact_displacement": f["exact_displacement"]},
                 "objects": {"body": {"material": "elastic_al", "geometry": geometry,
                                      "particles_per_cell": per_axis,
                                      "velocity": f["velocity"],
                                      "body_force": f["body_force"]}}}
        path = os.path.join(work, f["field"] + ".json")
        with open(path, "w") as out:
            json.dump(scene, out, indent=1)
        check = subprocess.run([mpm, "check", path], capture_output=True, text=True)
        assert check.returncode == 0, (f["field"], check.stderr)
        out_dir = os.path.join(work, "out_" + f["field"])
        run = subprocess.run([mpm, "run", path, "--out", out_dir, "--threads", "1"],
                             capture_output=True, text=True)
        assert run.returncode == 0, (f["field"], run.stderr)
        with open(os.path.join(out_dir, "history.csv")) as h:
            lines = h.read().splitlines()
        header, last = lines[0].split(","), [float(x) for x in lines[-1].split(",")]
        # [J], or [J/m] and [J/rad] on the 2D grids (docs/mpm.md#ledger)
        work_done = last[[c.startswith("external_work [") for c in header].index(True)]
        error = last[header.index("displacement_error_max [m]")]
        print(f"{f['field']}: mpm check exit 0; after {last[0]:.2e} s external work "
              f"{work_done:.3e}, displacement error {error:.3e} m")
        assert all(math.isfinite(x) for x in last), last
        assert work_done != 0.0
    print("OK")


if __name__ == "__main__":
    main(*sys.argv[1:3])
