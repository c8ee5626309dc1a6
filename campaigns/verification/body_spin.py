#!/usr/bin/env python3
"""How one body of a run moves as a whole, from its particle snapshots (docs/verification.md): per
snapshot, the centre of mass x_c [m], its velocity v_c [m/s] and speed, and the angular velocity
about the centre, omega = L_z / I_z [rad/s] (L_z = sum m (d_x u_y - d_y u_x), I_z = sum m (d_x^2 +
d_y^2), d = x - x_c, u = v - v_c: the in-plane spin, exact for a rigid rotation in the xy plane;
a plane-strain body's, or a 3D body's about z). With --radius r also omega r / |v_c|, the ratio a
rolling body holds at 1 and a frictionless slide at 0.

  body_spin.py RUN --object NAME [--radius R] [--csv FILE]

RUN is a run folder with snapshots (output.snapshots, and output.fields holding velocity, mass
and object). The object's index is its place among the scene's objects in name order (the
order `mpm` reads them), checked against each object's particle count in summary.json.
Example (the disk in the rigid trough, docs/verification.md):

  mpm run data/scenes/verification/rigid_trough.json --out out/trough \\
      --set '{"output": {"snapshots": true, "fields": ["velocity", "mass", "object"]}}'
  campaigns/verification/body_spin.py out/trough --object disk --radius 1.5e-3
"""
import argparse
import csv
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
# impact.results (pure Python; python/ of the source tree) reads run folders.
sys.path.insert(0, os.path.join(ROOT, "python"))
from impact.results.vtu import read_points, snapshots  # noqa: E402


def object_index(run, name):
    """The index of object `name` in the run's snapshots, and its particle count."""
    with open(os.path.join(run, "summary.json")) as f:
        objects = json.load(f)["objects"]
    names = sorted(objects)
    if name not in objects:
        sys.exit(f"body_spin.py: {run}/summary.json: no object {name!r}; the objects are "
                 + ", ".join(names))
    return names.index(name), int(objects[name]["particles"])


def motion(points, index):
    """The count, centre of mass, its velocity and the in-plane omega of object `index`."""
    x, v, m, o = points["points"], points["velocity"], points["mass"], points["object"]
    M = 0.0
    xc = [0.0, 0.0, 0.0]
    vc = [0.0, 0.0, 0.0]
    chosen = [p for p in range(len(m)) if int(o[p]) == index and m[p] > 0.0]
    for p in chosen:
        M += m[p]
        for d in range(3):
            xc[d] += m[p] * x[p][d]
            vc[d] += m[p] * v[p][d]
    xc = [c / M for c in xc]
    vc = [c / M for c in vc]
    L = I = 0.0
    for p in chosen:
        dx, dy = x[p][0] - xc[0], x[p][1] - xc[1]
        ux, uy = v[p][0] - vc[0], v[p][1] - vc[1]
        L += m[p] * (dx * uy - dy * ux)
        I += m[p] * (dx * dx + dy * dy)
    return len(chosen), xc, vc, L / I


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("run")
    parser.add_argument("--object", required=True)
    parser.add_argument("--radius", type=float, help="r [m]: also omega r / |v_c|")
    parser.add_argument("--csv", help="also write the table to this file")
    a = parser.parse_args()
    index, count = object_index(a.run, a.object)
    header = ["time [s]", "x_c [m]", "y_c [m]", "z_c [m]", "speed [m/s]", "omega [rad/s]"]
    if a.radius:
        header.append("omega r / speed [-]")
    rows = []
    for time, path in snapshots(a.run):
        n, xc, vc, omega = motion(read_points(path, numpy=False), index)
        if not rows and n != count:
            sys.exit(f"body_spin.py: {path}: {n} particles of object index {index}, but "
                     f"summary.json gives {a.object!r} {count}: the object order is not the "
                     "name order")
        speed = math.sqrt(sum(c * c for c in vc))
        row = [time, *xc, speed, omega]
        if a.radius:
            row.append(omega * a.radius / speed if speed > 0.0 else 0.0)
        rows.append(row)
    print(" ".join(f"{h:>20s}" for h in header))
    for row in rows:
        print(" ".join(f"{value:20.6g}" for value in row))
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.writer(f)
            w.writerow(header)
            w.writerows(rows)


if __name__ == "__main__":
    main()
