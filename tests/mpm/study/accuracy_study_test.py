#!/usr/bin/env python3
"""Richardson extrapolation of campaigns/study/accuracy_study.py against a closed form.

A sequence f(h) = f_inf + C h^p (h = 1 / level) has, on the equal-ratio levels 1, 1.5, 2.25,
the observed order p and the limit f_inf exactly; a finer run (level 3) on the same curve must
confirm the extrapolation, one on the other side of f_inf or far off must not. Exit 0 when every
check holds (CTest: mpm_accuracy_study_richardson)."""

import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..",
                                "campaigns", "study"))
import accuracy_study as study  # noqa: E402

failures = []


def check(what, ok):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def run(level, value, name="x"):
    return {"level": level, "obs": {name: value}}


F_INF, C = 6.93e-3, -2.7e-3
for p in (1.0, 2.0):
    f = {lv: F_INF + C * (1.0 / lv) ** p for lv in (1.0, 1.5, 2.25, 3.0)}
    rich = study.richardson([f[1.0], f[1.5], f[2.25]], [1.0, 1.5, 2.25])
    check(f"order {p:g} recovered to 1e-9", rich is not None and abs(rich[0] - p) < 1e-9)
    check(f"limit recovered to 1e-12 relative (order {p:g})",
          rich is not None and abs(rich[1] - F_INF) < 1e-12 * abs(F_INF))
    last = run(2.25, f[2.25])
    check(f"a finer run on the curve confirms it (order {p:g})",
          study.confirmed_by_finer(rich, last, [run(3.0, f[3.0])], "x"))
    across = F_INF + (F_INF - f[3.0])  # mirrored through the limit: the other side
    check(f"a finer run on the other side of the limit rejects it (order {p:g})",
          not study.confirmed_by_finer(rich, last, [run(3.0, across)], "x"))
    far = F_INF + 3.0 * (f[3.0] - F_INF)  # same side, three times the predicted error
    check(f"a finer run three times the predicted error away rejects it (order {p:g})",
          not study.confirmed_by_finer(rich, last, [run(3.0, far)], "x"))

# Not contracting (equal differences, as the crater depth's 1.09 and 1.08 mm) or alternating:
# no extrapolation.
check("equal differences: none", study.richardson([1.0, 2.0, 3.0], [1.0, 1.5, 2.25]) is None)
check("alternating differences: none",
      study.richardson([1.0, 2.0, 1.5], [1.0, 1.5, 2.25]) is None)
check("unequal ratios: none", study.richardson([1.0, 1.5, 1.75], [1.0, 1.5, 3.0]) is None)

sys.exit(1 if failures else 0)
