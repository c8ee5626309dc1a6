#!/usr/bin/env python3
"""The worked example of docs/python.md: fit Johnson-Cook to the 6061-T6 room-temperature curves,
plot data and fit, then fire the House et al. (1995) Taylor shot H8 (328 m/s) with the published
and the fitted set and compare the rod's kinetic energy.

  PYTHONPATH=build/python python3 python/examples/fit_and_taylor.py [OUT_DIR]

Writes OUT_DIR/fit_and_taylor.png (default out/python/; the committed figure is regenerated with
OUT_DIR docs/figures/python) and prints the numbers quoted in docs/python.md.
"""
import json
import os
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import impact  # noqa: E402


def main(out_dir):
    os.makedirs(out_dir, exist_ok=True)
    work = tempfile.mkdtemp(prefix="impact_taylor_")  # the runs' outputs

    # 1. Fit B, n and C to the room-temperature curves, as a dict built on the shipped
    #    configuration: A held at the published yield, 324 MPa (on these curves A, B and n are
    #    almost perfectly correlated, docs/fitting.md), m fixed (no temperature series here).
    with open(impact.data_path("fits", "al6061_t6_room_temperature.json")) as f:
        config = json.load(f)
    config["parameters"] = {"A": {"free": False}, "m": {"free": False}}
    config["initial_guess"] = "start"  # from the published set
    # The configuration's relative paths ("data/experiments/...") are relative to the folder
    # holding data/.
    report = impact.fit(config, base_dir=os.path.dirname(impact.data_path()))
    fitted = {k: v["fitted"] for k, v in report["parameters"].items()}
    print("converged:", report["converged"])
    print("fitted:", {k: f"{v:.4g}" for k, v in fitted.items()})
    print(f"overall RMS: fitted {report['overall']['fitted_rms [Pa]'] / 1e6:.2f} MPa, "
          f"published {report['overall']['material_rms [Pa]'] / 1e6:.2f} MPa")

    fig, (ax_fit, ax_rod) = plt.subplots(1, 2, figsize=(12, 4.6), layout="constrained")
    shown = [s for s in report["series"]  # a readable subset: quasi-static and the fastest tests
             if s["data"]["strain_rate"] <= 1e-3 or s["data"]["strain_rate"] >= 1000]
    handles = []
    for k, s in enumerate(shown):
        # One colour per series and its fit; past the 10 colours, squares and dashes, so that no
        # two series look alike.
        colour = f"C{k % 10}"
        marker, dash = ("o", "-") if k < 10 else ("s", "--")
        ax_fit.plot(s["data"]["plastic_strain"], s["data"]["stress"] / 1e6, marker, ms=3,
                    color=colour)
        ax_fit.plot(s["fitted"]["plastic_strain"], s["fitted"]["stress"] / 1e6, dash, lw=1.2,
                    color=colour)
        handles.append(plt.Line2D([], [], color=colour, marker=marker, ms=3, ls=dash, lw=1.2,
                                  label=s["data"]["name"]))
    ax_fit.set(xlabel="true plastic strain [-]", ylabel="true stress [MPa]",
               title="6061-T6, 295 K: data (markers) and fit (line), one colour each",
               xlim=(0, 0.4))
    ax_fit.legend(handles=handles, fontsize=6, ncol=2)

    # 2. The Taylor shot with each set: the shipped scene, its material patched.
    scene = impact.data_path("scenes", "verification", "taylor_rod.json")
    for label, flow in (("published set", {}), ("fitted set", fitted)):
        patch = {"materials": {"al": {"overrides": {"constitutive_model": {"flow_stress": flow}}}},
                 "output": {"interval": 1e-6}}
        run = impact.run_scene(scene, out=os.path.join(work, label.split()[0]), patches=patch)
        h = run["history"]
        ax_rod.plot(h["time"] * 1e6, h["kinetic_energy"], label=label)
        print(f"{label}: exit {run['exit_code']}, kinetic energy {h['kinetic_energy'][0]:.2f} -> "
              f"{h['kinetic_energy'][-1]:.3f} J, energy error {h['energy_error'][-1]:.2e}")
    ax_rod.set(xlabel="time [us]", ylabel=f"kinetic energy [{h.units['kinetic_energy']}]",
               title="Taylor shot H8 (328 m/s), coarse rod")
    ax_rod.legend()
    figure = os.path.join(out_dir, "fit_and_taylor.png")
    fig.savefig(figure, dpi=110)
    print("wrote", figure)


def output_directory(argv):
    """OUT_DIR, else out/python: never the committed docs/figures/python unless asked for."""
    return argv[0] if argv else os.path.join("out", "python")


if __name__ == "__main__":
    main(output_directory(sys.argv[1:]))
