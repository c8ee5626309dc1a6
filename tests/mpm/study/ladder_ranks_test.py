#!/usr/bin/env python3
"""`ladder.py --ranks 2` runs every level under mpirun (docs/accuracy.md#grid-convergence-ladders):
the Taylor verification rod (failure off) at levels 1 and 2 on 2 ranks gives each level's run on 2
ranks (summary.json "ranks") and the same Lf and Dm, read from the .pvtu snapshots' pieces, as
the ladder on one rank, to 1e-12 relative (the particles' state agrees to round-off across ranks,
tests/mpm/parallel/mpirun_summary_test.py).

  ladder_ranks_test.py MPM MPIEXEC"""

import csv
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
SCENE = os.path.join(ROOT, "data", "scenes", "verification", "taylor_rod.json")
LADDER = os.path.join(ROOT, "campaigns", "study", "ladder.py")


def values(out):
    with open(os.path.join(out, "ladder.csv"), newline="") as f:
        return {(r["run"], r["observable"]): float(r["value"]) for r in csv.DictReader(f)}


def main():
    mpm, mpiexec = sys.argv[1], sys.argv[2]
    env = dict(os.environ, OMP_NUM_THREADS="1", OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    common = ["--levels", "1,2", "--threads", "1", "--mpm", mpm, "--no-plot", "--set",
              json.dumps({"physics": {"erosion": "none"}})]
    with tempfile.TemporaryDirectory() as tmp:
        one, two = os.path.join(tmp, "one"), os.path.join(tmp, "two")
        subprocess.run([sys.executable, LADDER, SCENE, "--out", one] + common, check=True, env=env)
        subprocess.run([sys.executable, LADDER, SCENE, "--out", two, "--ranks", "2", "--mpirun",
                        f"{mpiexec} --oversubscribe"] + common, check=True, env=env)
        failures = []
        for level in ("x1", "x2"):
            with open(os.path.join(two, "runs", level, "summary.json")) as f:
                if json.load(f).get("ranks") != 2:
                    failures.append(f"{level} did not run on 2 ranks")
        a, b = values(one), values(two)
        for key in sorted(a):
            if key not in b or abs(a[key] - b[key]) > 1e-12 * abs(a[key]):
                failures.append(f"{key}: 1 rank {a[key]}, 2 ranks {b.get(key)}")
        if len(a) != 4:
            failures.append(f"expected Lf and Dm at 2 levels, got {sorted(a)}")
    if failures:
        print("\n".join(failures))
        return 1
    print(f"ladder_ranks_test: Lf and Dm on 2 ranks as on 1: {a}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
