#!/usr/bin/env python3
"""Converts B. Banerjee's digitized 6061-T6 curves into the project's experiment format.

  python3 pointdriver/fit/convert_experiments.py SOURCE_DIR OUT_DIR [--points N]

SOURCE_DIR is the `stress_strain` folder of the shared 6061-T6 collection
(files SigEpsEp<rate>s<T>K[<P>MPa]<Src>.dat: columns confining pressure [MPa], temperature [K],
nominal strain rate [1/s], true total strain, true plastic strain, true stress [MPa]; MIT licence,
copyright 2017 Biswajit Banerjee). OUT_DIR receives one CSV per test in the format of
docs/fitting.md ("# key: value" header lines, then `true_plastic_strain [-],true_stress [Pa]`).

What is done to each curve (the same for every file, so the conversion is reproducible):
  1. tests under confining pressure (Davidson) and curves with fewer than 5 points or a
     plastic-strain range below 0.01 (single-point Eleiche entries, ASM yield-only curves) are
     skipped;
  2. elastic-ramp artefacts are dropped: points with plastic strain below 1e-3 and leading points
     whose stress is below 0.6 times the curve's median stress (e.g. Lesuer 8000 /s below 0.02);
  3. points are sorted by plastic strain and a point whose plastic strain does not exceed the
     previous kept one is dropped (digitizing back-steps);
  4. tension tests stop at the maximum stress (necking: the true stress after it is not the
     material's flow stress);
  5. the curve is resampled linearly in plastic strain to N points (default 25; fewer points are
     kept as they are) and stresses are written in Pa.
"""

import argparse
import os
import re
import sys

SOURCES = {
    "Hog": "Hoge, Exp. Mech. 6 (1966) 204-211",
    "Fis": "Fish, Oskay, Fan and Barsoum, RPI SCOREC report 2005-11",
    "Cad": "Cady and Gray, Mater. Sci. Eng. A 298 (2001) 56-62",
    "Gre": "Green and Babcock (1966), as reported by Eleiche, M.S. thesis, Brown University (1972)",
    "Ele": "Eleiche, M.S. thesis, Brown University (1972)",
    "Lee": "Lee, Shyu and Chiou, Scripta Mater. 42 (2000) 51-56",
    "Les": "Lesuer, Kay and LeBlanc, LLNL report UCRL-JC-134118",
    "Ram": "Jia and Ramesh, Exp. Mech. 44 (2004) 445-454",
    "Ros": "Rosenberg, Dawicke, Strader and Bless, Exp. Mech. 26(3) (1986)",
    "Oga": "Ogawa, J. Japan Inst. Light Metals 51(3) (2001) 173-181",
    "Yad": "Yadav, Chichili and Ramesh, Acta Metall. Mater. 43 (1995)",
    "ASM": "Aerospace Structural Metals Handbook",
}
# Only Ogawa's tests are stated to be tension tests in the collection's README; the others are
# taken as compression (Hopkinson-bar and quasi-static compression), as the README gives
# compression stresses as positive.
TENSION = {"Oga"}
DIGITIZED_BY = (
    "digitized and converted to true stress / true plastic strain by B. Banerjee, "
    "HighRateExptData (MIT licence, copyright 2017 Biswajit Banerjee)"
)

NAME = re.compile(r"^SigEpsEp(\d+)s(\d+)K(?:(\d+)MPa)?([A-Za-z]+)\.dat$")


def rate_from_name(digits):
    """'0001' -> 0.001, '000057' -> 0.00057, '1000' -> 1000 (the README's convention)."""
    if digits.startswith("0"):
        return float("0." + digits[1:])
    return float(digits)


def read_dat(path):
    rows = []
    with open(path) as f:
        for line in f:
            cells = line.split()
            if len(cells) != 6:
                continue
            rows.append([float(c) for c in cells])
    return rows


def clean(rows, tension):
    pts = [(r[4], r[5]) for r in rows if r[4] >= 1e-3]
    if not pts:
        return []
    stresses = sorted(s for _, s in pts)
    median = stresses[len(stresses) // 2]
    while pts and pts[0][1] < 0.6 * median:
        pts.pop(0)
    pts.sort(key=lambda p: p[0])
    kept = []
    for e, s in pts:
        if kept and e <= kept[-1][0]:
            continue
        kept.append((e, s))
    if tension and kept:
        imax = max(range(len(kept)), key=lambda i: kept[i][1])
        kept = kept[: imax + 1]
    return kept


def resample(pts, n):
    if len(pts) <= n:
        return pts
    e0, e1 = pts[0][0], pts[-1][0]
    out = []
    j = 0
    for k in range(n):
        e = e0 + (e1 - e0) * k / (n - 1)
        while j + 1 < len(pts) - 1 and pts[j + 1][0] < e:
            j += 1
        (ea, sa), (eb, sb) = pts[j], pts[j + 1]
        t = 0.0 if eb == ea else min(max((e - ea) / (eb - ea), 0.0), 1.0)
        out.append((e, sa + t * (sb - sa)))
    return out


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    parser.add_argument("source", help="the stress_strain folder of the shared collection")
    parser.add_argument("out", help="output folder (data/experiments/al6061_t6)")
    parser.add_argument("--points", type=int, default=25, help="points per curve (default 25)")
    args = parser.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    written, skipped = 0, []
    for name in sorted(os.listdir(args.source)):
        m = NAME.match(name)
        if not m:
            continue
        rate_digits, temp, pressure, src = m.groups()
        if pressure is not None:
            skipped.append((name, "confining pressure"))
            continue
        rows = read_dat(os.path.join(args.source, name))
        if not rows:
            skipped.append((name, "no data"))
            continue
        rate = rows[0][2] if rows[0][2] > 0 else rate_from_name(rate_digits)
        temperature = rows[0][1]
        tension = src in TENSION
        pts = clean(rows, tension)
        if len(pts) < 5 or pts[-1][0] - pts[0][0] < 0.01:
            skipped.append((name, f"{len(pts)} usable points"))
            continue
        pts = resample(pts, args.points)
        kind = "tension" if tension else "compression"
        stem = f"{src.lower()}_{temperature:g}K_{rate:g}per_s".replace("+", "")
        out = os.path.join(args.out, stem + ".csv")
        with open(out, "w") as f:
            f.write("# 6061-T6 aluminium, one test, true stress against true plastic strain\n")
            f.write(f"# test_type: uniaxial_{kind}\n")
            f.write(f"# strain_rate [1/s]: {rate:g}\n")
            f.write(f"# temperature [K]: {temperature:g}\n")
            f.write("# strain_measure: true_plastic\n")
            f.write("# stress_measure: true\n")
            f.write(f"# source: {SOURCES.get(src, src)}; {DIGITIZED_BY}\n")
            f.write(f"# converted_from: al6061t6_experiments/stress_strain/{name}\n")
            f.write(
                "# conversion: pointdriver/fit/convert_experiments.py (ramp artefacts dropped, "
                + ("stopped at the maximum stress, " if tension else "")
                + f"resampled to {len(pts)} points, MPa -> Pa)\n"
            )
            f.write("true_plastic_strain [-],true_stress [Pa]\n")
            for e, s in pts:
                f.write(f"{e:.6g},{s * 1e6:.6g}\n")
        written += 1
    print(f"{written} curves written to {args.out}")
    for name, why in skipped:
        print(f"  skipped {name}: {why}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
