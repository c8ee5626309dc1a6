#!/usr/bin/env python3
"""Displacement error of the manufactured solutions against the cell size (docs/verification.md
#manufactured-solutions): every scene data/scenes/verification/mms_<field>.json on a ladder of
grids, for linear and uGIMP shapes, USL and MUSL, at one or more CFL multipliers, each run to
the displacement's peak (t = L / 2c). Writes DIR/mms_convergence.csv (one row per run: the
history's final displacement_error_rms and _max [m], their largest over the run, the energy
error, particles and steps) and DIR/mms_convergence.md (the table with the observed order
log(e_coarse / e_fine) / log 2 of each refinement).

  mms_convergence.py DIR [--mpm build/bin/mpm] [--threads 2]
      [--fields axis_aligned,plane_strain,axisymmetric] [--cells-2d 16,32,64,128]
      [--cells-3d 8,16,32] [--multipliers 0.4,0.2] [--interpolations linear,gimp]
      [--schemes usl,musl] [--amplitude A]

--amplitude replaces the scenes' A = 0.05 m (|Grad u| up to 0.31, large deformation) by A [m],
e.g. 0.001 for the small-strain limit where the method's asymptotic order shows.
"""
import argparse
import csv
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
SCENES = os.path.join(ROOT, "data", "scenes", "verification")
# impact.results (pure Python; python/ of the source tree) runs mpm and reads its run folders.
sys.path.insert(0, os.path.join(ROOT, "python"))
from impact import results  # noqa: E402


def run_level(launcher, field, cells, interpolation, scheme, multiplier, threads, work,
              amplitude):
    name = f"{field}_{interpolation}_{scheme}_cfl{multiplier}_n{cells}"
    out = os.path.join(work, name)
    row = {"field": field, "cells": cells, "interpolation": interpolation, "scheme": scheme,
           "multiplier": multiplier}
    if not results.completed(out):  # resumable: a finished level is kept
        dims = 3 if field == "axis_aligned" else 2
        scene = {"extends": os.path.join(SCENES, f"mms_{field}.json"),
                 "grid": {"cells": [cells] * dims},
                 "solver": {"interpolation": interpolation, "scheme": scheme},
                 "time": {"multiplier": multiplier}}
        if amplitude is not None:
            scene["constants"] = {"A": amplitude}
        path = os.path.join(work, name + ".json")
        with open(path, "w") as f:
            json.dump(scene, f)
        try:
            launcher.run("run", path, out=out, threads=threads, options=["--overwrite"])
        except results.LaunchError as e:  # a run that stops is a row of the table, not the end
            return dict(row, failed=str(e).strip().splitlines()[-1][-200:])
    h = results.history_columns(out)
    rms, worst = h["displacement_error_rms [m]"], h["displacement_error_max [m]"]
    s = results.read_summary(out, required=True)
    return dict(row, **{"seconds": s.get("wall_time [s]", ""), "rms [m]": rms[-1],
                        "max [m]": worst[-1], "rms_over_run [m]": max(rms),
                        "energy_error [-]": h["energy_error [-]"][-1],
                        "particles": s.get("particles", ""), "steps": s.get("steps", ""),
                        "failed": ""})


def order(coarse, fine, key):
    a, b = coarse.get(key), fine.get(key)
    if not a or not b or a <= 0 or b <= 0:
        return float("nan")
    return math.log(a / b) / math.log(fine["cells"] / coarse["cells"])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("--mpm", default=None, help="the mpm program (default: build/bin/mpm)")
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--fields", default="axis_aligned,plane_strain,axisymmetric")
    ap.add_argument("--cells-2d", default="16,32,64,128")
    ap.add_argument("--cells-3d", default="8,16,32")
    ap.add_argument("--multipliers", default="0.4,0.2")
    ap.add_argument("--interpolations", default="linear,gimp")
    ap.add_argument("--schemes", default="usl,musl")
    ap.add_argument("--amplitude", type=float, default=None)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    work = os.path.join(a.out, "runs")
    os.makedirs(work, exist_ok=True)
    launcher = results.Launcher(a.mpm)
    rows = []
    for field in a.fields.split(","):
        cells = a.cells_3d if field == "axis_aligned" else a.cells_2d
        for interpolation in a.interpolations.split(","):
            for scheme in a.schemes.split(","):
                for m in (float(x) for x in a.multipliers.split(",")):
                    for n in (int(x) for x in cells.split(",")):
                        r = run_level(launcher, field, n, interpolation, scheme, m, a.threads,
                                      work, a.amplitude)
                        rows.append(r)
                        print(json.dumps(r), flush=True)
    header = {"field": "field", "interpolation": "interpolation", "scheme": "scheme",
              "multiplier": "cfl_multiplier [-]", "cells": "cells_per_axis [-]",
              "particles": "particles [-]", "steps": "steps [-]", "seconds": "wall_time [s]",
              "rms [m]": "displacement_error_rms [m]", "max [m]": "displacement_error_max [m]",
              "rms_over_run [m]": "largest_rms_over_the_run [m]",
              "energy_error [-]": "energy_error [-]", "failed": "failed"}
    with open(os.path.join(a.out, "mms_convergence.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header.values())
        for r in rows:
            w.writerow([r.get(k, "") for k in header])
    lines = ["| field | shapes | scheme | CFL | cells | rms [m] | order | max [m] | order |",
             "|---|---|---|---|---|---|---|---|---|"]
    for i, r in enumerate(rows):
        prev = rows[i - 1] if i > 0 else None
        same = prev and all(prev[k] == r[k] for k in ("field", "interpolation", "scheme",
                                                       "multiplier"))
        if r.get("failed"):
            lines.append(f"| {r['field']} | {r['interpolation']} | {r['scheme']} | "
                         f"{r['multiplier']} | {r['cells']} | failed: {r['failed'][:60]} | | | |")
            continue
        o_rms = f"{order(prev, r, 'rms [m]'):.2f}" if same else ""
        o_max = f"{order(prev, r, 'max [m]'):.2f}" if same else ""
        lines.append(f"| {r['field']} | {r['interpolation']} | {r['scheme']} | "
                     f"{r['multiplier']} | {r['cells']} | {r['rms [m]']:.3e} | {o_rms} | "
                     f"{r['max [m]']:.3e} | {o_max} |")
    with open(os.path.join(a.out, "mms_convergence.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    sys.exit(main())
