#!/usr/bin/env python3
"""`pointdriver plot` (pointdriver/plot/plot.py) never puts columns of different units on one axis.

  plot_units_test.py PLOT_SCRIPT WORK_DIR

Stress in Pa (~1e8) and temperature in K (~300) on one axis leave the temperature a flat line at
zero, which reads as "no heating". The y columns are grouped by the unit in their header's
brackets, one panel each, in the order the units first appear; columns of one unit share a panel.
Checked on the grouping function, on a CSV written with a UTF-8 byte-order mark (its first column
name must not carry the mark), and, where matplotlib is installed, on the figure itself: one axis
per unit, each labelled with its own columns only.
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


def main(script, work):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    plot = load(script)
    names = ["stress_xx [Pa]", "temperature [K]", "stress_yy [Pa]", "step"]
    panels = plot.unit_panels(names)
    assert panels == [["stress_xx [Pa]", "stress_yy [Pa]"], ["temperature [K]"], ["step"]], panels

    csv_file = os.path.join(work, "run.csv")
    with open(csv_file, "w", encoding="utf-8-sig") as f:  # as a spreadsheet saves "CSV UTF-8"
        f.write("time [s],stress_xx [Pa],temperature [K]\n")
        for i in range(5):
            f.write(f"{i * 1e-6},{-1e8 * i},{294 + 10 * i}\n")
    header, columns = plot.read_csv(csv_file)
    assert header[0] == "time [s]", header
    assert columns[2] == [294.0, 304.0, 314.0, 324.0, 334.0], columns[2]

    try:
        import matplotlib  # noqa: F401
    except ImportError:
        print("matplotlib not installed: the figure itself is not drawn; grouping checked")
        print("OK")
        return
    figures = []
    plot.save = lambda fig, path: figures.append(fig)
    args = argparse.Namespace(csv=[csv_file], x="time", y=["stress_xx", "temperature"],
                              output=os.path.join(work, "fig.png"), title=None, logx=False,
                              logy=False, label=None, ylabel=None, style_by=None, points=None)
    plot.plot_columns(args)
    axes = figures[0].axes
    labels = [a.get_ylabel() for a in axes]
    assert labels == ["stress_xx [MPa]", "temperature [K]"], labels  # -4e8 Pa: in MPa
    # Each panel holds only its own unit's line: the temperature panel's data are the 294..334 K.
    assert [len(a.get_lines()) for a in axes] == [1, 1]
    assert list(axes[1].get_lines()[0].get_ydata()) == [294.0, 304.0, 314.0, 324.0, 334.0]
    print("OK")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
