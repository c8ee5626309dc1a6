#!/usr/bin/env python3
"""`mpm plot RUN` draws one run's energy books, energy error, momentum and observables.

  plot_run_test.py MPM SOURCE_DIR WORK_DIR

The shipped rigid translation for 2e-5 s with a velocity gauge and a pressure gauge, run by
`mpm run`; then `mpm plot`. Asserted: exit 0; RUN/run.png is a PNG of 1320 x 880 pixels (12 x 8
in at 110 dpi) and `--out FIG.svg` an SVG; the columns it says it drew are, panel by panel,
those of history.csv's header: every [J] column before energy_error, energy_error, every
[kg m/s] and [N s] column, and the gauges after energy_error; a directory without history.csv
is an input error (exit 2) naming it. Without matplotlib (for /usr/bin/python3 or
$IMPACT_PYTHON) only the exit code 1 and the install hint are checked.
"""
import json
import os
import shutil
import struct
import subprocess
import sys


def run(cmd, code=0):
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != code:
        sys.exit(f"FAIL: {' '.join(cmd)} exited {done.returncode}, expected {code}\n"
                 f"{done.stdout}\n{done.stderr}")
    return done


def main(mpm, source, work):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    scene = os.path.join(source, "data", "scenes", "verification", "rigid_translation.json")
    patch = {"time": {"max_time": 2e-5}, "output": {"interval": 5e-6, "snapshots": False,
             "gauges": {"centre_vx": {"type": "velocity", "object": "block", "component": "x",
                                      "region": {"lower": [0.02, 0.02, 0.02],
                                                 "upper": [0.04, 0.04, 0.04]}},
                        "centre_p": {"type": "pressure", "object": "block",
                                     "region": {"lower": [0.02, 0.02, 0.02],
                                                "upper": [0.04, 0.04, 0.04]}}}}}
    out = os.path.join(work, "run")
    run([mpm, "run", scene, "--out", out, "--threads", "1", "--set", json.dumps(patch)])
    python = os.environ.get("IMPACT_PYTHON") or "/usr/bin/python3"
    if subprocess.run([python, "-c", "import matplotlib"], capture_output=True).returncode != 0:
        done = run([mpm, "plot", out], code=1)
        assert "python3-matplotlib" in done.stderr, done.stderr
        print("OK: no matplotlib: exit 1 with the install command")
        return
    done = run([mpm, "plot", out])
    figure = os.path.join(out, "run.png")
    with open(figure, "rb") as f:
        head = f.read(24)
    assert head[:8] == b"\x89PNG\r\n\x1a\n", head
    assert struct.unpack(">II", head[16:24]) == (1320, 880), struct.unpack(">II", head[16:24])
    drawn = {}
    for line in done.stdout.splitlines():
        if ": " in line and not line.startswith("wrote"):
            panel, columns = line.split(": ", 1)
            drawn[panel] = columns.split(", ")
    with open(os.path.join(out, "history.csv")) as f:
        header = f.readline().strip().split(",")
    end = header.index("energy_error [-]")
    expected = {
        "energy books": [c for c in header[:end] if c.endswith("[J]")],
        "energy error": ["energy_error [-]"],
        "momentum": [c for c in header[:end] if c.endswith(("[kg m/s]", "[N s]"))],
        "observables": header[end + 1:],
    }
    assert expected["observables"] == ["gauge_centre_p [Pa]", "gauge_centre_vx [m/s]"], header
    assert "kinetic_energy [J]" in expected["energy books"] and len(expected["momentum"]) == 6
    drawn["observables"].sort()  # grouped by unit in the figure
    assert drawn == expected, f"drew {drawn}\nexpected {expected}"
    svg = os.path.join(work, "run.svg")
    run([mpm, "plot", out, "--out", svg])
    with open(svg) as f:
        assert "<svg" in f.read(2000)
    empty = os.path.join(work, "empty")
    os.makedirs(empty)
    done = run([mpm, "plot", empty], code=2)
    assert f"mpm plot: {empty}: no history.csv" in done.stderr, done.stderr
    print(f"OK: {figure} ({os.path.getsize(figure)} B) and {svg}; panels as history.csv's header")


if __name__ == "__main__":
    main(*sys.argv[1:4])
