#!/usr/bin/env python3
"""An axisymmetric Taylor campaign against 3D quarter-model campaigns at the same resolutions.

  python3 campaigns/taylor/taylor_compare.py AXI_OUT REF_OUT [REF_OUT ...] [--out NAME]

Pairs each run of AXI_OUT/results.csv (campaigns/taylor/taylor.py --geometry axisymmetric) with
the run of the same set, failure mode, cells per radius and shot in the REF_OUT campaigns (the
quarter model on the mirror anvil; the first REF_OUT that has it), and writes AXI_OUT/NAME.csv
and AXI_OUT/NAME.md (NAME: compare_3d): Lf, Dm and their difference, the energy error of both,
the run time of both (`wall_time [s]` of mpm's summary) and its ratio, and per set and
resolution the mean and worst differences. Nothing is run.
"""

import argparse
import csv
import os
from collections import defaultdict


def rows_of(out):
    with open(os.path.join(out, "results.csv"), newline="") as f:
        return [r for r in csv.DictReader(f) if r["exit_code"] == "0"]


def mirror(r):
    """A quarter-model run on the mirror anvil (older campaigns have no geometry or anvil column)."""
    return (r.get("geometry") or "3d") == "3d" and (r.get("anvil") or "mirror") == "mirror" \
        and not r.get("anvil_friction")


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("axi")
    ap.add_argument("refs", nargs="+")
    ap.add_argument("--out", default="compare_3d")
    a = ap.parse_args()
    key = ("set", "failure", "cells_per_radius", "shot")
    ref = {}
    for out in a.refs:
        for r in rows_of(out):
            if mirror(r):
                ref.setdefault(tuple(r[k] for k in key), (r, out))
    table = []
    for r in rows_of(a.axi):
        if r.get("geometry") != "axisymmetric" or (r.get("anvil") or "mirror") != "mirror":
            continue
        hit = ref.get(tuple(r[k] for k in key))
        if hit is None:
            continue
        q, source = hit
        e = {k: r[k] for k in key}
        for m in ("Lf", "Dm"):
            e[f"{m} axi [m]"] = float(r[f"{m} [m]"])
            e[f"{m} 3d [m]"] = float(q[f"{m} [m]"])
            e[f"{m} axi - 3d [%]"] = 100.0 * (e[f"{m} axi [m]"] / e[f"{m} 3d [m]"] - 1.0)
        e["energy_error axi [-]"] = float(r["energy_error [-]"])
        e["energy_error 3d [-]"] = float(q["energy_error [-]"])
        e["wall axi [s]"] = float(r["wall_time [s]"])
        e["wall 3d [s]"] = float(q["wall_time [s]"])
        e["3d / axi wall [-]"] = e["wall 3d [s]"] / e["wall axi [s]"]
        e["3d campaign"] = os.path.relpath(source, a.axi)
        table.append(e)
    if not table:
        raise SystemExit("taylor_compare: no run of AXI_OUT has a quarter-model twin in REF_OUT")
    with open(os.path.join(a.axi, f"{a.out}.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, list(table[0].keys()), lineterminator="\n")
        w.writeheader()
        w.writerows(table)
    lines = ["# Axisymmetric against the 3D quarter model", "",
             "Written by campaigns/taylor/taylor_compare.py (difference: axisymmetric / 3D - 1; "
             "wall: mpm's run time, each on its own machine load).", "",
             "| set | failure | cells per radius [-] | shots [-] | "
             "Lf axi - 3d mean / worst abs [%] | "
             "Dm axi - 3d mean / worst abs [%] | energy error axi / 3d worst abs [%] | "
             "wall 3d / axi (sum) [-] |", "|---|---|---|---|---|---|---|---|"]
    groups = defaultdict(list)
    for e in table:
        groups[(e["set"], e["failure"], int(e["cells_per_radius"]))].append(e)
    for (s, f, n), es in sorted(groups.items()):
        lf = [e["Lf axi - 3d [%]"] for e in es]
        dm = [e["Dm axi - 3d [%]"] for e in es]
        lines.append(
            f"| {s} | {f} | {n} | {len(es)} | {sum(lf) / len(lf):+.2f} / {max(map(abs, lf)):.2f} | "
            f"{sum(dm) / len(dm):+.2f} / {max(map(abs, dm)):.2f} | "
            f"{100 * max(abs(e['energy_error axi [-]']) for e in es):.2f} / "
            f"{100 * max(abs(e['energy_error 3d [-]']) for e in es):.2f} | "
            f"{sum(e['wall 3d [s]'] for e in es) / sum(e['wall axi [s]'] for e in es):.1f} |")
    lines += ["", "| set | cells per radius [-] | shot | Lf axi / 3d [mm] | diff [%] | "
              "Dm axi / 3d [mm] | "
              "diff [%] | wall axi / 3d [s] |", "|---|---|---|---|---|---|---|---|"]
    for e in table:
        lines.append(
            f"| {e['set']} | {e['cells_per_radius']} | {e['shot']} | "
            f"{1e3 * e['Lf axi [m]']:.3f} / {1e3 * e['Lf 3d [m]']:.3f} | "
            f"{e['Lf axi - 3d [%]']:+.2f} | {1e3 * e['Dm axi [m]']:.2f} / "
            f"{1e3 * e['Dm 3d [m]']:.2f} | {e['Dm axi - 3d [%]']:+.2f} | "
            f"{e['wall axi [s]']:.1f} / {e['wall 3d [s]']:.1f} |")
    with open(os.path.join(a.axi, f"{a.out}.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print(f"taylor_compare: {len(table)} pairs; wrote {a.axi}/{a.out}.csv and .md")


if __name__ == "__main__":
    main()
