#!/usr/bin/env python3
"""What the machine's second core gives: one `mpm` run on 1 thread alone, two such runs at once,
and one run on 2 threads, alternating (docs/performance.md, "What a second core gives here").

Two 1-thread runs at once share nothing but the machine: the cache levels the cores share, the
memory bus and, on a VM, whatever the host places beside them (a sibling hyper-thread, a busy
neighbour). Their summed rate over the solo rate is the most a second thread can give this
workload on this machine; the 2-thread run's rate over the solo rate is what it does give. The
gap between the two is the solver's (serial parts, fork-join, imbalance); the gap from 2 to the
ceiling is the machine's.

  core_pairs.py MPM OUT_DIR [--scene S] [--max-time 1e-5] [--repeats 3]

Prints one row per repeat (M particle-steps/s: solo, each of the pair, 2 threads), each phase's
seconds on 1 and 2 threads, and the medians with the two ratios. A benchmark, not a test: its figures depend on the VM.
"""
import argparse
import json
import os
import statistics
import sys

# impact.results (pure Python; python/ of the source tree) runs mpm.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from impact import results  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def summary(out):
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def rate(out):
    return summary(out)["particle_steps_per_second"] / 1e6


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("mpm")
    ap.add_argument("out")
    ap.add_argument("--scene", default=os.path.join(ROOT, "data/scenes/sphere_cylinder/recommended.json"))
    ap.add_argument("--max-time", type=float, default=1e-5, help="end time [s]")
    ap.add_argument("--repeats", type=int, default=3)
    a = ap.parse_args()
    if not (os.path.isfile(a.mpm) and os.access(a.mpm, os.X_OK)):
        sys.exit(f"core_pairs.py: MPM: {a.mpm} is not an executable file (an mpm binary)")
    if not os.path.isfile(a.scene):
        sys.exit(f"core_pairs.py: --scene: {a.scene} is not a file")
    if a.repeats < 1 or not a.max_time > 0.0:
        sys.exit("core_pairs.py: --repeats: expected an integer >= 1; --max-time: expected a time > 0 [s]")
    os.makedirs(a.out, exist_ok=True)
    scene = os.path.join(a.out, "scene.json")
    with open(scene, "w") as f:
        json.dump({"extends": os.path.abspath(a.scene), "time": {"max_time": a.max_time},
                   "output": {"interval": 1.0, "fields": ["velocity"]}}, f)
    launcher = results.Launcher(os.path.abspath(a.mpm))

    def run(out, threads):
        done = launcher.run("run", scene, out=out, threads=threads, check=False)
        if done.returncode != 0:
            sys.exit(f"core_pairs.py: {a.mpm} exited {done.returncode}\n{done.stderr}")
        return rate(out)

    rows = []
    print("repeat solo pair_a pair_b two_threads  [M particle-steps/s]")
    for r in range(a.repeats):
        solo = run(os.path.join(a.out, f"solo_r{r}"), 1)
        outs = [os.path.join(a.out, f"pair{k}_r{r}") for k in "ab"]
        pair = [launcher.start("run", scene, out=o, threads=1, stdout=open(os.devnull, "w"),
                               stderr=open(os.devnull, "w")) for o in outs]
        if any(p.wait() != 0 for p in pair):
            sys.exit(f"core_pairs.py: a run of the pair failed (see {outs})")
        pa, pb = (rate(o) for o in outs)
        two = run(os.path.join(a.out, f"two_r{r}"), 2)
        rows.append((solo, pa, pb, two))
        print(f"{r} {solo:.3f} {pa:.3f} {pb:.3f} {two:.3f}", flush=True)
    solo = statistics.median(x[0] for x in rows)
    pair = statistics.median(x[1] + x[2] for x in rows)
    two = statistics.median(x[3] for x in rows)
    # Where the second thread is lost: each phase's seconds on 1 and on 2 threads (medians).
    phases = {}
    for r in range(a.repeats):
        for name, threads in (("solo", 1), ("two", 2)):
            for k, v in summary(os.path.join(a.out, f"{name}_r{r}")).get("phase_seconds [s]", {}).items():
                phases.setdefault(k, {}).setdefault(threads, []).append(v)
    print("\nphase seconds_1_thread seconds_2_threads speed-up  [medians]")
    for k, v in phases.items():
        one, two_s = statistics.median(v[1]), statistics.median(v[2])
        print(f"{k} {one:.3f} {two_s:.3f} {one / two_s if two_s > 0 else float('nan'):.2f}")
    print(f"\nmedian: solo {solo:.3f}, pair's sum {pair:.3f} ({pair / solo:.2f}x solo: the machine's "
          f"ceiling), 2 threads {two:.3f} ({two / solo:.2f}x solo, {two / pair:.2f} of the ceiling)")


if __name__ == "__main__":
    main()
