#!/usr/bin/env python3
"""Quarter model against the full model of a centred sphere-cylinder impact (
docs/performance.md#quarter-model).

  quarter_model.py OUT [--mpm build/bin/mpm] [--threads 2] [--max-time 40e-6]

The recommended scene (data/scenes/sphere_cylinder/recommended.json) with the sphere moved onto
the cylinder axis (y = z = 0; the report's deck is off axis, so it has no symmetry) is run
1. in full: the report's box, y and z from -33 to 33 mm, 20 cells each;
2. as a quarter: y and z from 0 to 33 mm, 10 cells each, the same cell size, the faces y = 0 and
   z = 0 symmetric (a mirror: grid/boundary.cpp) like every face of the deck. The seed points
   of the quarter are those of the full model in y, z > 0 (cell-centred, the planes are cell
   faces), the crater axis is fixed at the symmetry corner (output.crater axis_y, axis_z).
Compared: every observable of summary.json (per-object kinetic energy and mass x 4 in the
quarter), the ledger's energy_error, and each gauge's history (the largest difference over the
run relative to the largest magnitude of the full model's history); cost: particles, wall time.
Writes OUT/quarter.csv (one row per observable), OUT/quarter.md and OUT/quarter_gauges.png.
Exit codes: 0 done, 1 usage, 3 a run failed.
"""

import argparse
import csv
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "python"))  # impact.results (pure Python)
from impact import results  # noqa: E402

BASE = os.path.join(ROOT, "data", "scenes", "sphere_cylinder", "recommended.json")
# Extensive quantities scale with the modelled fraction of the body.
EXTENSIVE = ("kinetic_energy [J]", "mass [kg]")


def scenes(out, max_time):
    full = {"extends": BASE,
            "description": "recommended.json with the sphere on the cylinder axis (full model)",
            "objects": {"sphere": {"geometry": {"center": [9.75e-3, 0.0, 0.0]}}},
            "time": {"max_time": max_time},
            "output": {"crater": {"object": "target", "face": 15.0e-3,
                                  "axis_y": 0.0, "axis_z": 0.0}}}
    quarter = {"extends": "full.json",
               "description": "quarter of full.json: y, z >= 0, symmetric planes y = 0 and z = 0",
               "grid": {"lower": [0.0, 0.0, 0.0], "upper": [119.0e-3, 33.0e-3, 33.0e-3],
                        "cells": [50, 10, 10]}}
    os.makedirs(os.path.join(out, "scenes"), exist_ok=True)
    paths = {}
    for name, doc in (("full", full), ("quarter", quarter)):
        paths[name] = os.path.join(out, "scenes", name + ".json")
        with open(paths[name], "w") as f:
            json.dump(doc, f, indent=1)
    return paths


def run(mpm, scene, out_dir, threads):
    launcher = results.Launcher(mpm)
    cmd = launcher.command("run", scene, out=out_dir, threads=threads)
    print("quarter_model.py:", " ".join(cmd), flush=True)
    return launcher.run("run", scene, out=out_dir, threads=threads, check=False,
                        capture=False).returncode == 0


def flatten(prefix, node, out):
    if isinstance(node, dict):
        for k, v in node.items():
            flatten(f"{prefix}.{k}" if prefix else k, v, out)
    elif isinstance(node, list):
        for i, v in enumerate(node):
            flatten(f"{prefix}[{i}]", v, out)
    elif isinstance(node, (int, float)) and not isinstance(node, bool):
        out[prefix] = float(node)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("--mpm", default=os.path.join(ROOT, "build", "bin", "mpm"))
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--max-time", type=float, default=40e-6)
    a = ap.parse_args()
    paths = scenes(a.out, a.max_time)
    summary, hist = {}, {}
    for name in ("full", "quarter"):
        d = os.path.join(a.out, "runs", name)
        if not run(a.mpm, paths[name], d, a.threads):
            print(f"quarter_model.py: the {name} run failed (see {d})", file=sys.stderr)
            return 3
        with open(os.path.join(d, "summary.json")) as f:
            summary[name] = json.load(f)
        hist[name] = results.history_rows(d)

    rows = []
    fl = {}
    for name in ("full", "quarter"):
        fl[name] = {}
        flatten("", summary[name].get("observables", {}), fl[name])
        fl[name]["final.energy_error [-]"] = summary[name]["final"]["energy_error [-]"]
    for key, full in fl["full"].items():
        if key not in fl["quarter"] or "time [s]" in key or "particles" in key:
            continue
        q = fl["quarter"][key]
        factor = 4.0 if key.endswith(EXTENSIVE) else 1.0
        if key.endswith("axis_yz [m][0]") or key.endswith("axis_yz [m][1]"):
            continue
        if "mean_velocity" in key and not key.endswith("[0]"):
            # y, z means vanish by symmetry in the full model; the quarter's are one quadrant's.
            continue
        scaled = factor * q
        if key == "final.energy_error [-]":
            diff = scaled - full  # already relative
        else:
            diff = (scaled - full) / abs(full) if full != 0 else float("nan")
        rows.append((key, full, scaled, diff))
    # Gauge histories: the largest difference over the run / the largest |full| value.
    hf, df = hist["full"]
    hq, dq = hist["quarter"]
    n = min(len(df), len(dq))
    gauge_rows = []
    for c, name in enumerate(hf):
        if not name.startswith("gauge_") or name not in hq:
            continue
        cq = hq.index(name)
        peak = max(abs(r[c]) for r in df[:n]) or 1.0
        worst = max(abs(df[i][c] - dq[i][cq]) for i in range(n)) / peak
        gauge_rows.append((name, peak, worst))
    cost = {name: (summary[name]["particles"], summary[name]["steps"],
                   summary[name]["wall_time [s]"]) for name in ("full", "quarter")}

    with open(os.path.join(a.out, "quarter.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["observable", "full", "quarter (x4 if extensive)", "relative difference [-]"])
        for r in rows:
            w.writerow(r)
        w.writerow([])
        w.writerow(["gauge history", "peak |full|", "max |quarter - full| / peak [-]", ""])
        for g in gauge_rows:
            w.writerow(list(g) + [""])
        w.writerow([])
        w.writerow(["cost", "particles [-]", "steps [-]", "wall time [s]"])
        for name, c in cost.items():
            w.writerow([name, *c])

    with open(os.path.join(a.out, "quarter.md"), "w") as f:
        f.write(f"Centred impact, {a.max_time * 1e6:g} us, {a.threads} threads "
                f"(`campaigns/study/quarter_model.py`).\n\n")
        f.write("| run | particles [-] | steps [-] | wall time [s] |\n|---|---:|---:|---:|\n")
        for name, (p, s, t) in cost.items():
            f.write(f"| {name} | {p} | {s} | {t:.1f} |\n")
        f.write(f"\nCost ratio quarter/full: {cost['quarter'][2] / cost['full'][2]:.3f} "
                f"(particles {cost['quarter'][0] / cost['full'][0]:.3f}).\n\n")
        f.write("| observable [unit] | full | quarter (x4 if extensive) | "
                "relative difference [-] |\n"
                "|---|---:|---:|---:|\n")
        for k, fv, qv, d in rows:
            f.write(f"| {k} | {fv:.6g} | {qv:.6g} | {d:+.2e} |\n")
        f.write("\n| gauge history [unit] | peak of the full model | max difference / peak [-] |\n"
                "|---|---:|---:|\n")
        for name, peak, worst in gauge_rows:
            f.write(f"| {name} | {peak:.4g} | {worst:.2e} |\n")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("quarter_model.py: matplotlib missing; no figure", file=sys.stderr)
        return 0
    gauges = [g[0] for g in gauge_rows]
    fig, axes = plt.subplots(len(gauges), 1, figsize=(7, 1.9 * len(gauges)), sharex=True)
    for ax, name in zip(axes, gauges):
        c, cq = hf.index(name), hq.index(name)
        ax.plot([r[0] * 1e6 for r in df], [r[c] for r in df], "k-", label="full")
        ax.plot([r[0] * 1e6 for r in dq], [r[cq] for r in dq], "r--", label="quarter")
        ax.set_ylabel(name.replace("gauge_", ""), fontsize=7)
        ax.tick_params(labelsize=7)
    axes[0].legend(fontsize=7)
    axes[-1].set_xlabel("time [us]")
    fig.suptitle("Centred impact: full model vs quarter model with symmetric planes", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "quarter_gauges.png"), dpi=110)
    print("quarter_model.py: wrote", os.path.join(a.out, "quarter.md"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
