#!/usr/bin/env python3
"""campaigns/study/study_plot.py's summary.md prints a run's discretization error as the ladder
allows it to be quoted (issue 52; docs/accuracy.md#grid-convergence-ladders), on a synthetic
study (summary.json and history.csv written here, no mpm run):

- a quotable entry ("quotable": true): this run's value, the extrapolated value, the signed error
  against it, GCI_fine and the order, each number with its unit;
- an entry that is not quotable: the verdict and the range of converged values
  ("... : 3-14 m/s for p in [0.5, 1]"), with '-' where an extrapolation, an error or a GCI
  would be, even though the entry carries an "error [-]" (-180.9 % before);
- an entry of a ladder table made before ranges existed (no "quotable"): its status and where the
  range would come from, no percentage.
No signed percentage stands in a row that is not quotable, and every table renders; an output
that cannot be written (summary.csv a directory) gives one line and exit 3. Also
energy.png's momentum balances, p - boundary impulse per component, for x, y and z (before, x
alone; the figure itself is looked at, not asserted).

  study_plot_test.py"""

import json
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
SCRIPT = os.path.join(ROOT, "campaigns", "study", "study_plot.py")
sys.path.insert(0, HERE)
import markdown_tables_test  # noqa: E402

ENTRIES = {
    "crater depth": {"path": "/observables/crater/depth [m]", "value": 0.00423,
                     "extrapolated": 0.0075, "error [-]": -0.436, "gci_fine [-]": 0.0386,
                     "gci_conservative [-]": 0.31, "order": 1.2, "status": "extrapolated; in the "
                     "asymptotic range (two triples agree)", "quotable": True,
                     "verdict": "in the asymptotic range",
                     "range": {"low": 0.0075, "high": 0.0078, "unit": "m", "order_low": 1.0,
                               "order_high": 1.2, "levels": 3, "basis": "Richardson"}},
    "sphere residual velocity": {
        "path": "/observables/objects/sphere/mean_velocity [m~1s]/0", "value": -18.47,
        "extrapolated": 22.84, "error [-]": -1.809, "gci_fine [-]": 6.26, "order": 0.353,
        "status": "extrapolated with an implausible order 0.35", "quotable": False,
        "verdict": "order 0.353 outside the plausible [0.5, 2]; not in the asymptotic range",
        "range": {"low": 3.0899, "high": 13.856, "unit": "m/s", "order_low": 0.5,
                  "order_high": 1.0, "levels": 3, "basis": "Richardson"}},
    "crater diameter": {"path": "/observables/crater/half_depth_diameter [m]", "value": 0.016,
                        "extrapolated": None, "error [-]": None, "gci_fine [-]": None,
                        "order": None, "status": "monotonic divergence; not in the asymptotic "
                        "range"},
}
WANT = {
    "crater depth": "| crater depth [mm] | 4.23 mm | 7.5 mm | -43.6 | 3.9 | 1.2 | quotable: in the "
                    "asymptotic range |",
    "sphere residual velocity": "| sphere residual velocity [m/s] | -18.47 m/s | - | - | - | - | "
                                "order 0.353 outside the plausible [0.5, 2]; not in the "
                                "asymptotic range: 3-14 m/s for p in [0.5, 1] |",
    "crater diameter": "| crater diameter [mm] | 16 mm | - | - | - | - | monotonic divergence; "
                       "not in the asymptotic range: no range in the ladder table (re-analyse it: "
                       "campaigns/study/ladder.py --analyse-only) |",
}
HISTORY = ("time [s],kinetic_energy [J],strain_energy [J],total_energy [J],momentum_x [kg m/s],"
           "momentum_y [kg m/s],momentum_z [kg m/s],boundary_impulse_x [N s],"
           "boundary_impulse_y [N s],boundary_impulse_z [N s],energy_error [-]\n"
           "0,10,0,10,2,0,0,0,0,0,0\n"
           "1e-6,6,4,10,1.5,-0.3,0.1,-0.5,-0.3,0.1,0\n")


PLANE_STRAIN_HISTORY = (
    "time [s],kinetic_energy [J/m],strain_energy [J/m],total_energy [J/m],"
    "momentum_x [(kg m/s)/m],momentum_y [(kg m/s)/m],momentum_z [(kg m/s)/m],"
    "boundary_impulse_x [(N s)/m],boundary_impulse_y [(N s)/m],boundary_impulse_z [(N s)/m],"
    "friction_heat [J/m],energy_error [-]\n"
    "0,8,0,8,1e-17,0,0,0,0,0,0,0\n"
    "1e-6,5,2.5,7.5,3e-17,0,0,0,0,0,0.5,0\n")


def write_case(out, name, summary, history):
    """A case directory as `mpm run` leaves it: summary.json and history.csv."""
    case = os.path.join(out, name)
    os.makedirs(case)
    with open(os.path.join(case, "summary.json"), "w") as f:
        json.dump(summary, f)
    with open(os.path.join(case, "history.csv"), "w") as f:
        f.write(history)
    return case


def plane_strain_study():
    """A plane-strain run books per metre of thickness: the table's heads say J/m, the initial
    energy and the drift are read from "initial_energy [J/m]", the sink column is tabulated, and
    two head-on bodies whose momenta cancel are judged against sqrt(2 M E0) with M read from
    "mass [kg/m]" (before: heads in J, the drift blank, the friction heat left out and the
    momentum error 0.86, round-off over round-off)."""
    failures = []
    with tempfile.TemporaryDirectory() as out:
        write_case(out, "case01",
                   {"status": "completed", "particles": 4, "initial_energy [J/m]": 8.0,
                    "initial_momentum [(kg m/s)/m]": [1e-17, 0.0, 0.0], "mass [kg/m]": 1.0,
                    "steps": 2, "wall_time [s]": 0.1}, PLANE_STRAIN_HISTORY)
        done = subprocess.run([sys.executable, SCRIPT, out, "--no-figures"], capture_output=True,
                              text=True)
        if done.returncode != 0:
            return [f"plane strain: study_plot.py exit {done.returncode}: {done.stderr}"]
        with open(os.path.join(out, "summary.csv")) as f:
            head, row = [line.rstrip("\n").split(",") for line in f.readlines()[:2]]
        cells = dict(zip(head, row))
        for name in ("initial_kinetic_energy [J/m]", "final_total_energy [J/m]",
                     "friction_heat_end [J/m]"):
            if name not in cells:
                failures.append(f"plane strain: no column {name!r} in {head}")
        if any(h.endswith("[J]") for h in head):
            failures.append(f"plane strain: a column in J: {head}")
        # drift (7.5 - 8) / 8; momentum residual 2e-17 against sqrt(2 * 1 * 8) = 4.
        checks = {"relative_drift [-]": -0.0625, "momentum_balance_error [-]": 2e-17 / 4.0,
                  "friction_heat_end [J/m]": 0.5}
        for name, want in checks.items():
            got = cells.get(name, "")
            if not got or abs(float(got) - want) > 1e-9 * max(abs(want), 1e-12):
                failures.append(f"plane strain: {name} {got!r}, want {want}")
    return failures


def main():
    failures = []
    with tempfile.TemporaryDirectory() as out:
        case = write_case(
            out, "recommended",
            {"status": "completed", "particles": 10, "initial_energy [J]": 10.0,
             "initial_momentum [kg m/s]": [2.0, 0.0, 0.0], "mass [kg]": 1.0, "steps": 2,
             "wall_time [s]": 0.1, "particle_steps_per_second": 200.0,
             "discretization_error": {"table": "x.ladder.json", "level": 1.0,
                                      "ladder_commit": "abc", "observables": ENTRIES}},
            HISTORY)
        done = subprocess.run([sys.executable, SCRIPT, out, "--no-figures"], capture_output=True,
                              text=True)
        if done.returncode != 0:
            failures.append(f"study_plot.py exit {done.returncode}: {done.stderr}")
        with open(os.path.join(out, "summary.md")) as f:
            md = f.read()
        rows = {name: next((line for line in md.splitlines() if line.startswith(f"| {name} [")),
                           None) for name in WANT}
        for name, want in WANT.items():
            if rows[name] != want:
                failures.append(f"{name}:\n  got  {rows[name]}\n  want {want}")
        for name in ("sphere residual velocity", "crater diameter"):
            if rows[name] and re.search(r"[+-]\d[\d.]*\s*%|\|\s*[+-]\d[\d.]*\s*\|", rows[name]):
                failures.append(f"{name}: a signed error in a row that is not quotable")
        if "-180.9" in md or "180.9" in md:
            failures.append("the error against the extrapolation of a non-quotable entry")
        bad = markdown_tables_test.problems(os.path.join(out, "summary.md"))
        if bad:
            failures.append(f"summary.md tables that do not render: {bad}")
        # energy.png draws the balance of every component (p - boundary impulse), not x's
        # alone: y and z move by what the faces exert, and their balances stay flat.
        sys.path.insert(0, os.path.dirname(SCRIPT))
        import study_plot  # noqa: E402
        balances = study_plot.momentum_balances(
            study_plot.History(os.path.join(case, "history.csv")))
        if balances != {"x": [2.0, 2.0], "y": [0.0, 0.0], "z": [0.0, 0.0]}:
            failures.append(f"momentum balances {balances}")
        # An output that cannot be written: one line and exit 3 (a traceback before).
        blocked = os.path.join(out, "summary.csv")
        os.remove(blocked)
        os.makedirs(blocked)
        done = subprocess.run([sys.executable, SCRIPT, out, "--no-figures"], capture_output=True,
                              text=True)
        want = f"study_plot.py: {blocked}: cannot be written: Is a directory"
        if done.returncode != 3 or done.stderr.strip() != want:
            failures.append(f"summary.csv a directory: exit {done.returncode}, stderr "
                            f"{done.stderr.strip()!r}, want 3 and {want!r}")
        os.rmdir(blocked)
        try:
            import matplotlib  # noqa: F401
            done = subprocess.run([sys.executable, SCRIPT, out], capture_output=True, text=True)
            if done.returncode != 0 or not os.path.isfile(os.path.join(case, "energy.png")):
                failures.append(f"energy.png: exit {done.returncode}: {done.stderr}")
        except ImportError:
            print("study_plot_test: matplotlib missing: energy.png not drawn")
    failures += plane_strain_study()
    for f in failures:
        print("FAIL", f)
    print(f"study_plot_test: {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
