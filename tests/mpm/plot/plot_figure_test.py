#!/usr/bin/env python3
"""What `mpm plot` draws (campaigns/plot/run_plot.py, loaded as a module, on run directories
written here), independent of any run:

  plot_figure_test.py RUN_PLOT_PY WORK_DIR

- Units from the header: a plane-strain history (`kinetic_energy [J/m]`, `momentum_x
  [(kg m/s)/m]`, `boundary_impulse_x [(N s)/m]`) is drawn in its energy and momentum panels with
  the axis labels `energy [J/m]` and `momentum, impulse [(kg m/s)/m = (N s)/m]`, and a 3D one
  with `energy [J]` and `[kg m/s = N s]` (the plane-strain columns were left out, before).
- Round-off: momentum_x 1.5 kg m/s with a last-bit wobble (4.4e-16), momentum_y +-1e-17, the
  rest exactly 0: the momentum axis spans +-1.1 x 1.5 (autoscaling zoomed into the wobble,
  before) and the legend says "constant to round-off", "zero to round-off", "exactly 0".
- Observables without gauges: the summary's text without axes around it (an empty frame with
  ticks, before), in the keys' units (`KE 12.5 J/m`, `max p 250 MPa`); gauges in Pa on an axis
  in MPa.
Without matplotlib: exit 77 (CTest: skipped).
"""
import importlib.util
import json
import os
import shutil
import sys


def load(script):
    spec = importlib.util.spec_from_file_location("run_plot", script)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def write_run(directory, per_metre, gauges=False):
    """history.csv with the ledger's columns (in plane strain per metre), status and summary."""
    os.makedirs(directory)
    energy, momentum, impulse = (("J/m", "(kg m/s)/m", "(N s)/m") if per_metre
                                 else ("J", "kg m/s", "N s"))
    header = ["time [s]"] + [f"{n} [{energy}]" for n in
                             ("kinetic_energy", "strain_energy", "total_energy")]
    header += [f"momentum_{c} [{momentum}]" for c in "xyz"]
    header += [f"boundary_impulse_{c} [{impulse}]" for c in "xyz"]
    header += ["energy_error [-]"] + (["gauge_p [Pa]", "gauge_vx [m/s]"] if gauges else [])
    rows = []
    for k in range(5):
        p_x = 1.5 + (2 * k % 3) * 2.220446049250313e-16  # 1.5 and its next doubles up
        row = [k * 1e-6, 12.5, 0.0, 12.5, p_x, (-1) ** k * 1e-17, 0.0, 0.0, 0.0, 0.0, 1e-15 * k]
        rows.append(row + ([2e8 * k, 100.0] if gauges else []))
    with open(os.path.join(directory, "history.csv"), "w") as f:
        f.write(",".join(header) + "\n")
        for r in rows:
            f.write(",".join(repr(v) for v in r) + "\n")
    with open(os.path.join(directory, "status.json"), "w") as f:
        json.dump({"status": "completed", "step": 4}, f)
    with open(os.path.join(directory, "summary.json"), "w") as f:
        json.dump({"observables": {"objects": {"block": {
            f"kinetic_energy [{energy}]": 12.5, "mean_velocity [m/s]": [100.0, 0.0, 0.0],
            "max_pressure [Pa]": 2.5e8}}}}, f)
    return header


def draw(run_plot, directory):
    figures = []
    run_plot.save_figure = lambda fig, path, **options: figures.append(fig)
    assert run_plot.main([directory, "--out", os.path.join(directory, "fig.png")]) == 0
    energy, error, momentum, observables = figures[0].axes[:4]
    return energy, error, momentum, observables, figures[0]


def main(script, work):
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        print("no matplotlib: skipped")
        sys.exit(77)
    shutil.rmtree(work, ignore_errors=True)
    run_plot = load(script)

    plane = os.path.join(work, "plane_strain")
    write_run(plane, per_metre=True)
    energy, _, momentum, observables, _ = draw(run_plot, plane)
    assert energy.get_ylabel() == "energy [J/m]", energy.get_ylabel()
    assert [line.get_label() for line in energy.get_lines()] == [
        "kinetic_energy", "strain_energy", "total_energy (wide)"], energy.get_lines()
    assert momentum.get_ylabel() == "momentum, impulse [(kg m/s)/m = (N s)/m]", \
        momentum.get_ylabel()
    labels = [line.get_label() for line in momentum.get_lines()]
    assert labels[0] == "momentum_x (constant to round-off, spread 4.4e-16)", labels
    assert labels[1] == "momentum_y (zero to round-off, |max| 1.0e-17)", labels
    assert labels[2:] == ["momentum_z (exactly 0)"] + [
        f"boundary_impulse_{c} (exactly 0)" for c in "xyz"], labels
    low, high = momentum.get_ylim()
    assert abs(low + 1.65) < 1e-9 and abs(high - 1.65) < 1e-9, (low, high)
    assert not observables.axison, "observables without gauges: text only, no axes"
    text = observables.texts[0].get_text()
    assert text == "block: KE 12.5 J/m, mean v (100, 0, 0) m/s, max p 250 MPa", text

    solid = os.path.join(work, "three_d")
    write_run(solid, per_metre=False, gauges=True)
    energy, _, momentum, observables, figure = draw(run_plot, solid)
    assert energy.get_ylabel() == "energy [J]", energy.get_ylabel()
    assert momentum.get_ylabel() == "momentum, impulse [kg m/s = N s]", momentum.get_ylabel()
    assert observables.axison and observables.get_ylabel() == "gauges [MPa]", \
        observables.get_ylabel()
    assert max(observables.get_lines()[0].get_ydata()) == 800.0  # 8e8 Pa in MPa
    twin = figure.axes[4]
    assert twin.get_ylabel() == "gauges [m/s] (dotted)", twin.get_ylabel()
    print("OK: per-metre and 3D units from the header, momentum round-off named, no empty axes")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
