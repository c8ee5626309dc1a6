#!/usr/bin/env python3
"""Quick figures from point-driver CSV files (python3 + matplotlib; Debian: python3-matplotlib).

  plot.py OUT.csv [MORE.csv ...] --x COL --y COL [--y COL ...] -o FIG.png
          [--title T] [--logx] [--logy] [--label NAME ...]
      One line per (file, y column). Columns are named as in the CSV header, with or without the
      unit suffix: `stress_xx` matches `stress_xx [Pa]`. Axis labels carry the units; y columns of
      different units go on separate panels (one per unit, stacked, sharing x), never on one
      axis. Several files are overlaid with a legend (labels: the file names, or --label, one per
      file).

  plot.py --convergence convergence.csv OUTDIR
      The accuracy-versus-cost figures of `pointdriver convergence`:
      OUTDIR/convergence_error_vs_time.png and OUTDIR/convergence_error_vs_dt.png.

Exit codes: 0 done, 1 usage error, 2 input error (missing file or column), 4 matplotlib missing.
`pointdriver plot` runs this script; it can also be run directly.
"""

import argparse
import csv
import math
import os
import re
import sys

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


def plot_columns(args):
    files = args.csv
    if args.label and len(args.label) != len(files):
        raise InputError(f"--label given {len(args.label)} times for {len(files)} files")
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
    plt = import_pyplot()
    height = 4.6 if len(panels) == 1 else 2.0 + 2.2 * len(panels)
    fig, axes = plt.subplots(len(panels), 1, sharex=True, squeeze=False, figsize=(6.4, height))
    axes = [a[0] for a in axes]
    panel_of = {name: k for k, names in enumerate(panels) for name in names}
    for k, (path, header, columns, ix, iys) in enumerate(resolved):
        name = args.label[k] if args.label else os.path.basename(path)
        for j, iy in enumerate(iys):
            parts = []
            if len(files) > 1:
                parts.append(name)
            if len(args.y) > 1:
                parts.append(strip_unit(header[iy]))
            ax = axes[panel_of[header[iy]]]
            # One colour per file (per column for one file), one line style per column.
            colour = f"C{k % 10}" if len(files) > 1 else f"C{j % 10}"
            style = ["-", "--", ":", "-."][j % 4] if len(files) > 1 else "-"
            ax.plot(columns[ix], columns[iy], style, color=colour, label=", ".join(parts) or None)
    for ax, names in zip(axes, panels):
        ax.set_ylabel("; ".join(names))
        if args.logx:
            ax.set_xscale("log")
        if args.logy:
            ax.set_yscale("log")
        if len(files) > 1 or len(names) > 1:
            ax.legend(fontsize="small")
        ax.grid(True, which="both", alpha=0.3)
    axes[-1].set_xlabel(x_label)
    if args.title:
        axes[0].set_title(args.title)
    fig.tight_layout()
    save(fig, args.output)
    plt.close(fig)


def save(fig, path):
    directory = os.path.dirname(path)
    if directory:
        os.makedirs(directory, exist_ok=True)
    try:
        fig.savefig(path, dpi=130)
    except OSError as e:
        raise InputError(f"{path}: cannot write: {e.strerror}")
    print(f"wrote {path}")


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


def main(argv):
    if len(argv) >= 1 and argv[0] == "--convergence":
        if len(argv) != 3:
            sys.stderr.write("usage: plot.py --convergence convergence.csv OUTDIR\n")
            return 1
        plot_convergence(argv[1], argv[2])
        return 0
    parser = argparse.ArgumentParser(
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
    args = parser.parse_args(argv)
    plot_columns(args)
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except InputError as e:
        sys.stderr.write(f"plot.py: {e}\n")
        sys.exit(2)
