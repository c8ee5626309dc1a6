#!/usr/bin/env python3
"""campaigns/study/ladder.py (and `mpm study --ladder`, which runs it) answers an output it cannot
write and a Ctrl-C with one line on stderr and the documented code, not a traceback (issue 52):

- --out under /proc (no directory can be made there, even as root): exit 3, "ladder: PATH: cannot
  be written (--out): REASON";
- --out below a regular file: exit 3, the path and "Not a directory";
- --out in a read-only directory (only when not root: root writes anyway): exit 3;
- --analyse-only without --levels and nothing run in --out: exit 1, the folder untouched;
- SIGINT while the ladder draws its figures (--analyse-only, so nothing runs; a stand-in
  matplotlib on PYTHONPATH writes a marker and waits, so the signal arrives inside the drawing):
  exit 130, "ladder: interrupted; ...".
With MPM given, `mpm study --ladder 1 SCENE --out /proc/...` exits 3 with the same line.

  ladder_errors_test.py [MPM]"""

import os
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
LADDER = os.path.join(ROOT, "campaigns", "study", "ladder.py")
SCENE = os.path.join(ROOT, "data", "scenes", "verification", "taylor_rod.json")
SLOW_MATPLOTLIB = """import os, time
open(os.environ["LADDER_TEST_MARKER"], "w").close()
time.sleep(60)
"""


def one_line(done):
    lines = done.stderr.strip().splitlines()
    return lines[0] if len(lines) == 1 else None


def main():
    mpm = sys.argv[1] if len(sys.argv) > 1 else None
    failures = []

    def expect(cmd, code, prefix, contains, env=None):
        done = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=120)
        line = one_line(done)
        if (done.returncode != code or line is None or not line.startswith(prefix)
                or contains not in line):
            failures.append(f"{' '.join(cmd)}: exit {done.returncode} (expected {code}), stderr "
                            f"{done.stderr.strip()!r} (expected one line '{prefix}...{contains}"
                            "...')")

    base = [sys.executable, LADDER, SCENE, "--levels", "1", "--analyse-only", "--no-plot"]
    expect(base + ["--out", "/proc/impact_ladder_test"], 3, "ladder: /proc/impact_ladder_test",
           "cannot be written (--out): ")
    with tempfile.TemporaryDirectory() as tmp:
        plain = os.path.join(tmp, "a_file")
        open(plain, "w").close()
        expect(base + ["--out", os.path.join(plain, "out")], 3,
               f"ladder: {os.path.join(plain, 'out')}", "cannot be written (--out): Not a "
               "directory")
        if os.geteuid() != 0:
            locked = os.path.join(tmp, "locked")
            os.makedirs(locked, mode=0o555)
            expect(base + ["--out", os.path.join(locked, "out")], 3,
                   f"ladder: {os.path.join(locked, 'out')}", "Permission denied")
        # --analyse-only without --levels re-analyses the levels already run (ladder.json's, else
        # runs/x<level>); with none there it stops (exit 1, usage) and leaves the folder as it was,
        # where it used to write an empty analysis of the default levels over it.
        empty = os.path.join(tmp, "analysed")
        os.makedirs(empty)
        with open(os.path.join(empty, "ladder.md"), "w") as f:
            f.write("a good analysis\n")
        done = subprocess.run([sys.executable, LADDER, SCENE, "--analyse-only", "--no-plot",
                               "--out", empty], capture_output=True, text=True, timeout=120)
        with open(os.path.join(empty, "ladder.md")) as f:
            kept = f.read() == "a good analysis\n"
        if (done.returncode != 1 or "no --levels given and none found" not in done.stderr
                or not kept or sorted(os.listdir(empty)) != ["ladder.md"]):
            failures.append(f"--analyse-only without levels: exit {done.returncode}, "
                            f"{done.stderr.strip()[-200:]!r}, ladder.md kept {kept}, "
                            f"files {sorted(os.listdir(empty))}")
        # Ctrl-C while the figures are drawn.
        fake = os.path.join(tmp, "fake")
        os.makedirs(os.path.join(fake, "matplotlib"))
        with open(os.path.join(fake, "matplotlib", "__init__.py"), "w") as f:
            f.write(SLOW_MATPLOTLIB)
        marker = os.path.join(tmp, "drawing")
        env = dict(os.environ, PYTHONPATH=fake, LADDER_TEST_MARKER=marker)
        cmd = [sys.executable, LADDER, SCENE, "--levels", "1", "--analyse-only", "--out",
               os.path.join(tmp, "out")]
        proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                env=env)
        start = time.time()
        while not os.path.exists(marker) and proc.poll() is None and time.time() - start < 60:
            time.sleep(0.05)
        if os.path.exists(marker):
            proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=60)
        lines = err.strip().splitlines()
        if (not os.path.exists(marker) or proc.returncode != 130 or len(lines) != 1
                or not lines[0].startswith("ladder: interrupted")):
            failures.append(f"Ctrl-C while drawing: marker {os.path.exists(marker)}, exit "
                            f"{proc.returncode} (expected 130), stderr {err.strip()!r}")
    if mpm:
        expect([mpm, "study", "--ladder", "1", SCENE, "--out", "/proc/impact_ladder_test",
                "--threads", "1"], 3, "ladder: /proc/impact_ladder_test",
               "cannot be written (--out): ")
    for f in failures:
        print("FAIL", f)
    print(f"ladder_errors_test: {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
