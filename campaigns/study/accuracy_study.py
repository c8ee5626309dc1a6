#!/usr/bin/env python3
"""Speed versus accuracy on the recommended sphere-cylinder scene (docs/accuracy.md).

  accuracy_study.py OUT [--mpm build/bin/mpm] [--max-time 40e-6] [--levels 1,1.5,2.25,3]
                        [--max-level-others 2.25] [--threads 2] [--jobs 1] [--analyse-only]

1. Writes variants of data/scenes/sphere_cylinder/recommended.json into OUT/scenes/ (each a
   two-line scene that `extends` it): per method (interpolation gimp/linear x scheme musl/usl)
   a resolution ladder (the report's 50 x 20 x 20 grid times each level), plus, on the report's
   grid with gimp/musl, time-step multipliers 0.2, 0.4, 0.8 and 1 and 3 particles per cell.
2. Runs them with `mpm study OUT/scenes --out OUT/runs --no-plot` (one after another), or with
   --jobs N as N concurrent `mpm run` processes (the most expensive first).
3. Reads every run's summary.json: wall time, particle-steps, the ledger's energy_error, and every
   number under "observables" (per-object mean velocity and kinetic energy, crater depth and
   diameter, peak pressure, gauges: docs/mpm.md). The reference of each observable is the finest
   gimp/musl run; where the gimp/musl ladder converges monotonically over three levels with one
   refinement ratio (1, 1.5, 2.25), with an observed order in [0.5, 3] and confirmed by any finer
   run (3), Richardson extrapolation gives the reference instead and the observed order is
   reported. The 3x level runs for gimp/musl only (--max-level-others).
4. Writes OUT/accuracy.csv (one row per run and observable), OUT/accuracy.md (the table of the
   cheapest setting that reaches 1 %, 5 % and 10 % error per observable, and the observed orders)
   and OUT/pareto_<observable>.png (error versus wall time, one curve per method, the Pareto front
   marked).
Exit codes: 0 done, 1 usage error, 2 input error, 3 a run failed (analysed without it).
"""

import argparse
import concurrent.futures
import csv
import json
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(ROOT, "python"))  # impact.results (pure Python)
import gci  # noqa: E402
from impact import results  # noqa: E402
BASE = os.path.join(ROOT, "data", "scenes", "sphere_cylinder", "recommended.json")
BASE_CELLS = (50, 20, 20)
METHODS = [("gimp", "musl"), ("gimp", "usl"), ("linear", "musl"), ("linear", "usl")]
# The observables compared (summary.json "observables" flattened, plus the gauges' last history
# row); bookkeeping numbers (masses, particle counts, times of the peaks) are not accuracy.
OBSERVABLES = ["abs_energy_error", "crater.depth [m]", "crater.half_depth_diameter [m]",
               "objects.sphere.mean_velocity [m/s][0]", "objects.sphere.kinetic_energy [J]",
               "objects.target.kinetic_energy [J]", "objects.sphere.max_pressure [Pa]",
               "objects.target.max_pressure [Pa]"]


def variant_name(interp, scheme, level, multiplier, ppc):
    return f"case_{interp}_{scheme}_r{level:g}_m{multiplier:g}_p{ppc}"


def variants(levels, max_level_others):
    out = []
    for interp, scheme in METHODS:
        for level in levels:
            # The finest levels (3x: 27x the particles, 3x the steps) only for the reference method.
            if (interp, scheme) != ("gimp", "musl") and level > max_level_others:
                continue
            out.append((interp, scheme, level, 0.1, 2))
    for m in (0.2, 0.4, 0.8):
        out.append(("gimp", "musl", levels[0], m, 2))
    for ppc in (1, 3):
        out.append(("gimp", "musl", levels[0], 0.1, ppc))
    return out


def write_scene(path, interp, scheme, level, multiplier, ppc, max_time):
    cells = [int(round(c * level)) for c in BASE_CELLS]
    patch = {
        "extends": BASE,
        "description": f"{interp}/{scheme}, grid x{level:g} ({cells[0]}x{cells[1]}x{cells[2]}), "
        f"multiplier {multiplier:g}, {ppc} particles per cell per axis",
        "grid": {"cells": cells},
        "solver": {"interpolation": interp, "scheme": scheme},
        "time": {"multiplier": multiplier, "max_time": max_time},
        "objects": {o: {"particles_per_cell": [ppc] * 3} for o in ("sphere", "target")},
        "output": {"snapshots": False},
    }
    with open(path, "w") as f:
        json.dump(patch, f, indent=1)


def estimated_cost(v):
    """Relative cost of a variant: particles (level^3 ppc^3) x steps (level / multiplier)."""
    interp, scheme, level, multiplier, ppc = v
    return level ** 4 * ppc ** 3 / multiplier


def run_in_parallel(mpm, scenes, runs_dir, table, jobs, threads):
    """`mpm run` of every variant, JOBS at a time, the most expensive first (so the last to start
    are the short ones). Each run writes runs_dir/NAME/ as `mpm study` would; a run that stops
    before its summary gets one saying so. Returns 0, or 3 when a run failed, as mpm study does."""
    order = sorted(table, key=estimated_cost, reverse=True)

    def one(v):
        name = variant_name(*v)
        out = os.path.join(runs_dir, name)
        os.makedirs(out, exist_ok=True)
        for stale in ("summary.json", "history.csv"):
            if os.path.exists(os.path.join(out, stale)):
                os.remove(os.path.join(out, stale))
        with open(os.path.join(out, "mpm.log"), "w") as log:
            code = results.Launcher(mpm).run(
                "run", os.path.join(scenes, name + ".json"), out=out, threads=threads,
                check=False, stdout=log, stderr=subprocess.STDOUT).returncode
        if not os.path.exists(os.path.join(out, "summary.json")):
            with open(os.path.join(out, "summary.json"), "w") as f:
                json.dump({"status": "failed", "exit_code": code}, f)
        print(f"accuracy_study: {name}: exit {code}", flush=True)
        return code

    with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as pool:
        codes = list(pool.map(one, order))
    return 3 if any(c != 0 for c in codes) else 0


def flatten(prefix, node, into):
    if isinstance(node, dict):
        for k, v in node.items():
            flatten(f"{prefix}.{k}" if prefix else k, v, into)
    elif isinstance(node, list):
        for i, v in enumerate(node):
            flatten(f"{prefix}[{i}]", v, into)
    elif isinstance(node, (int, float)) and not isinstance(node, bool):
        into[prefix] = float(node)


def read_runs(runs_dir, table):
    runs = []
    for interp, scheme, level, multiplier, ppc in table:
        name = variant_name(interp, scheme, level, multiplier, ppc)
        path = os.path.join(runs_dir, name, "summary.json")
        if not os.path.exists(path):
            continue
        with open(path) as f:
            s = json.load(f)
        flat = {}
        flatten("", s.get("observables", {}), flat)
        flat["abs_energy_error"] = abs(s.get("final", {}).get("energy_error [-]", float("nan")))
        obs = {k: v for k, v in flat.items() if k in OBSERVABLES}
        histories = {}
        if os.path.exists(os.path.join(runs_dir, name, "history.csv")):
            head, rows = results.history_rows(os.path.join(runs_dir, name))
            if rows:
                t = [x[0] for x in rows]
                for i, h in enumerate(head):
                    if h.startswith("gauge_"):
                        obs[h] = rows[-1][i]
                        histories[h] = (t, [x[i] for x in rows])
        runs.append({
            "name": name, "interp": interp, "scheme": scheme, "level": level,
            "multiplier": multiplier, "ppc": ppc, "status": s.get("status", "?"),
            "wall": float(s.get("wall_time [s]", float("nan"))),
            "particle_steps": float(s.get("particles", 0)) * float(s.get("steps", 0)),
            "obs": obs, "histories": histories,
            # Scales of the observables that pass through zero (docs/accuracy.md): the initial
            # kinetic energy and the impact speed |p0| / m_sphere.
            "e0": float(s.get("initial_energy [J]", float("nan"))),
            "v0": (math.sqrt(sum(x * x for x in s.get("initial_momentum [kg m/s]", [0.0])))
                   / s.get("observables", {}).get("objects", {}).get("sphere", {})
                   .get("mass [kg]", float("nan"))),
        })
    return runs


MIN_ORDER, MAX_ORDER = 0.5, 3.0


def scale_of(name, reference, finest):
    """What an observable's error is relative to: the initial kinetic energy for the bodies'
    kinetic energies and the impact speed for their mean velocities (both pass near zero late in
    the impact, where a relative error says nothing), else the reference value itself."""
    if name.endswith("kinetic_energy [J]") and finest["e0"] > 0:
        return finest["e0"]
    if "mean_velocity" in name and finest["v0"] > 0:
        return finest["v0"]
    return abs(reference) if abs(reference) > 0 else 1.0


def interp(xs, ys, x):
    """Piecewise-linear y(x) on ascending xs (x within [xs[0], xs[-1]])."""
    lo, hi = 0, len(xs) - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if xs[mid] <= x:
            lo = mid
        else:
            hi = mid
    if xs[hi] == xs[lo]:
        return ys[lo]
    w = (x - xs[lo]) / (xs[hi] - xs[lo])
    return ys[lo] + w * (ys[hi] - ys[lo])


def richardson(values, levels):
    """Three levels h1 > h2 > h3 (h = 1/level), values f1, f2, f3: the observed order p and the
    extrapolated value when the differences keep their sign and shrink (monotone convergence) and
    the two refinement ratios are equal (this study's triples; campaigns/study/gci.py's
    arithmetic, Celik et al. 2008)."""
    (f1, f2, f3), (r1, r2, r3) = values, levels
    if abs(r2 / r1 - r3 / r2) > 1e-9:
        return None
    t = gci.gci_triple((f3, f2, f1), (1.0 / r3, 1.0 / r2, 1.0 / r1))
    if t["condition"] != "monotonic" or t["order"] is None:
        return None
    return t["order"], t["extrapolated"]


def equal_ratio_triples(ref_runs):
    """Triples of runs (coarse to fine) whose levels have one refinement ratio, finest first."""
    out = []
    n = len(ref_runs)
    for k in range(n - 1, 1, -1):
        for j in range(k - 1, 0, -1):
            for i in range(j - 1, -1, -1):
                a, b, c = (ref_runs[x]["level"] for x in (i, j, k))
                if abs(b / a - c / b) < 1e-9:
                    out.append((ref_runs[i], ref_runs[j], ref_runs[k]))
    return out


def confirmed_by_finer(rich, last, finer, name):
    """A run finer than the triple tests the extrapolation: with order p and limit f, it should
    approach f from the same side as the triple, its error about |f_last - f| (h/h_last)^p. A
    finer run on the other side of f, or more than twice that (and 0.1 % of f) away, means the
    triple was not in the asymptotic range: no Richardson then."""
    p, f = rich
    tolerance = 1e-3 * abs(f)
    for r in finer:
        v = r["obs"].get(name)
        if v is None:
            continue
        side = last["obs"][name] - f
        predicted = abs(side) * (last["level"] / r["level"]) ** p
        crossed = abs(v - f) > tolerance and (v - f > 0) != (side > 0)
        if crossed or abs(v - f) > max(2.0 * predicted, tolerance):
            return False
    return True


# A gauge the wave has not reached by max_time reads round-off: no accuracy to measure. Per unit,
# the magnitude below which the finest run's value (or history) is taken as such.
ROUND_OFF_FLOOR = {"[-]": 1e-6, "[m/s]": 1e-3, "[Pa]": 1e3}
RUN_COLUMNS = ("name", "interp", "scheme", "level", "multiplier", "ppc", "status", "wall",
               "particle_steps")


def reference_runs(runs):
    """(the completed gimp/musl runs at multiplier 0.1 and 2 particles per cell by level, the
    finest, the next-finest or the finest again); SystemExit when there is none."""
    ref_runs = [r for r in runs if (r["interp"], r["scheme"]) == ("gimp", "musl")
                and r["multiplier"] == 0.1 and r["ppc"] == 2 and r["status"] == "completed"]
    ref_runs.sort(key=lambda r: r["level"])
    if not ref_runs:
        raise SystemExit("accuracy_study: no completed gimp/musl reference run")
    return ref_runs, ref_runs[-1], ref_runs[-2] if len(ref_runs) > 1 else ref_runs[-1]


def measured_names(runs, finest):
    """The observables of any run, less those the finest run reads at round-off."""
    names = sorted(set().union(*(r["obs"].keys() for r in runs)))
    return [n for n in names if not any(n.endswith(u) and abs(finest["obs"].get(n, 0.0)) < f
                                        for u, f in ROUND_OFF_FLOOR.items())]


def references(names, ref_runs, finest):
    """(reference value, Richardson's accepted order, the rejected order) per observable: the
    extrapolation of the finest three levels of one ratio where its order lies in [MIN_ORDER,
    MAX_ORDER] and the finer runs confirm it, else the finest run's value."""
    reference, orders, rejected = {}, {}, {}
    for n in names:
        if n == "abs_energy_error":
            reference[n] = 0.0  # exact: the books close
            continue
        reference[n] = finest["obs"].get(n)
        # The finest three levels with one refinement ratio (e.g. 1, 1.5, 2.25 among 1, 1.5,
        # 2.25, 3): Richardson's closed form needs equal ratios.
        for t in equal_ratio_triples(ref_runs):
            vals = [r["obs"].get(n) for r in t]
            if any(v is None for v in vals):
                continue
            rich = richardson(vals, [r["level"] for r in t])
            # An observed order far from the methods' 1-2 means the three grids are not in the
            # asymptotic range (the extrapolation would be wild): keep the finest run then.
            if rich and MIN_ORDER <= rich[0] <= MAX_ORDER and confirmed_by_finer(
                    rich, t[-1], [r for r in ref_runs if r["level"] > t[-1]["level"]], n):
                orders[n] = rich[0]
                reference[n] = rich[1]
            elif rich:
                rejected[n] = rich[0]
            break
    return reference, orders, rejected


def history_errors(runs, finest):
    """(the gauge histories compared, their rows). Gauge histories (the VISAR-like far-end
    velocity, the wall's strain gauges): the error is the largest difference over the
    reference's output times (linear interpolation) relative to the reference history's largest
    magnitude; the reference is the finest run (no Richardson for a whole history)."""
    history_names = [h for h in sorted(finest["histories"])
                     if max(map(abs, finest["histories"][h][1]), default=0.0) >
                     next((f for u, f in ROUND_OFF_FLOOR.items() if h.endswith(u)), 0.0)]
    rows = []
    for r in runs:
        for h in history_names:
            if h not in r["histories"]:
                continue
            tr, vr = finest["histories"][h]
            t, v = r["histories"][h]
            common = [(a, b) for a, b in zip(tr, vr) if t and t[0] <= a <= t[-1]]
            if not common:
                continue
            peak = max(abs(b) for _, b in common)
            diff = max(abs(interp(t, v, a) - b) for a, b in common)
            rows.append({**{k: r[k] for k in RUN_COLUMNS},
                         "observable": "history " + h, "value": max(map(abs, v)),
                         "reference": peak, "error": diff / peak})
    return history_names, rows


def observable_errors(runs, names, reference, finest):
    """A row per run and observable: its value, the reference and the relative error."""
    rows = []
    for r in runs:
        for n in names:
            v, ref = r["obs"].get(n), reference.get(n)
            if v is None or ref is None:
                continue
            if n == "abs_energy_error":
                err = v
            else:
                err = abs(v - ref) / scale_of(n, ref, finest)
            rows.append({**{k: r[k] for k in RUN_COLUMNS},
                         "observable": n, "value": v, "reference": ref, "error": err})
    return rows


def write_accuracy_csv(out, rows):
    with open(os.path.join(out, "accuracy.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["run", "interpolation", "scheme", "grid_level [-]", "multiplier [-]",
                    "particles_per_cell [-]", "status", "wall_time [s]", "particle_steps [-]",
                    "observable", "value [SI]", "reference [SI]", "relative_error [-]"])
        for x in rows:
            w.writerow([x["name"], x["interp"], x["scheme"], x["level"], x["multiplier"],
                        x["ppc"], x["status"], x["wall"], x["particle_steps"], x["observable"],
                        x["value"], x["reference"], x["error"]])


def table_head(finest, second, orders):
    """accuracy.md's title, the reference's description and the observables table's header."""
    return ["# Speed versus accuracy: recommended sphere-cylinder scene", "",
            f"Reference: {'Richardson extrapolation where marked, else ' if orders else ''}"
            f"the finest gimp/musl run ({finest['name']}). Errors relative to the reference "
            "(abs_energy_error: the ledger's |energy_error| itself; kinetic energies relative "
            f"to the initial kinetic energy E0 = {finest['e0']:.5g} J, mean velocities relative "
            f"to the impact speed {finest['v0']:.5g} m/s; gauge histories: the largest "
            "difference over time relative to the reference history's largest magnitude). "
            f"Richardson's observed order is accepted in [{MIN_ORDER:g}, {MAX_ORDER:g}].", "",
            f"The column x{second['level']:g} is the error of the next-finest gimp/musl level: "
            "where the reference is the finest run itself, how far from converged the reference "
            "may still be; where that exceeds a tolerance, no run is named for it (\"reference "
            "not converged\").", "",
            f"| observable [unit] | reference [the observable's unit] | observed order [-] | "
            f"x{second['level']:g} error [%] | cheapest run <= 1 % (its wall time) | <= 5 % | "
            "<= 10 % |",
            "|---|---|---|---|---|---|---|"]


def observable_row(n, rows, finest, second, reference, orders, rejected):
    """(the table's row of observable n, the next-finest level's error or None)."""
    cells = []
    prev = next((x["error"] for x in rows if x["observable"] == n
                 and x["name"] == second["name"]), None)
    for tol in (0.01, 0.05, 0.10):
        # A reference that the next-finest level misses by more than tol is not known to
        # tol itself: a coarse run that happens to land within tol of it is a coincidence.
        if (n != "abs_energy_error" and n not in orders and prev is not None
                and prev > tol):
            cells.append("reference not converged")
            continue
        # The finest run is a candidate only where the reference is not the run itself.
        ok = [x for x in rows if x["observable"] == n and x["error"] <= tol
              and x["status"] == "completed"
              and (n in orders or x["name"] != finest["name"])]
        best = min(ok, key=lambda x: x["wall"]) if ok else None
        cells.append(f"{best['name']} ({best['wall']:.1f} s)" if best else "none")
    ref = reference.get(n)
    shown = n if "[" in n else n + " [-]"  # every row names its unit
    if n.startswith("history "):
        line = f"| {shown} (max over time) | finest run | - |"
    else:
        line = (f"| {shown} | {ref:.4g} | {orders[n]:.2f} (Richardson) |" if n in orders
                else f"| {shown} | {ref:.4g} | {rejected[n]:.2f} (not used: see below) |"
                if n in rejected else f"| {shown} | {ref:.4g} | - |")
    line += (f" {prev * 100:.1f} |" if prev is not None else " - |")
    return line + " " + " | ".join(cells) + " |", prev


def analyse(out, runs, levels):
    """Writes accuracy.csv and accuracy.md of the runs; returns (rows, the observables' names,
    {observable: (the next-finest level's error, that level)} where the reference is the finest
    run itself)."""
    ref_runs, finest, second = reference_runs(runs)
    names = measured_names(runs, finest)
    reference, orders, rejected = references(names, ref_runs, finest)
    history_names, rows = history_errors(runs, finest)
    rows += observable_errors(runs, names, reference, finest)
    write_accuracy_csv(out, rows)
    lines = table_head(finest, second, orders)
    names = names + ["history " + h for h in history_names]
    uncertainty = {}
    for n in names:
        line, prev = observable_row(n, rows, finest, second, reference, orders, rejected)
        if n != "abs_energy_error" and n not in orders and prev is not None:
            uncertainty[n] = (prev, second["level"])
        lines.append(line)
    if rejected:
        lines += ["", "Not used: an order outside the accepted window, or a finer run that the "
                  "extrapolation does not predict (farther from the extrapolated value than twice "
                  "the error its order implies); the reference is then the finest run."]
    lines += ["", "| run | status | wall [s] | particle-steps [-] | abs(energy_error) [-] |",
              "|---|---|---|---|---|"]
    for r in runs:
        lines.append(f"| {r['name']} | {r['status']} | {r['wall']:.1f} | {r['particle_steps']:.3g} "
                     f"| {r['obs'].get('abs_energy_error', float('nan')):.3g} |")
    with open(os.path.join(out, "accuracy.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    return rows, names, uncertainty


def pareto_front(points):
    """Non-dominated (cost, error) points: no other point is both cheaper and more accurate."""
    front = []
    for c, e, tag in sorted(points):
        if not front or e < front[-1][1]:
            front.append((c, e, tag))
    return front


def draw(out, rows, names, wall_label, uncertainty):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("accuracy_study: matplotlib missing: no figures (table written)", file=sys.stderr)
        return
    for n in names:
        pts = [x for x in rows if x["observable"] == n and x["status"] == "completed"
               and x["error"] > 0]
        if not pts:
            continue
        fig, axes = plt.subplots(1, 2, figsize=(13, 5))
        for ax, cost, label in ((axes[0], "wall", wall_label),
                                (axes[1], "particle_steps", "particle-steps [-]")):
            for interp, scheme in METHODS:
                ladder = sorted((x for x in pts if (x["interp"], x["scheme"]) == (interp, scheme)
                                 and x["multiplier"] == 0.1 and x["ppc"] == 2),
                                key=lambda x: x["level"])
                if ladder:
                    grids = ", x".join("%g" % x["level"] for x in ladder)
                    ax.loglog([x[cost] for x in ladder], [x["error"] for x in ladder], "o-",
                              label=f"{interp}/{scheme} (grid x{grids})")
            for x in pts:
                if x["multiplier"] != 0.1 or x["ppc"] != 2:
                    ax.loglog(x[cost], x["error"], "s", color="gray")
                    ax.annotate(f"m {x['multiplier']:g}, ppc {x['ppc']}", (x[cost], x["error"]),
                                fontsize=7)
            front = pareto_front([(x[cost], x["error"], x["name"]) for x in pts])
            ax.loglog([c for c, _, _ in front], [e for _, e, _ in front], "k--", lw=1,
                      label="Pareto front")
            if n in uncertainty:
                # Below the next-finest level's error the reference (the finest run) is not
                # known well enough to rank runs: a point there agrees with it by chance.
                u, lv = uncertainty[n]
                ax.axhspan(min(x["error"] for x in pts) / 2, u, color="gold", alpha=0.25,
                           label=f"below the x{lv:g} level's own error: not resolved")
            ax.set_xlabel(label)
            ax.set_ylabel(f"relative error of {n} [-]")
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=7)
        safe = "".join(ch if ch.isalnum() or ch in "._-" else "_" for ch in n)
        fig.tight_layout()
        fig.savefig(os.path.join(out, f"pareto_{safe}.png"), dpi=110)
        plt.close(fig)


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("out")
    p.add_argument("--mpm", default=os.path.join(ROOT, "build", "bin", "mpm"))
    p.add_argument("--max-time", type=float, default=40e-6)
    p.add_argument("--levels", default="1,1.5,2.25,3",
                   help="grid levels (x the deck's 50x20x20 cells per axis)")
    p.add_argument("--max-level-others", type=float, default=2.25,
                   help="finest level run for the methods other than gimp/musl")
    p.add_argument("--threads", type=int, default=2, help="threads per run")
    p.add_argument("--jobs", type=int, default=1,
                   help="runs at a time (e.g. --jobs 2 --threads 1 on 2 cores: more runs per "
                   "hour than one 2-thread run at a time; wall times are then 1-thread times)")
    p.add_argument("--analyse-only", action="store_true")
    a = p.parse_args()
    try:
        levels = [float(x) for x in a.levels.split(",")]
    except ValueError:
        p.error("--levels: expected comma-separated numbers, e.g. 1,1.5,2")
    table = variants(levels, a.max_level_others)
    scenes, runs_dir = os.path.join(a.out, "scenes"), os.path.join(a.out, "runs")
    os.makedirs(scenes, exist_ok=True)
    code = 0
    if not a.analyse_only:
        for v in table:
            write_scene(os.path.join(scenes, variant_name(*v) + ".json"), *v, a.max_time)
        if a.jobs == 1:
            code = results.Launcher(a.mpm).run("study", scenes, out=runs_dir, threads=a.threads,
                                               extra=["--no-plot"], check=False,
                                               capture=False).returncode
        else:
            code = run_in_parallel(a.mpm, scenes, runs_dir, table, a.jobs, a.threads)
        if code not in (0, 3):
            return code
    rows, names, uncertainty = analyse(a.out, read_runs(runs_dir, table), levels)
    draw(a.out, rows, names, f"wall time [s] ({a.threads} thread(s) per run, {a.jobs} run(s) "
         "at a time)", uncertainty)
    print(f"accuracy_study: wrote {a.out}/accuracy.md, accuracy.csv and pareto_*.png")
    return code


if __name__ == "__main__":
    sys.exit(main())
