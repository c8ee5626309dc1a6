#!/usr/bin/env python3
"""campaigns/study/ladder.py --analyse-only --refingerprint (issue 53): a level whose run recorded a
fingerprint the scene no longer has (its scene lost a key that changed no number) is labelled in
the ladder table with the fingerprint the scene has today (`mpm check --fingerprint`), and stderr
names the level and both fingerprints; without the option the table keeps the run's own. A stand-in
run (summary.json "completed" with fingerprint deadbeefdeadbeef) of data/scenes/verification/
elastic_bar.json at level 1 stands for the real one: nothing is run.

  ladder_refingerprint_test.py MPM"""

import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
LADDER = os.path.join(ROOT, "campaigns", "study", "ladder.py")
SCENE = os.path.join(ROOT, "data", "scenes", "verification", "elastic_bar.json")
RECORDED = "deadbeefdeadbeef"


def main():
    mpm = sys.argv[1]
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        out, runs, table = (os.path.join(tmp, n) for n in ("out", "runs", "table.json"))
        base = [sys.executable, LADDER, SCENE, "--levels", "1", "--analyse-only", "--no-plot",
                "--out", out, "--runs", runs, "--table", table, "--mpm", mpm]
        done = subprocess.run(base, capture_output=True, text=True, timeout=120)
        scene_path = os.path.join(out, "scenes", "x1.json")
        if done.returncode != 0 or not os.path.exists(scene_path):
            print(f"FAIL the ladder without runs: exit {done.returncode}, {done.stderr.strip()!r}")
            return 1
        run_dir = os.path.join(runs, "x1")
        os.makedirs(run_dir)
        with open(scene_path) as f, open(os.path.join(run_dir, "ladder_scene.json"), "w") as g:
            g.write(f.read())
        with open(os.path.join(run_dir, "summary.json"), "w") as f:
            json.dump({"status": "completed", "scene_fingerprint": RECORDED, "particles": 1,
                       "steps": 1, "final": {"energy_error [-]": 0.0}}, f)
        today = subprocess.run([mpm, "check", scene_path, "--fingerprint"], capture_output=True,
                               text=True, timeout=120).stdout.strip()
        if len(today) != 16 or today == RECORDED:
            failures.append(f"mpm check --fingerprint: {today!r}")

        def table_fingerprint():
            with open(table) as f:
                return json.load(f)["levels"][0]["fingerprint"]

        for extra, expected in (([], RECORDED), (["--refingerprint"], today)):
            done = subprocess.run(base + extra, capture_output=True, text=True, timeout=120)
            said = f"x1: fingerprint {RECORDED} of the run, {today} of the scene today"
            if done.returncode != 0 or table_fingerprint() != expected:
                failures.append(f"{extra}: exit {done.returncode}, table fingerprint "
                                f"{table_fingerprint()!r} (expected {expected!r}), stderr "
                                f"{done.stderr.strip()!r}")
            if bool(extra) != (said in done.stderr):
                failures.append(f"{extra}: stderr {done.stderr.strip()!r} (expected "
                                f"{'' if extra else 'no '}line '{said}')")
        done = subprocess.run([sys.executable, LADDER, SCENE, "--levels", "1", "--refingerprint",
                               "--out", out, "--mpm", mpm], capture_output=True, text=True,
                              timeout=120)
        if done.returncode == 0 or "--refingerprint goes with --analyse-only" not in done.stderr:
            failures.append(f"--refingerprint without --analyse-only: exit {done.returncode}, "
                            f"{done.stderr.strip()!r}")
    for f in failures:
        print("FAIL", f)
    print(f"ladder_refingerprint_test: {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
