#!/usr/bin/env python3
"""Writes the SYNTHETIC fracture-strain example of `pointdriver fit` in damage mode.

  python3 pointdriver/fit/make_synthetic_fracture.py OUT.csv

No public 6061-T6 fracture-strain table (strain at fracture against triaxiality, rate and
temperature) was available to this project, so the example is synthetic and labelled as such:
fracture strains from report eq. 7 with the material file's set (D1 = -0.77, D2 = 1.45,
D3 = -0.47, D4 = 0, D5 = 1.6; T_room = 294 K, T_melt = 925 K, reference rate 1 /s) at
triaxialities 0 to 1.2 (quasi-static, 294 K), rates 1e-3 to 1e4 /s (eta = 1/3) and temperatures
294 to 700 K (eta = 1/3, 1e-3 /s), each multiplied by (1 + 0.03 z), z standard normal from
random.Random(6061) (3 % scatter, deterministic).
"""

import math
import random
import sys

D = (-0.77, 1.45, -0.47, 0.0, 1.6)
T_ROOM, T_MELT, RATE0 = 294.0, 925.0, 1.0


def eps_f(eta, rate, T):
    ts = min(max((T - T_ROOM) / (T_MELT - T_ROOM), 0.0), 1.0)
    return (
        (D[0] + D[1] * math.exp(D[2] * eta))
        * (1 + D[3] * math.log(max(rate / RATE0, 1.0)))
        * (1 + D[4] * ts)
    )


def main(argv):
    if len(argv) != 1:
        sys.stderr.write(__doc__)
        return 1
    rng = random.Random(6061)
    rows = []
    for eta in (0.0, 0.1, 0.2, 1.0 / 3.0, 0.45, 0.6, 0.75, 0.9, 1.05, 1.2):
        rows.append((eta, 1e-3, 294.0))
    for rate in (1e-1, 10.0, 1e2, 1e3, 1e4):
        rows.append((1.0 / 3.0, rate, 294.0))
    for T in (350.0, 450.0, 550.0, 700.0):
        rows.append((1.0 / 3.0, 1e-3, T))
    with open(argv[0], "w") as f:
        f.write("# SYNTHETIC DATA, NOT MEASUREMENTS: the example of `pointdriver fit` in damage mode\n")
        f.write(
            "# source: synthetic, report eq. 7 with D1..D5 = -0.77, 1.45, -0.47, 0, 1.6 and 3 % "
            "Gaussian scatter (pointdriver/fit/make_synthetic_fracture.py, seed 6061)\n"
        )
        f.write("triaxiality [-],strain_rate [1/s],temperature [K],fracture_strain [-]\n")
        for eta, rate, T in rows:
            e = eps_f(eta, rate, T) * (1 + 0.03 * rng.gauss(0.0, 1.0))
            f.write(f"{eta:.6g},{rate:g},{T:g},{e:.6g}\n")
    print(f"{len(rows)} synthetic fracture strains written to {argv[0]}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
