#!/usr/bin/env python3
"""Two `mpm` binaries on one scene, alternating, so the VM's drift hits both alike
(docs/performance.md, "Speed per core, second round").

Each binary runs SCENE cut to --max-time [s] without snapshots (the scene is written beside the
runs, extending SCENE by absolute path), on each thread count in turn, --repeats times. Prints
one row per run from its summary.json (particle-steps per second, steps, the stress update's
and the transfers' seconds where the binary reports them), then the median and best of each
binary per thread count, and NEW's speed-up against OLD (median over median, best over best).

  side_by_side.py OLD_MPM NEW_MPM OUT_DIR [--scene S] [--max-time 1e-5] [--threads 1 2]
                  [--repeats 3]

OLD_MPM may be any earlier build: only `mpm run SCENE --out DIR --threads N` is used.
"""
import argparse
import json
import os
import statistics
import sys
import time

# impact.results (pure Python; python/ of the source tree) runs mpm.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from impact import results  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def run(mpm, scene, out, threads):
    start = time.perf_counter()
    done = results.Launcher(mpm).run("run", scene, out=out, threads=threads, check=False)
    wall = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit(f"side_by_side.py: {mpm} on {scene} exited {done.returncode}\n{done.stderr}")
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    return wall, summary


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("out")
    ap.add_argument("--scene", default=os.path.join(ROOT, "data/scenes/sphere_cylinder/recommended.json"))
    ap.add_argument("--max-time", type=float, default=1e-5, help="end time [s]")
    ap.add_argument("--threads", type=int, nargs="+", default=[1, 2])
    ap.add_argument("--repeats", type=int, default=3)
    a = ap.parse_args()
    for what, path in (("OLD_MPM", a.old), ("NEW_MPM", a.new)):
        if not (os.path.isfile(path) and os.access(path, os.X_OK)):
            sys.exit(f"side_by_side.py: {what}: {path} is not an executable file (an mpm binary)")
    if not os.path.isfile(a.scene):
        sys.exit(f"side_by_side.py: --scene: {a.scene} is not a file")
    if a.repeats < 1 or min(a.threads) < 1 or not a.max_time > 0.0:
        sys.exit("side_by_side.py: --repeats and --threads: expected integers >= 1; "
                 "--max-time: expected a time > 0 [s]")
    os.makedirs(a.out, exist_ok=True)
    scene = os.path.join(a.out, "scene.json")
    with open(scene, "w") as f:
        json.dump({"extends": os.path.abspath(a.scene), "time": {"max_time": a.max_time},
                   "output": {"interval": 1.0, "fields": ["velocity"]}}, f)
    rate = {}
    print("binary threads repeat wall[s] steps particle_steps_per_s stress[s] transfers[s]")
    for repeat in range(a.repeats):
        for threads in a.threads:
            for name, mpm in (("old", a.old), ("new", a.new)):
                out = os.path.join(a.out, f"{name}_t{threads}_r{repeat}")
                wall, s = run(os.path.abspath(mpm), scene, out, threads)
                phases = s.get("phase_seconds [s]", {})
                transfers = sum(phases.get(k, 0.0) for k in ("particles_to_grid", "remap", "grid_to_particles"))
                rate.setdefault((name, threads), []).append(s["particle_steps_per_second"])
                print(f"{name} {threads} {repeat} {wall:.2f} {s['steps']} "
                      f"{s['particle_steps_per_second'] / 1e6:.3f}M {phases.get('stress', float('nan')):.2f} "
                      f"{transfers:.2f}", flush=True)
    print("\nthreads old_median old_best new_median new_best speedup_median speedup_best  [M particle-steps/s]")
    for threads in a.threads:
        o, n = rate[("old", threads)], rate[("new", threads)]
        print(f"{threads} {statistics.median(o) / 1e6:.3f} {max(o) / 1e6:.3f} {statistics.median(n) / 1e6:.3f} "
              f"{max(n) / 1e6:.3f} {statistics.median(n) / statistics.median(o):.3f} {max(n) / max(o):.3f}")


if __name__ == "__main__":
    main()
