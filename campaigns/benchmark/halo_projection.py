#!/usr/bin/env python3
"""The halo term of docs/mpi.md's projection ("Cost model"), from the boxes `mpm check --ranks N`
plans: per step, the node sums of particles-to-grid (64 B per node and field) and of the MUSL
re-map (24 B), one axis after another. A message to a neighbour along axis d carries 3 node layers
of the rank's stored box across the other two axes (its cells and 3 halo layers each side,
clipped to [-1, cells + 1]); it costs ALPHA + bytes / BETA.

- posted at once (since c3d4345): along an axis each rank sends to both neighbours and waits once,
  the two messages sharing its link: ALPHA + (b_lower + b_upper) / BETA, the busiest rank per axis;
- the chain before it: each rank exchanged with its lower neighbour (a size, then the data, each a
  blocking MPI_Sendrecv), then with its upper one, so the boundaries of a line of p_d boxes were
  crossed one after another: sum over the line of (2 ALPHA + b / BETA), the slowest line per axis
  (when every rank arrives at once; a rank arriving late overlaps part of it).

Prints, per exchange pattern, the halo milliseconds per step and the busiest rank's particles.

  halo_projection.py MPM SCENE RANKS [--set JSON] [--alpha 2e-6] [--beta 1e10] [--fields 1]
"""
import argparse
import itertools
import json
import os
import sys

# impact.results (pure Python; python/ of the source tree) runs mpm.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from impact import results  # noqa: E402

NODE_BYTES = (64, 24)  # P2G node data, MUSL re-map momentum [B per node and field]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("mpm")
    ap.add_argument("scene")
    ap.add_argument("ranks", type=int)
    ap.add_argument("--set", default=None)
    ap.add_argument("--alpha", type=float, default=2e-6, help="latency per message [s]")
    ap.add_argument("--beta", type=float, default=1e10, help="bandwidth per rank [B/s]")
    ap.add_argument("--fields", type=int, default=1)
    a = ap.parse_args()
    text = results.Launcher(a.mpm).run("check", a.scene, options=["--ranks", str(a.ranks)],
                                       sets=[a.set] if a.set else []).stdout
    checked = json.loads(text)  # mpm check: {"resolved", "warnings", "refusal", "report"}
    plan = checked["report"]["decomposition"]
    resolved = checked["resolved"]
    cells = resolved["grid"]["cells"]
    first = [plan["boxes"][k] for k in "xyz"]
    p = [len(f) - 1 for f in first]
    stored = [[min(f[i + 1] + 3, cells[d] + 1) - max(f[i] - 3, -1) + 1 for i in range(p[d])]
              for d, f in enumerate(first)]

    def layer(d, c, node_bytes):  # bytes of one message along axis d from the box at c
        e, f = (d + 1) % 3, (d + 2) % 3
        return 3 * stored[e][c[e]] * stored[f][c[f]] * a.fields * node_bytes

    at_once = chain = 0.0
    boxes = list(itertools.product(*(range(n) for n in p)))
    for node_bytes in NODE_BYTES:
        for d in range(3):
            if p[d] == 1:
                continue
            at_once += max(a.alpha + sum(layer(d, c, node_bytes) for n in (-1, 1)
                                         if 0 <= c[d] + n < p[d]) / a.beta for c in boxes)
            chain += max(sum(2 * a.alpha + layer(d, c, node_bytes) / a.beta
                             for c in boxes if c[d] > 0 and all(
                                 c[k] == line[k] for k in range(3) if k != d))
                         for line in boxes if line[d] == 0)
    print(f"{a.ranks} ranks, {p[0]} x {p[1]} x {p[2]}: busiest box "
          f"{plan['particles_per_rank']['max']:.0f} particles (mean "
          f"{plan['particles_per_rank']['mean']:.0f}); halo per step: posted at once "
          f"{at_once * 1e3:.3f} ms, as a chain {chain * 1e3:.3f} ms "
          f"(alpha {a.alpha:g} s, beta {a.beta:g} B/s)")


if __name__ == "__main__":
    main()
