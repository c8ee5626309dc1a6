#!/usr/bin/env python3
"""A relocatable install: `cmake --install` into a scratch prefix, the prefix moved elsewhere,
then the three programs run from the moved prefix, with the shipped files (data, plot scripts)
found beside the binaries (support/shipped_file.hpp) and the source tree ruled out
(IMPACT_NO_SOURCE_TREE=1), from a working directory outside both trees.

  relocation_test.py BUILD_DIR WORK_DIR [--python PYTHON]

With --python, the installed Python module is imported from the moved prefix's site-packages
and used: a material from the shipped data, an update, a path and a short scene.
"""
import os
import shutil
import subprocess
import sys


def run(cmd, cwd, env, code=0):
    done = subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True)
    if done.returncode != code:
        sys.exit(f"FAIL: {' '.join(cmd)} exited {done.returncode}, expected {code}\n"
                 f"{done.stdout}\n{done.stderr}")
    return done


PYTHON_SNIPPET = """
import os, sys
import numpy as np
import impact
assert impact.__file__.startswith(sys.argv[1]), impact.__file__
m = impact.Material(impact.data_path("materials", "al6061_t6.json"))
state, report = impact.update(m, m.initial_state(), np.diag([1e3, 0.0, 0.0])[None], 1e-7)
assert report["status"][0] == "ok" and state["stress"][0, 0, 0] > 0.0
r = impact.run_path(impact.data_path("paths", "uniaxial_stress_1000.json"))
assert r.completed and r.units["stress_xx"] == "Pa"
scene = {"extends": impact.data_path("scenes", "verification", "taylor_rod.json"),
         "time": {"max_time": 2e-6}, "output": {"snapshots": False}}
run = impact.run_scene(scene, out="py_rod", threads=1)
assert run["exit_code"] == 0 and run["summary"]["status"] == "completed", run
print("python OK", impact.__file__)
"""

# impact.results from the install's share/impact/python alone (no compiled module there).
RESULTS_SNIPPET = """
import sys
sys.path.insert(0, sys.argv[1])
from impact.results import read_run
run = read_run("rod")
assert run.summary["status"] == "completed" and len(run.history["time"]) > 1, run
import impact
assert impact.__file__.startswith(sys.argv[1]) and "impact._impact" not in sys.modules
"""


def main(build, work, python=None):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    first, moved = os.path.join(work, "prefix"), os.path.join(work, "moved", "elsewhere")
    run(["cmake", "--install", build, "--prefix", first], work, os.environ)
    os.makedirs(os.path.dirname(moved))
    shutil.move(first, moved)
    env = dict(os.environ, IMPACT_NO_SOURCE_TREE="1")
    bin_dir, share = os.path.join(moved, "bin"), os.path.join(moved, "share", "impact")
    cwd = os.path.join(work, "cwd")
    os.makedirs(cwd)
    for program in ("material_check", "pointdriver", "mpm"):
        assert os.access(os.path.join(bin_dir, program), os.X_OK), program
    material = os.path.join(share, "data", "materials", "al6061_t6.json")
    run([os.path.join(bin_dir, "material_check"), material], cwd, env)
    # A shipped path: its material found from the path file's folders upwards in share/.
    path = os.path.join(share, "data", "paths", "uniaxial_stress_1000.json")
    run([os.path.join(bin_dir, "pointdriver"), "run", path, "-o", "u.csv"], cwd, env)
    # The verification suite finds the shipped material and Hugoniot data.
    done = run([os.path.join(bin_dir, "pointdriver"), "verify", "--case", "elastic_uniaxial",
                "--out", "verify"], cwd, env)
    assert "checks pass" in done.stdout, done.stdout
    # The plot script is the installed one (matplotlib present: a PNG).
    run([os.path.join(bin_dir, "pointdriver"), "plot", "u.csv", "--x", "time [s]", "--y",
         "stress_xx [Pa]", "-o", "u.png"], cwd, env)
    assert os.path.getsize(os.path.join(cwd, "u.png")) > 1000
    # mpm: a shipped verification scene, 2 us.
    scene = os.path.join(share, "data", "scenes", "verification", "taylor_rod.json")
    run([os.path.join(bin_dir, "mpm"), "check", scene], cwd, env)
    short = os.path.join(cwd, "rod.json")
    with open(short, "w") as f:
        f.write('{"extends": "%s", "time": {"max_time": 2e-6}, "output": {"snapshots": false}}'
                % scene)
    run([os.path.join(bin_dir, "mpm"), "run", short, "--out", "rod", "--threads", "1"], cwd, env)
    assert os.path.exists(os.path.join(cwd, "rod", "summary.json"))
    # The installed plot script and ladder find impact.results (pure Python) at
    # share/impact/python, with no compiled module: `mpm plot`, the ladder's --help, and the
    # run read back from there.
    run([os.path.join(bin_dir, "mpm"), "plot", "rod", "--out", "rod.png"], cwd, env)
    assert os.path.getsize(os.path.join(cwd, "rod.png")) > 1000
    ladder = os.path.join(share, "campaigns", "study", "ladder.py")
    run(["/usr/bin/python3", ladder, "--help"], cwd, env)
    run(["/usr/bin/python3", "-s", "-c", RESULTS_SNIPPET, os.path.join(share, "python")], cwd,
        {k: v for k, v in env.items() if k != "PYTHONPATH"})
    checked = ("material_check, pointdriver run/verify/plot, mpm check/run/plot and "
               "impact.results")
    if python:
        version = subprocess.run([python, "-c", "import sys; print('%d.%d' % sys.version_info[:2])"],
                                 capture_output=True, text=True, check=True).stdout.strip()
        site = None
        for root, dirs, _ in os.walk(moved):
            if os.path.basename(root) == "site-packages" and "impact" in dirs:
                site = root
        assert site and f"python{version}" in site, f"no site-packages/impact under {moved}"
        run([python, "-c", PYTHON_SNIPPET, moved], cwd, dict(env, PYTHONPATH=site))
        checked += " and the Python module"
    print(f"OK: installed, moved to {moved}; {checked} work from there")


if __name__ == "__main__":
    extra = sys.argv[3:]
    main(sys.argv[1], sys.argv[2], extra[1] if extra[:1] == ["--python"] else None)
