#!/usr/bin/env python3
"""The campaign scripts the docs run directly are programs (issue 52): every script under
campaigns/study, campaigns/taylor and campaigns/benchmark with a `__main__` block starts with
`#!/usr/bin/env python3` and is executable, and `SCRIPT --help`, run as a program, exits 0 with its
usage on stdout and nothing on stderr while `import numpy` fails (a directory holding a numpy.py
that raises ImportError comes first on PYTHONPATH): the options are read before NumPy is needed.
Also the Taylor campaign's exit codes without NumPy: a usage error 1 (also a missing --mpm), an
unreadable table of shots 2, each one line on stderr naming the option or the file. And one
launcher (issue 54): no script under campaigns/ builds an `mpm run|check|study` argument list or
calls subprocess on one; they go through impact.results.Launcher (python/impact/results/).

  campaign_scripts_test.py"""

import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
FOLDERS = ("campaigns/study", "campaigns/taylor", "campaigns/benchmark")
SHEBANG = "#!/usr/bin/env python3"
EXPECTED_MIN = 15  # 17 today: a lower count means the folders moved


def scripts():
    for folder in FOLDERS:
        base = os.path.join(ROOT, folder)
        for name in sorted(os.listdir(base)):
            path = os.path.join(base, name)
            if name.endswith(".py"):
                with open(path) as f:
                    text = f.read()
                if 'if __name__ == "__main__":' in text:
                    yield path, text


def private_launchers(source):
    """Every `mpm` the campaign scripts run goes through impact.results.launcher: no script
    under campaigns/ builds an mpm argument list (`mpm, "run"`, `args.mpm, "check"`, ...) or
    calls subprocess on one."""
    found = []
    argv = re.compile(r"\bmpm\w*\s*,\s*[\"'](?:run|check|study)[\"']")
    call = re.compile(r"subprocess\.(?:run|call|Popen|check_call|check_output)\(")
    for root, _, names in os.walk(os.path.join(source, "campaigns")):
        for name in sorted(names):
            if not name.endswith(".py"):
                continue
            path = os.path.join(root, name)
            with open(path) as f:
                text = f.read()
            hits = list(argv.finditer(text)) + [
                m for m in call.finditer(text)
                if re.search(r"\bmpm\b|mpirun", text[m.start():m.start() + 150])]
            for m in hits:  # (a call on an argument list is found twice: one line each)
                line = text.count("\n", 0, m.start()) + 1
                found.append(f"{os.path.relpath(path, source)}:{line}")
    return sorted(set(found))


def main():
    failures = []
    found = list(scripts())
    if len(found) < EXPECTED_MIN:
        failures.append(f"only {len(found)} scripts found in {FOLDERS}")
    with tempfile.TemporaryDirectory() as tmp:
        with open(os.path.join(tmp, "numpy.py"), "w") as f:
            f.write("raise ImportError('numpy is hidden by campaign_scripts_test.py')\n")
        env = dict(os.environ, PYTHONPATH=tmp, PYTHONDONTWRITEBYTECODE="1")
        # The interpreter running this test first on PATH, so that `env python3` finds one.
        env["PATH"] = os.path.dirname(sys.executable) + os.pathsep + env.get("PATH", "")
        for path, text in found:
            rel = os.path.relpath(path, ROOT)
            if not text.startswith(SHEBANG + "\n"):
                failures.append(f"{rel}: the first line is not '{SHEBANG}'")
            if not os.access(path, os.X_OK):
                failures.append(f"{rel}: not executable (git update-index --chmod=+x {rel})")
                continue
            if rel.startswith("campaigns/benchmark/plot_benchmark"):
                continue  # takes its directory before options (not in the docs with --help)
            done = subprocess.run([path, "--help"], capture_output=True, text=True, env=env,
                                  cwd=tmp, timeout=60)
            if done.returncode != 0 or "usage" not in done.stdout.lower() or done.stderr:
                failures.append(f"{rel} --help without NumPy: exit {done.returncode}, stderr "
                                f"{done.stderr.strip()[-300:]!r}")
        taylor = os.path.join(ROOT, "campaigns", "taylor", "taylor.py")
        out = os.path.join(tmp, "out")
        for args, code, message in [
                (["--cells-per-radius", "0"], 1,
                 "taylor: --cells-per-radius: expected whole numbers >= 1, comma separated "
                 "(got '0')"),
                (["--data", os.path.join(tmp, "none.csv")], 2,
                 f"taylor: {os.path.join(tmp, 'none.csv')}: cannot read the table of shots: "
                 "No such file or directory"),
                (["--bogus"], 1, "taylor: unrecognized arguments: --bogus"),
                (["--mpm", os.path.join(tmp, "no_mpm")], 1,
                 f"taylor: --mpm {os.path.join(tmp, 'no_mpm')}: not an executable (build it: "
                 "cmake --build build)")]:
            done = subprocess.run([sys.executable, taylor, out] + args, capture_output=True,
                                  text=True, env=env, cwd=tmp, timeout=60)
            last = done.stderr.strip().splitlines()[-1:] or [""]
            if done.returncode != code or last[0] != message or "Traceback" in done.stderr:
                failures.append(f"taylor.py {' '.join(args)}: exit {done.returncode} (expected "
                                f"{code}), stderr {done.stderr.strip()!r}")
    failures += [f"{where}: runs mpm itself (use impact.results.Launcher)"
                 for where in private_launchers(ROOT)]
    for f in failures:
        print(f"FAIL {f}")
    print(f"{len(found)} scripts, {len(failures)} problems")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
