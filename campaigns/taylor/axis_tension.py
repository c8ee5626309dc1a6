#!/usr/bin/env python3
"""Peak hydrostatic tension on the axis of a Taylor rod in the first microseconds, by resolution.

  python3 campaigns/taylor/axis_tension.py [--shot H8] [--cells-per-radius 3,4,6,8] [--mpm build/bin/mpm]

Runs the shot's quarter-model scene (campaigns/taylor/taylor.py, failure off) to 3 us with a snapshot
every 50 ns and prints, over the core particles (initial radius <= R0/2), the largest tensile and
compressive mean stress seen. The release waves from the free surface converge on the axis behind
the impact face and put it in tension (docs/taylor.md, "What fails in the rod"): this shows whether
that tension is a converged feature of the model or a discretisation artefact.
"""

import argparse
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import taylor  # noqa: E402  (its import puts python/ on the path: impact.results)
from impact import results  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--shot", default="H8")
    ap.add_argument("--cells-per-radius", default="3,4,6,8")
    ap.add_argument("--mpm", default=os.path.join(taylor.REPO, "build", "bin", "mpm"))
    a = ap.parse_args()
    shot = next(s for s in taylor.read_shots() if s["shot"] == a.shot)
    print("cells/radius,core max tension [Pa],core max compression [Pa]")
    with tempfile.TemporaryDirectory() as work:
        for n in [int(x) for x in a.cells_per_radius.split(",")]:
            sc = taylor.scene(shot, taylor.MATERIAL, "off", n)
            sc["time"]["max_time"] = 3e-6
            sc["output"]["interval"] = 5e-8
            sc["output"]["fields"] = ["stress"]
            scene_file = os.path.join(work, f"n{n}.json")
            with open(scene_file, "w") as f:
                json.dump(sc, f)
            run = os.path.join(work, f"n{n}")
            results.Launcher(a.mpm).run("run", scene_file, out=run, threads=2,
                                        stdout=subprocess.DEVNULL)
            snaps = [results.read_points(f) for _, f in results.snapshots(run)]
            X0 = snaps[0]["points"]
            core = (X0[:, 1] ** 2 + X0[:, 2] ** 2) ** 0.5 <= 0.25 * shot["D0"]
            mean = [d["stress"][core, :3].mean(axis=1) for d in snaps]
            print(f"{n},{max(m.max() for m in mean):.4g},{-min(m.min() for m in mean):.4g}",
                  flush=True)


if __name__ == "__main__":
    main()
