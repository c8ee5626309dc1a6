#!/usr/bin/env python3
"""Converts the House et al. (1995) Taylor-impact table into the project's SI data file.

  python3 campaigns/taylor/convert_house1995.py SOURCE_CSV data/experiments/taylor/house1995.csv

SOURCE_CSV: the 23 shots of 6061-T6 rods as transcribed in B. Banerjee's public collection of
high-rate test data (HighRateExptData, TaylorData; MIT licence, copyright 2017 Biswajit Banerjee),
columns shot, L0_over_D0, D0_mm, L0_mm, U0_m_per_s, T0_K, rho0_kg_per_m3, Lf_mm, Xf_mm, Dm_mm.
The output has the same shots with lengths in metres (SI) and unit-bearing headers; nothing else is
changed. `campaigns/taylor/taylor.py` (./run.sh taylor) reads it.
"""

import csv
import sys

COLUMNS = [  # (output header, source column, factor to SI)
    ("shot", "shot", None),
    ("L0_over_D0 [-]", "L0_over_D0", 1.0),
    ("D0 [m]", "D0_mm", 1e-3),
    ("L0 [m]", "L0_mm", 1e-3),
    ("U0 [m/s]", "U0_m_per_s", 1.0),
    ("T0 [K]", "T0_K", 1.0),
    ("rho0 [kg/m^3]", "rho0_kg_per_m3", 1.0),
    ("Lf [m]", "Lf_mm", 1e-3),
    ("Dm [m]", "Dm_mm", 1e-3),
    ("Xf [m]", "Xf_mm", 1e-3),
]


def main(argv):
    usage = "usage: convert_house1995.py SOURCE_CSV OUT_CSV"
    if len(argv) == 2 and argv[1] in ("-h", "--help"):
        print(usage + "\n\n" + __doc__)
        return 0
    if len(argv) != 3:
        print(f"{usage}\nconvert_house1995.py: expected two arguments, got {len(argv) - 1}",
              file=sys.stderr)
        return 1
    with open(argv[1], newline="") as f:
        rows = list(csv.DictReader(f))
    with open(argv[2], "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow([c[0] for c in COLUMNS])
        for r in rows:
            w.writerow([r[src] if k is None else repr(round(float(r[src]) * k, 9))
                        for _, src, k in COLUMNS])
    print(f"wrote {len(rows)} shots to {argv[2]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
