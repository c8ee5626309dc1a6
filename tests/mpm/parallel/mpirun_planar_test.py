#!/usr/bin/env python3
"""`mpm run` under mpirun on a 2D grid writes what one rank writes (docs/mpi.md, "Cost model", 2D grids).

  mpirun_planar_test.py MPM MPIEXEC RANKS WORK_DIR

The sphere-cylinder case01 in axisymmetry (data/scenes/sphere_cylinder/case01.json with the
sphere on the axis, 50 x 10 cells over the half-section, 2 x 2 particles per cell: friction
contact with four velocity fields, artificial viscosity, erosion, particle conversion) to 3 us,
and the same with single_velocity contact and an x+ `wall` face with friction (wall touch bits
in the halo). Each once on one rank and on RANKS ranks, split automatically and in boxes across
x and y (solver.ranks_per_axis [RANKS/2, 2]). Asserted: summary.json's numbers and every
history column within 1e-9 as in mpirun_summary_test.py; the boxes never split z (z [0, 1]);
each rank's halo bytes and messages per step equal the cost model with one node plane along z
(a 2D grid stores k = 0 only), and `mpm check --ranks RANKS` plans the run's boxes and halo
bytes without running; every .pvtu names RANKS pieces holding every particle once at z = 0;
stopped by SIGTERM after step 40 and restarted on as many ranks, every file bit for bit.
Before the stored box of a 2D grid was one node plane, `mpm check --ranks` planned 4 planes
along z: 4 times the halo bytes and grid nodes the run has.
"""
import json
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, HERE)
from mpirun_summary_test import columns, run, same_observables, same_particles, vtu_arrays  # noqa: E402

CELLS = [50, 10, 1]


def scene(work, name, patch):
    """case01 on an axisymmetric grid with `patch` on top, written to WORK/name.json."""
    doc = {"extends": os.path.join(ROOT, "data/scenes/sphere_cylinder/case01.json"),
           "grid": {"geometry": "axisymmetric", "lower": [0.0, 0.0], "upper": [119.0e-3, 33.0e-3],
                    "cells": CELLS[:2], "boundary": {"z-": None, "z+": None}},
           "objects": {"sphere": {"geometry": {"center": [9.75e-3, 0.0, 0.0]},
                                  "particles_per_cell": [2, 2]},
                       "target": {"particles_per_cell": [2, 2]}},
           "time": {"max_time": 3.0e-6, "multiplier": 0.2},
           "output": {"fields": ["velocity", "pressure", "id"]}}
    doc.update({k: v for k, v in patch.items() if k not in doc})
    for k, v in patch.items():
        if k in doc and isinstance(v, dict):
            doc[k].update(v)
    path = os.path.join(work, name + ".json")
    with open(path, "w") as f:
        json.dump(doc, f)
    return path


def planar_halo_traffic(summary, fields, walls, musl=True):
    """docs/mpi.md's cost model on a 2D grid: per neighbour along x or y, 3 node layers times the
    stored extent along the other in-plane axis times ONE node along z."""
    load = summary["ranks_load"]
    boxes = load["boxes"]
    p = boxes["ranks_per_axis"]
    assert p[2] == 1 and boxes["z"] == [0, 1], boxes
    first = [boxes["x"], boxes["y"]]
    per_node = 64 + (1 if walls else 0) + (24 if musl else 0)
    for r in range(p[0] * p[1]):
        c = (r // p[1], r % p[1])
        extent = [min(first[d][c[d] + 1] + 3, CELLS[d] + 1) - max(first[d][c[d]] - 3, -1) + 1
                  for d in range(2)]
        nbytes = messages = 0
        for d in range(2):
            neighbours = (c[d] > 0) + (c[d] + 1 < p[d])
            layer = extent[1 - d] * 1 * fields
            nbytes += neighbours * 3 * layer * per_node
            messages += neighbours * (2 + (1 if walls else 0))
            if fields > 1:
                nbytes += neighbours * layer * 64
                messages += neighbours
        assert load["halo_bytes_sent_per_step [B]"][r] == nbytes, (r, load, nbytes)
        assert load["halo_messages_sent_per_step"][r] == messages, (r, load, messages)
    print(f"  halo traffic per step as the cost model with one node plane along z: "
          f"{load['halo_bytes_sent_per_step [B]']} B")


def planned(mpm, path, ranks, summary):
    """`mpm check --ranks` plans the run's boxes and halo bytes."""
    checked = subprocess.run([mpm, "check", path, "--ranks", str(ranks)], capture_output=True,
                             text=True)
    assert checked.returncode == 0, checked.stderr
    text = checked.stdout
    plan = json.loads(text)["report"]["decomposition"]
    load = summary["ranks_load"]
    assert load["rebalances"] == 0, load
    for axis in "xyz":
        assert plan["boxes"][axis] == load["boxes"][axis], (plan, load)
    measured = load["halo_bytes_sent_per_step [B]"]
    assert plan["halo_bytes_sent_per_step [B]"]["max"] == max(measured), (plan, measured)
    assert plan["halo_bytes_sent_per_step [B]"]["mean"] == sum(measured) / ranks, (plan, measured)
    print(f"  mpm check --ranks {ranks}: boxes {plan['ranks_per_axis']} and halo bytes as the run")


def same_history(one, many):
    ha, ra = columns(os.path.join(one, "history.csv"))
    hb, rb = columns(os.path.join(many, "history.csv"))
    assert ha == hb and len(ra) == len(rb), "history.csv: other columns or rows"
    for c, column in enumerate(ha.split(",")):
        scale = max(abs(r[c]) for r in ra)
        for x, y in zip(ra, rb):
            assert abs(x[c] - y[c]) <= 1e-9 * scale, (column, x[c], y[c])


def in_plane_pieces(one, many, ranks, n):
    sa = sorted(f for f in os.listdir(os.path.join(one, "particles")) if f.endswith(".vtu"))
    sb = sorted(f for f in os.listdir(os.path.join(many, "particles")) if f.endswith(".pvtu"))
    assert [f[:-4] for f in sa] == [f[:-5] for f in sb] and len(sa) >= 4, (sa, sb)
    for va, pb in zip(sa, sb):
        same_particles(os.path.join(one, "particles", va), os.path.join(many, "particles", pb),
                       ranks, n)
    assert all(x[2] == 0.0 for x in vtu_arrays(os.path.join(one, "particles", sa[-1]))["points"])


def restart_bit_for_bit(launch, path, whole, work, env):
    cut = os.path.join(work, os.path.basename(whole) + "_cut")
    done = subprocess.run(launch + [path, "--out", cut, "--inject-fault", "sigterm:40"],
                          capture_output=True, text=True, env=env)
    assert done.returncode == 143, (done.returncode, done.stderr)
    run(launch + ["--restart", cut], env)
    for name in ["history.csv", "particles.pvd"] + [
            os.path.join("particles", f) for f in sorted(os.listdir(os.path.join(whole, "particles")))]:
        with open(os.path.join(whole, name), "rb") as f, open(os.path.join(cut, name), "rb") as g:
            assert f.read() == g.read(), f"{name}: the restarted run differs"
    print("  stopped after step 40 and restarted: every file bit for bit")


def main(mpm, mpiexec, ranks, work):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    env = dict(os.environ, OMP_NUM_THREADS="1", OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    launch = [mpiexec, "-np", str(ranks), "--oversubscribe", mpm, "run", "--threads", "1"]
    variants = [
        ("friction", {}, 4, False),
        ("wall", {"physics": {"contact": {"type": "single_velocity", "mu": None}},
                  "grid": {"boundary": {"x+": "wall", "z-": None, "z+": None},
                           "wall_friction": {"x+": 0.2}}}, 1, True),
    ]
    for name, patch, fields, walls in variants:
        path = scene(work, name, patch)
        one = os.path.join(work, name + "_one")
        run([mpm, "run", path, "--out", one, "--threads", "1"])
        a = json.load(open(os.path.join(one, "summary.json")))
        assert a["status"] == "completed", a["status"]
        split = scene(work, name + "_boxes", dict(patch, solver={"ranks_per_axis": [ranks // 2, 2]}))
        for label, p in (("automatic split", path), (f"boxes {ranks // 2} x 2", split)):
            many = os.path.join(work, f"{name}_{ranks}_{os.path.basename(p)[:-5]}")
            run(launch + [p, "--out", many], env)
            b = json.load(open(os.path.join(many, "summary.json")))
            print(f"{name}, {label}:")
            same_observables(a, b, ranks)
            same_history(one, many)
            planar_halo_traffic(b, fields, walls)
            planned(mpm, p, ranks, b)
            in_plane_pieces(one, many, ranks, a["particles"])
            restart_bit_for_bit(launch, p, many, work, env)
    print("OK")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4])
