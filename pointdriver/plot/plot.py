#!/usr/bin/env python3
"""Quick figures from point-driver CSV files (python3 + matplotlib; Debian: python3-matplotlib).

  plot.py OUT.csv [MORE.csv ...] --x COL --y COL [--y COL ...] -o FIG.png
          [--title T] [--logx] [--logy] [--label NAME ...]
      One line per (file, y column). Columns are named as in the CSV header, with or without the
      unit suffix: `stress_xx` matches `stress_xx [Pa]`. Axis labels carry the units. Several files
      are overlaid with a legend (labels: the file names, or --label, one per file).

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
        with open(path, newline="") as f:
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


def plot_columns(args):
    files = args.csv
    if args.label and len(args.label) != len(files):
        raise InputError(f"--label given {len(args.label)} times for {len(files)} files")
    data = [(f,) + read_csv(f) for f in files]
    plt = import_pyplot()
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    x_label = None
    y_labels = []
    for k, (path, header, columns) in enumerate(data):
        ix = find_column(header, args.x, path)
        x_label = x_label or header[ix]
        name = args.label[k] if args.label else os.path.basename(path)
        for y in args.y:
            iy = find_column(header, y, path)
            if header[iy] not in y_labels:
                y_labels.append(header[iy])
            parts = []
            if len(files) > 1:
                parts.append(name)
            if len(args.y) > 1:
                parts.append(strip_unit(header[iy]))
            ax.plot(columns[ix], columns[iy], label=", ".join(parts) or None)
    ax.set_xlabel(x_label)
    ax.set_ylabel(y_labels[0] if len(y_labels) == 1 else "; ".join(y_labels))
    if args.logx:
        ax.set_xscale("log")
    if args.logy:
        ax.set_yscale("log")
    if args.title:
        ax.set_title(args.title)
    if len(files) > 1 or len(args.y) > 1:
        ax.legend(fontsize="small")
    ax.grid(True, which="both", alpha=0.3)
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
    with open(table, newline="") as f:
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
