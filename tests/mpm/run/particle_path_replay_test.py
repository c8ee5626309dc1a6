#!/usr/bin/env python3
"""A particle's path written by `mpm run` (output.particle_paths) replayed by `pointdriver run`
gives the particle's own stress history (docs/scenes.md: a law's behaviour inside an impact can be
unit-tested along its real path).

  particle_path_replay_test.py MPM POINTDRIVER SOURCE_DIR WORK_DIR

The scene: the Taylor rod of data/scenes/verification/taylor_rod.json (House H8, 328 m/s), failure
off, F advanced by exp(L dt) (solver.deformation_gradient = exponential, the driver's update), with
two recorded particles: on the axis at the impact face (plastic strain 1.4, 557 K) and at the rim
of the impact face. Asserted, at every one of the ~690 steps: each stress component of the replay
within 1e-9 of the largest stress magnitude of the MPM history (measured 1.5e-12), and the final
plastic strain to 1e-9 relative. The two run the same ElasticPlastic::update with the same L, dt
and start temperature; anything more than round-off means the path lost information (a rotation,
a temperature, a step).
"""
import csv
import json
import os
import subprocess
import sys

COMPONENTS = ["stress_xx [Pa]", "stress_yy [Pa]", "stress_zz [Pa]", "stress_xy [Pa]",
              "stress_yz [Pa]", "stress_zx [Pa]"]


def main(mpm, pointdriver, source, work):
    os.makedirs(work, exist_ok=True)
    with open(os.path.join(source, "data/scenes/verification/taylor_rod.json")) as f:
        scene = json.load(f)
    scene["materials"]["al"]["file"] = os.path.join(source, "data/materials/al6061_t6.json")
    scene["physics"]["erosion"] = "none"
    scene["solver"] = {"deformation_gradient": "exponential"}
    scene["output"]["particle_paths"] = {
        "face_axis": {"object": "rod", "position": [0.3e-3, 0.3e-3, 0.3e-3]},
        "face_rim": {"object": "rod", "position": [0.3e-3, 3.5e-3, 0.5e-3]}}
    scene_file = os.path.join(work, "scene.json")
    with open(scene_file, "w") as f:
        json.dump(scene, f)
    out = os.path.join(work, "run")
    subprocess.run([mpm, "run", scene_file, "--out", out, "--threads", "1"], check=True,
                   stdout=subprocess.DEVNULL)
    failures = []
    for name in ["face_axis", "face_rim"]:
        paths = os.path.join(out, "paths")
        replay = os.path.join(paths, name + "_replay.csv")
        subprocess.run([pointdriver, "run", os.path.join(paths, name + ".json"), "-o", replay],
                       check=True, stdout=subprocess.DEVNULL)
        with open(os.path.join(paths, name + ".csv")) as f:
            mpm_rows = list(csv.DictReader(f))
        with open(replay) as f:
            driver_rows = list(csv.DictReader(f))[1:]  # row 0 is the initial state
        if len(mpm_rows) != len(driver_rows) or len(mpm_rows) < 100:
            failures.append(f"{name}: {len(mpm_rows)} MPM steps, {len(driver_rows)} replayed")
            continue
        scale = max(abs(float(r[c])) for r in mpm_rows for c in COMPONENTS)
        worst = max(abs(float(a[c]) - float(b[c])) / scale
                    for a, b in zip(mpm_rows, driver_rows) for c in COMPONENTS)
        ep_mpm = float(mpm_rows[-1]["plastic_strain [-]"])
        ep_drv = float(driver_rows[-1]["plastic_strain [-]"])
        print(f"{name}: {len(mpm_rows)} steps, worst stress difference {worst:.2e} of "
              f"{scale:.3e} Pa, plastic strain {ep_mpm:.6f} (MPM) {ep_drv:.6f} (replay)")
        if not worst < 1e-9:
            failures.append(f"{name}: stress differs by {worst:.2e} of the largest stress")
        if not ep_mpm > 0.1:
            failures.append(f"{name}: plastic strain {ep_mpm}: the path should be plastic")
        if not abs(ep_drv / ep_mpm - 1.0) < 1e-9:
            failures.append(f"{name}: plastic strain {ep_drv} replayed, {ep_mpm} in the MPM run")
    for f in failures:
        print("FAILED:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:5]))
