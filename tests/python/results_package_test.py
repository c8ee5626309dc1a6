#!/usr/bin/env python3
"""impact.results, the pure-Python results package (docs/python.md#results): importable from the
source tree's python/ alone, without the compiled module (`impact._impact` is not imported) and,
for the launcher and the plain readers, without NumPy; the launcher's command lines (--out,
--threads, --set, extra flags, mpirun -np N for ranks); find_mpm() from an install's layout
(<prefix>/bin/mpm beside share/impact/python or site-packages); a short real `mpm run` of the rigid
translation (2e-6 s via --set) read back with read_run, history_rows and read_points; a run that
fails raises LaunchError carrying mpm's stderr. (That no campaign script keeps its own `mpm`
subprocess is campaign_scripts_test.py's.)

  results_package_test.py MPM SOURCE_DIR WORK_DIR"""
import json
import os
import shutil
import subprocess
import sys


def fail(message):
    sys.exit(f"FAIL: {message}")


def isolated(source, code, hide_numpy=False, work="."):
    """Runs `code` in a fresh interpreter that sees only <source>/python (no PYTHONPATH, no
    build tree); with hide_numpy, `import numpy` raises ImportError."""
    prelude = (f"import sys; sys.path.insert(0, {os.path.join(source, 'python')!r})\n")
    if hide_numpy:
        prelude += "sys.modules['numpy'] = None\n"  # `import numpy` then raises ImportError
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    done = subprocess.run([sys.executable, "-s", "-c", prelude + code], capture_output=True,
                          text=True, env=env, cwd=work, timeout=300)
    if done.returncode != 0:
        fail(f"isolated import:\n{code}\n{done.stderr}")
    return done.stdout


def check_imports(source):
    # Without the compiled module, `import impact` and `impact.results` load no NumPy and leave
    # the environment alone (an mpm the scripts start keeps libgomp's default wait policy);
    # impact.results is an attribute; the code tables raise the compiled module's ImportError;
    # data_path finds the source tree's data.
    out = isolated(source, """
import os
os.environ.pop('OMP_WAIT_POLICY', None)
import impact
from impact.results import Launcher, history_rows
assert 'numpy' not in sys.modules, 'numpy was imported'
assert 'OMP_WAIT_POLICY' not in os.environ, os.environ['OMP_WAIT_POLICY']
assert impact.results.Launcher is Launcher
try:
    impact.failure_causes
except ImportError as e:
    assert 'not built or not installed' in str(e), e
else:
    raise AssertionError('impact.failure_causes without the compiled module did not raise')
assert os.path.isfile(impact.data_path('materials', 'al6061_t6.json'))
print('ok')
""")
    if out.strip() != "ok":
        fail(f"import without the compiled module: {out!r}")
    out = isolated(source, """
import impact, impact.results
from impact.results import read_run, read_history, read_points, launch, Launcher, history_rows
assert impact.read_run is read_run and impact.Table is impact.results.Table
assert 'impact._impact' not in sys.modules, 'the compiled module was imported'
assert impact.__file__.endswith('python/impact/__init__.py'), impact.__file__
try:
    impact.Material('x.json')
except ImportError as e:
    assert 'not built or not installed' in str(e) and 'impact.results' in str(e), e
else:
    raise AssertionError('impact.Material without the compiled module did not raise')
print('ok')
""")
    assert out.strip() == "ok", out
    # The launcher and the plain readers on a machine without NumPy (the campaigns' --help).
    out = isolated(source, """
from impact.results import Launcher, launch, history_columns, read_summary, find_mpm
from impact.results.vtu import read_points
assert 'numpy' not in sys.modules or sys.modules['numpy'] is None
print('ok')
""", hide_numpy=True)
    assert out.strip() == "ok", out


def check_command_lines(source):
    out = isolated(source, """
import json
from impact.results import Launcher
m = Launcher('/opt/mpm', mpirun='mpirun --oversubscribe')
print(json.dumps([
    m.command('run', 'a.json', out='o', threads=2),
    m.command('run', 'a.json', out='o', options=['--overwrite'], threads=1,
              sets=['{"time": {"max_time": 1e-6}}', {"output": {"snapshots": False}}],
              extra=['-q']),
    m.command('run', options=['--restart', 'o'], threads=3, ranks=4, extra=['-q']),
    m.command('check', 'a.json', options=['--ranks', '2'], sets='{"x": 1}'),
    m.command('study', 'scenes', out='runs', threads=2, extra=['--no-plot']),
    Launcher('/opt/mpm', mpirun_options=['--oversubscribe']).command('run', 'a', ranks=2),
    m.command('run', 'a', threads=0, sets=None, options='--overwrite', extra=None)]))
for bad in ({'ranks': 0}, {'ranks': 1.5}, {'threads': 1.7}, {'threads': -1},
            {'sets': {'time': {'max_time': float('nan')}}}):
    try:
        m.command('run', 'a', **bad)
    except ValueError:
        pass
    else:
        raise AssertionError(bad)
""")
    got = json.loads(out)
    expected = [
        ["/opt/mpm", "run", "a.json", "--out", "o", "--threads", "2"],
        ["/opt/mpm", "run", "a.json", "--out", "o", "--overwrite", "--threads", "1", "--set",
         '{"time": {"max_time": 1e-6}}', "--set", '{"output": {"snapshots": false}}', "-q"],
        ["mpirun", "--oversubscribe", "-np", "4", "/opt/mpm", "run", "--restart", "o",
         "--threads", "3", "-q"],
        ["/opt/mpm", "check", "a.json", "--ranks", "2", "--set", '{"x": 1}'],
        ["/opt/mpm", "study", "scenes", "--out", "runs", "--threads", "2", "--no-plot"],
        ["mpirun", "-np", "2", "--oversubscribe", "/opt/mpm", "run", "a"],
        # threads 0 is the program's default (as run_scene's), one string is one option
        ["/opt/mpm", "run", "a", "--overwrite"]]
    if len(got) != len(expected):
        fail(f"{len(got)} command lines, expected {len(expected)}")
    for g, e in zip(got, expected):
        if g != e:
            fail(f"command line {g}, expected {e}")


def check_find_mpm(source, work):
    """find_mpm() without an argument: the mpm of the install the package lies in (its
    share/impact/python and its lib/python3.X/site-packages alike)."""
    for package_dir in (("share", "impact", "python"), ("lib", "python3.9", "site-packages")):
        prefix = os.path.join(work, "prefix_" + package_dir[0])
        shutil.copytree(os.path.join(source, "python", "impact"),
                        os.path.join(prefix, *package_dir, "impact"),
                        ignore=shutil.ignore_patterns("__pycache__"))
        os.makedirs(os.path.join(prefix, "bin"))
        mpm = os.path.join(prefix, "bin", "mpm")
        with open(mpm, "w") as f:
            f.write("#!/bin/sh\n")
        os.chmod(mpm, 0o755)
        code = ("import sys; sys.path.insert(0, sys.argv[1])\n"
                "from impact.results import find_mpm; print(find_mpm())")
        done = subprocess.run([sys.executable, "-s", "-c", code,
                               os.path.join(prefix, *package_dir)],
                              capture_output=True, text=True, timeout=60)
        if done.returncode != 0 or done.stdout.strip() != mpm:
            fail(f"find_mpm() from {os.path.join(*package_dir)}: {done.stdout.strip()!r} "
                 f"{done.stderr.strip()[-300:]}, expected {mpm}")
    # A build tree's copy of the package finds <build>/bin/mpm; a source tree without a build
    # finds nothing of its own, and never an mpm beside the tree (<src>/../bin/mpm, a decoy).
    for layout in ("build", "source"):
        tree = os.path.join(work, "layout_" + layout, "tree")
        shutil.copytree(os.path.join(source, "python", "impact"),
                        os.path.join(tree, "python", "impact"),
                        ignore=shutil.ignore_patterns("__pycache__"))
        marker = "CMakeCache.txt" if layout == "build" else "CMakeLists.txt"
        open(os.path.join(tree, marker), "w").close()
        own = os.path.join(tree, "bin", "mpm")
        decoy = os.path.join(work, "layout_" + layout, "bin", "mpm")
        for exe in (own, decoy) if layout == "build" else (decoy,):
            os.makedirs(os.path.dirname(exe), exist_ok=True)
            with open(exe, "w") as f:
                f.write("#!/bin/sh\n")
            os.chmod(exe, 0o755)
        code = ("import sys; sys.path.insert(0, sys.argv[1])\n"
                "from impact.results import find_mpm\n"
                "try:\n    print(find_mpm())\nexcept FileNotFoundError:\n    print('none')")
        done = subprocess.run([sys.executable, "-s", "-c", code, os.path.join(tree, "python")],
                              capture_output=True, text=True, timeout=60,
                              env=dict(os.environ, PATH="/nonexistent"))
        expected = own if layout == "build" else "none"
        if done.returncode != 0 or done.stdout.strip() != expected:
            fail(f"find_mpm() from a {layout} tree: {done.stdout.strip()!r} "
                 f"{done.stderr.strip()[-300:]}, expected {expected}")


def check_real_run(mpm, source, work):
    scene = os.path.join(source, "data", "scenes", "verification", "rigid_translation.json")
    out = isolated(source, f"""
import json
from impact.results import (Launcher, LaunchError, read_run, history_rows, read_points,
                            snapshots, read_summary, completed)
m = Launcher({mpm!r})
done = m.run('run', {scene!r}, out='short', threads=1,
             sets=[{{"time": {{"max_time": 2e-6}}}},
                   '{{"output": {{"snapshots": true, "interval": 1e-6}}}}'])
assert done.returncode == 0, done
assert completed('short') and read_summary('short')['status'] == 'completed'
run = read_run('short')
assert run.status['status'] == 'completed', run.status
assert abs(run.history['time'][-1] - 2e-6) < 1e-12, run.history['time']
assert run.history.units['kinetic_energy'] == 'J'
header, rows = history_rows('short')
assert header[0] == 'time [s]' and len(rows) == len(run.history['time'])
snaps = snapshots('short')
assert snaps and snaps[-1][0] == run.snapshots[-1].time
last = read_points(snaps[-1][1])
plain = read_points(snaps[-1][1], numpy=False)
assert last['points'].shape == run.snapshots[-1].positions.shape
assert [tuple(p) for p in last['points'].tolist()] == plain['points']
assert last['velocity'].shape == (len(plain['velocity']), 3)
check = m.run('check', {scene!r}, sets='{{"time": {{"max_time": 2e-6}}}}')
assert check.returncode == 0 and check.stdout, check
try:
    m.run('run', 'no_such_scene.json', out='bad', threads=1)
except LaunchError as e:
    assert e.returncode == 2 and 'no_such_scene.json' in str(e) and e.stderr, (e.returncode, e)
else:
    raise AssertionError('a run of a missing scene did not raise')
print('ok')
""", work=work)
    assert out.strip() == "ok", out


def main(mpm, source, work):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    check_imports(source)
    check_command_lines(source)
    check_find_mpm(source, work)
    check_real_run(os.path.abspath(mpm), source, work)
    print("results_package_test: ok")


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    main(*sys.argv[1:])
