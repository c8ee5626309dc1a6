#!/usr/bin/env python3
"""What `pointdriver plot` draws (pointdriver/plot/plot.py loaded as a module) reads as it is:

  plot_figure_test.py PLOT_SCRIPT WORK_DIR

- Stresses in MPa or GPa (3e8 Pa is 300 on an axis labelled [MPa], 4e9 Pa 4 [GPa]) and no
  axis offset (the axis said "1e8" and Pa, before); the axis label names the columns while they
  fit in 40 characters, else how many there are ("4 columns [GPa]": the list was clipped,
  before), or the --ylabel given.
- A line within 0.2 % of the panel's range of an earlier one (b = a (1 + 1e-5)) is drawn with
  open markers on top and labelled "b (coincides with a)"; a line 5 % away is not (it was
  hidden, before).
- --style-by '[0-9]+K': a colour per rate, a line style per temperature (12 series took 10
  colours in turn, two of them twice, before).
- --points FILE: that file's series as markers without a line (measured Hugoniot points were
  joined into a zigzag, before).
- Each panel's axis label and lines are printed (the text the legend shows).
Without matplotlib: exit 77 (CTest: skipped).
"""
import argparse
import importlib.util
import os
import shutil
import sys


def load(script):
    spec = importlib.util.spec_from_file_location("plot", script)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def write_csv(path, header, rows):
    with open(path, "w") as f:
        f.write(",".join(header) + "\n")
        for r in rows:
            f.write(",".join(repr(v) for v in r) + "\n")


def arguments(csv, y, **more):
    options = dict(csv=csv, x="strain", y=y, output="unused.png", title=None, logx=False,
                   logy=False, label=None, ylabel=None, style_by=None, points=None)
    options.update(more)
    return argparse.Namespace(**options)


def main(script, work):
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        print("no matplotlib: skipped")
        sys.exit(77)
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    plot = load(script)
    figures = []
    plot.save = lambda fig, path: figures.append(fig)

    # Coincident and distinct lines, in MPa.
    csv = os.path.join(work, "curves.csv")
    strain = [k * 0.01 for k in range(101)]
    a = [3e8 * (1 - 0.97 ** k) for k in range(101)]
    write_csv(csv, ["strain [-]", "a [Pa]", "b [Pa]", "c [Pa]", "d [Pa]"],
              [(e, s, s * (1 + 1e-5), s * 1.05, s * 0.5) for e, s in zip(strain, a)])
    lines = plot.plot_columns(arguments([csv], ["a", "b", "c", "d"]))
    ax = figures[-1].axes[0]
    assert ax.get_ylabel() == "a, b, c, d [MPa]", ax.get_ylabel()
    assert not ax.yaxis.get_major_formatter().get_useOffset()
    drawn = ax.get_lines()
    assert abs(max(drawn[0].get_ydata()) - max(a) / 1e6) < 1e-9, max(drawn[0].get_ydata())
    assert [line.get_label() for line in drawn] == ["a", "b (coincides with a)", "c", "d"]
    assert [line.get_marker() for line in drawn] == ["None", "o", "None", "None"]
    assert lines == ["wrote unused.png",
                     "  a, b, c, d [MPa]: a, b (coincides with a), c, d"], lines
    plot.plot_columns(arguments([csv], ["a", "b"], ylabel=["axial stress"]))
    assert figures[-1].axes[0].get_ylabel() == "axial stress [MPa]"
    try:
        plot.plot_columns(arguments([csv], ["a"], ylabel=["one", "two"]))
        raise AssertionError("two --ylabel for one panel were accepted")
    except plot.InputError as e:
        assert "--ylabel given 2 times for 1 panels" in str(e), e

    # A line style per temperature, a colour per rate; GPa.
    grid = os.path.join(work, "grid.csv")
    names = [f"s_{rate}_per_s_{t}K" for t in (294, 500) for rate in (1, 1000)]
    write_csv(grid, ["strain [-]"] + [f"{n} [Pa]" for n in names],
              [(e,) + tuple(1e9 * (k + 1) * (1 + e) for k in range(4)) for e in strain])
    plot.plot_columns(arguments([grid], names, style_by="[0-9]+K"))
    ax = figures[-1].axes[0]
    assert ax.get_ylabel() == "4 columns [GPa]", ax.get_ylabel()
    styles = [(line.get_color(), line.get_linestyle()) for line in ax.get_lines()]
    assert styles == [("C0", "-"), ("C1", "-"), ("C0", "--"), ("C1", "--")], styles

    # Measurements as points.
    measured = os.path.join(work, "measured.csv")
    write_csv(measured, ["strain [-]", "a [Pa]"], [(e, s * 1.2) for e, s in zip(strain, a)])
    plot.plot_columns(arguments([csv, measured], ["a"], points=[measured],
                                label=["driver", "experiments"]))
    line, points = figures[-1].axes[0].get_lines()
    assert line.get_linestyle() == "-" and points.get_linestyle() == "None"
    assert points.get_marker() == "o"
    print("OK: MPa/GPa without offsets, coincident lines marked, styles by temperature, points")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
