#!/usr/bin/env python3
"""`pip install .` from the repository into a virtual environment, with no network: the in-tree
PEP 517 backend (pyproject.toml, python/build_backend/impact_build.py) packs the extension this
build made, and nothing is downloaded (--no-index: pip may not even look).

  pip_install_test.py SOURCE_DIR BUILD_DIR WORK_DIR PYTHON

PYTHON makes the venv (--system-site-packages: Debian's NumPy, the wheel's one requirement).
Asserted: pip installs with build isolation on and no index; the module imports from the venv's
site-packages, not from the source or build tree, with its type stub and py.typed; data_path
finds the shipped data under the venv's share/impact/data; a material loads and a point updates;
the subpackage impact.results is installed with it;
pip show names the version of CMakeLists.txt; pip uninstall removes every file it installed.
"""
import os
import re
import shutil
import subprocess
import sys

SNIPPET = """
import os, sys
import numpy as np
import impact
venv = sys.argv[1]
assert impact.__file__.startswith(venv), impact.__file__
here = os.path.dirname(impact.__file__)
assert os.path.exists(os.path.join(here, "__init__.pyi")), os.listdir(here)
assert os.path.exists(os.path.join(here, "py.typed"))
assert not os.path.exists(os.path.join(here, "_source_tree.py"))
material = impact.data_path("materials", "al6061_t6.json")
assert material == os.path.join(venv, "share", "impact", "data", "materials", "al6061_t6.json")
m = impact.Material(material)
state, report = impact.update(m, m.initial_state(), np.diag([1e3, 0.0, 0.0]), 1e-7)
assert report["status"] == "ok" and state["stress"][0, 0] > 0.0
import impact.results  # the subpackage is in the wheel too
assert impact.results.__file__.startswith(venv) and impact.read_run is impact.results.read_run
print("import OK", impact.__file__)
"""


def run(cmd, **kw):
    done = subprocess.run(cmd, capture_output=True, text=True, **kw)
    if done.returncode != 0:
        sys.exit(f"FAIL: {' '.join(cmd)} exited {done.returncode}\n{done.stdout}\n{done.stderr}")
    return done


def main(source, build, work, python):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    venv = os.path.join(work, "venv")
    run([python, "-m", "venv", "--system-site-packages", venv])
    vpython = os.path.join(venv, "bin", "python")
    # No network: --no-index; the build requirements are none, so isolation needs nothing either.
    env = dict(os.environ, PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1")
    env.pop("PYTHONPATH", None)
    run([vpython, "-m", "pip", "install", "--no-index", "--config-settings",
         f"build-dir={build}", source], env=env, cwd=work)
    cwd = os.path.join(work, "cwd")
    os.makedirs(cwd)
    print(run([vpython, "-c", SNIPPET, venv], env=dict(env, IMPACT_NO_SOURCE_TREE="1"),
              cwd=cwd).stdout.strip())
    with open(os.path.join(source, "CMakeLists.txt")) as f:
        version = re.search(r"project\(impact_mpm VERSION ([0-9.]+)", f.read()).group(1)
    shown = run([vpython, "-m", "pip", "show", "-f", "impact-mpm"], env=env).stdout
    assert f"Version: {version}" in shown, shown
    installed = [line.strip() for line in shown.split("Files:", 1)[1].splitlines() if line.strip()]
    site = run([vpython, "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
               env=env).stdout.strip()
    paths = [os.path.normpath(os.path.join(site, f)) for f in installed]
    assert all(os.path.exists(p) for p in paths), [p for p in paths if not os.path.exists(p)]
    run([vpython, "-m", "pip", "uninstall", "-y", "impact-mpm"], env=env)
    left = [p for p in paths if os.path.exists(p) and not os.path.isdir(p)
            and "__pycache__" not in p]
    assert not left, f"left after uninstall: {left}"
    print(f"OK: pip install . (version {version}, {len(installed)} files) into {venv}, imported, "
          "uninstalled")


if __name__ == "__main__":
    main(*sys.argv[1:5])
