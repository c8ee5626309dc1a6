#!/usr/bin/env python3
"""One run's figure (`mpm plot RUN`, docs/mpm.md#output): what `mpm run` wrote into RUN.

  run_plot.py RUN [--out FIG]

Draws from RUN/history.csv (columns read by name, so ledger columns added later are picked up):
  energy books   every `[J]` column (kinetic, strain, total, the booked sinks, outflow, external
                 work) [J] against time [us]
  energy error   energy_error [-] (docs/mpm.md#ledger)
  momentum       every `[kg m/s]` and `[N s]` column (momentum, boundary, outflow and external
                 impulses by component)
  observables    the gauges (the columns after energy_error, each in its unit); without gauges,
                 the end-of-run observables of RUN/summary.json as text
and titles it with RUN/status.json (status, steps, time). FIG defaults to RUN/run.png; its format
follows its suffix (.png, .pdf, .svg). Prints the columns drawn in each panel.
Needs only the standard library and matplotlib (not the Python module impact).

Exit codes: 0 done, 1 usage error, 2 input error (no history.csv or an unreadable one),
4 matplotlib missing.
"""
import argparse
import csv
import json
import os
import re
import sys

MISSING_MATPLOTLIB = 4


class InputError(Exception):
    pass


def split(cell):
    """'momentum_x [kg m/s]' -> ('momentum_x', 'kg m/s')."""
    m = re.match(r"^(.*?)\s*\[([^\]]*)\]\s*$", cell.strip())
    return (m.group(1), m.group(2)) if m else (cell.strip(), "")


def read_history(run):
    path = os.path.join(run, "history.csv")
    if not os.path.isfile(path):
        raise InputError(f"{run}: no history.csv (expected a directory `mpm run` wrote)")
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    if not rows:
        raise InputError(f"{path}: empty file")
    header = [split(c) for c in rows[0]]
    data = []
    for row in rows[1:]:
        try:  # a run killed mid-write leaves a short or broken last line: skipped
            values = [float(c) for c in row]
        except ValueError:
            continue
        if len(values) == len(header):
            data.append(values)
    if not data or header[0][0] != "time":
        raise InputError(f"{path}: expected a header starting with 'time [s]' and numeric rows")
    return header, [[r[k] for r in data] for k in range(len(header))]


def read_json(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def panels(header):
    """The column indices of each panel."""
    names = [n for n, _ in header]
    end = names.index("energy_error") if "energy_error" in names else len(names)
    energy = [k for k, (_, u) in enumerate(header[:end]) if u == "J"]
    momentum = [k for k, (_, u) in enumerate(header[:end]) if u in ("kg m/s", "N s")]
    error = [end] if end < len(names) else []
    gauges = list(range(end + 1, len(names)))
    return energy, error, momentum, gauges


def observables_text(summary):
    """End-of-run observables of summary.json, one line each."""
    lines = []
    obs = (summary or {}).get("observables", {})
    for name, o in obs.get("objects", {}).items():
        v = o.get("mean_velocity [m/s]", [])
        lines.append(f"{name}: KE {o.get('kinetic_energy [J]', 0):.4g} J, mean v "
                     f"({', '.join(f'{c:.4g}' for c in v)}) m/s, max p "
                     f"{o.get('max_pressure [Pa]', 0) / 1e9:.4g} GPa")
    crater = obs.get("crater")
    if crater:
        lines.append(f"crater: depth {crater.get('depth [m]', 0) * 1e3:.4g} mm, diameter "
                     f"{crater.get('diameter [m]', 0) * 1e3:.4g} mm")
    return lines


class Parser(argparse.ArgumentParser):
    def error(self, message):  # a usage error is exit code 1, as in the programs
        self.print_usage(sys.stderr)
        print(f"mpm plot: {message}", file=sys.stderr)
        sys.exit(1)


def main(argv):
    parser = Parser(prog="mpm plot", description=__doc__.split("\n")[0])
    parser.add_argument("run", metavar="RUN")
    parser.add_argument("--out", "-o", metavar="FIG")
    args = parser.parse_args(argv)
    try:
        header, columns = read_history(args.run)
    except InputError as e:
        print(f"mpm plot: {e}", file=sys.stderr)
        return 2
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("mpm plot: matplotlib missing (apt-get install -y python3-matplotlib)",
              file=sys.stderr)
        return MISSING_MATPLOTLIB
    out = args.out or os.path.join(args.run, "run.png")
    status = read_json(os.path.join(args.run, "status.json")) or {}
    summary = read_json(os.path.join(args.run, "summary.json"))
    energy, error, momentum, gauges = panels(header)
    t_us = [t * 1e6 for t in columns[0]]

    fig, axes = plt.subplots(2, 2, figsize=(12, 8), sharex=True)
    drawn = {}

    def draw(ax, name, indices, ylabel):
        for k in indices:
            ax.plot(t_us, columns[k], label=header[k][0],
                    ls="--" if header[k][1] == "N s" else "-")
        ax.set(ylabel=ylabel, title=name)
        if indices:
            ax.legend(fontsize=7)
        ax.grid(alpha=0.3)
        drawn[name] = [f"{header[k][0]} [{header[k][1]}]" for k in indices]

    draw(axes[0, 0], "energy books", energy, "energy [J]")
    draw(axes[0, 1], "energy error", error, "energy error [-]")
    draw(axes[1, 0], "momentum", momentum, "momentum, impulse [kg m/s = N s]")
    ax = axes[1, 1]
    # One y axis per unit (a pressure in Pa beside a velocity in m/s): the first on the left,
    # the others on the right, offset outwards.
    units = list(dict.fromkeys(header[k][1] for k in gauges))
    draw(ax, "observables", [k for k in gauges if header[k][1] == units[0]] if units else [],
         f"[{units[0]}]" if units else "")
    for n, unit in enumerate(units[1:]):
        twin = ax.twinx()
        twin.spines["right"].set_position(("outward", 50 * n))
        indices = [k for k in gauges if header[k][1] == unit]
        for k in indices:  # colours continue after the left axis' lines
            twin.plot(t_us, columns[k], label=header[k][0], ls=":",
                      color=f"C{len(drawn['observables']) % 10}")
            drawn["observables"].append(f"{header[k][0]} [{unit}]")
        twin.set_ylabel(f"[{unit}] (dotted)")
        twin.legend(fontsize=7, loc="lower right")
    if not gauges:
        lines = observables_text(summary)
        drawn["observables"] = ["summary.json observables"] if lines else []
        ax.text(0.02, 0.95, "\n".join(lines) or "no gauges, no summary.json yet",
                transform=ax.transAxes, va="top", fontsize=8, family="monospace")
        ax.set_title("observables at the end (summary.json)")
    for a in axes[1]:
        a.set_xlabel("time [us]")
    fig.suptitle(f"{os.path.abspath(args.run)}: {status.get('status', 'no status.json')}, "
                 f"step {status.get('step', '?')}, t = {columns[0][-1] * 1e6:.4g} us",
                 fontsize=10)
    fig.tight_layout()
    try:
        fig.savefig(out, dpi=110)
    except (OSError, ValueError) as e:
        print(f"mpm plot: cannot write {out}: {e}", file=sys.stderr)
        return 2
    print(f"wrote {out}")
    for name, cols in drawn.items():
        print(f"{name}: {', '.join(cols) if cols else '(none)'}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
