#!/usr/bin/env python3
"""What campaigns/study/ladder.py lets a reader quote, on synthetic levels (no mpm run): the
analysis and the written ladder table, ladder.md and figures of four levels h = 4, 3, 2, 1 mm
(ratios 4/3, 3/2, 2) of three observables with closed forms (docs/accuracy.md#grid-convergence-
ladders):

- "depth" [m] = 0.008 - 0.001 (h / 1 mm): a power law of order 1. Both triples give p = 1 and the
  limit 8 mm: quotable, range "7.0-8.0 mm for p = 1" (from the finest value 7 mm to the limit;
  formal and observed orders coincide), the
  extrapolated value 8 mm, GCI_fine = 1.25 (7 - 6)/7 / (2 - 1) = 18 % (the conservative GCI is
  Celik's at the formal order) and x1's error (x1 the coarsest level, 4 mm): -50 %.
- "speed" [m/s] = 5 + 2 (h / 1 mm)^3, with the coarsest value moved so that the coarser triple
  converges with another order: the finest triple's p = 3 lies outside [0.5, 2]: not quotable;
  range from phi1 to Richardson's for p in [1, 2], in closed form phi1 + (phi1 - phi2)/(r^q - 1)
  with r = 2, phi1 = 7, phi2 = 21: 2.333... and -7, so [-7, 7], i.e. "-7 to 7 m/s for p in
  [1, 2]" (the ends to the decimals that give the span two significant digits); every level is
  positive but the range spans 0: the verdict adds "the converged value's sign is not
  determined".
- "pressure" [Pa]: 3e9, 2e9, 4e9, 1e9 from the finest: oscillatory, not quotable, the band of
  the finest three, "2.0-4.0 GPa over the finest 3 levels".
No signed percentage may stand in a row that is not quotable; every table of ladder.md renders;
the ladder table carries "quotable", "verdict" and "range" {low, high, unit, order_low,
order_high, levels, sign_determined, basis}; the figures are drawn, and the cost chart only for a quotable
observable.

  ladder_analysis_test.py"""

import json
import os
import re
import sys
import tempfile
import types

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "campaigns", "study"))
sys.path.insert(0, HERE)
import ladder  # noqa: E402
import markdown_tables_test  # noqa: E402

H = [4e-3, 3e-3, 2e-3, 1e-3]  # coarsest first [m]
OBSERVABLES = [("depth", "/observables/depth [m]", "m"), ("speed", "/speed [m~1s]", "m/s"),
               ("pressure", "/pressure [Pa]", "Pa")]


def values(h):
    x = h / 1e-3
    return {"depth": 0.008 - 0.001 * x, "speed": 5.0 + 2.0 * x ** 3,
            "pressure": {4: 1e9, 3: 4e9, 2: 2e9, 1: 3e9}[round(x)]}


def runs():
    out = []
    for i, h in enumerate(H):
        v = values(h)
        if i == 0:
            v["speed"] = 5.0 + 2.0 * 27.0 + 200.0  # the coarser triple: another order
        out.append({"name": f"x{i + 1}", "level": float(i + 1), "ppc": None, "cells": [i + 1] * 3,
                    "h": h, "scene_path": "",
                    "data": {"values": v, "particles": 100 * (i + 1), "steps": 10 * (i + 1),
                             "wall": 1.0 + i, "threads": 1, "ranks": 1, "fingerprint": "f",
                             "energy_error": -1e-3}})
    return out


def main():
    failures = []

    def check(ok, what):
        if not ok:
            failures.append(what)

    result = ladder.analyse(runs(), OBSERVABLES)
    depth, speed, pressure = result["depth"], result["speed"], result["pressure"]
    check(depth["quotable"] is True and depth["verdict"] == "in the asymptotic range"
          and abs(depth["extrapolated"] - 0.008) < 1e-15
          and abs(depth["range"]["low"] - 0.007) < 1e-15
          and abs(depth["range"]["high"] - 0.008) < 1e-15 and depth["range"]["sign_determined"]
          and abs(depth["range"]["order_low"] - 1.0) < 1e-9
          and abs(depth["range"]["order_high"] - 1.0) < 1e-9,
          f"depth: {depth['quotable']}, {depth['verdict']}, {depth['range']}")
    r = speed["range"]
    check(speed["quotable"] is False and speed["verdict"].startswith("order 3 outside the "
                                                                    "plausible [0.5, 2]")
          and r["order_low"] == 1.0 and r["order_high"] == 2.0
          and abs(r["low"] - (7.0 + (7.0 - 21.0) / (2.0 - 1.0))) < 1e-12
          and abs(r["high"] - 7.0) < 1e-12 and r["sign_determined"] is False
          and speed["verdict"].endswith("; the converged value's sign is not determined")
          and r["unit"] == "m/s" and r["levels"] == 3,
          f"speed: {speed['quotable']}, {speed['verdict']}, {r}")
    r = pressure["range"]
    check(pressure["quotable"] is False
          and pressure["verdict"].startswith("oscillatory convergence")
          and (r["low"], r["high"], r["order_low"], r["unit"]) == (2e9, 4e9, None, "Pa"),
          f"pressure: {pressure['verdict']}, {r}")

    with tempfile.TemporaryDirectory() as out:
        args = types.SimpleNamespace(out=out, command_line="ladder_analysis_test",
                                     table=os.path.join(out, "table.json"))
        ladder.write_outputs(args, os.path.join(out, "scene.json"), runs(), OBSERVABLES, result,
                             True, {})
        with open(os.path.join(out, "ladder.md")) as f:
            md = f.read()
        rows = {line.split(" | ")[0][2:]: line for line in md.splitlines()
                if line.startswith("| depth") or line.startswith("| speed")
                or line.startswith("| pressure")}
        want = {
            "depth [mm]": "| depth [mm] | 7 | 6 | 5 | 4 | in the asymptotic range | 7.0-8.0 mm for p = 1 "
                          "| 8 | 1 | 18 | 18 | -50 |",
            "speed [m/s]": "| speed [m/s] | 7 | 21 | 59 | 259 | order 3 outside the plausible "
                           "[0.5, 2]; not in the asymptotic range; the converged value's sign is "
                           "not determined | -7 to 7 m/s for p in [1, 2] "
                           "| - | 3 | - | - | - |",
            "pressure [GPa]": "| pressure [GPa] | 3 | 2 | 4 | 1 | oscillatory convergence; "
                              "not in the asymptotic range | 2.0-4.0 GPa over the finest 3 levels | - "
                              "| - | - | - | - |",
        }
        for name, line in want.items():
            check(rows.get(name) == line, f"ladder.md row {name}:\n  got  {rows.get(name)}\n"
                  f"  want {line}")
        for name in ("speed [m/s]", "pressure [GPa]"):
            check(not re.search(r"[+-]\d[\d.]*\s*%?\s*\|\s*$", rows.get(name, "")),
                  f"a signed error in the row of {name}, which is not quotable")
        bad = markdown_tables_test.problems(os.path.join(out, "ladder.md"))
        check(not bad, f"ladder.md tables that do not render: {bad}")
        with open(args.table) as f:
            table = json.load(f)
        keys = {o["name"]: o for o in table["observables"]}
        check(all({"quotable", "verdict", "range"} <= set(o) for o in keys.values())
              and set(keys["speed"]["range"]) == {"low", "high", "unit", "order_low",
                                                  "order_high", "levels", "sign_determined",
                                                  "basis"},
              f"ladder table keys: {sorted(keys['speed'])}, range {keys['speed'].get('range')}")
        try:
            import matplotlib  # noqa: F401
            figures = sorted(f for f in os.listdir(out) if f.endswith(".png"))
            check(figures == ["ladder_cost.png", "ladder_depth.png", "ladder_pressure.png",
                              "ladder_speed.png"], f"figures {figures}")
            # Without a quotable observable there is no cost chart, and a stale one goes.
            for res in result.values():
                res["quotable"] = False
            ladder.write_outputs(args, os.path.join(out, "scene.json"), runs(), OBSERVABLES,
                                 result, True, {})
            check(not os.path.exists(os.path.join(out, "ladder_cost.png")),
                  "a cost chart against extrapolations that may not be quoted")
        except ImportError:
            print("ladder_analysis_test: matplotlib missing: figures not checked")
    for f in failures:
        print("FAIL", f)
    print(f"ladder_analysis_test: {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
