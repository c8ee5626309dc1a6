#!/usr/bin/env python3
"""OpenMP threads against a busy core: the wall time of one run at 1 and all threads under each
OpenMP wait policy, on an idle machine and with one core held by another process.

  python3 campaigns/benchmark/thread_wait_policy.py build/bin/mpm [--scene SCENE] [--repeats N]

Policies: `passive` (mpm's default since issue 38: support/omp_wait_policy.hpp), `active` and
libgomp's own default (OMP_WAIT_POLICY set to an empty string, which mpm keeps and libgomp reads as
unset: it spins a while at each barrier, then sleeps). The load is one busy-looping process. Prints
a Markdown table of the median wall time per configuration (docs/performance.md#threads). A
benchmark, not a test: the figures depend on the machine and on what else runs on it.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

# impact.results (pure Python; python/ of the source tree) runs mpm.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from impact import results  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_SCENE = os.path.join(HERE, "..", "..", "data", "scenes", "verification", "taylor_rod.json")


def run_once(mpm, scene, threads, policy, out):
    env = dict(os.environ)
    env.pop("OMP_WAIT_POLICY", None)
    env["OMP_WAIT_POLICY"] = {"libgomp default": "", "active": "active", "passive": "passive"}[policy]
    start = time.perf_counter()
    results.Launcher(mpm).run("run", scene, out=out, threads=threads, extra=["-q"], env=env,
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - start


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("mpm")
    ap.add_argument("--scene", default=DEFAULT_SCENE)
    ap.add_argument("--repeats", type=int, default=3)
    a = ap.parse_args()
    cores = os.cpu_count() or 1
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for loaded in (False, True):
            busy = None
            if loaded:  # one core held by another process for the whole set
                busy = subprocess.Popen([sys.executable, "-c", "while True: pass"])
                time.sleep(0.5)
            try:
                for policy in ("libgomp default", "active", "passive"):
                    for threads in sorted({1, cores}):
                        times = [run_once(a.mpm, a.scene, threads, policy, os.path.join(tmp, "r"))
                                 for _ in range(a.repeats)]
                        rows.append((loaded, policy, threads, statistics.median(times), times))
                        print(json.dumps({"loaded": loaded, "policy": policy, "threads": threads,
                                          "seconds": times}), file=sys.stderr, flush=True)
            finally:
                if busy:
                    busy.kill()
                    busy.wait()
    print(f"| machine | policy | threads | median wall [s] | runs [s] |")
    print("|---|---|---|---|---|")
    for loaded, policy, threads, median, times in rows:
        print(f"| {'one core busy' if loaded else 'idle'} | {policy} | {threads} | {median:.2f} | "
              + ", ".join(f"{t:.2f}" for t in times) + " |")


if __name__ == "__main__":
    main()
