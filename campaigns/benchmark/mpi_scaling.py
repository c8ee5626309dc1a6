#!/usr/bin/env python3
"""Ranks against threads on one machine: the recommended sphere-cylinder on the 2.25x grid
(112 x 45 x 45 cells, 344 906 particles) to 5 us without snapshots, run as 1 rank of 1 thread,
RANKS ranks of 1 thread (mpirun) and 1 rank of RANKS threads, REPEATS times in turn (the VM is
noisy: compare within a repeat). `--splits 1x2x1 ...` adds a RANKS-rank run per box split
(solver.ranks_per_axis; the plain RANKS-rank run takes the automatic split). Prints one row per run
from each summary.json: wall time of the step loop, particle-steps per second, speed-up against
the 1-rank run of the same repeat, each rank's time in MPI calls and in the stress update
(docs/mpi.md, "Speed").

  mpi_scaling.py MPM OUT_DIR [--ranks 2] [--repeats 2] [--mpirun mpirun] [--splits AxBxC ...]
"""
import argparse
import json
import os
import sys

# impact.results (pure Python; python/ of the source tree) runs mpm.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from impact import results  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def run(launcher, scene, ranks, out, threads, env):
    cmd = launcher.command("run", scene, out=out, threads=threads, ranks=ranks)
    done = launcher.run("run", scene, out=out, threads=threads, ranks=ranks, env=env, check=False)
    if done.returncode != 0:
        sys.exit(f"mpi_scaling.py: {' '.join(cmd)} exited {done.returncode}\n{done.stderr}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("mpm")
    ap.add_argument("out")
    ap.add_argument("--ranks", type=int, default=2)
    ap.add_argument("--repeats", type=int, default=2)
    ap.add_argument("--mpirun", default="mpirun")
    ap.add_argument("--splits", nargs="*", default=[])
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    scene = os.path.join(a.out, "scene_2.25x.json")
    with open(scene, "w") as f:
        json.dump({"extends": os.path.join(ROOT, "data/scenes/sphere_cylinder/recommended.json"),
                   "grid": {"cells": [112, 45, 45]}, "time": {"max_time": 5.0e-6},
                   "output": {"snapshots": False}}, f)
    env = results.mpi_environment()
    launcher = results.Launcher(a.mpm, [a.mpirun], mpirun_options=["--oversubscribe"])
    runs = [("1 rank, 1 thread", scene, 1, 1),
            (f"{a.ranks} ranks, 1 thread", scene, a.ranks, 1)]
    for split in a.splits:
        p = [int(x) for x in split.split("x")]
        split_scene = os.path.join(a.out, f"scene_2.25x_{split}.json")
        with open(split_scene, "w") as f:
            json.dump({"extends": scene, "solver": {"ranks_per_axis": p}}, f)
        runs.append((f"{a.ranks} ranks, {split}", split_scene, a.ranks, 1))
    runs.append((f"1 rank, {a.ranks} threads", scene, 1, a.ranks))
    print("repeat  run                  wall [s]  M p-steps/s  speed-up  seconds in MPI per rank"
          "  stress seconds per rank")
    for rep in range(a.repeats):
        base = None
        for label, run_scene, ranks, threads in runs:
            out = os.path.join(a.out, f"run_{rep}_{label.replace(' ', '_').replace(',', '')}")
            run(launcher, run_scene, ranks, out, threads, dict(env, OMP_NUM_THREADS=str(threads)))
            s = json.load(open(os.path.join(out, "summary.json")))
            wall = s["wall_time [s]"]
            base = base or wall
            mpi = s.get("ranks_load", {}).get("seconds_in_mpi [s]", [])
            stress = s["phase_seconds [s]"]["stress"]
            stress = stress if isinstance(stress, list) else [stress]
            print(f"{rep:6d}  {label:20s} {wall:8.1f}  {s['particle_steps_per_second'] / 1e6:11.3f}"
                  f"  {base / wall:8.2f}  {' '.join(f'{x:.1f}' for x in mpi):>23s}"
                  f"  {' '.join(f'{x:.1f}' for x in stress)}", flush=True)


if __name__ == "__main__":
    main()
