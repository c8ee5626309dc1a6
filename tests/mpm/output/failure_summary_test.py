#!/usr/bin/env python3
"""summary.json's failed_by_cause and the VTU failure fields count the same particles.

  failure_summary_test.py MPM WORK_DIR

`mpm run` on the verification Taylor rod (House H8, 3 cells per radius, the material's failure
stack as shipped but with stability_check.outcome = report) for 3 us, with a snapshot at the end.
From the last snapshot (read with impact.results.vtu) the failed particles are counted per
failure_cause code (1 melting, 2 tepla, 3 drucker, 4 becker), failed with a tensile mean stress
(failed_in_tension), and flagged by a stability check without failing (instability bits: 1
Drucker, 2 Becker). Every count must equal summary.json's failed_by_cause entry, the causes must
add up to failed_particles, and the run must exercise them: TEPLA failures, tensile failures and
reported Drucker points all non-zero (measured: TEPLA 177, in tension 175, Drucker reported 61),
and no point failed by Drucker (the outcome is report).
"""
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "python"))  # impact.results, without the compiled module
from impact.results import vtu  # noqa: E402

CAUSES = {1: "melting", 2: "tepla", 3: "drucker", 4: "becker"}


def main(mpm, work):
    os.makedirs(work, exist_ok=True)
    scene = {
        "extends": os.path.join(ROOT, "data", "scenes", "verification", "taylor_rod.json"),
        "materials": {"al": {"overrides": {"constitutive_model": {
            "stability_check": {"outcome": "report"}}}}},
        "time": {"max_time": 3e-6},
        "output": {"interval": 3e-6, "snapshots": True,
                   "fields": ["failed", "failure_cause", "failed_in_tension", "instability"]},
    }
    path = os.path.join(work, "scene.json")
    with open(path, "w") as f:
        json.dump(scene, f)
    out = os.path.join(work, "run")
    subprocess.run([mpm, "run", path, "--out", out], check=True, capture_output=True)
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    last = vtu.read_points(vtu.snapshots(out)[-1][1])
    failed = last["failed"] > 0.5
    counted = {name: int((failed & (last["failure_cause"] == code)).sum())
               for code, name in CAUSES.items()}
    counted["in_tension"] = int((failed & (last["failed_in_tension"] > 0.5)).sum())
    bits = last["instability"].astype(int)
    counted["drucker_reported"] = int(((bits & 1) != 0).sum())
    counted["becker_reported"] = int(((bits & 2) != 0).sum())
    by_cause = summary["failed_by_cause"]
    print(f"summary {by_cause}, failed_particles {summary['failed_particles']}")
    print(f"counted {counted}, failed {int(failed.sum())}")
    problems = [f"{k}: summary {by_cause.get(k)} against {v} in the snapshot"
                for k, v in counted.items() if by_cause.get(k) != v]
    if sum(counted[c] for c in CAUSES.values()) != summary["failed_particles"]:
        problems.append("the causes do not add up to failed_particles")
    if int(failed.sum()) != summary["failed_particles"]:
        problems.append("the snapshot's failed count differs from failed_particles")
    for key in ("tepla", "in_tension", "drucker_reported"):
        if counted[key] == 0:
            problems.append(f"{key}: none, the run does not exercise it")
    if counted["drucker"] != 0:
        problems.append("Drucker failed points although its outcome is report")
    for p in problems:
        print("FAIL:", p)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
