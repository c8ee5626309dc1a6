#!/usr/bin/env python3
"""Batch updates from NumPy: N points of 6061-T6 under random velocity gradients, one step at a
time, and the throughput (the figure docs/python.md quotes).

  PYTHONPATH=build/python python3 python/examples/batch_update.py [N] [STEPS]
"""
import sys
import time

import numpy as np

import impact


def main(n, steps):
    m = impact.Material(impact.data_path("materials", "al6061_t6.json"))
    rng = np.random.default_rng(1)
    L = rng.normal(scale=1e4, size=(n, 3, 3))  # [1/s]
    state = m.initial_state(n=n)
    start = time.perf_counter()
    for _ in range(steps):
        state, report = impact.update(m, state, L, 1e-7)
    seconds = time.perf_counter() - start
    print(f"{n} points x {steps} steps: {seconds:.3f} s, "
          f"{n * steps / seconds / 1e6:.2f} M point-updates/s (one thread, NumPy in and out); "
          f"plastic {report['plastic'].mean() * 100:.0f} %, "
          f"max eps_p {state['plastic_strain'].max():.4f}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 100000,
         int(sys.argv[2]) if len(sys.argv) > 2 else 20)
