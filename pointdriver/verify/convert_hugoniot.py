#!/usr/bin/env python3
"""Converts B. Banerjee's digitized aluminium compression data into the project's Hugoniot file.

  python3 pointdriver/verify/convert_hugoniot.py SOURCE_DIR OUT_FILE

SOURCE_DIR is the `hugoniot` folder of B. Banerjee's 6061-T6 collection (HighRateExptData, MIT
licence, copyright 2017 Biswajit Banerjee): files AlEOS<Author><year>.dat, two columns, the
specific-volume ratio V/V0 and the pressure in GPa. OUT_FILE receives one CSV with the columns
`source,volume_ratio [-],pressure [Pa]`, sorted by source then by decreasing V/V0, pressures in
Pa (SI). Nothing else is changed. The point driver's verification suite reads OUT_FILE
(data/experiments/al6061_t6_hugoniot/hugoniot.csv) for its Mie-Gruneisen figure.
"""

import os
import sys

SOURCES = {
    "McQueen70": "McQueen, Marsh, Taylor, Fritz and Carter (1970), in High-Velocity Impact "
                 "Phenomena (Kinslow, ed.), Academic Press, 293-417: shock Hugoniot",
    "Mitchell81": "Mitchell and Nellis (1981), J. Appl. Phys. 52, 3363-3374: shock Hugoniot",
    "Vaidya70": "Vaidya and Kennedy (1970), J. Phys. Chem. Solids 31, 2329-2345: static "
                "compression to 4.5 GPa (an isotherm, not a shock)",
}


def main(argv):
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 1
    source_dir, out_file = argv[1], argv[2]
    rows = []
    for key in sorted(SOURCES):
        path = os.path.join(source_dir, "AlEOS" + key + ".dat")
        with open(path) as f:
            points = [tuple(float(x) for x in line.split()[:2]) for line in f if line.strip()]
        for ratio, gpa in sorted(points, key=lambda p: -p[0]):
            rows.append((key, ratio, gpa * 1e9))
    with open(out_file, "w") as f:
        f.write("source,volume_ratio [-],pressure [Pa]\n")
        for key, ratio, pa in rows:
            f.write(f"{key},{ratio:.10g},{pa:.10g}\n")
    print(f"convert_hugoniot.py: {len(rows)} points from {len(SOURCES)} sources -> {out_file}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
