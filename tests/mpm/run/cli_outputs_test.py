#!/usr/bin/env python3
"""What `mpm run` and `mpm check` write, against numbers derived here from the scene.

  cli_outputs_test.py MPM WORK_DIR run|check|set|rerun|unfinished|fingerprint

run: the rigid translation (data/scenes/verification/rigid_translation.json: a 20 mm aluminium
  cube, 2 particles per cell per axis in 5 mm cells, at (30, -20, 10) m/s on a free grid) to
  2e-4 s with snapshots every 5e-5 s, 2 threads. history.csv: the ledger's 11 columns by name and
  unit, one row at t = 0, one at the first step at or after each interval (the step is below
  interval / 10 here) and one at max_time exactly; in every row the kinetic energy m v^2 / 2 =
  15.12 J and the momentum m v = (0.648, -0.432, 0.216) kg m/s (m = 2700 kg/m^3 x (0.02 m)^3 =
  0.0216 kg) to 1e-9 relative, the strain energy below 1e-9 J (the cube translates unstrained).
  particles.pvd: well-formed XML naming one snapshot per history row at the history's times; each
  .vtu read back (impact.results.vtu, its byte counts checked against NumberOfPoints) holds the
  8^3 = 512 particles, each at its seed position (sub-cell centres) plus v t to 1e-12 m and moving
  at v.
check: `mpm check` on Case 1 of the sphere-cylinder. Per object the particles are counted here by
  seeding the scene again (the sub-cell centres, 2 per cell per axis, inside the sphere or the
  closed hollow cylinder): the count must equal the report's, the particle volume count x cell
  volume / 8, the geometric volume the closed forms 4/3 pi r^3 and pi (R^2 - r_i^2) H +
  pi r_i^2 t_cap (to 1e-12), the mass 2700 kg/m^3 x particle volume, the volume ratio their
  quotient; and the sphere's particle volume lies between the volumes of the spheres of radius
  r -+ d, d = half the particle cell's diagonal (a particle's cell lies within d of its centre).
set: `mpm run --set '{"time": {"max_time": 1e-6}}'` on the rigid translation (2e-4 s in its
  file): the run stops at the patched time (the last history row and status.json at 1e-6 s; the
  scene.json written to the output directory carries the patch).
rerun: a second run into the directory of a first (the rigid translation with snapshots every
  5e-5 s, a checkpoint every 100 steps and a particle path; then 2e-6 s with snapshots every
  1e-6 s, no checkpoint, no path): every file under particles/ is one the new particles.pvd names,
  no checkpoint.bin and no paths/ of the first run is left, summary.json is the second run's, two
  files not written by mpm stay; stderr counts the removed files (those of the first run); stdout
  is one line whose steps, time, energy error and directory are those of status.json and
  summary.json.
unfinished: a run stopped by SIGTERM (injected at step 5, checkpoint written) is not replaced by
  a new run into its directory (exit 2 naming --restart and --overwrite; the checkpoint unchanged
  byte for byte); `--restart` continues it and removes a snapshot the checkpoint does not list
  (planted: step_999999.vtu) and nothing else; after a second SIGTERM, `--overwrite` starts over
  (no checkpoint left, every snapshot named by the .pvd).
exact: output.exact_displacement (--set) 1 m/s off the rigid translation's: history.csv ends in
  displacement_error_rms [m] and displacement_error_max [m], each t x 1 m/s in every row to 1e-9.
fingerprint: `mpm check --fingerprint` on the rigid translation prints 16 lowercase hex digits and
  a newline, nothing else on stdout, exit 0; the same with a --set of output keys only, another
  with a --set of the grid; it is the "scene_fingerprint" of `mpm check`'s report and of the
  summary.json of `mpm run` with the same --set (time.max_time 1e-6).
"""
import json
import math
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "python"))  # impact.results, without the compiled module
from impact.results import vtu  # noqa: E402

SCENES = os.path.join(ROOT, "data", "scenes")
RIGID = os.path.join(SCENES, "verification", "rigid_translation.json")
LEDGER = ["time [s]", "kinetic_energy [J]", "strain_energy [J]", "total_energy [J]",
          "momentum_x [kg m/s]", "momentum_y [kg m/s]", "momentum_z [kg m/s]",
          "boundary_impulse_x [N s]", "boundary_impulse_y [N s]", "boundary_impulse_z [N s]",
          "energy_error [-]"]
DENSITY = 2700.0  # data/materials/al6061_t6.json [kg/m^3]


def run_mpm(mpm, args):
    done = subprocess.run([mpm] + args, capture_output=True, text=True)
    assert done.returncode == 0, (args, done.returncode, done.stderr)
    return done.stdout


def history(out):
    with open(os.path.join(out, "history.csv")) as f:
        lines = f.read().splitlines()
    return lines[0].split(","), [[float(x) for x in line.split(",")] for line in lines[1:]]


def close(a, b, rel):
    return abs(a - b) <= rel * abs(b)


def check_run(mpm, work):
    out = os.path.join(work, "run")
    shutil.rmtree(out, ignore_errors=True)
    interval, max_time = 5e-5, 2e-4
    run_mpm(mpm, ["run", RIGID, "--out", out, "--threads", "2", "--set",
                  json.dumps({"output": {"snapshots": True, "interval": interval}})])
    header, rows = history(out)
    assert header == LEDGER, header
    assert len(rows) == 5, [r[0] for r in rows]
    m, v = DENSITY * 0.02 ** 3, np.array([30.0, -20.0, 10.0])
    for k, r in enumerate(rows):
        t = r[0]
        if k == 0:
            assert t == 0.0, r
        elif k == len(rows) - 1:
            assert t == max_time, r
        else:  # the first step at or after k intervals
            assert k * interval <= t < k * interval + interval / 10, (k, r)
        assert close(r[1], 0.5 * m * v @ v, 1e-9), (r, 0.5 * m * v @ v)
        assert abs(r[2]) < 1e-9, r
        for d in range(3):
            assert close(r[4 + d], m * v[d], 1e-9), (d, r, m * v)
    print(f"history.csv: {len(rows)} rows at {[r[0] for r in rows]} s, KE {rows[-1][1]} J")

    pvd = ET.parse(os.path.join(out, "particles.pvd")).getroot()
    datasets = pvd.findall("./Collection/DataSet")
    times = [float(d.get("timestep")) for d in datasets]
    assert times == [r[0] for r in rows], (times, rows)
    # The seed points: sub-cell centres of the 5 mm cells covering the cube [0.02, 0.04]^3.
    h = 0.06 / 12
    axis = 0.02 + h * (np.arange(8) // 2 + (np.arange(8) % 2 + 0.5) / 2)
    seeds = np.array(np.meshgrid(axis, axis, axis, indexing="ij")).reshape(3, -1).T
    seeds = seeds[np.lexsort((seeds[:, 2], seeds[:, 1], seeds[:, 0]))]
    for t, d in zip(times, datasets):
        path = os.path.join(out, d.get("file"))
        with open(path, "rb") as f:
            head = f.read().split(b"<AppendedData", 1)[0].decode()
        n = int(head.split('NumberOfPoints="', 1)[1].split('"', 1)[0])
        s = vtu.read_points(path)
        assert n == 512 and s["points"].shape == (512, 3), (path, n, s["points"].shape)
        assert s["velocity"].shape == (512, 3) and s["mass"].shape == (512,), path
        x = s["points"][np.lexsort((s["points"][:, 2], s["points"][:, 1], s["points"][:, 0]))]
        assert np.abs(x - (seeds + v * t)).max() < 1e-12, (path, np.abs(x - seeds - v * t).max())
        assert np.abs(s["velocity"] - v).max() < 1e-9 * 30, path
        assert close(s["mass"].sum(), m, 1e-12), (path, s["mass"].sum())
    print(f"particles.pvd: {len(times)} snapshots of 512 particles at seed + v t")


def seed_count(scene, obj, earlier):
    """Sub-cell centres of the grid inside `obj` and none of `earlier` (mpm/particles/seeding.cpp,
    mpm/geometry/geometry.cpp), counted with numpy."""
    g = scene["grid"]
    lower, upper, cells = (np.array(g[k], dtype=float) for k in ("lower", "upper", "cells"))
    h = (upper - lower) / cells
    ppc = obj["particles_per_cell"]
    axes = [lower[d] + h[d] * (np.arange(int(cells[d]) * ppc[d]) // ppc[d]
                               + (np.arange(int(cells[d]) * ppc[d]) % ppc[d] + 0.5) / ppc[d])
            for d in range(3)]
    x = np.stack(np.meshgrid(*axes, indexing="ij"), axis=-1).reshape(-1, 3)

    def inside(geo):
        if geo["type"] == "sphere":
            return ((x - np.array(geo["center"])) ** 2).sum(axis=1) <= geo["radius"] ** 2
        assert geo["type"] == "hollow_cylinder", geo
        b, top = np.array(geo["bottom"]), np.array(geo["top"])
        height = np.linalg.norm(top - b)
        e = (top - b) / height
        s = (x - b) @ e
        r = np.linalg.norm((x - b) - np.outer(s, e), axis=1)
        solid = (s >= 0) & (s <= height) & (r <= geo["radius"])
        return solid & ((r >= geo["radius"] - geo["thickness"]) | (s <= geo["cap_thickness"]))

    mask = inside(obj["geometry"])
    for o in earlier:
        mask &= ~inside(o["geometry"])
    return int(mask.sum()), h.prod() / np.prod(ppc), h


def check_check(mpm, work):
    case01 = os.path.join(SCENES, "sphere_cylinder", "case01.json")
    text = run_mpm(mpm, ["check", case01])
    report = json.loads(text)["report"]
    with open(case01) as f:
        scene = json.load(f)
    objects = sorted(scene["objects"].items())  # seeded in name order (docs/scenes.md)
    for i, (name, obj) in enumerate(objects):
        got = report["objects"][name]
        count, v0, h = seed_count(scene, obj, [o for _, o in objects[:i]])
        geo = obj["geometry"]
        if geo["type"] == "sphere":
            exact = 4.0 / 3.0 * math.pi * geo["radius"] ** 3
        else:
            ri = geo["radius"] - geo["thickness"]
            height = np.linalg.norm(np.array(geo["top"]) - np.array(geo["bottom"]))
            exact = (math.pi * (geo["radius"] ** 2 - ri ** 2) * height
                     + math.pi * ri ** 2 * geo["cap_thickness"])
        print(f"{name}: {got['particles']} particles ({count} counted here), particle volume "
              f"{got['particle_volume [m^3]']:.6e} m^3 ({count * v0:.6e}), geometric "
              f"{got['geometric_volume [m^3]']:.6e} m^3 ({exact:.6e}), ratio {got['volume_ratio']}")
        assert got["particles"] == count, (name, got, count)
        assert close(got["particle_volume [m^3]"], count * v0, 1e-12), (name, got, count * v0)
        assert close(got["geometric_volume [m^3]"], exact, 1e-12), (name, got, exact)
        assert close(got["mass [kg]"], DENSITY * count * v0, 1e-12), (name, got)
        assert close(got["geometric_mass [kg]"], DENSITY * exact, 1e-12), (name, got)
        assert close(got["volume_ratio"], count * v0 / exact, 1e-12), (name, got)
        if geo["type"] == "sphere":
            d = 0.5 * np.linalg.norm(h / np.array(obj["particles_per_cell"]))
            lo, hi = (4.0 / 3.0 * math.pi * (geo["radius"] + s * d) ** 3 for s in (-1, 1))
            print(f"  within [{lo:.4e}, {hi:.4e}] m^3 (radius -+ {d * 1e3:.3f} mm)")
            assert lo <= got["particle_volume [m^3]"] <= hi, (lo, hi, got)
    assert report["particles"] == sum(report["objects"][n]["particles"] for n, _ in objects)


def check_set(mpm, work):
    out = os.path.join(work, "set")
    shutil.rmtree(out, ignore_errors=True)
    run_mpm(mpm, ["run", RIGID, "--out", out, "--threads", "1", "--set",
                  json.dumps({"time": {"max_time": 1e-6}})])
    with open(RIGID) as f:
        assert json.load(f)["time"]["max_time"] == 2e-4  # the file's own, unlike the patch
    _, rows = history(out)
    with open(os.path.join(out, "status.json")) as f:
        status = json.load(f)
    with open(os.path.join(out, "scene.json")) as f:
        written = json.load(f)
    print(f"last history row at {rows[-1][0]} s after {status['step']} steps; status "
          f"{status['status']} at {status['time [s]']} s")
    assert rows[-1][0] == 1e-6 and status["time [s]"] == 1e-6, (rows[-1], status)
    assert status["status"] == "completed", status
    assert written["time"]["max_time"] == 1e-6, written["time"]


def check_exact(mpm, work):
    out = os.path.join(work, "exact")
    shutil.rmtree(out, ignore_errors=True)
    # The block's exact displacement is (30, -20, 10) m/s x t; the one given is 1 m/s off along x.
    run_mpm(mpm, ["run", RIGID, "--out", out, "--threads", "2", "--set",
                  json.dumps({"output": {"exact_displacement": ["31*t", "-20*t", "10*t"],
                                         "snapshots": False}})])
    header, rows = history(out)
    rms = header.index("displacement_error_rms [m]")
    top = header.index("displacement_error_max [m]")
    assert header[-2:] == ["displacement_error_rms [m]", "displacement_error_max [m]"], header
    for row in rows:
        t = row[0]
        assert abs(row[rms] - t) <= 1e-9 * max(t, 1e-12), (t, row[rms])
        assert abs(row[top] - t) <= 1e-9 * max(t, 1e-12), (t, row[top])
    print(f"{len(rows)} rows: displacement error {rows[-1][rms]} m at t = {rows[-1][0]} s")


def check_fingerprint(mpm, work):
    def fingerprint(*patches):
        sets = [a for p in patches for a in ("--set", json.dumps(p))]
        stdout = run_mpm(mpm, ["check", RIGID, "--fingerprint"] + sets)
        assert re.fullmatch(r"[0-9a-f]{16}\n", stdout), repr(stdout)
        return stdout.strip()

    short = {"time": {"max_time": 1e-6}}
    base = fingerprint(short)
    print(f"rigid translation to 1e-6 s: fingerprint {base}")
    assert fingerprint(short, {"output": {"snapshots": False, "directory": "x"}}) == base
    # the history interval sets the rows at which peaks are sampled: another fingerprint
    assert fingerprint(short, {"output": {"interval": 1e-7}}) != base
    assert fingerprint(short, {"grid": {"cells": [24, 24, 24]}}) != base
    assert fingerprint() != base  # max_time 2e-4: another run
    checked = json.loads(run_mpm(mpm, ["check", RIGID, "--set", json.dumps(short)]))
    assert sorted(checked) == ["refusal", "report", "resolved", "warnings"], sorted(checked)
    assert checked["report"]["scene_fingerprint"] == base, checked["report"]
    assert checked["refusal"] == "" and checked["warnings"] == [], checked
    out = os.path.join(work, "fingerprint")
    shutil.rmtree(out, ignore_errors=True)
    run_mpm(mpm, ["run", RIGID, "--out", out, "--threads", "1", "--set", json.dumps(short)])
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    assert summary["scene_fingerprint"] == base, summary["scene_fingerprint"]


def run_mpm_code(mpm, args):
    done = subprocess.run([mpm] + args, capture_output=True, text=True)
    return done.returncode, done.stdout, done.stderr


def snapshot_files(out):
    """The files under particles/ and the files particles.pvd names."""
    on_disk = sorted(os.listdir(os.path.join(out, "particles")))
    pvd = ET.parse(os.path.join(out, "particles.pvd")).getroot()
    named = sorted(os.path.basename(d.get("file")) for d in pvd.findall("./Collection/DataSet"))
    return on_disk, named


def check_rerun(mpm, work):
    out = os.path.join(work, "rerun")
    shutil.rmtree(out, ignore_errors=True)
    first = {"output": {"snapshots": True, "interval": 5e-5, "checkpoint_interval_steps": 100,
                        "particle_paths": {"corner": {"object": "block",
                                                      "position": [0.02, 0.02, 0.02]}}}}
    run_mpm(mpm, ["run", RIGID, "--out", out, "--threads", "1", "--set", json.dumps(first)])
    before, _ = snapshot_files(out)
    owned = len(before) + len(os.listdir(os.path.join(out, "paths")))
    owned += sum(os.path.exists(os.path.join(out, f)) for f in (
        "history.csv", "summary.json", "status.json", "scene.json", "particles.pvd",
        "checkpoint.bin"))
    assert os.path.exists(os.path.join(out, "checkpoint.bin")), os.listdir(out)
    for foreign in ("notes.txt", os.path.join("particles", "README")):
        with open(os.path.join(out, foreign), "w") as f:
            f.write("not written by mpm\n")
    second = {"time": {"max_time": 2e-6}, "output": {"snapshots": True, "interval": 1e-6}}
    code, stdout, stderr = run_mpm_code(
        mpm, ["run", RIGID, "--out", out, "--threads", "1", "--set", json.dumps(second)])
    assert code == 0, (code, stderr)
    print(f"first run: {len(before)} snapshots, {owned} files; second run stderr: {stderr.strip()}")
    on_disk, named = snapshot_files(out)
    assert on_disk == sorted(named + ["README"]), (on_disk, named)
    assert len(named) == 3, named  # t = 0, 1e-6, 2e-6 s
    assert not os.path.exists(os.path.join(out, "checkpoint.bin"))
    assert not os.path.exists(os.path.join(out, "paths"))
    assert os.path.exists(os.path.join(out, "notes.txt"))
    assert f"mpm: replacing the previous run in {out} ({owned} file(s) removed)" in stderr, stderr
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    with open(os.path.join(out, "status.json")) as f:
        status = json.load(f)
    assert summary["time [s]"] == 2e-6 and summary["steps"] == status["step"], summary
    line = stdout.strip()
    print(f"stdout: {line}")
    assert "\n" not in line, stdout
    m = re.fullmatch(r"mpm run: completed (\d+) steps to t = (\S+) s in (\S+) s wall, "
                     r"energy_error (\S+); results in (.+) \(summary.json, history.csv, "
                     r"particles.pvd\)", line)
    assert m, line
    assert int(m.group(1)) == status["step"], (m.group(1), status)
    assert close(float(m.group(2)), 2e-6, 1e-3), m.group(2)
    assert close(float(m.group(3)), status["wall_time [s]"], 1e-3), (m.group(3), status)
    error = summary["final"]["energy_error [-]"]
    assert abs(float(m.group(4)) - error) <= 1e-3 * abs(error) + 1e-300, (m.group(4), error)
    assert m.group(5) == out, m.group(5)
    # A directory that never held a run (no status.json of mpm's): the user's files there stay,
    # even one named like a run's file.
    mine = os.path.join(work, "mine")
    shutil.rmtree(mine, ignore_errors=True)
    os.makedirs(mine)
    with open(os.path.join(mine, "particles.pvd"), "w") as f:  # a run without snapshots
        f.write("my notes\n")                                       # writes no particles.pvd
    code, _, stderr = run_mpm_code(mpm, ["run", RIGID, "--out", mine, "--threads", "1", "--set",
                                         json.dumps({"time": {"max_time": 1e-6}})])
    assert code == 0, (code, stderr)
    assert "replacing the previous run" not in stderr, stderr
    with open(os.path.join(mine, "particles.pvd")) as f:
        assert f.read() == "my notes\n"


def check_unfinished(mpm, work):
    out = os.path.join(work, "unfinished")
    shutil.rmtree(out, ignore_errors=True)
    snapshots = ["--set", json.dumps({"output": {"snapshots": True, "interval": 1e-6}})]
    stop = ["run", RIGID, "--out", out, "--threads", "1", "--inject-fault", "sigterm:5"] + snapshots
    code, _, stderr = run_mpm_code(mpm, stop)
    assert code == 143, (code, stderr)
    checkpoint = os.path.join(out, "checkpoint.bin")
    with open(checkpoint, "rb") as f:
        saved = f.read()
    code, _, stderr = run_mpm_code(mpm, ["run", RIGID, "--out", out, "--threads", "1"] + snapshots)
    print(f"new run over an interrupted one: exit {code}: {stderr.strip()}")
    assert code == 2, (code, stderr)
    assert (f"{checkpoint}: the checkpoint of a run that has not finished (status.json: "
            f"\"interrupted\", checkpoint at step 5): continue it with 'mpm run --restart {out}', "
            f"or start a new run over it with --overwrite") in stderr, stderr
    with open(checkpoint, "rb") as f:
        assert f.read() == saved
    # A status.json cut short (a kill while it was written) is named so: "missing" before.
    status_file = os.path.join(out, "status.json")
    with open(status_file) as f:
        status_text = f.read()
    with open(status_file, "w") as f:
        f.write(status_text[:len(status_text) // 2])
    code, _, stderr = run_mpm_code(mpm, ["run", RIGID, "--out", out, "--threads", "1"] + snapshots)
    assert code == 2, (code, stderr)
    assert (f"{checkpoint}: the checkpoint of a run that has not finished (status.json: not JSON "
            f"(cut short?)): continue it") in stderr, stderr
    with open(status_file, "w") as f:
        f.write(status_text)
    planted = os.path.join(out, "particles", "step_999999.vtu")
    shutil.copy(os.path.join(out, "particles", "step_000000.vtu"), planted)
    kept, _ = snapshot_files(out)
    code, _, stderr = run_mpm_code(mpm, ["run", "--restart", out])
    assert code == 0, (code, stderr)
    on_disk, named = snapshot_files(out)
    print(f"restart: {len(kept)} snapshot files before (one planted), {len(on_disk)} after, "
          f"{len(named)} named by the .pvd")
    assert not os.path.exists(planted)
    assert on_disk == named, (on_disk, named)
    assert set(kept) - {"step_999999.vtu"} <= set(on_disk), (kept, on_disk)
    code, _, stderr = run_mpm_code(mpm, stop)  # over a completed run: no refusal
    assert code == 143, (code, stderr)
    code, stdout, stderr = run_mpm_code(mpm, ["run", RIGID, "--out", out, "--threads", "1",
                                              "--overwrite"] + snapshots)
    assert code == 0, (code, stderr)
    assert not os.path.exists(checkpoint)
    on_disk, named = snapshot_files(out)
    assert on_disk == named, (on_disk, named)
    assert stdout.startswith("mpm run: completed "), stdout


if __name__ == "__main__":
    mpm_program, work_dir, what = sys.argv[1:4]
    os.makedirs(work_dir, exist_ok=True)
    {"run": check_run, "check": check_check, "set": check_set, "rerun": check_rerun,
     "unfinished": check_unfinished, "fingerprint": check_fingerprint,
     "exact": check_exact}[what](mpm_program, work_dir)
    print("OK")
