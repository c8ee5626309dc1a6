#!/usr/bin/env python3
"""`mpm run` under mpirun writes what one rank writes, to round-off.

  mpirun_summary_test.py MPM MPIEXEC RANKS WORK_DIR

The recommended sphere-cylinder to 3 us (snapshots at 1 us) once on one rank (no mpirun) and
once on RANKS ranks. Asserted: both complete; summary.json's numbers (ledger, observables,
crater, failures, particle and mass counts) agree to 1e-9 relative, or 1e-9 of E0 for the
energies and of sqrt(2 M E0) for momenta and impulses (quantities that start at zero); the
history has the same rows and columns and every column (ledger and gauges, the gauges reduced
over the ranks) agrees to 1e-9 of its largest magnitude; every snapshot is a .pvtu naming one
.vtu piece per rank, the pieces hold every particle once (by the `id` field) at the position and
velocity of the one-rank .vtu to 1e-9 relative. What is left to differ is the order of the sums
at the shared node planes and in the reductions. The run stopped by SIGTERM after step 40 (one checkpoint
file per rank) and restarted on as many ranks writes every file bit for bit as the uninterrupted
run. A NaN stress injected into the last particle (on the last rank) in step 5 stops every rank
with exit code 3 and a message naming the step, the rank and the particle. Particle paths whose
particles cross slab boundaries are written as on one rank (paths_across_ranks). The scene
split in boxes across y and z (solver.ranks_per_axis 1 x 2 x RANKS/2) gives the same summary
and restarts bit for bit; a split that does not multiply to RANKS is refused
(boxes_across_y_and_z), as is one the grid cannot hold along y, and a restart on another rank
count. Each rank's halo bytes and messages per step equal the cost model's
count (halo_traffic).
"""
import json
import math
import os
import re
import shutil
import struct
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
# The recommended scene's grid (data/scenes/sphere_cylinder/case01.json).
with open(os.path.join(ROOT, "data/scenes/sphere_cylinder/case01.json")) as _case01:
    CELLS = json.load(_case01)["grid"]["cells"]
SKIP = ("wall_time", "particles_per_second", "particle_steps_per_second", "memory", "threads",
        "ranks", "available", "seconds_in_mpi", "phase_seconds")


def numbers(node, path=""):
    if isinstance(node, dict):
        for k, v in node.items():
            yield from numbers(v, path + "/" + k)
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from numbers(v, f"{path}[{i}]")
    elif isinstance(node, (int, float)) and not isinstance(node, bool):
        yield path, float(node)


def vtu_arrays(path):
    """{name: list of tuples} of a raw-appended .vtu as vtu_writer.cpp writes it (Float64 points
    and point data, UInt64 headers); the points under the name "points"."""
    blob = open(path, "rb").read()
    head, data = blob.split(b'<AppendedData encoding="raw">\n_', 1)
    text = head.decode("latin-1")
    out = {}
    for m in re.finditer(r'<DataArray type="(\w+)"( Name="(\w+)")? NumberOfComponents="(\d+)" '
                         r'format="appended" offset="(\d+)"/>', text):
        kind, name, comps, offset = m.group(1), m.group(3) or "points", int(m.group(4)), int(m.group(5))
        if kind != "Float64":
            continue
        (nbytes,) = struct.unpack_from("<Q", data, offset)
        values = struct.unpack_from(f"<{nbytes // 8}d", data, offset + 8)
        out[name] = [values[i:i + comps] for i in range(0, len(values), comps)]
    return out


def same_particles(one_vtu, pvtu, ranks, n):
    """The pieces a .pvtu names hold every particle of the one-rank .vtu once, at its position
    and velocity to 1e-9 relative."""
    text = open(pvtu).read()
    pieces = re.findall(r'<Piece Source="([^"]+)"/>', text)
    assert len(pieces) == ranks, (pvtu, pieces)
    assert 'Name="id"' in text and 'Name="velocity" NumberOfComponents="3"' in text, text
    ref = vtu_arrays(one_vtu)
    assert len(ref["id"]) == n
    seen = set()
    scale_x = max(abs(c) for p in ref["points"] for c in p)
    scale_v = max(max(abs(c) for p in ref["velocity"] for c in p), 1.0)
    for piece in pieces:
        a = vtu_arrays(os.path.join(os.path.dirname(pvtu), piece))
        for (i,), x, v in zip(a["id"], a["points"], a["velocity"]):
            i = int(i)
            assert i not in seen, f"{piece}: particle {i} twice"
            seen.add(i)
            assert all(abs(p - q) <= 1e-9 * scale_x for p, q in zip(x, ref["points"][i])), (piece, i)
            assert all(abs(p - q) <= 1e-9 * scale_v for p, q in zip(v, ref["velocity"][i])), (piece, i)
    assert len(seen) == n, f"{pvtu}: {len(seen)} of {n} particles"


def piece_of(pvtu, ids):
    """{id: the piece's rank} for the given seed indices, from the pieces a .pvtu names."""
    where = {}
    for r, piece in enumerate(re.findall(r'<Piece Source="([^"]+)"/>', open(pvtu).read())):
        for (i,) in vtu_arrays(os.path.join(os.path.dirname(pvtu), piece))["id"]:
            if int(i) in ids:
                where[int(i)] = r
    return where


def columns(csv):
    lines = open(csv).read().splitlines()
    return lines[0], [[float(x) for x in line.split(",")] for line in lines[1:]]


def paths_across_ranks(mpm, mpiexec, ranks, work, env):
    """Particle paths on several ranks: the flyer plate (verification scene, shocked in 6 us) with
    a path starting one cell upstream of every slab boundary, so the particle crosses to the
    neighbour's slab before the shock stops it. The path files equal the one-rank run's to 1e-9
    of each column's largest magnitude, and at least one tracked particle changed rank."""
    flyer = os.path.join(ROOT, "data/scenes/verification/flyer_plate.json")
    probe = os.path.join(work, "flyer_probe")
    run([mpiexec, "-np", str(ranks), "--oversubscribe", mpm, "run", flyer, "--out", probe,
         "--threads", "1"], env)
    slabs = json.load(open(os.path.join(probe, "summary.json")))["ranks_load"]["boxes"]["x"]
    x0, dx = -0.022, 0.2e-3  # the scene's grid
    paths = {}
    for k, b in enumerate(slabs[1:-1]):
        xb = x0 + b * dx
        # upstream: the flyer (x < 0) moves +x, the target -x until the shock reaches them
        x = xb - 0.75 * dx if xb < 0 else xb + 0.75 * dx
        paths[f"boundary{k}"] = {"object": "flyer" if x < 0 else "target",
                                 "position": [x, 1.0e-4, 1.0e-4]}
    scene = os.path.join(work, "flyer_paths.json")
    with open(scene, "w") as f:
        json.dump({"extends": flyer, "output": {"particle_paths": paths, "snapshots": True,
                                                "interval": 6.0e-6, "fields": ["id"]}}, f)
    one, many = os.path.join(work, "flyer_one"), os.path.join(work, "flyer_many")
    run([mpm, "run", scene, "--out", one, "--threads", "1"])
    run([mpiexec, "-np", str(ranks), "--oversubscribe", mpm, "run", scene, "--out", many,
         "--threads", "1"], env)
    sa = json.load(open(os.path.join(one, "summary.json")))
    sb = json.load(open(os.path.join(many, "summary.json")))
    assert sa["particle_paths"] == sb["particle_paths"], (sa["particle_paths"], sb["particle_paths"])
    for name in paths:
        ha, ra = columns(os.path.join(one, "paths", name + ".csv"))
        hb, rb = columns(os.path.join(many, "paths", name + ".csv"))
        assert ha == hb and len(ra) == len(rb) > 100, (name, len(ra), len(rb))
        for c in range(len(ra[0])):
            scale = max(abs(r[c]) for r in ra)
            assert all(abs(x[c] - y[c]) <= 1e-9 * scale for x, y in zip(ra, rb)), (name, c)
        ja = json.load(open(os.path.join(one, "paths", name + ".json")))
        jb = json.load(open(os.path.join(many, "paths", name + ".json")))
        assert len(ja["legs"]) == len(jb["legs"]) == len(ra)
        for k in ja["legs"][0]["velocity_gradient"]:
            scale = max(abs(leg["velocity_gradient"][k]) for leg in ja["legs"])
            for la, lb in zip(ja["legs"], jb["legs"]):
                d = abs(la["velocity_gradient"][k] - lb["velocity_gradient"][k])
                assert d <= 1e-9 * scale, (name, k, d, scale)
    ids = set(sb["particle_paths"].values())
    pv = sorted(f for f in os.listdir(os.path.join(many, "particles")) if f.endswith(".pvtu"))
    start = piece_of(os.path.join(many, "particles", pv[0]), ids)
    end = piece_of(os.path.join(many, "particles", pv[-1]), ids)
    moved = [i for i in ids if start[i] != end[i]]
    assert moved, (start, end)
    print(f"particle paths on {ranks} ranks: {len(paths)} paths as on one rank; particles "
          f"{sorted(moved)} changed rank on the way")


def same_observables(a, b, ranks):
    """Every number of summary b (several ranks) within 1e-9 of one-rank summary a: energies
    relative to E0, momenta to sqrt(2 M E0), the rest to their magnitude."""
    assert a["status"] == b["status"] == "completed", (a["status"], b["status"])
    assert b["ranks"] == ranks, b["ranks"]
    e0 = a["initial_energy [J]"]
    mass = a["mass [kg]"]
    p_scale = math.sqrt(2.0 * mass * e0)
    nb = dict(numbers(b))
    worst = (0.0, "")
    for path, x in numbers(a):
        if any(s in path for s in SKIP):
            continue
        assert path in nb, f"{path} missing on {ranks} ranks"
        y = nb[path]
        if "[J]" in path:
            scale = e0
        elif "momentum" in path or "impulse" in path:
            scale = p_scale
        else:
            scale = max(abs(x), abs(y))
        d = abs(x - y) / scale if scale > 0 else 0.0
        worst = max(worst, (d, path))
    print(f"{ranks} ranks ({b['ranks_load']['boxes']['ranks_per_axis']} boxes) against one: "
          f"worst relative difference {worst[0]:.3e} at {worst[1]}")
    assert worst[0] < 1e-9, worst


def halo_traffic(summary, cells, fields=1):
    """The bytes and messages each rank sent per step, against docs/mpi.md's cost model: per
    neighbour along axis d, the node sums of particles-to-grid (64 B per node and field) and of
    the MUSL re-map (24 B) over 3 node layers times the rank's stored extents on the other two
    axes (its cells and 3 halo layers each side, clipped to the grid and its ghost layers); one
    message per neighbour and exchange (no size first: both send the same length). Scenes
    without contact or nodal stress."""
    load = summary["ranks_load"]
    boxes = load["boxes"]
    p = boxes["ranks_per_axis"]
    first = [boxes["x"], boxes["y"], boxes["z"]]
    for r in range(p[0] * p[1] * p[2]):
        c = (r // (p[1] * p[2]), (r // p[2]) % p[1], r % p[2])
        extent = [min(first[d][c[d] + 1] + 3, cells[d] + 1) - max(first[d][c[d]] - 3, -1) + 1
                  for d in range(3)]
        nbytes = messages = 0
        for d in range(3):
            neighbours = (c[d] > 0) + (c[d] + 1 < p[d])
            face = extent[(d + 1) % 3] * extent[(d + 2) % 3]
            nbytes += neighbours * 3 * face * fields * (64 + 24)
            messages += neighbours * 2  # the P2G sums and the re-map momentum
        assert load["halo_bytes_sent_per_step [B]"][r] == nbytes, (r, load, nbytes)
        assert load["halo_messages_sent_per_step"][r] == messages, (r, load, messages)
    print(f"halo traffic per step as the cost model: {load['halo_bytes_sent_per_step [B]']} B")


def boxes_across_y_and_z(mpm, mpiexec, ranks, work, env, one):
    """The same scene split 1 x 2 x ranks/2 (solver.ranks_per_axis): the summary as on one rank,
    and stopped after step 40 and restarted, every file bit for bit as the uninterrupted run. A
    split whose product is not the rank count is refused naming the key."""
    scene = os.path.join(work, "boxes.json")
    with open(scene, "w") as f:
        json.dump({"extends": os.path.join(work, "scene.json"),
                   "solver": {"ranks_per_axis": [1, 2, ranks // 2]}}, f)
    launch = [mpiexec, "-np", str(ranks), "--oversubscribe", mpm, "run", "--threads", "1"]
    whole, cut = os.path.join(work, "boxes_whole"), os.path.join(work, "boxes_cut")
    run(launch + [scene, "--out", whole], env)
    b = json.load(open(os.path.join(whole, "summary.json")))
    assert b["ranks_load"]["boxes"]["ranks_per_axis"] == [1, 2, ranks // 2], b["ranks_load"]
    same_observables(json.load(open(os.path.join(one, "summary.json"))), b, ranks)
    halo_traffic(b, CELLS)
    # `mpm check --ranks` plans the same boxes and traffic without running (no re-balance here).
    checked = subprocess.run([mpm, "check", scene, "--ranks", str(ranks)], capture_output=True,
                             text=True)
    assert checked.returncode == 0, checked.stderr
    text = checked.stdout
    plan = json.loads(text)["report"]["decomposition"]
    assert b["ranks_load"]["rebalances"] == 0, b["ranks_load"]
    for axis in "xyz":
        assert plan["boxes"][axis] == b["ranks_load"]["boxes"][axis], (plan, b["ranks_load"])
    measured = b["ranks_load"]["halo_bytes_sent_per_step [B]"]
    assert plan["halo_bytes_sent_per_step [B]"]["max"] == max(measured), (plan, measured)
    assert plan["halo_bytes_sent_per_step [B]"]["mean"] == sum(measured) / ranks, (plan, measured)
    print(f"mpm check --ranks {ranks}: the run's boxes and halo bytes, planned without running")
    done = subprocess.run(launch + [scene, "--out", cut, "--inject-fault", "sigterm:40"],
                          capture_output=True, text=True, env=env)
    assert done.returncode == 143, (done.returncode, done.stderr)
    run(launch + ["--restart", cut], env)
    for name in ["history.csv", "particles.pvd"] + [
            os.path.join("particles", n) for n in sorted(os.listdir(os.path.join(whole, "particles")))]:
        with open(os.path.join(whole, name), "rb") as f, open(os.path.join(cut, name), "rb") as g:
            assert f.read() == g.read(), f"{name}: the restarted run (boxes) differs"
    print(f"boxes 1 x 2 x {ranks // 2}: restart bit-identical")
    wrong = os.path.join(work, "boxes_wrong.json")
    with open(wrong, "w") as f:
        json.dump({"extends": scene, "solver": {"ranks_per_axis": [ranks, 2, 1]}}, f)
    done = subprocess.run(launch + [wrong, "--out", os.path.join(work, "wrong")],
                          capture_output=True, text=True, env=env)
    assert done.returncode == 2, (done.returncode, done.stderr)
    assert (f"boxes_wrong.json: /solver/ranks_per_axis: [{ranks}, 2, 1] makes {2 * ranks} boxes; "
            f"expected their product to be the rank count {ranks}") in done.stderr, done.stderr
    # A split the grid cannot hold along y: the axis named, an input error.
    thin = os.path.join(work, "boxes_thin.json")
    with open(thin, "w") as f:
        json.dump({"extends": scene, "solver": {"ranks_per_axis": [1, ranks, 1]},
                   "grid": {"cells": [CELLS[0], 3 * ranks - 1, CELLS[2]]}}, f)
    done = subprocess.run(launch + [thin, "--out", os.path.join(work, "thin")],
                          capture_output=True, text=True, env=env)
    assert done.returncode == 2, (done.returncode, done.stderr)
    assert (f"boxes_thin.json: /solver/ranks_per_axis: {3 * ranks - 1} grid cells along y cannot "
            f"be split into {ranks} slabs") in done.stderr, done.stderr
    print("a split that does not match the rank count or the grid: refused, naming the key")


def run(cmd, env=None):
    done = subprocess.run(cmd, capture_output=True, text=True, env=env)
    if done.returncode != 0:
        sys.exit(f"FAIL: {' '.join(cmd)} exited {done.returncode}\n{done.stderr}")


def main(mpm, mpiexec, ranks, work):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    scene = os.path.join(work, "scene.json")
    with open(scene, "w") as f:
        json.dump({"extends": os.path.join(ROOT, "data/scenes/sphere_cylinder/recommended.json"),
                   "time": {"max_time": 3.0e-6},
                   "output": {"fields": ["velocity", "pressure", "id"]}}, f)
    one, many = os.path.join(work, "one"), os.path.join(work, "many")
    run([mpm, "run", scene, "--out", one, "--threads", "1"])
    env = dict(os.environ, OMP_NUM_THREADS="1", OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    run([mpiexec, "-np", str(ranks), "--oversubscribe", mpm, "run", scene, "--out", many,
         "--threads", "1"], env)
    a = json.load(open(os.path.join(one, "summary.json")))
    b = json.load(open(os.path.join(many, "summary.json")))
    same_observables(a, b, ranks)
    halo_traffic(b, CELLS)
    ha = open(os.path.join(one, "history.csv")).read().splitlines()
    hb = open(os.path.join(many, "history.csv")).read().splitlines()
    assert ha[0] == hb[0] and len(ha) == len(hb), "history.csv: other columns or rows"
    rows_a = [[float(x) for x in r.split(",")] for r in ha[1:]]
    rows_b = [[float(x) for x in r.split(",")] for r in hb[1:]]
    for c, column in enumerate(ha[0].split(",")):
        scale = max(abs(r[c]) for r in rows_a)
        for ra, rb in zip(rows_a, rows_b):
            assert abs(ra[c] - rb[c]) <= 1e-9 * scale, (column, ra[c], rb[c])
    print(f"history.csv: {len(rows_a)} rows, every column within 1e-9 of its largest magnitude")
    sa = sorted(f for f in os.listdir(os.path.join(one, "particles")) if f.endswith(".vtu"))
    sb = sorted(f for f in os.listdir(os.path.join(many, "particles")) if f.endswith(".pvtu"))
    assert [f[:-4] for f in sa] == [f[:-5] for f in sb] and len(sa) >= 4, (sa, sb)
    n = a["particles"]
    for va, pb in zip(sa, sb):
        same_particles(os.path.join(one, "particles", va), os.path.join(many, "particles", pb),
                       ranks, n)
    try:  # VTK's own reader, when its Python module is installed (python3-vtk9; not in CI)
        import vtk
        reader = vtk.vtkXMLPUnstructuredGridReader()
        reader.SetFileName(os.path.join(many, "particles", sb[-1]))
        reader.Update()
        assert reader.GetOutput().GetNumberOfPoints() == n, reader.GetOutput().GetNumberOfPoints()
        print(f"VTK reads {sb[-1]} as one data set of {n} points")
    except ImportError:
        pass
    pvd = open(os.path.join(many, "particles.pvd")).read()
    assert all(f'file="particles/{f}"' in pvd for f in sb), pvd
    print(f"{len(sb)} snapshots: {ranks} pieces each, every particle once, as on one rank")
    # Stopped by SIGTERM after step 40 (a checkpoint per rank), then restarted on as many ranks:
    # every file as in the uninterrupted run, bit for bit.
    launch = [mpiexec, "-np", str(ranks), "--oversubscribe", mpm, "run"]
    cut = os.path.join(work, "cut")
    done = subprocess.run(launch + [scene, "--out", cut, "--threads", "1", "--inject-fault",
                                    "sigterm:40"], capture_output=True, text=True, env=env)
    assert done.returncode == 143, (done.returncode, done.stderr)
    assert os.path.exists(os.path.join(cut, "checkpoint.rank1.bin"))
    # On another rank count each rank would continue another box: refused, naming the count.
    for other in ([mpm, "run"], [mpiexec, "-np", str(ranks + 1), "--oversubscribe", mpm, "run"]):
        done = subprocess.run(other + ["--restart", cut], capture_output=True, text=True, env=env)
        assert done.returncode == 2, (other, done.returncode, done.stderr)
        assert f"checkpoint.bin: written by a run on {ranks} rank(s)" in done.stderr, done.stderr
        assert f"mpirun -np {ranks} mpm run --restart" in done.stderr, done.stderr
    print(f"restart on 1 or {ranks + 1} ranks: refused, naming the run's {ranks}")
    run(launch + ["--restart", cut], env)
    for name in ["history.csv", "particles.pvd"] + [os.path.join("particles", n) for n in
                                                    sorted(os.listdir(os.path.join(many, "particles")))]:
        with open(os.path.join(many, name), "rb") as f, open(os.path.join(cut, name), "rb") as g:
            assert f.read() == g.read(), f"{name}: the restarted run differs"
    c = json.load(open(os.path.join(cut, "summary.json")))
    # Each phase's seconds per rank: one entry per rank, none negative, their sum within the
    # run's wall time (the phase clock runs inside the step loop).
    for d in (b, c):
        phases = d["phase_seconds [s]"]
        assert sorted(phases) == sorted(["particles_to_grid", "grid_update", "grid_to_particles",
                                         "remap", "stress"]), phases
        for r in range(ranks):
            spent = [phases[name][r] for name in phases]
            assert min(spent) >= 0 and sum(spent) <= d["wall_time [s]"], (r, phases)
    for k in ("wall_time [s]", "particle_steps_per_second", "peak_resident_memory [MB]",
              "available_memory [MB]"):
        b.pop(k, None)
        c.pop(k, None)
    for d in (b, c):  # timings and memory
        d.pop("phase_seconds [s]")
        d["ranks_load"].pop("seconds_in_mpi [s]")
        d["ranks_load"].pop("peak_resident_memory [MB]")
        # traffic counters of this process (checked against the cost model in halo_traffic)
        d["ranks_load"].pop("halo_bytes_sent_per_step [B]")
        d["ranks_load"].pop("halo_messages_sent_per_step")
    assert b == c, "summary.json of the restarted run differs"
    print(f"restart on {ranks} ranks: bit-identical")
    # A fault on one rank stops every rank: the last particle (seed index n - 1, at the far end
    # of the cylinder, on the last rank) gets a NaN stress in step 5.
    bad = os.path.join(work, "fault")
    done = subprocess.run(launch + [scene, "--out", bad, "--threads", "1", "--inject-fault",
                                    f"nan:5:{n - 1}"], capture_output=True, text=True, env=env)
    assert done.returncode == 3, (done.returncode, done.stderr)
    assert "step 5, time" in done.stderr, done.stderr
    assert f"rank {ranks - 1}, particle {n - 1} " in done.stderr, done.stderr
    status = json.load(open(os.path.join(bad, "status.json")))
    assert status["status"] == "failed" and status["step"] == 4, status
    print("a fault on one rank: every rank stopped, the message names rank, step and particle")
    paths_across_ranks(mpm, mpiexec, ranks, work, env)
    boxes_across_y_and_z(mpm, mpiexec, ranks, work, env, one)
    print("OK")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4])
