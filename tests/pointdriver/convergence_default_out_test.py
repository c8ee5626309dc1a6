#!/usr/bin/env python3
"""`pointdriver convergence` without --out writes into ./pointdriver_convergence/, never over the
committed docs/figures/ (it wrote docs/figures/ of the working directory, before: run from the
repository root, the committed tables and figures were overwritten by any trial run).

  convergence_default_out_test.py POINTDRIVER SOURCE_DIR WORK_DIR

Runs `pointdriver convergence --quick --no-plots` in an empty WORK_DIR, the material named
(the default is found relative to the source tree). Asserted: exit 0; WORK_DIR holds only
pointdriver_convergence/ with convergence.csv, convergence_orders.csv and convergence.md; the
printed paths name that directory.
"""
import os
import shutil
import subprocess
import sys


def main(exe, source, work):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    material = os.path.join(source, "data", "materials", "al6061_t6.json")
    done = subprocess.run([exe, "convergence", "--quick", "--no-plots", "--material", material],
                          cwd=work, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, f"exit {done.returncode}\n{done.stdout[-2000:]}\n{done.stderr}"
    assert os.listdir(work) == ["pointdriver_convergence"], os.listdir(work)
    written = sorted(os.listdir(os.path.join(work, "pointdriver_convergence")))
    assert written == ["convergence.csv", "convergence.md", "convergence_orders.csv"], written
    assert ("wrote pointdriver_convergence/convergence.csv and "
            "pointdriver_convergence/convergence.md") in done.stdout, done.stdout[-500:]
    print("OK: default output pointdriver_convergence/")


if __name__ == "__main__":
    main(*sys.argv[1:4])
