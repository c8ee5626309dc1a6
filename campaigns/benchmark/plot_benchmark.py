#!/usr/bin/env python3
"""Figures of mpm_benchmark's CSVs (docs/performance.md).

  plot_benchmark.py DIR      reads DIR/scaling.csv, DIR/features.csv, DIR/box.csv (whichever
                             exist) and writes DIR/scaling.png, DIR/features.png, DIR/box.png
                             and DIR/tables.md (the tables of docs/performance.md, made from
                             the same CSVs so that text and figures cannot disagree)

scaling.png: wall time per step against the particle count (log-log, least-squares slope in the
legend) and particle-steps per second, per interpolation and thread count. features.png: cost of
each optional feature relative to the minimal deck (error bar: the spread of the repeats).
box.png: seconds per particle-step and active nodes for the report's, the tight and the 2x box,
dense grid against active blocks.
"""

import csv
import math
import os
import sys


def read(path):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def slope(xs, ys):
    lx, ly = [math.log(x) for x in xs], [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    sxx = sum((x - mx) ** 2 for x in lx)
    return sum((x - mx) * (y - my) for x, y in zip(lx, ly)) / sxx if sxx > 0 else float("nan")


def scaling_series(rows):
    """{(interpolation, threads): [(particles, wall per step, particle-steps per second)]}, by
    particle count, and the log-log slope of wall per step against particles (nan for one point)."""
    series = {}
    for r in rows:
        series.setdefault((r["interpolation"], r["threads [-]"]), []).append(
            (float(r["particles [-]"]), float(r["wall [s]"]) / float(r["steps [-]"]),
             float(r["particle_steps_per_second [1/s]"])))
    out = {}
    for key in sorted(series, key=lambda k: (k[0], int(k[1]))):
        pts = sorted(series[key])
        s = slope([p[0] for p in pts], [p[1] for p in pts]) if len(pts) > 1 else float("nan")
        out[key] = (pts, s)
    return out


def save(plt, fig, out, name):
    fig.tight_layout()
    fig.savefig(os.path.join(out, name), dpi=110)
    plt.close(fig)


def scaling(plt, rows, out):
    fig, (a, b) = plt.subplots(1, 2, figsize=(12, 4.5))
    for (interp, threads), (pts, s) in scaling_series(rows).items():
        n = [p[0] for p in pts]
        a.loglog(n, [p[1] for p in pts], "o-", label=f"{interp}, {threads} thread(s): slope {s:.2f}")
        b.semilogx(n, [p[2] / 1e6 for p in pts], "o-", label=f"{interp}, {threads} thread(s)")
    a.set_xlabel("particles [-]")
    a.set_ylabel("wall time per step [s]")
    b.set_xlabel("particles [-]")
    b.set_ylabel("million particle-steps per second [1/s]")
    b.set_ylim(bottom=0)
    for ax in (a, b):
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle("recommended.json (MUSL), grid x1, x1.5, x2, x3 of the report's 50 x 20 x 20")
    save(plt, fig, out, "scaling.png")


def features(plt, rows, out):
    fig, ax = plt.subplots(figsize=(10, 4.8))
    names = [r["variant"] for r in rows]
    rel = [float(r["relative_to_minimal [-]"]) for r in rows]
    spread = [float(r["spread [-]"]) * x for r, x in zip(rows, rel)]
    ax.barh(range(len(rows)), rel, xerr=spread, color="tab:blue", alpha=0.8, capsize=3)
    ax.axvline(1.0, color="k", lw=1)
    ax.set_yticks(range(len(rows)))
    ax.set_yticklabels(names, fontsize=8)
    ax.invert_yaxis()
    ax.set_xlabel("seconds per particle-step relative to the minimal deck [-] "
                  "(bar: best of the repeats; whisker: their spread)")
    ax.grid(True, axis="x", alpha=0.3)
    save(plt, fig, out, "features.png")


def box(plt, rows, out):
    boxes = list(dict.fromkeys(r["box"] for r in rows))
    fig, (a, b) = plt.subplots(1, 2, figsize=(12, 4.2))
    width = 0.38
    for k, grid in enumerate(("dense", "active_blocks")):
        sel = {r["box"]: r for r in rows if r["grid"] == grid}
        xs = [i + (k - 0.5) * width for i in range(len(boxes))]
        a.bar(xs, [float(sel[x]["seconds_per_particle_step [s]"]) * 1e9 if x in sel else 0
                   for x in boxes], width, label=grid)
        b.bar(xs, [float(sel[x]["active_nodes [-]"]) if x in sel else 0 for x in boxes], width,
              label=grid)
    for ax, label in ((a, "ns per particle-step"), (b, "nodes visited per step [-]")):
        ax.set_xticks(range(len(boxes)))
        ax.set_xticklabels(boxes, fontsize=8)
        ax.set_ylabel(label)
        ax.grid(True, axis="y", alpha=0.3)
        ax.legend(fontsize=8)
    b.set_yscale("log")
    save(plt, fig, out, "box.png")


def fmt_int(x):
    return f"{int(round(float(x))):,}".replace(",", " ")


def scaling_table(rows):
    levels = sorted({float(r["level [-]"]) for r in rows})
    cols = [(i, t) for i in ("linear", "gimp") for t in ("1", "2")]
    out = ["| level | particles | " + " | ".join(f"{i} {t} th" for i, t in cols)
           + " | grid B/particle (2 th) |", "|---" * (len(cols) + 3) + "|"]
    for lv in levels:
        sel = {(r["interpolation"], r["threads [-]"]): r for r in rows
               if float(r["level [-]"]) == lv}
        any_row = next(iter(sel.values()))
        cells = [f"{float(sel[c]['particle_steps_per_second [1/s]']) / 1e6:.2f}" if c in sel
                 else "-" for c in cols]
        grid = sel.get(("gimp", "2"), any_row)["grid_bytes_per_particle [B]"]
        out.append(f"| {lv:g} | {fmt_int(any_row['particles [-]'])} | " + " | ".join(cells)
                   + f" | {float(grid):.0f} |")
    out.append("")
    series = scaling_series(rows)
    out.append("Log-log slope of wall time per step against particles: " + ", ".join(
        f"{i} {t} th {series[(i, t)][1]:.2f}" for i, t in cols
        if (i, t) in series and len(series[(i, t)][0]) > 1) + ".")
    speed = []
    for i in ("linear", "gimp"):
        ratios = []
        for lv in levels:
            sel = {r["threads [-]"]: float(r["particle_steps_per_second [1/s]"]) for r in rows
                   if r["interpolation"] == i and float(r["level [-]"]) == lv}
            if "1" in sel and "2" in sel:
                ratios.append(sel["2"] / sel["1"])
        if ratios:
            speed.append(f"{i} {min(ratios):.2f}-{max(ratios):.2f}x")
    out.append("Second thread: " + ", ".join(speed) + ".")
    spreads = [float(r["spread [-]"]) for r in rows if r.get("spread [-]")]
    if spreads:
        out.append(f"Spread of the repeats (max/min - 1): {min(spreads) * 100:.1f} to "
                   f"{max(spreads) * 100:.1f} %.")
    return out


def features_table(rows):
    out = ["| variant | ns/particle-step | spread | vs minimal | fields | B/particle | B/node |",
           "|---|---|---|---|---|---|---|"]
    for r in rows:
        out.append(f"| {r['variant']} | {float(r['seconds_per_particle_step [s]']) * 1e9:.1f} | "
                   f"{float(r['spread [-]']) * 100:.1f} % | {float(r['relative_to_minimal [-]']):.3f} | "
                   f"{r['fields [-]']} | {r['particle_bytes_per_particle [B]']} | "
                   f"{float(r['grid_bytes_per_node [B]']):.0f} |")
    return out


def box_table(rows):
    out = ["| box | grid | nodes | nodes visited per step | ns per particle-step | spread | "
           "grid-update share |", "|---|---|---|---|---|---|---|"]
    for r in rows:
        out.append(f"| {r['box']} | {r['grid']} | {fmt_int(r['nodes [-]'])} | "
                   f"{fmt_int(r['active_nodes [-]'])} | "
                   f"{float(r['seconds_per_particle_step [s]']) * 1e9:.1f} | "
                   f"{float(r['spread [-]']) * 100:.1f} % | "
                   f"{float(r['share_grid_update [-]']) * 100:.1f} % |")
    return out


def write_tables(out):
    lines = ["<!-- written by campaigns/benchmark/plot_benchmark.py from the CSVs beside it -->", ""]
    for name, table in (("scaling", scaling_table), ("features", features_table),
                        ("box", box_table)):
        rows = read(os.path.join(out, name + ".csv"))
        if rows:
            lines += [f"## {name}.csv", ""] + table(rows) + [""]
    with open(os.path.join(out, "tables.md"), "w") as f:
        f.write("\n".join(lines))


def main():
    if len(sys.argv) != 2:
        print(__doc__.splitlines()[2].strip(), file=sys.stderr)
        return 1
    out = sys.argv[1]
    if not os.path.isdir(out):
        print(f"plot_benchmark: {out}: no such directory (mpm_benchmark --out {out} writes it)",
              file=sys.stderr)
        return 2
    write_tables(out)
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("plot_benchmark: matplotlib missing (python3-matplotlib): no figures", file=sys.stderr)
        return 1
    wrote = []
    for name, draw in (("scaling", scaling), ("features", features), ("box", box)):
        rows = read(os.path.join(out, name + ".csv"))
        if rows:
            draw(plt, rows, out)
            wrote.append(name + ".png")
    print(f"plot_benchmark: wrote tables.md, {', '.join(wrote) or 'no figures'} in {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
