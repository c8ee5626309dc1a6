#!/usr/bin/env python3
"""The observables campaigns/study/ladder.py reads for scenes written with expressions
(docs/scenes.md#expressions): a velocity component that is an expression counts as 0 when the
ladder picks the fastest object (it used to stop the ladder with a TypeError), and
output.exact_displacement adds "displacement error rms" and "displacement error max", read from
the last history.csv row of a run (here a written one: 1e-6 m and 3e-6 m), None for a run
without those columns.

  ladder_observables_test.py"""
import os
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "campaigns", "study"))
import ladder  # noqa: E402


def main():
    scene = {"objects": {"bar": {"velocity": ["A*sin(2*pi*X/L)", 0, 0]},
                         "plate": {"velocity": [0, -5.0, 0]}},
             "output": {"exact_displacement": ["A*sin(2*pi*X/L)*sin(pi*c*t/L)", 0, 0]}}
    names = [name for name, _, _ in ladder.observables_of(scene, None)]
    print(names)
    assert "plate residual velocity" in names, names  # the only numeric velocity
    assert "displacement error rms" in names and "displacement error max" in names, names
    with tempfile.TemporaryDirectory() as run:
        with open(os.path.join(run, "history.csv"), "w") as f:
            f.write("time [s],energy_error [-],displacement_error_rms [m],"
                    "displacement_error_max [m]\n0,0,0,0\n1e-5,0.01,1e-06,3e-06\n")
        assert ladder.final_history_value(run, "displacement_error_rms") == 1e-6
        assert ladder.final_history_value(run, "displacement_error_max") == 3e-6
        assert ladder.final_history_value(run, "no_such_column") is None
    with tempfile.TemporaryDirectory() as empty:
        assert ladder.final_history_value(empty, "displacement_error_rms") is None
    print("OK")


if __name__ == "__main__":
    main()
