#!/usr/bin/env python3
"""What a graded grid buys (issue 56, item 6): accuracy against cost for uniform and graded
grids, from the ladder tables and campaign tables the project already commits (nothing is run).

  graded_cost.py OUT [--uniform data/scenes/sphere_cylinder/recommended.ladder.json]
                     [--graded data/scenes/sphere_cylinder/recommended_refined.ladder.json]
                     [--taylor docs/figures/taylor_graded] [--observable "crater depth"]

Writes OUT/graded_cost.csv, one row per run: case, grid (uniform or graded), level, the fine cell
size h [m] (the box's on a graded grid), particle_steps [-], the observable's value (SI) and its
difference from the reference [-]. The references: for the flagship, the uniform ladder's level
with the same cells as the graded level (so the difference is the error of the cells outside the
box; the uniform level whose cells are within 1 % of the box's, as whole cells make them), and
the range of converged values of the uniform ladder; for the Taylor rod H8
(campaigns/taylor/graded_taylor.py), the uniform fine grid. With matplotlib it also draws
OUT/graded_cost.png: the flagship's value against particle-steps (log) for both grids with the
uniform ladder's range shaded, and the Taylor rod's |Lf| and |Dm| differences from the fine grid
against particle-steps for the base, graded and fine grids.
With the axisymmetric Taylor rod's two ladders in --taylor-ladders (taylor_h8_axisymmetric/ and
taylor_h8_axisymmetric_refined/ladder.json), a third panel: their Lf and Dm against
particle-steps, as the difference from the uniform ladder's finest level.
Exit codes: 0 done, 1 usage error, 2 a table unreadable, 3 an output not written.
"""
import argparse
import csv
import json
import os
import sys

REPO = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


def ladder_points(path, observable):
    """[(level, h, particle_steps, value)] of a ladder table's levels, finest first, and the
    observable's entry (its range and verdict)."""
    with open(path) as f:
        table = json.load(f)
    entry = next(o for o in table["observables"] if o["name"] == observable)
    # The table keeps each observable's values in the order of its levels.
    values = dict(zip([lv["level"] for lv in table["levels"]], entry["values"]))
    points = [(lv["level"], lv["h [m]"], lv["particle_steps"], values.get(lv["level"]))
              for lv in table["levels"]]
    return points, entry


def taylor_rows(folder):
    rows = []
    for geometry in ("axisymmetric", "3d"):
        path = os.path.join(folder, geometry, "graded.csv")
        if not os.path.exists(path):
            continue
        with open(path) as f:
            for r in csv.DictReader(f):
                rows.append({"case": f"Taylor H8 {geometry}", "grid": r["run"],
                             "particle_steps": float(r["particle_steps"]),
                             "Lf": float(r["Lf [m]"]), "Dm": float(r["Dm [m]"]),
                             "dLf": float(r["dLf vs fine [-]"]),
                             "dDm": float(r["dDm vs fine [-]"])})
    return rows


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out")
    ap.add_argument("--uniform", default=os.path.join(
        REPO, "data", "scenes", "sphere_cylinder", "recommended.ladder.json"))
    ap.add_argument("--graded", default=os.path.join(
        REPO, "data", "scenes", "sphere_cylinder", "recommended_refined.ladder.json"))
    ap.add_argument("--taylor", default=os.path.join(REPO, "docs", "figures", "taylor_graded"))
    ap.add_argument("--observable", default="crater depth")
    ap.add_argument("--taylor-ladders", default=os.path.join(REPO, "docs", "figures", "ladder"),
                    help="folder of the Taylor rod's uniform and graded ladders "
                         "(taylor_h8_axisymmetric/ and taylor_h8_axisymmetric_refined/)")
    a = ap.parse_args(argv)
    try:
        uniform, u_entry = ladder_points(a.uniform, a.observable)
        graded, _ = ladder_points(a.graded, a.observable)
    except (OSError, ValueError, KeyError, StopIteration) as e:
        print(f"graded_cost: cannot read the ladder tables ({type(e).__name__}: {e})",
              file=sys.stderr)
        return 2
    def same_cells(h):  # the uniform level whose cells are the box's, to 1 % (whole cells)
        near = [v for _, hu, _, v in uniform if abs(hu / h - 1.0) < 0.01]
        return near[0] if near else None

    rows = []
    for grid, points in (("uniform", uniform), ("graded", graded)):
        for level, h, steps, value in points:
            same = same_cells(h)
            rows.append({"case": "sphere-cylinder " + a.observable, "grid": grid, "level": level,
                         "h [m]": h, "particle_steps [-]": steps, "value": value,
                         "vs uniform at the same h [-]": (value / same - 1.0
                                                          if grid == "graded" and same else None)})
    taylor = taylor_rows(a.taylor)
    for r in taylor:
        rows.append({"case": r["case"] + " Lf", "grid": r["grid"], "level": None, "h [m]": None,
                     "particle_steps [-]": r["particle_steps"], "value": r["Lf"],
                     "vs uniform at the same h [-]": r["dLf"]})
        rows.append({"case": r["case"] + " Dm", "grid": r["grid"], "level": None, "h [m]": None,
                     "particle_steps [-]": r["particle_steps"], "value": r["Dm"],
                     "vs uniform at the same h [-]": r["dDm"]})
    # The axisymmetric Taylor rod's ladders, uniform and graded, against the uniform ladder's
    # finest level (the reference: its error is the smallest measured).
    ladders = {}
    for grid, folder in (("uniform", "taylor_h8_axisymmetric"),
                         ("graded", "taylor_h8_axisymmetric_refined")):
        path = os.path.join(a.taylor_ladders, folder, "ladder.json")
        if os.path.exists(path):
            ladders[grid] = {q: ladder_points(path, q)[0] for q in ("Lf", "Dm")}
    reference = ({q: min(ladders["uniform"][q], key=lambda p: p[1])[3] for q in ("Lf", "Dm")}
                 if "uniform" in ladders else {})
    for grid, per in ladders.items():
        for q, points in per.items():
            for level, h, steps, value in points:
                rows.append({"case": f"Taylor H8 axisymmetric ladder {q}", "grid": grid,
                             "level": level, "h [m]": h, "particle_steps [-]": steps,
                             "value": value,
                             "vs uniform at the same h [-]": value / reference[q] - 1.0})
    try:
        os.makedirs(a.out, exist_ok=True)
        with open(os.path.join(a.out, "graded_cost.csv"), "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0]))
            w.writeheader()
            w.writerows(rows)
    except OSError as e:
        print(f"graded_cost: {a.out}: cannot write ({e.strerror})", file=sys.stderr)
        return 3
    print(f"graded_cost: {os.path.join(a.out, 'graded_cost.csv')}")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("graded_cost: no matplotlib: the table only", file=sys.stderr)
        return 0
    fig, axes = plt.subplots(1, 3 if ladders else 2, figsize=(16 if ladders else 11, 4.2))
    ax, bx = axes[0], axes[1]
    for grid, points, style in (("uniform", uniform, "o-"), ("graded", graded, "s-")):
        pts = sorted((s, v) for _, _, s, v in points if v is not None)
        ax.plot([s for s, _ in pts], [v * 1e3 for _, v in pts], style, label=f"{grid} grid")
        for level, h, s, v in points:
            if v is not None:
                ax.annotate(f"{h * 1e3:.2f} mm", (s, v * 1e3), textcoords="offset points",
                            xytext=(4, -10 if grid == "graded" else 4), fontsize=7)
    rng = u_entry.get("range")
    if isinstance(rng, dict) and rng.get("low") is not None:
        ax.axhspan(rng["low"] * 1e3, rng["high"] * 1e3, color="0.85",
                   label="uniform ladder's range of converged values")
    ax.set_xscale("log")
    ax.set_xlabel("particle-steps [-]")
    ax.set_ylabel(f"{a.observable} [mm]")
    ax.set_title("sphere-cylinder (recommended scene); label: fine cell", fontsize=9)
    ax.legend(fontsize=8)
    for case, marker in (("axisymmetric", "o"), ("3d", "s")):
        sel = [r for r in taylor if r["case"].endswith(case) and r["grid"] != "fine"]
        for r in sel:
            for key, colour in (("dLf", "C0"), ("dDm", "C1")):
                bx.loglog([r["particle_steps"]], [max(abs(r[key]), 1e-6)], marker, color=colour,
                          fillstyle="full" if r["grid"] == "graded" else "none")
                bx.annotate(f"{r['grid']} {case}", (r["particle_steps"], max(abs(r[key]), 1e-6)),
                            textcoords="offset points", xytext=(4, 2), fontsize=7)
    for r in taylor:  # the reference's own cost
        if r["grid"] == "fine":
            bx.axvline(r["particle_steps"], color="0.6", ls=":", lw=1)
            bx.annotate(f"fine {r['case'].split()[-1]}", (r["particle_steps"], 1.2e-5),
                        rotation=90, fontsize=7, color="0.4")
    bx.plot([], [], "o", color="C0", label="|Lf - Lf(fine)| / Lf(fine)")
    bx.plot([], [], "o", color="C1", label="|Dm - Dm(fine)| / Dm(fine)")
    bx.set_xlabel("particle-steps [-]")
    bx.set_ylabel("difference from the uniform fine grid [-]")
    bx.set_title("Taylor rod H8: base (open), graded (filled); dotted: the fine grid's cost",
                 fontsize=9)
    bx.legend(fontsize=8)
    if ladders:
        cx = axes[2]
        for grid, marker in (("uniform", "o-"), ("graded", "s-")):
            for q, colour in (("Lf", "C0"), ("Dm", "C1")):
                pts = sorted((s_, abs(v / reference[q] - 1.0))
                             for _, h, s_, v in ladders.get(grid, {}).get(q, [])
                             if v is not None and abs(v / reference[q] - 1.0) > 0)
                cx.loglog([p[0] for p in pts], [p[1] for p in pts], marker, color=colour,
                          fillstyle="full" if grid == "graded" else "none",
                          label=f"{q}, {grid} ladder")
        cx.set_xlabel("particle-steps [-]")
        cx.set_ylabel("difference from the finest uniform level [-]")
        cx.set_title("Taylor rod H8, axisymmetric ladders (finest uniform: 24 cells per radius)",
                     fontsize=9)
        cx.legend(fontsize=8)
    fig.tight_layout()
    try:
        fig.savefig(os.path.join(a.out, "graded_cost.png"), dpi=110)
    except OSError as e:
        print(f"graded_cost: {a.out}: cannot write ({e.strerror})", file=sys.stderr)
        return 3
    print(f"graded_cost: {os.path.join(a.out, 'graded_cost.png')}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
