#!/usr/bin/env python3
"""One run's figure (`mpm plot RUN`, docs/mpm.md#output): what `mpm run` wrote into RUN.

  run_plot.py RUN [--out FIG]

Draws from RUN/history.csv (columns read by the name before " [", their unit from the header, so
ledger columns added later are picked up and a plane-strain run's per-metre units, `[J/m]`,
`[(kg m/s)/m]`, label its axes):
  energy books   every energy column (`[J]`, or `[J/m]`) before energy_error (kinetic, strain,
                 total drawn wide beneath the others, the booked sinks, outflow, external work)
                 against time [us], in J, kJ or MJ
  energy error   energy_error [-] (docs/mpm.md#ledger)
  momentum       every momentum and impulse column (`[kg m/s]`, `[N s]`, or per metre), against
                 an axis that spans the largest of them (a conserved momentum is a flat line, not
                 its round-off magnified); the legend names a column that is exactly 0, or
                 zero or constant to round-off (within 1e-9 of that scale)
  observables    the gauges (the columns after energy_error, each in its unit); without gauges,
                 the end-of-run observables of RUN/summary.json as text (no axes)
and titles it with RUN/status.json (status, steps, time). Stresses and pressures in MPa or GPa.
FIG defaults to RUN/run.png; its format follows its suffix (.png, .pdf, .svg; another name is a
usage error) and it is written whole or not at all (pointdriver/plot/plot_output.py). Prints
`wrote FIG` and the columns drawn in each panel.
Needs only the standard library and matplotlib (not the Python module impact).

Exit codes: 0 done, 1 usage error, 2 input error (no history.csv or an unreadable one), 3 the
figure or stdout could not be written (one line: the file and the system's reason), 4 matplotlib
missing, 130 Ctrl-C, 141 stdout closed by its reader (`| head`: nothing more is said).
"""
import argparse
import json
import math
import os
import re
import sys

# The plot scripts' shared modules (figures written whole, units with SI prefixes), beside
# pointdriver's plot.py in the source tree and under share/impact alike.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "pointdriver", "plot"))
# impact.results (pure Python): python/ of the source tree, share/impact/python of an install.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from axis_units import scaled_unit  # noqa: E402
from impact.results import history_rows  # noqa: E402
from plot_output import figure_format, print_lines, run_script, save_figure  # noqa: E402

MISSING_MATPLOTLIB = 4
ROUND_OFF = 1e-9  # a momentum column within this fraction of the panel's scale is round-off


class InputError(Exception):
    pass


def split(cell):
    """'momentum_x [kg m/s]' -> ('momentum_x', 'kg m/s'): the name is what comes before " [",
    the unit what the brackets hold ('(kg m/s)/m' in plane strain)."""
    cell = cell.strip()
    if " [" in cell and cell.endswith("]"):
        name, unit = cell.split(" [", 1)
        return name, unit[:-1]
    return cell, ""


def per_metre_of(unit):
    """The unit a plane-strain column is per metre of: 'J/m' -> 'J', '(kg m/s)/m' -> 'kg m/s';
    a 3D unit is returned as it is."""
    if unit.endswith("/m"):
        unit = unit[:-2]
        if unit.startswith("(") and unit.endswith(")"):
            unit = unit[1:-1]
    return unit


def named(mapping, name):
    """(value, unit) of the key of `mapping` whose name before " [" is `name`; (None, "")."""
    for key, value in (mapping or {}).items():
        key_name, unit = split(key)
        if key_name == name:
            return value, unit
    return None, ""


def read_history(run):
    path = os.path.join(run, "history.csv")
    if not os.path.isfile(path):
        raise InputError(f"{run}: no history.csv (expected a directory `mpm run` wrote)")
    head, data = history_rows(run)  # a short or broken line (a run killed mid-write): skipped
    if not head:
        raise InputError(f"{path}: empty file")
    header = [split(c) for c in head]
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
    energy = [k for k, (_, u) in enumerate(header[:end]) if per_metre_of(u) == "J"]
    momentum = [k for k, (_, u) in enumerate(header[:end])
                if per_metre_of(u) in ("kg m/s", "N s")]
    error = [end] if end < len(names) else []
    gauges = list(range(end + 1, len(names)))
    return energy, error, momentum, gauges


def observables_text(summary):
    """End-of-run observables of summary.json, one line each, in the units of its keys."""
    lines = []
    obs = (summary or {}).get("observables", {})
    for name, o in obs.get("objects", {}).items():
        energy, energy_unit = named(o, "kinetic_energy")
        velocity, velocity_unit = named(o, "mean_velocity")
        pressure, pressure_unit = named(o, "max_pressure")
        parts = []
        if energy is not None:
            parts.append(f"KE {energy:.4g} {energy_unit}")
        if velocity is not None:
            parts.append(f"mean v ({', '.join(f'{c:.4g}' for c in velocity)}) {velocity_unit}")
        if pressure is not None:
            factor, unit = scaled_unit(pressure_unit, [pressure])
            parts.append(f"max p {pressure / factor:.4g} {unit}")
        lines.append(f"{name}: {', '.join(parts)}")
    crater = obs.get("crater")
    if crater:
        parts = [f"{name} {length_text(*named(crater, name))}"
                 for name in ("depth", "diameter") if named(crater, name)[0] is not None]
        lines.append(f"crater: {', '.join(parts)}")
    return lines


def length_text(value, unit):
    """A length as a reader quotes a crater: 5.99 mm rather than 0.00599 m."""
    return f"{value * 1e3:.4g} mm" if unit == "m" else f"{value:.4g} {unit}"


class Parser(argparse.ArgumentParser):
    def error(self, message):  # a usage error is exit code 1, as in the programs
        self.print_usage(sys.stderr)
        print(f"mpm plot: {message}", file=sys.stderr)
        sys.exit(1)


def draw_lines(ax, t_us, columns, header, indices, factor=1.0):
    for k in indices:
        options = {"label": header[k][0]}
        if header[k][0] == "total_energy":  # wide and light beneath: kinetic often lies on it
            options.update(lw=5, alpha=0.35, zorder=1, label="total_energy (wide)")
        ax.plot(t_us, [v / factor for v in columns[k]], **options)


def unit_label(header, indices):
    """The units of the columns, as an axis label shows them: 'J', 'kg m/s = N s'."""
    return " = ".join(dict.fromkeys(header[k][1] for k in indices))


def momentum_panel(ax, t_us, columns, header, indices):
    """Momentum and impulses against an axis spanning the largest of them on both sides of zero:
    a conserved momentum is a flat line at its value (autoscaling would magnify its last-digit
    round-off into a wave), and a column within ROUND_OFF of that scale is labelled round-off.
    Returns the labels drawn."""
    scale = max((abs(v) for k in indices for v in columns[k] if math.isfinite(v)), default=0.0)
    labels = []
    for k in indices:
        values = [v for v in columns[k] if math.isfinite(v)]
        label = header[k][0]
        largest = max((abs(v) for v in values), default=0.0)
        spread = max(values, default=0.0) - min(values, default=0.0)
        if largest == 0.0:
            label += " (exactly 0)"
        elif scale > 0.0 and largest <= ROUND_OFF * scale:
            label += f" (zero to round-off, |max| {largest:.1e})"
        elif scale > 0.0 and 0.0 < spread <= ROUND_OFF * scale:
            label += f" (constant to round-off, spread {spread:.1e})"
        ax.plot(t_us, columns[k], label=label,
                ls="--" if per_metre_of(header[k][1]) == "N s" else "-")
        labels.append(label)
    if indices:
        ax.legend(fontsize=6.5, ncol=2, loc="best")
    if scale > 0.0:
        ax.set_ylim(-1.1 * scale, 1.1 * scale)
    else:  # nothing moves: say so rather than draw an axis of zeros
        ax.text(0.5, 0.5, "all momentum and impulse columns are exactly 0",
                transform=ax.transAxes, ha="center", fontsize=9)
    return labels


def main(argv):
    parser = Parser(prog="mpm plot", description=__doc__.split("\n")[0])
    parser.add_argument("run", metavar="RUN")
    parser.add_argument("--out", "-o", metavar="FIG")
    args = parser.parse_args(argv)
    out = args.out or os.path.join(args.run, "run.png")
    figure_format(out)  # a name the figure cannot take is refused before any work
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
    status = read_json(os.path.join(args.run, "status.json")) or {}
    summary = read_json(os.path.join(args.run, "summary.json"))
    energy, error, momentum, gauges = panels(header)
    t_us = [t * 1e6 for t in columns[0]]

    fig, axes = plt.subplots(2, 2, figsize=(12, 8), sharex=True, layout="constrained")
    drawn = {}

    def finish_axes(ax, name, indices, ylabel, legend_loc="best"):
        ax.set(ylabel=ylabel, title=name)
        ax.ticklabel_format(axis="y", useOffset=False)
        if indices and ax.get_legend() is None:
            ax.legend(fontsize=7, loc=legend_loc)
        ax.grid(alpha=0.3)
        drawn[name] = [f"{header[k][0]} [{header[k][1]}]" for k in indices]

    factor, unit = scaled_unit(per_metre_of(unit_label(header, energy)),
                               [v for k in energy for v in columns[k]])
    per_metre = unit_label(header, energy).endswith("/m")
    draw_lines(axes[0, 0], t_us, columns, header, energy, factor)
    finish_axes(axes[0, 0], "energy books", energy,
                f"energy [{unit}/m]" if per_metre else f"energy [{unit}]")
    draw_lines(axes[0, 1], t_us, columns, header, error)
    finish_axes(axes[0, 1], "energy error", error, "energy error [-]")
    momentum_panel(axes[1, 0], t_us, columns, header, momentum)
    finish_axes(axes[1, 0], "momentum", momentum,
                f"momentum, impulse [{unit_label(header, momentum)}]")
    ax = axes[1, 1]
    if gauges:
        # One y axis per unit (a pressure beside a velocity): the first on the left, the others
        # on the right, offset outwards; a pressure in MPa or GPa.
        units = list(dict.fromkeys(header[k][1] for k in gauges))
        first = [k for k in gauges if header[k][1] == units[0]]
        factor, unit = scaled_unit(units[0], [v for k in first for v in columns[k]])
        draw_lines(ax, t_us, columns, header, first, factor)
        finish_axes(ax, "observables", first, f"gauges [{unit}]", "upper left")
        for n, gauge_unit in enumerate(units[1:]):
            twin = ax.twinx()
            twin.spines["right"].set_position(("outward", 50 * n))
            indices = [k for k in gauges if header[k][1] == gauge_unit]
            factor, unit = scaled_unit(gauge_unit, [v for k in indices for v in columns[k]])
            for k in indices:  # colours continue after the left axis' lines
                twin.plot(t_us, [v / factor for v in columns[k]], label=header[k][0], ls=":",
                          color=f"C{len(drawn['observables']) % 10}")
                drawn["observables"].append(f"{header[k][0]} [{gauge_unit}]")
            twin.set_ylabel(f"gauges [{unit}] (dotted)")
            twin.ticklabel_format(axis="y", useOffset=False)
            twin.legend(fontsize=7, loc="lower right")
    else:  # the end-of-run observables as text, without an empty axes around them
        lines = observables_text(summary)
        drawn["observables"] = ["summary.json observables"] if lines else []
        ax.axis("off")
        ax.text(0.02, 0.95, "\n".join(lines) or "no gauges (output.gauges), no summary.json yet",
                transform=ax.transAxes, va="top", fontsize=8, family="monospace")
        ax.set_title("observables at the end (summary.json; no gauges)")
        axes[0, 1].xaxis.set_tick_params(labelbottom=True)  # the time axis above the text
        axes[0, 1].set_xlabel("time [us]")
    for a in axes[1]:
        a.set_xlabel("time [us]")
    fig.suptitle(f"{os.path.abspath(args.run)}: {status.get('status', 'no status.json')}, "
                 f"step {status.get('step', '?')}, t = {columns[0][-1] * 1e6:.4g} us",
                 fontsize=10)
    save_figure(fig, out, dpi=110)
    return print_lines([f"wrote {out}"] + [f"{name}: {', '.join(cols) if cols else '(none)'}"
                                           for name, cols in drawn.items()], "mpm plot")


if __name__ == "__main__":
    sys.exit(run_script(main, sys.argv[1:], "mpm plot"))
