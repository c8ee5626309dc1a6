#!/usr/bin/env python3
"""Tables and figures of a Taylor-impact campaign (campaigns/taylor/taylor.py OUT).

  campaigns/taylor/taylor_report.py OUT [--tables-only]

Reads OUT/results.csv and OUT/profiles/, writes OUT/results.md and (unless --tables-only, which
needs neither NumPy nor matplotlib) the figures
OUT/lf_dm_vs_speed.png, OUT/profiles.png, OUT/failure_causes_<set>_<failure>.png (failure modes
other than off) and OUT/ladder.png (when more than one resolution was run). With three or more
resolutions, also OUT/convergence.csv: per shot, Lf and Dm extrapolated from the three finest
levels (Richardson, with the observed order; `richardson` below) and the errors of every level
and of the extrapolation against the experiment.

A shot whose measurement is empty in the data table has no error: its prediction is in the tables
and it is left out of the error statistics (not judged). Xf is never judged.

Exit codes: 0 done, 1 usage error, 2 input error (OUT/results.csv missing or unreadable),
3 an output could not be written, 130 interrupted.
"""

import argparse
import csv
import math
import os
import sys
from collections import defaultdict

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "study"))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import gci  # noqa: E402
from impact import results  # noqa: E402

CAUSES = ["none", "melting", "tepla", "drucker", "becker"]
CAUSE_COLOURS = {"none": "#c8c8c8", "melting": "tab:orange", "tepla": "tab:red",
                 "drucker": "tab:blue", "becker": "tab:green"}
SET_MARKERS = {"table1": "s", "fit_all": "o", "fit_room": "^", "scg": "D", "fit_za": "v", "fit_ptw": "P"}
PROFILE_SHOTS = ["H3", "H8", "H10", "H13", "H16", "H21"]
TEXT_COLUMNS = {"set", "failure", "anvil", "geometry", "shot", "message", "last_snapshot",
                "material_reached_faces", "confined_attempts"}


def load(out):
    """The rows of OUT/results.csv, numbers as floats, an empty number (a measurement the data
    table leaves empty, and its error) as None; `order` numbers the shots as the file lists them."""
    with open(os.path.join(out, "results.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    order = {}
    for r in rows:
        for k, v in list(r.items()):
            if k in TEXT_COLUMNS:
                continue
            try:
                r[k] = float(v)
            except (TypeError, ValueError):
                r[k] = None if v == "" else v
        r["cells_per_radius"] = int(r["cells_per_radius"])
        r["ok"] = r["exit_code"] == 0
        order.setdefault(r["shot"], len(order))
    for r in rows:
        r["order"] = order[r["shot"]]
    return rows


def judged(rows, key):
    """The errors `key` of the rows whose shot has that measurement."""
    return [r[key] for r in rows if r.get(key) is not None]


def error_stats(errors):
    """'mean / mean abs / worst abs' of a list of errors [%], or 'not measured'."""
    if not errors:
        return "not measured"
    return (f"{sum(errors) / len(errors):+.2f} / {sum(map(abs, errors)) / len(errors):.2f} / "
            f"{max(map(abs, errors)):.2f}")


def richardson(levels, values):
    """Richardson extrapolation from three resolutions (cells per radius n1 < n2 < n3, the values
    f1, f2, f3): (p, f_ext), the observed order and the extrapolated value, or None unless the
    three converge monotonically (differences of one sign that shrink). The arithmetic is
    campaigns/study/gci.py's (Celik et al. 2008, eqs. 3-4, h = 1 / n: unequal ratios solved)."""
    (n1, n2, n3), (f1, f2, f3) = levels, values
    t = gci.gci_triple((f3, f2, f1), (1.0 / n3, 1.0 / n2, 1.0 / n1))
    if t["condition"] != "monotonic" or t["order"] is None:
        return None
    return t["order"], t["extrapolated"]


def group(rows, *keys):
    g = defaultdict(list)
    for r in rows:
        g[tuple(r[k] for k in keys)].append(r)
    return g


def summary_table(rows):
    lines = ["| set | failure | cells per radius [-] | runs (ok) [-] | Lf error mean / mean abs / "
             "worst abs [%] | Dm error mean / mean abs / worst abs [%] | failed particles (core, "
             "core under pressure) [-] | at rest by [us] | energy error worst [%] | wall [s] |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for (s, f, n), rs in sorted(group(rows, "set", "failure", "cells_per_radius").items()):
        ok = [r for r in rs if r["ok"]]
        if not ok:
            lines.append(f"| {s} | {f} | {n} | {len(rs)} (0) | | | | | | |")
            continue
        lf = judged(ok, "Lf_error [%]")
        dm = judged(ok, "Dm_error [%]")
        rest = [r["time_to_rest [s]"] for r in ok]
        rest_text = ("not all" if any(math.isnan(x) for x in rest)
                     else f"{1e6 * max(rest):.0f}")
        lines.append(
            f"| {s} | {f} | {n} | {len(rs)} ({len(ok)}) | {error_stats(lf)} | "
            f"{error_stats(dm)} | {sum(int(r['failed']) for r in ok)} "
            f"({sum(int(r['failed_core']) for r in ok)}, "
            f"{sum(int(r['failed_core_under_pressure']) for r in ok)}) | {rest_text} | "
            f"{100 * max(abs(r['energy_error [-]']) for r in ok):.2f} | "
            f"{sum(r['wall_time [s]'] for r in ok):.0f} |")
    return lines


def shot_table(rows, failure="off"):
    finest = defaultdict(int)
    for r in rows:
        if r["failure"] == failure:
            finest[r["set"]] = max(finest[r["set"]], r["cells_per_radius"])
    sets = sorted(finest)
    by = {(r["set"], r["shot"]): r for r in rows
          if r["failure"] == failure and r["cells_per_radius"] == finest[r["set"]]}
    head = "| shot | L0/D0 [-] | U0 [m/s] | Lf exp [mm] | " + " | ".join(
        f"Lf {s} [mm] (%)" for s in sets) + " | Dm exp [mm] | " + " | ".join(
        f"Dm {s} [mm] (%)" for s in sets) + " | Xf exp [mm] | " + " | ".join(
        f"Xf {s} [mm]" for s in sets) + " |"
    lines = [f"Failure {failure}, at {', '.join(f'{s}: {finest[s]}' for s in sets)} cells per "
             "radius; Xf is reported, never judged (0: the plastic edge reached the rear end).", "",
             head, "|" + "---|" * (6 + 3 * len(sets))]
    shots = sorted({(r["order"], r["shot"]) for r in rows})
    for _, sh in shots:
        ref = next((by[(s, sh)] for s in sets if (s, sh) in by), None)
        if ref is None:
            continue

        def cell(s, key, err):
            r = by.get((s, sh))
            if r is None or not r["ok"]:
                return "stopped" if r is not None else ""
            if err is None:
                return f"{1e3 * r[key]:.1f}"
            if r[err] is None:
                return f"{1e3 * r[key]:.2f} (not judged)"
            return f"{1e3 * r[key]:.2f} ({r[err]:+.1f})"

        def measured(key):
            return "-" if ref[key] is None else f"{1e3 * ref[key]:.1f}"

        lines.append(
            f"| {sh} | {ref['L0_over_D0 [-]']:g} | {ref['U0 [m/s]']:g} | "
            f"{measured('Lf_exp [m]')} | " +
            " | ".join(cell(s, "Lf [m]", "Lf_error [%]") for s in sets) +
            f" | {measured('Dm_exp [m]')} | " +
            " | ".join(cell(s, "Dm [m]", "Dm_error [%]") for s in sets) +
            f" | {measured('Xf_exp [m]')} | " +
            " | ".join(cell(s, "Xf [m]", None) for s in sets) + " |")
    return lines


def ladder_table(rows):
    levels = sorted({r["cells_per_radius"] for r in rows})
    if len(levels) < 2:
        return []
    lines = ["| set | failure | shot | " + " | ".join(f"Lf at {n} [mm]" for n in levels) +
             " | change between the two finest [%] | " +
             " | ".join(f"Dm at {n} [mm]" for n in levels) + " |",
             "|" + "---|" * (4 + 2 * len(levels))]
    for (s, f, sh), rs in sorted(group(rows, "set", "failure", "shot").items()):
        by = {r["cells_per_radius"]: r for r in rs if r["ok"]}
        if len(by) < 2:
            continue
        have = sorted(by)
        change = 100 * (by[have[-1]]["Lf [m]"] / by[have[-2]]["Lf [m]"] - 1)
        lines.append(f"| {s} | {f} | {sh} | " + " | ".join(
            f"{1e3 * by[n]['Lf [m]']:.3f}" if n in by else "" for n in levels) +
            f" | {change:+.2f} | " + " | ".join(
            f"{1e3 * by[n]['Dm [m]']:.2f}" if n in by else "" for n in levels) + " |")
    return lines


def equal_ratio_triple(levels):
    """The triple n1 < n2 < n3 of `levels` with n2 / n1 = n3 / n2 that ends at the finest level,
    the finest such (e.g. 4, 8, 16 of 4..16), or None: the closed form's check on the three
    finest."""
    finest = levels[-1]
    for n2 in sorted(levels[:-1], reverse=True):
        n1 = n2 * n2 / finest
        if n1 in levels[:-1] and n1 < n2:
            return (int(n1), n2, finest)
    return None


def convergence(rows, out=None):
    """Per set and failure mode with three or more resolutions: per shot, Lf and Dm at every level
    and extrapolated from the three finest (richardson; the observed order p in brackets, '-'
    where the differences oscillate or grow), then the errors against the experiment at every
    level and of the extrapolations; where the levels hold a triple with one refinement ratio
    that ends at the finest (equal_ratio_triple) and is not the three finest, its extrapolation
    too. With `out`, the per-shot figures go to OUT/convergence.csv."""
    lines, table = [], []
    for (s, f), rs in sorted(group([r for r in rows if r["ok"]], "set", "failure").items()):
        levels = sorted({r["cells_per_radius"] for r in rs})
        if len(levels) < 3:
            continue
        by_shot = defaultdict(dict)
        for r in rs:
            by_shot[(r["order"], r["shot"])][r["cells_per_radius"]] = r
        triple = equal_ratio_triple(levels)
        if triple == tuple(levels[-3:]):
            triple = None
        extra = f" | from {'/'.join(map(str, triple))} [mm] (p)" if triple else ""
        head = ("| shot | " + " | ".join(f"Lf at {n} [mm]" for n in levels) +
                " | Lf extrapolated [mm] (p)" + extra + " | " +
                " | ".join(f"Dm at {n} [mm]" for n in levels) + " | Dm extrapolated [mm] (p)" +
                extra + " |")
        lines += [f"Set {s}, failure {f}: extrapolated from the three finest levels each shot has "
                  "(Richardson with the observed order p; general form for a non-constant ratio)" +
                  (f", and from {'/'.join(map(str, triple))} (one ratio, the closed form)"
                   if triple else "") + "; '-': the differences oscillate or grow.",
                  "", head, "|" + "---|" * (3 + 2 * len(levels) + (2 if triple else 0))]
        errors = defaultdict(lambda: defaultdict(list))  # [key][level or "ext"] -> errors [%]
        for (_, sh), by in sorted(by_shot.items()):
            have = sorted(by)
            ref = by[have[-1]]
            entry = {"set": s, "failure": f, "shot": sh}
            cells = {}
            for key in ("Lf", "Dm"):
                exp = ref[f"{key}_exp [m]"]
                for n in have:
                    entry[f"{key} n{n} [m]"] = by[n][f"{key} [m]"]
                    if exp is not None:
                        errors[key][n].append(100.0 * (by[n][f"{key} [m]"] / exp - 1.0))
                est = (richardson(have[-3:], [by[n][f"{key} [m]"] for n in have[-3:]])
                       if len(have) >= 3 else None)
                entry[f"{key}_levels"] = "/".join(str(n) for n in have[-3:])
                entry[f"{key} extrapolated [m]"] = est[1] if est else ""
                entry[f"{key} observed order [-]"] = est[0] if est else ""
                entry[f"{key}_exp [m]"] = "" if exp is None else exp
                entry[f"{key} extrapolated error [%]"] = (
                    100.0 * (est[1] / exp - 1.0) if est and exp is not None else "")
                if est and exp is not None:
                    errors[key]["ext"].append(100.0 * (est[1] / exp - 1.0))
                cells[key] = (" | ".join(f"{1e3 * by[n][f'{key} [m]']:.3f}" if n in by else ""
                                         for n in levels) + " | " +
                              (f"{1e3 * est[1]:.3f} ({est[0]:.2f})" if est else "-"))
                if triple:
                    alt = (richardson(triple, [by[n][f"{key} [m]"] for n in triple])
                           if all(n in by for n in triple) else None)
                    tag = "/".join(map(str, triple))
                    entry[f"{key} extrapolated {tag} [m]"] = alt[1] if alt else ""
                    entry[f"{key} observed order {tag} [-]"] = alt[0] if alt else ""
                    if alt and exp is not None:
                        errors[key]["alt"].append(100.0 * (alt[1] / exp - 1.0))
                    cells[key] += " | " + (f"{1e3 * alt[1]:.3f} ({alt[0]:.2f})" if alt else "-")
            table.append(entry)
            lines.append(f"| {sh} | {cells['Lf']} | {cells['Dm']} |")
        lines += ["", "| cells per radius [-] | shots judged (Lf / Dm) [-] | Lf error mean / "
                  "mean abs / worst abs [%] | "
                  "Dm error mean / mean abs / worst abs [%] |", "|---|---|---|---|"]
        names = {"ext": "extrapolated from the three finest",
                 "alt": f"extrapolated from {'/'.join(map(str, triple or ()))}"}
        for n in levels + ["ext"] + (["alt"] if triple else []):
            lines.append(f"| {names.get(n, n)} | {len(errors['Lf'][n])} / {len(errors['Dm'][n])} | "
                         f"{error_stats(errors['Lf'][n])} | {error_stats(errors['Dm'][n])} |")
        lines.append("")
    if out and table:
        keys = []
        for e in table:
            keys += [k for k in e if k not in keys]
        with open(os.path.join(out, "convergence.csv"), "w", newline="") as f:
            w = csv.DictWriter(f, keys, lineterminator="\n")
            w.writeheader()
            w.writerows(table)
    return lines


def failure_table(rows):
    fr = [r for r in rows if r["failure"] != "off" and r["ok"]]
    if not fr:
        return []
    lines = ["| set | failure | cells per radius [-] | shot | particles [-] | failed [-] | "
             "melting [-] | tepla [-] | drucker [-] | becker [-] | core failed (of) [-] | "
             "core under pressure [-] | reported unstable [-] | Lf [mm] (% of failure off) |",
             "|" + "---|" * 14]
    off = {(r["set"], r["cells_per_radius"], r["shot"]): r for r in rows
           if r["failure"] == "off" and r["ok"]}
    for r in sorted(fr, key=lambda r: (r["set"], r["failure"], r["cells_per_radius"],
                                       r["order"])):
        o = off.get((r["set"], r["cells_per_radius"], r["shot"]))
        rel = f"{100 * (r['Lf [m]'] / o['Lf [m]'] - 1):+.2f}" if o else "n/a"
        lines.append(
            f"| {r['set']} | {r['failure']} | {r['cells_per_radius']} | {r['shot']} | "
            f"{int(r['particles'])} | {int(r['failed'])} | {int(r['failed_melting'])} | "
            f"{int(r['failed_tepla'])} | {int(r['failed_drucker'])} | {int(r['failed_becker'])} | "
            f"{int(r['failed_core'])} ({int(r['core'])}) | {int(r['failed_core_under_pressure'])} | "
            f"{int(r['reported_unstable'])} | {1e3 * r['Lf [m]']:.2f} ({rel}) |")
    return lines


def figures(out, rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    off = [r for r in rows if r["failure"] == "off" and r["ok"]]
    finest = defaultdict(int)
    for r in off:
        finest[r["set"]] = max(finest[r["set"]], r["cells_per_radius"])
    off = [r for r in off if r["cells_per_radius"] == finest[r["set"]]]
    aspects = sorted({r["L0_over_D0 [-]"] for r in rows})
    colours = {a: plt.cm.viridis(i / max(1, len(aspects) - 1)) for i, a in enumerate(aspects)}
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.8))
    for ax, key, exp, ref, label in [(axes[0], "Lf [m]", "Lf_exp [m]", "L0 [m]", "Lf / L0"),
                                     (axes[1], "Dm [m]", "Dm_exp [m]", "D0 [m]", "Dm / D0")]:
        for a in aspects:
            ex = sorted({(r["U0 [m/s]"], r[exp] / r[ref]) for r in rows
                         if r["L0_over_D0 [-]"] == a and r[exp] is not None})
            ax.plot([x for x, _ in ex], [y for _, y in ex], "*", ms=11, color=colours[a],
                    mec="k", label=f"L0/D0 = {a:g}, experiment" if key == "Lf [m]" else None)
            for s in sorted(finest):
                sim = sorted((r["U0 [m/s]"], r[key] / r[ref]) for r in off
                             if r["set"] == s and r["L0_over_D0 [-]"] == a)
                ax.plot([x for x, _ in sim], [y for _, y in sim],
                        SET_MARKERS.get(s, "d") + "-", mfc="none", color=colours[a], lw=0.8)
        ax.set_xlabel("impact speed U0 [m/s]")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    for s in sorted(finest):
        axes[1].plot([], [], SET_MARKERS.get(s, "d"), mfc="none", color="k",
                     label=f"{s} ({finest[s]} cells/radius)")
    axes[0].legend(fontsize=7)
    axes[1].legend(fontsize=8)
    fig.suptitle("Taylor impact of 6061-T6 (House et al. 1995): experiment (stars) and MPM "
                 "prediction, failure off")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "lf_dm_vs_speed.png"), dpi=110)
    plt.close(fig)

    shots = [s for s in PROFILE_SHOTS if any(r["shot"] == s for r in off)]
    if shots:
        fig, axes = plt.subplots(2, 3, figsize=(13, 7))
        for ax, sh in zip(axes.flat, shots):
            for r in off:
                if r["shot"] != sh:
                    continue
                tag = f"{r['set']}_off_n{r['cells_per_radius']}"
                with open(os.path.join(out, "profiles", f"{tag}_{sh}.csv")) as f:
                    pts = [tuple(map(float, line.split(",")[:2])) for line in f.readlines()[1:]]
                ax.plot([1e3 * x for x, _ in pts], [1e3 * y for _, y in pts],
                        label=f"{r['set']} ({r['cells_per_radius']} cells/radius)")
                exp = r
            if exp["Dm_exp [m]"] is not None:
                ax.plot([0.0], [0.5e3 * exp["Dm_exp [m]"]], "k*", ms=12, label="experiment Dm/2")
            if exp["Lf_exp [m]"] is not None:
                ax.axvline(1e3 * exp["Lf_exp [m]"], color="k", ls="--", lw=0.8,
                           label="experiment Lf")
            ax.axhline(0.5e3 * exp["D0 [m]"], color="0.6", ls=":", lw=0.8)
            ax.set_title(f"{sh}: L0/D0 = {exp['L0_over_D0 [-]']:g}, {exp['U0 [m/s]']:g} m/s",
                         fontsize=9)
            ax.set_xlabel("x (distance from the anvil) [mm]")
            ax.set_ylabel("radius [mm]")
            ax.grid(alpha=0.3)
        axes.flat[0].legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(out, "profiles.png"), dpi=110)
        plt.close(fig)

    for (s, f, n), rs in sorted(group([r for r in rows if r["failure"] != "off" and r["ok"]],
                                      "set", "failure", "cells_per_radius").items()):
        shots = [r for r in sorted(rs, key=lambda r: r["order"])]
        cols = min(4, len(shots))
        nrows = math.ceil(len(shots) / cols)
        fig, axes = plt.subplots(nrows, cols, figsize=(3.6 * cols, 2.8 * nrows), squeeze=False)
        for ax in axes.flat:
            ax.axis("off")
        for ax, r in zip(axes.flat, shots):
            ax.axis("on")
            snapshot = os.path.join(out, r["last_snapshot"])  # relative to OUT
            if not os.path.exists(snapshot):
                continue
            d = results.read_points(snapshot)
            rod = d["object"] == d["object"].max()
            h = 0.5 * r["D0 [m]"] / r["cells_per_radius"] / 2
            cut = rod & (d["points"][:, 2] < h)  # the layer on the mirror plane z = 0
            x, y = 1e3 * d["points"][cut, 0], 1e3 * d["points"][cut, 1]
            cause = d["failure_cause"][cut].astype(int)
            tension = d["failed_in_tension"][cut] > 0.5
            for i, c in enumerate(CAUSES):
                m = cause == i
                ax.scatter(x[m & ~tension], y[m & ~tension], s=3, color=CAUSE_COLOURS[c],
                           label=c if c != "none" else "not failed")
                ax.scatter(x[m & tension], y[m & tension], s=5, marker="x",
                           color=CAUSE_COLOURS[c])
            ax.set_aspect("equal")
            ax.set_title(f"{r['shot']}: {int(r['failed'])} of {int(r['particles'])} failed",
                         fontsize=8)
            ax.tick_params(labelsize=6)
        axes.flat[0].legend(fontsize=6, markerscale=3)
        fig.suptitle(f"Failed particles by cause, {s}, failure {f}, {n} cells/radius\nlayer on the "
                     "mirror plane z = 0: x [mm] from the anvil across, radius [mm] up; x marks: "
                     "failed with a tensile mean stress", fontsize=9)
        fig.tight_layout()
        fig.savefig(os.path.join(out, f"failure_causes_{s}_{f}_n{n}.png"), dpi=110)
        plt.close(fig)

    levels = sorted({r["cells_per_radius"] for r in rows})
    if len(levels) > 1:
        fig, ax = plt.subplots(figsize=(6.5, 4.5))
        for (s, f, sh), rs in sorted(group([r for r in rows if r["ok"]], "set", "failure",
                                           "shot").items()):
            rs = sorted(rs, key=lambda r: r["cells_per_radius"])
            if len(rs) < 2 or any(r["Lf_error [%]"] is None for r in rs):
                continue
            ax.plot([r["cells_per_radius"] for r in rs], [r["Lf_error [%]"] for r in rs],
                    SET_MARKERS.get(s, "d") + "-", label=f"{s}, {sh}" + ("" if f == "off" else f))
        ax.set_xlabel("cells per rod radius")
        ax.set_ylabel("Lf error against the experiment [%]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(os.path.join(out, "ladder.png"), dpi=110)
        plt.close(fig)


def report(out, draw=True):
    """OUT/results.md from OUT/results.csv, and the figures unless draw is False."""
    rows = load(out)
    lines = ["# Taylor impact campaign", "",
             "Written by campaigns/taylor/taylor_report.py from results.csv (errors: simulation / "
             "experiment - 1; lengths in mm in the tables, SI in results.csv).", ""]
    anvils = sorted({r.get("anvil") or "mirror" for r in rows})
    geometries = sorted({r.get("geometry") or "3d" for r in rows})
    lines += [f"Anvil: {', '.join(anvils)} (mirror: the symmetric x- face, rigid and frictionless; "
              "wall:MU: a rigid wall that never pulls, Coulomb friction MU; rigid:MU: a rigid "
              "body at rest in contact, likewise; rigid_particles:0: that body met at the rod's "
              "particles, frictionless).", "",
              f"Geometry: {', '.join(geometries)} (3d: the quarter model; axisymmetric: the r-z "
              "section on a 2D grid).", "",
              "## Per parameter set, failure mode and resolution", ""]
    lines += summary_table(rows)
    for f in sorted({r["failure"] for r in rows}):
        lines += ["", f"## Per shot, failure {f}", ""] + shot_table(rows, f)
    lad = ladder_table(rows)
    if lad:
        lines += ["", "## Resolution ladder", ""] + lad
    conv = convergence(rows, out)
    if conv:
        lines += ["", "## Convergence (Richardson)", ""] + conv
    ft = failure_table(rows)
    if ft:
        lines += ["", "## Failed particles by cause", ""] + ft
    confined = [r for r in rows if r.get("material_reached_faces")]
    enlarged = [r for r in rows if r.get("confined_attempts") and not r.get(
        "material_reached_faces")]
    if confined or enlarged:
        lines += ["", "## Grids enlarged, and runs whose material reached an outer face", "",
                  "A run whose mushroom reached the grid's outer face (y+, z+: a mirror) is run "
                  "again on a grid 1.5 times wider (docs/taylor.md); those still confined are "
                  "flagged: their Lf and Dm may be wrong.", ""]
        lines += [f"- {r['set']} {r['failure']} {r['cells_per_radius']} {r['shot']}: "
                  + (f"CONFINED at {r['radial_extent_over_R0 [-]']:.3g} R0: "
                     f"{r['material_reached_faces']}" if r in confined else
                     f"grid {r['radial_extent_over_R0 [-]']:.3g} R0")
                  + (f" (before: {r['confined_attempts']})" if r.get("confined_attempts")
                     else "") for r in confined + enlarged]
    stopped = [r for r in rows if not r["ok"]]
    if stopped:
        lines += ["", "## Stopped runs", ""] + [
            f"- {r['set']} {r['failure']} {r['cells_per_radius']} {r['shot']}: exit "
            f"{int(r['exit_code'])}: {r.get('message', '')}" for r in stopped]
    with open(os.path.join(out, "results.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    if draw:
        figures(out, rows)
    print(f"taylor: wrote {out}/results.md" + (" and the figures" if draw else ""))


class Parser(argparse.ArgumentParser):
    def error(self, message):  # a usage error exits 1 (argparse's 2 is our input error)
        self.print_usage(sys.stderr)
        print(f"taylor_report: {message}", file=sys.stderr)
        sys.exit(1)


def main(argv):
    ap = Parser(prog="taylor_report.py", description=__doc__,
                formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out", help="the campaign's directory (campaigns/taylor/taylor.py OUT)")
    ap.add_argument("--tables-only", action="store_true",
                    help="write results.md only (no figures: needs neither NumPy nor matplotlib)")
    args = ap.parse_args(argv)
    table = os.path.join(args.out, "results.csv")
    if not os.path.isfile(table):
        print(f"taylor_report: {table}: no such file (run campaigns/taylor/taylor.py "
              f"{args.out} first)", file=sys.stderr)
        return 2
    try:
        report(args.out, not args.tables_only)
    except (KeyError, ValueError) as e:
        print(f"taylor_report: {table}: not a campaign's table ({type(e).__name__}: {e})",
              file=sys.stderr)
        return 2
    except OSError as e:
        print(f"taylor_report: {e.filename or args.out}: cannot write: {e.strerror}",
              file=sys.stderr)
        return 3
    except KeyboardInterrupt:
        print("taylor_report: interrupted", file=sys.stderr)
        return 130
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
