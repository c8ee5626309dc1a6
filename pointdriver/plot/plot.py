#!/usr/bin/env python3
"""Quick figures from point-driver CSV files (python3 + matplotlib; Debian: python3-matplotlib).

  plot.py OUT.csv [MORE.csv ...] --x COL --y COL [--y COL ...] -o FIG.png
          [--title T] [--logx] [--logy] [--label NAME ...] [--ylabel TEXT ...]
          [--style-by REGEX] [--points CSV ...]
      One line per (file, y column). Columns are named as in the CSV header, with or without the
      unit suffix: `stress_xx` matches `stress_xx [Pa]`. Axis labels carry the units; y columns of
      different units go on separate panels (one per unit, stacked, sharing x), never on one
      axis; a stress or an energy is drawn in the prefixed unit its values read best in (MPa, GPa,
      kJ: axis_units.py), and no axis shows an offset. --ylabel names a panel's quantity (one per
      panel; default: the column names while they fit). Several files are overlaid with a legend
      (labels: the file names, or --label, one per file); --points draws a file's series as
      points (measurements). --style-by REGEX: series whose names give the same match share a
      line style and are coloured by the rest of the name (e.g. '[0-9]+K': a colour per rate, a
      line style per temperature). A line that lies on an earlier one of its panel (within 0.2 %
      of the panel's range) is drawn thin with open markers over the earlier one drawn wide, and
      its legend says "coincides with".
      The legend goes beside the axes when a panel has more than 6 series.

  plot.py --convergence convergence.csv OUTDIR
      The accuracy-versus-cost figures of `pointdriver convergence`:
      OUTDIR/convergence_error_vs_time.png and OUTDIR/convergence_error_vs_dt.png.

The figure's format follows its suffix (.png, .pdf, .svg; any other name is a usage error); it is
written whole or not at all (plot_output.py). Prints `wrote FIG` per figure and, for each panel of
a --x/--y figure, its axis label and its lines as the legend names them.
Exit codes: 0 done, 1 usage error, 2 input error (missing file or column), 3 a figure or stdout
could not be written (one line: the file and the system's reason), 4 matplotlib missing, 130
Ctrl-C, 141 stdout closed by its reader (`| head`: nothing more is said).
`pointdriver plot` runs this script; it can also be run directly.
"""

import argparse
import csv
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # its modules, also when imported
from axis_units import scaled_unit  # noqa: E402
from plot_output import FigureError, figure_format, print_lines, run_script, save_figure  # noqa: E402

MISSING_MATPLOTLIB = 4


def import_pyplot():
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.stderr.write(
            "plot.py: matplotlib is not installed; install it with:\n"
            "  apt-get install -y python3-matplotlib\n"
        )
        sys.exit(MISSING_MATPLOTLIB)
    return plt


class InputError(Exception):
    pass


def read_csv(path):
    """Header cells and columns (lists of floats; non-numeric cells become NaN)."""
    try:
        # utf-8-sig: a spreadsheet's byte-order mark would otherwise stick to the first column name.
        with open(path, newline="", encoding="utf-8-sig") as f:
            rows = list(csv.reader(f))
    except OSError as e:
        raise InputError(f"{path}: cannot read: {e.strerror}")
    if not rows:
        raise InputError(f"{path}: empty file")
    header = [h.strip() for h in rows[0]]
    columns = [[] for _ in header]
    for row in rows[1:]:
        for i in range(len(header)):
            cell = row[i].strip() if i < len(row) else ""
            try:
                columns[i].append(float(cell))
            except ValueError:
                columns[i].append(float("nan"))
    return header, columns


def strip_unit(name):
    return re.sub(r"\s*\[[^\]]*\]\s*$", "", name).strip()


def find_column(header, name, path):
    """Index of `name` in `header`: exact match first, then the name without its unit."""
    if name in header:
        return header.index(name)
    bare = strip_unit(name)
    matches = [i for i, h in enumerate(header) if strip_unit(h) == bare]
    if len(matches) == 1:
        return matches[0]
    if len(matches) > 1:
        raise InputError(f"{path}: column '{name}' is ambiguous: {[header[i] for i in matches]}")
    close = [h for h in header if bare in strip_unit(h)][:8]
    hint = f" (did you mean: {', '.join(close)}?)" if close else ""
    raise InputError(f"{path}: no column '{name}'{hint}; columns: {', '.join(header)}")


def unit_of(name):
    """The unit in a column name's brackets ("stress_xx [Pa]" -> "Pa"); "" without brackets."""
    m = re.search(r"\[([^\]]*)\]\s*$", name)
    return m.group(1).strip() if m else ""


def unit_panels(columns):
    """The y columns grouped by unit, in the order the units first appear: one axis each, since
    a stress in Pa and a temperature in K on one axis make one of them a flat line at zero."""
    panels = {}
    for c in columns:
        panels.setdefault(unit_of(c), []).append(c)
    return list(panels.values())


def coincides(x, y, other_x, other_y, tolerance):
    """Whether the series (x, y) lies on (other_x, other_y) within `tolerance` wherever both are
    defined (other_y interpolated at x), the two sharing at least 90 % of the x range of each."""
    import numpy as np

    def finite(xs, ys):
        xs, ys = np.asarray(xs, float), np.asarray(ys, float)
        keep = np.isfinite(xs) & np.isfinite(ys)
        order = np.argsort(xs[keep], kind="stable")
        return xs[keep][order], ys[keep][order]

    x, y = finite(x, y)
    ox, oy = finite(other_x, other_y)
    if len(x) < 2 or len(ox) < 2:
        return False
    low, high = max(x[0], ox[0]), min(x[-1], ox[-1])
    shared = high - low
    if shared <= 0 or shared < 0.9 * (x[-1] - x[0]) or shared < 0.9 * (ox[-1] - ox[0]):
        return False
    inside = (x >= low) & (x <= high)
    return bool(np.max(np.abs(y[inside] - np.interp(x[inside], ox, oy))) <= tolerance)


def axis_label(quantity, names, unit):
    """`quantity [unit]` when given (--ylabel); else the column names when they fit on the axis
    (40 characters), else how many columns there are (the legend names them)."""
    if not quantity:
        bare = [strip_unit(n) for n in names]
        quantity = ", ".join(bare) if len(", ".join(bare)) <= 40 else f"{len(bare)} columns"
    return f"{quantity} [{unit}]" if unit else quantity


def plot_columns(args):
    files = args.csv
    if args.label and len(args.label) != len(files):
        raise InputError(f"--label given {len(args.label)} times for {len(files)} files")
    for f in args.points or []:
        if f not in files:
            raise InputError(f"--points {f}: not one of the CSV files")
    figure_format(args.output)  # a name the figure cannot take is refused before any work
    style_by = None
    if args.style_by:
        try:
            style_by = re.compile(args.style_by)
        except re.error as e:
            raise InputError(f"--style-by {args.style_by}: not a regular expression ({e})")
    data = [(f,) + read_csv(f) for f in files]
    # Resolve every column first, so that a missing one is an input error before matplotlib loads.
    resolved = []  # (path, columns, x index, [y indices])
    x_label = None
    for path, header, columns in data:
        ix = find_column(header, args.x, path)
        x_label = x_label or header[ix]
        resolved.append((path, header, columns, ix, [find_column(header, y, path) for y in args.y]))
    y_names = []
    for _, header, _, _, iys in resolved:
        for iy in iys:
            if header[iy] not in y_names:
                y_names.append(header[iy])
    panels = unit_panels(y_names)
    if args.ylabel and len(args.ylabel) != len(panels):
        raise InputError(f"--ylabel given {len(args.ylabel)} times for {len(panels)} panels "
                         f"(one per unit: {', '.join(unit_of(p[0]) or '-' for p in panels)})")
    panel_of = {name: k for k, names in enumerate(panels) for name in names}

    # The series of each panel: (file index, y index in the file, y column, label).
    series = [[] for _ in panels]
    for k, (path, header, columns, ix, iys) in enumerate(resolved):
        name = args.label[k] if args.label else os.path.basename(path)
        for j, iy in enumerate(iys):
            parts = []
            if len(files) > 1:
                parts.append(name)
            if len(args.y) > 1:
                parts.append(strip_unit(header[iy]))
            series[panel_of[header[iy]]].append((k, j, iy, ", ".join(parts) or None))
    # Each panel in its unit with an SI prefix (MPa, not Pa with "1e8" over the axis).
    scales = []
    for names, members in zip(panels, series):
        values = [v for k, _, iy, _ in members for v in resolved[k][2][iy]]
        scales.append(scaled_unit(unit_of(names[0]), values))

    plt = import_pyplot()
    many = max(len(m) for m in series) > 6  # a long legend goes beside the axes, not over lines
    width = 9.6 if many else 6.4
    height = 4.6 if len(panels) == 1 else 2.0 + 2.2 * len(panels)
    fig, axes = plt.subplots(len(panels), 1, sharex=True, squeeze=False, figsize=(width, height),
                             layout="constrained")
    axes = [a[0] for a in axes]
    styles = ["-", "--", ":", "-."]
    style_keys, colour_keys = [], []
    legends = []
    for p, (ax, members) in enumerate(zip(axes, series)):
        factor = scales[p][0]
        finite = [v / factor for k, _, iy, _ in members for v in resolved[k][2][iy]
                  if math.isfinite(v)]
        tolerance = 2e-3 * (max(finite) - min(finite)) if finite else 0.0
        drawn = []  # (x, y, label, index in `pending`) of the lines on this panel so far
        pending = []  # (x, y, plot options), drawn in this order once all are known
        legend = []  # what each line is, as the legend says (the column when it has no label)
        for k, j, iy, label in members:
            path, header, columns, ix = resolved[k][:4]
            x, y = columns[ix], [v / factor for v in columns[iy]]
            bare = strip_unit(header[iy])
            if style_by:  # colour by the rest of the name, line style by the match
                match = style_by.search(bare)
                key = match.group(0) if match else ""
                rest = style_by.sub("", bare) if match else bare
                style_keys += [key] if key not in style_keys else []
                colour_keys += [rest] if rest not in colour_keys else []
                colour = f"C{colour_keys.index(rest) % 10}"
                style = styles[style_keys.index(key) % 4]
            else:  # one colour per file (per column for one file), one line style per column
                colour = f"C{k % 10}" if len(files) > 1 else f"C{j % 10}"
                style = styles[j % 4] if len(files) > 1 else "-"
            options = {"color": colour, "label": label}
            if path in (args.points or []):  # measured points: markers, never joined
                options.update(marker="o", ms=3, ls="none")
            else:
                options.update(ls=style)
                same = [d for d in drawn if coincides(x, y, d[0], d[1], tolerance)]
                if same:  # a thin line with open markers over a wide one: both show
                    step = max(1, len(x) // 15)
                    options.update(lw=1.0, marker="o", ms=5, mfc="none",
                                   markevery=(len(drawn) * step // 3 % step, step))
                    pending[same[0][3]][2]["lw"] = 3.0
                    if label:
                        options["label"] = f"{label} (coincides with {same[0][2]})"
                drawn.append((x, y, label, len(pending)))
            pending.append((x, y, options))
            legend.append(options["label"] or bare)
        for x, y, options in pending:
            ax.plot(x, y, **options)
        legends.append(legend)
    for ax, names, (_, unit), p in zip(axes, panels, scales, range(len(panels))):
        ax.set_ylabel(axis_label(args.ylabel[p] if args.ylabel else None, names, unit))
        if args.logx:
            ax.set_xscale("log")
        if args.logy:
            ax.set_yscale("log")
        else:
            ax.ticklabel_format(axis="y", useOffset=False)
        if any(label for *_, label in series[p]):
            if many:
                ax.legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.02, 1.0))
            else:
                ax.legend(fontsize="small")
        ax.grid(True, which="both", alpha=0.3)
    axes[-1].set_xlabel(x_label)
    if args.title:
        axes[0].set_title(args.title)
    save(fig, args.output)
    plt.close(fig)
    return [f"wrote {args.output}"] + [f"  {ax.get_ylabel()}: {', '.join(legend)}"
                                       for ax, legend in zip(axes, legends)]


def save(fig, path):
    save_figure(fig, path, dpi=130)


def plot_convergence(table, outdir):
    """Error versus wall time and versus dt; one series per (path, variant); runs that were not
    solved or gave non-finite output are drawn as crosses (in the path's colour) on the top edge."""
    read_csv(table)  # reports a missing or empty file as an InputError
    with open(table, newline="", encoding="utf-8-sig") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise InputError(f"{table}: no runs")
    for key in ("path", "variant", "steps", "dt [s]", "wall time [s]", "error [-]", "status"):
        if key not in rows[0]:
            raise InputError(f"{table}: missing column '{key}'")
    plt = import_pyplot()
    series = {}
    for r in rows:
        series.setdefault((r["path"], r["variant"]), []).append(r)
    paths = sorted({p for p, _ in series}, key=lambda p: [r["path"] for r in rows].index(p))
    colours = {p: c for p, c in zip(paths, ["C0", "C1", "C2", "C3", "C4"])}
    styles = ["o-", "s--", "^:", "d-."]

    def num(r, key):
        try:
            return float(r[key])
        except (ValueError, KeyError):
            return float("nan")

    written = []
    errors = [num(r, "error [-]") for r in rows]
    finite = [e for e in errors if math.isfinite(e) and e > 0]
    top = max(finite) * 3 if finite else 1.0
    for xkey, name, xlabel in (
        ("wall time [s]", "convergence_error_vs_time.png", "wall time of the run [s]"),
        ("dt [s]", "convergence_error_vs_dt.png", "step size dt [s]"),
    ):
        fig, ax = plt.subplots(figsize=(10.0, 5.2))
        variants_seen = {}
        failed_label = True
        for (p, v), rs in series.items():
            k = variants_seen.setdefault(p, [])
            style = styles[len(k) % len(styles)]
            k.append(v)
            good = [(num(r, xkey), num(r, "error [-]")) for r in rs]
            good = [(x, e) for x, e in good if math.isfinite(e) and e > 0 and x > 0]
            bad = [r for r in rs if r["status"] not in ("ok", "reference")]
            if good:
                ax.plot(*zip(*good), style, color=colours[p], label=f"{p}: {v}", ms=4)
            for r in bad:
                x = num(r, xkey)
                e = num(r, "error [-]")
                y = e if math.isfinite(e) and e > 0 else top
                ax.plot(
                    [x],
                    [y],
                    "x",
                    color=colours[p],
                    ms=9,
                    mew=2,
                    label="x: run not solved / not finite (at the top edge)" if failed_label else None,
                )
                failed_label = False
        if xkey == "dt [s]":
            ax.set_title("error against the most refined run of each series")
        else:
            ax.set_title("accuracy versus cost (error against the most refined run)")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel(xlabel)
        ax.set_ylabel("relative stress error, max over the curve [-]")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize="x-small", loc="upper left", bbox_to_anchor=(1.02, 1.0))
        fig.tight_layout()
        save(fig, os.path.join(outdir, name))
        plt.close(fig)
        written.append(f"wrote {os.path.join(outdir, name)}")
    return written


def main(argv):
    if len(argv) >= 1 and argv[0] == "--convergence":
        program = "pointdriver convergence"
        if len(argv) != 3:
            sys.stderr.write("usage: plot.py --convergence convergence.csv OUTDIR\n")
            return 1
        return finish(lambda: plot_convergence(argv[1], argv[2]), program)
    parser = Parser(
        prog="pointdriver plot",
        description="Quick figure from point-driver CSV files (columns with or without units).",
    )
    parser.add_argument("csv", nargs="+", help="CSV files (several: overlaid with a legend)")
    parser.add_argument("--x", required=True, help="x column, e.g. log_strain_xx")
    parser.add_argument("--y", required=True, action="append", help="y column (repeatable)")
    parser.add_argument("-o", "--output", required=True, help="figure file (.png, .pdf, .svg)")
    parser.add_argument("--title")
    parser.add_argument("--logx", action="store_true")
    parser.add_argument("--logy", action="store_true")
    parser.add_argument("--label", action="append", help="legend label per file (repeatable)")
    parser.add_argument("--ylabel", action="append",
                        help="quantity of a panel's axis, its unit added (one per panel)")
    parser.add_argument("--style-by", metavar="REGEX",
                        help="series whose names match alike share a line style, coloured by "
                        "the rest of the name")
    parser.add_argument("--points", action="append", metavar="CSV",
                        help="draw this file's series as points (measurements; repeatable)")
    args = parser.parse_args(argv)
    return finish(lambda: plot_columns(args), parser.prog)


class Parser(argparse.ArgumentParser):
    def error(self, message):  # a usage error is exit code 1, as in the programs
        self.print_usage(sys.stderr)
        sys.stderr.write(f"{self.prog}: {message}\n")
        sys.exit(1)


def finish(draw, program):
    """Runs `draw` (it returns the lines for stdout) and prints them: an input error is one line
    and exit 2, a figure name refused or a figure that cannot be written one line and 1 or 3, a
    full or closed stdout 3 or 141 (plot_output.py)."""
    try:
        lines = draw()
    except InputError as e:
        sys.stderr.write(f"{program}: {e}\n")
        return 2
    except FigureError as e:
        sys.stderr.write(f"{program}: {e}\n")
        return e.exit_code
    return print_lines(lines, program)


if __name__ == "__main__":
    convergence = sys.argv[1:2] == ["--convergence"]
    sys.exit(run_script(main, sys.argv[1:],
                        "pointdriver convergence" if convergence else "pointdriver plot"))
