#!/usr/bin/env python3
"""VTU snapshots of a 2D grid hold its plane (docs/mpm.md#output, 2D grids).

  planar_vtu_test.py MPM WORK_DIR

The Taylor rod in axisymmetry (data/scenes/verification/taylor_rod.json on a 26 x 14 grid over
the r-z half-plane, 2 x 2 particles per cell) and the contact blocks in plane strain
(contact_blocks.json, 20 x 12 cells), each run to a few microseconds with snapshots. Asserted for
every snapshot: the .vtu parses as XML (up to its raw appended data) with the header and the
arrays vtu_writer.cpp writes; NumberOfPoints = NumberOfCells = the particles of summary.json (one
vertex cell each); every point lies at z = 0 inside the grid's x-y rectangle (axisymmetric:
y >= 0, the radius); the velocity has no z component; particles.pvd lists every snapshot and
parses. The Taylor rod's points are the seeded meridian section: its count equals `mpm check`'s.
"""
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
SCENES = os.path.join(ROOT, "data", "scenes", "verification")


def arrays(path):
    """(header element, {name: list of tuples}) of a raw-appended .vtu (Float64 arrays; the
    points under "points")."""
    blob = open(path, "rb").read()
    head, data = blob.split(b'<AppendedData encoding="raw">\n_', 1)
    # The XML before its binary part, closed where the raw data begins.
    root = ET.fromstring(head.decode("ascii") + "</VTKFile>")
    out = {}
    for a in root.iter("DataArray"):
        if a.get("type") != "Float64":
            continue
        name, comps, offset = a.get("Name", "points"), int(a.get("NumberOfComponents")), int(a.get("offset"))
        (nbytes,) = struct.unpack_from("<Q", data, offset)
        values = struct.unpack_from(f"<{nbytes // 8}d", data, offset + 8)
        out[name] = [values[i:i + comps] for i in range(0, len(values), comps)]
    return root, out


def check(mpm, work, name, doc, axisymmetric):
    scene = os.path.join(work, name + ".json")
    with open(scene, "w") as f:
        json.dump(doc, f)
    out = os.path.join(work, name)
    done = subprocess.run([mpm, "run", scene, "--out", out, "--threads", "1"], capture_output=True,
                          text=True)
    assert done.returncode == 0, done.stderr
    summary = json.load(open(os.path.join(out, "summary.json")))
    n = summary["particles"]
    grid = doc["grid"]
    snaps = sorted(f for f in os.listdir(os.path.join(out, "particles")) if f.endswith(".vtu"))
    assert len(snaps) >= 3, snaps
    pvd = ET.parse(os.path.join(out, "particles.pvd")).getroot()
    listed = [d.get("file") for d in pvd.iter("DataSet")]
    assert listed == ["particles/" + s for s in snaps], (listed, snaps)
    for s in snaps:
        root, a = arrays(os.path.join(out, "particles", s))
        assert root.get("type") == "UnstructuredGrid" and root.get("header_type") == "UInt64"
        piece = root.find("UnstructuredGrid/Piece")
        assert int(piece.get("NumberOfPoints")) == n == int(piece.get("NumberOfCells")), (s, n)
        assert len(a["points"]) == n and len(a["velocity"]) == n
        for x, v in zip(a["points"], a["velocity"]):
            assert x[2] == 0.0 and v[2] == 0.0, (s, x, v)
            assert grid["lower"][0] <= x[0] <= grid["upper"][0], (s, x)
            assert grid["lower"][1] <= x[1] <= grid["upper"][1], (s, x)
            if axisymmetric:
                assert x[1] >= 0.0, (s, x)
    checked = subprocess.run([mpm, "check", scene], capture_output=True, text=True)
    assert checked.returncode == 0, checked.stderr
    text = checked.stdout
    seeded = json.loads(text)["report"]["particles"]
    assert seeded == n, (seeded, n)
    print(f"{name}: {len(snaps)} snapshots of {n} points each, all at z = 0 in the grid's "
          f"plane, as many as mpm check seeds")


def main(mpm, work):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    output = {"snapshots": True, "interval": 1.0e-6, "fields": ["velocity", "pressure", "id"]}
    taylor = {"extends": os.path.join(SCENES, "taylor_rod.json"),
              "grid": {"geometry": "axisymmetric", "lower": [0.0, 0.0],
                       "upper": [0.016455833333333336, 0.008860833333333333], "cells": [26, 14],
                       "boundary": {"z-": None, "z+": None}},
              "objects": {"rod": {"particles_per_cell": [2, 2]}},
              "time": {"max_time": 3.0e-6}, "output": output}
    check(mpm, work, "taylor_axisymmetric", taylor, True)
    blocks = {"extends": os.path.join(SCENES, "contact_blocks.json"),
              "grid": {"geometry": "plane_strain", "lower": [0.0, 0.0], "upper": [0.02, 0.012],
                       "cells": [20, 12], "boundary": {"z-": None, "z+": None}},
              "objects": {"left": {"geometry": {"lower": [0.004, 0.002, -0.002],
                                                "upper": [0.010, 0.010, 0.002]},
                                   "particles_per_cell": [2, 2]},
                          "right": {"geometry": {"lower": [0.010, 0.002, -0.002],
                                                 "upper": [0.016, 0.010, 0.002]},
                                    "particles_per_cell": [2, 2]}},
              "time": {"max_time": 3.0e-6}, "output": output}
    check(mpm, work, "blocks_plane_strain", blocks, False)
    print("OK")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
