#!/usr/bin/env python3
"""Taylor impact of 6061-T6 rods (House et al. 1995): predicted shapes against the experiments.

  python3 campaigns/taylor/taylor.py OUT [--sets table1,fit_all] [--failure off]
                              [--cells-per-radius 4] [--shots H1,H8] [--anvil mirror]
                              [--geometry 3d] [--data CSV] [--jobs J] [--threads T]
                              [--mpm build/bin/mpm] [--pointdriver build/bin/pointdriver]

For every parameter set x failure mode x resolution x shot it generates a scene (the rod along x,
its impact face on the x- face of the grid, the anvil), runs `mpm run`, and measures on the last
snapshot. The grid reaches 2.2 R0 from the axis; where the mushroom's material reaches that outer
face (mpm's summary.json "material_reached_faces"), the shot is run again with the grid 1.5 times
wider, up to three times (7.4 R0): results.csv records the extent used
(`radial_extent_over_R0 [-]`), the faces the last attempt's material still reached
(`material_reached_faces`, empty: none) and the attempts before (`confined_attempts`); stderr
says so for each. Geometry (--geometry, one per OUT):
  3d            a quarter model: mirror planes y = 0 and z = 0 (the default);
  axisymmetric  the r-z section on a 2D grid (docs/scenes.md#2d-grids): x the axis, y the radius,
                the grid's y- face the axis; every particle a ring, 2 x 2 per cell.
The measures:
  Lf  final length: the largest particle x plus the distance by which the outermost seeded particle
      lay inside the rod's end at t = 0 (seed_offsets: the measure is exact at t = 0);
  Dm  mushroom diameter: twice the largest radius of the particles within 0.5 mm of the anvil, plus
      the radial seed offset likewise;
  Xf  undeformed length: Lf minus the axial position where the cross-section mean plastic strain
      falls below 0.2 % (Taylor 1948's X; reported, never judged);
  the deformed profile (radius against axial position, per particle-spacing bin), the energy books
  (history.csv), failed particles per cause and in the compressed core (initial radius <= R0/2).
  A rod that bounced off a `wall` or `rigid` anvil is measured from its impact face (face_lift: how far its
  lowest particle rose above its lowest position over the run).
Anvil (--anvil, one per OUT):
  mirror   the symmetric x- face: rigid and frictionless, and it holds the rod in tension too;
  wall:MU  a rigid wall that never pulls, with Coulomb friction MU (docs/scenes.md#grid);
  wall_particles:MU  the same wall met at the rod's particles, by the penalty against its plane
           (grid.wall_contact "particles", docs/scenes.md#grid);
  rigid:MU a rigid body at rest, two cells thick, below x = 0 (objects.anvil.rigid,
           docs/scenes.md#rigid-objects), met through multi-field contact with Coulomb friction MU
           (the normal is the anvil's own face);
  rigid_particles  the same body met at the rod's particles, frictionless
           (physics.contact.rigid_contact "particles", docs/scenes.md#rigid-objects).

Parameter sets (calibration kept apart from validation: none is tuned to a Taylor shot):
  table1   data/materials/al6061_t6.json as shipped (the report's Table 1 Johnson-Cook set);
  fit_all  `pointdriver fit data/fits/al6061_t6_all.json` run first, here, from the stress-strain
           curves alone (docs/fitting.md); its material file is what the scenes use;
  fit_room `pointdriver fit data/fits/al6061_t6_room_temperature.json`, likewise;
  scg      data/materials/al6061_t6_scg.json as shipped (Steinberg's 1996 SCG set and EOS, unfitted);
  fit_za   `pointdriver fit data/fits/al6061_t6_za_all.json`: Zerilli-Armstrong (fcc) fitted to
           fit_all's curves;
  fit_ptw  `pointdriver fit data/fits/al6061_t6_ptw_all.json`: Preston-Tonks-Wallace, likewise.
Failure modes:
  off                erosion none: no failure detection (physics.erosion = none);
  shipped            the material file's failure stack (JC damage, TEPLA, Drucker-Becker, erosion);
  compression_aware  shipped plus the opt-in choices of docs/models.md (failure causes and failure
                     in compression): damage.cutoff_triaxiality = -1/3, tepla.porosity_growth =
                     tension, stability_check.outcome = report with drucker_steps = loading.

Shots (--data CSV, default data/experiments/taylor/house1995.csv): one row per shot in that file's
columns, `shot`, `D0 [m]`, `L0 [m]`, `U0 [m/s]`, `T0 [K]` required (`L0_over_D0 [-]` from them if
absent), the measurements `Lf [m]`, `Dm [m]`, `Xf [m]` optional: one left empty is reported (the
prediction is printed) and not judged (no error, not in the error statistics).

A run whose directory holds the result of the same scene and material file content (result.json,
written when it finished) is not run again: a campaign stopped part-way resumes where it was, and
a ladder can be extended one level at a time into the same OUT.

Writes OUT/results.csv (one row per run, SI units), OUT/results.md (errors per set, shot table,
resolution ladder), OUT/profiles/*.csv and the figures OUT/lf_dm_vs_speed.png,
OUT/profiles.png, OUT/failure_causes_<set>_<failure>.png, OUT/ladder.png (with more than one
resolution). Runs go to --runs DIR (default OUT/runs/; history every 1/40 of the run; only the
last snapshot is kept).
"""

import argparse
import concurrent.futures
import csv
import hashlib
import json
import math
import os
import subprocess
import sys
import time

# impact.results (python/, or share/impact/python of an install) runs mpm and reads the runs; it
# imports NumPy only where a snapshot is read, so that --help, the usage errors and the table of
# shots need the standard library only.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
from impact import results  # noqa: E402

REPO = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
DATA = os.path.join(REPO, "data", "experiments", "taylor", "house1995.csv")
MATERIAL = os.path.join(REPO, "data", "materials", "al6061_t6.json")
PUBLISHED = {"table1": MATERIAL,
             "scg": os.path.join(REPO, "data", "materials", "al6061_t6_scg.json")}
FITS = {"fit_all": "data/fits/al6061_t6_all.json",
        "fit_room": "data/fits/al6061_t6_room_temperature.json",
        "fit_za": "data/fits/al6061_t6_za_all.json",
        "fit_ptw": "data/fits/al6061_t6_ptw_all.json"}
COMPRESSION_AWARE = {"constitutive_model": {
    "damage": {"cutoff_triaxiality": -1.0 / 3.0},
    "tepla": {"porosity_growth": "tension"},
    "stability_check": {"outcome": "report", "drucker_steps": "loading"}}}
PPC = 2                 # particles per cell per axis
GEOMETRIES = ("3d", "axisymmetric")
MEASURED = ("Lf", "Dm", "Xf")
JUDGED = ("Lf", "Dm")   # Xf is reported, never judged (docs/taylor.md): no error is computed
ANVIL_LAYER = 0.5e-3    # Dm from the particles within this distance of the anvil [m]
PLASTIC_EDGE = 2e-3     # Xf: the cross-section mean plastic strain below which a section is undeformed
CAUSES = ["none", "melting", "tepla", "drucker", "becker"]
# The grid's radial extent from the rod's axis [R0]: House's widest mushroom (H3, Dm/D0 = 1.69)
# leaves 2-3 cells to the face; a mushroom that reaches the face (a faster shot) is run again on
# a grid ENLARGEMENT times wider, at most MAX_ENLARGEMENTS times (docs/taylor.md).
RADIAL_EXTENT = 2.2
ENLARGEMENT = 1.5
MAX_ENLARGEMENTS = 3


class InputError(Exception):
    """A table of shots that cannot be read: the message names the file, row and column (exit 2)."""


def read_shots(path=DATA):
    """The shots of a table in the columns of house1995.csv. The measurements Lf, Dm, Xf may be
    left empty (or the column left out): None, reported and not judged. Anything else missing or
    not a positive number raises InputError with the file, row and column."""
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
    except (OSError, UnicodeDecodeError, csv.Error) as e:
        raise InputError(f"taylor: {path}: cannot read the table of shots: "
                         f"{getattr(e, 'strerror', None) or e}")

    def number(r, row, column, required):
        text = (r.get(column) or "").strip()
        if not text and not required:
            return None
        try:
            value = float(text)
        except ValueError:
            value = float("nan")
        if not (math.isfinite(value) and value > 0.0):
            what = "a number > 0" + ("" if required else " or empty (not measured)")
            raise InputError(f"taylor: {path}: row {row} ({r.get('shot') or '?'}), column "
                             f"'{column}': '{text}' is not {what}")
        return value

    shots, names = [], set()
    for row, r in enumerate(rows, start=2):  # row 1 is the header
        name = (r.get("shot") or "").strip()
        if not name or name in names:
            raise InputError(f"taylor: {path}: row {row}: the column 'shot' needs a name, unique "
                             f"in the file (got '{name}')")
        names.add(name)
        shot = {"shot": name, "D0": number(r, row, "D0 [m]", True),
                "L0": number(r, row, "L0 [m]", True), "U0": number(r, row, "U0 [m/s]", True),
                "T0": number(r, row, "T0 [K]", True)}
        aspect = number(r, row, "L0_over_D0 [-]", False)
        shot["aspect"] = aspect if aspect is not None else shot["L0"] / shot["D0"]
        for key in MEASURED:
            shot[key] = number(r, row, f"{key} [m]", False)
        shots.append(shot)
    if not shots:
        raise InputError(f"taylor: {path}: no shots")
    return shots


def end_time(shot):
    """Long enough for the rod to come to rest: the plastic front stops within about 0.4 L0/U0
    (docs/taylor.md); 0.8 L0/U0 + 20 us leaves the ringing to settle."""
    return 0.8 * shot["L0"] / shot["U0"] + 20e-6


def parse_anvil(text):
    """'mirror' (the symmetric x- face: frictionless, and it holds the rod in tension),
    'wall[:MU]' (a rigid wall that never pulls, Coulomb friction MU, default 0),
    'wall_particles[:MU]' (that wall met at the rod's particles), 'rigid[:MU]' (a rigid body at
    rest in contact, likewise) or 'rigid_particles' (that body met at the rod's particles,
    frictionless): (kind, mu)."""
    kind, _, mu = text.partition(":")
    if kind in ("mirror", "rigid_particles") and not mu:
        return kind, 0.0
    if kind in ("wall", "wall_particles", "rigid"):
        try:
            value = float(mu) if mu else 0.0
        except ValueError:
            value = -1.0
        if 0.0 <= value <= 10.0:
            return kind, value
    sys.exit(f"taylor: --anvil: '{text}': expected mirror, wall, wall:MU, wall_particles, "
             "wall_particles:MU, rigid, rigid:MU with MU in [0, 10], or rigid_particles")


def scene(shot, material_file, failure, cells_per_radius, anvil=("mirror", 0.0), geometry="3d",
          radial=None):
    """The shot's scene (module docstring), its grid `radial` R0 from the axis (default
    RADIAL_EXTENT; run_one enlarges it when the mushroom reaches the face)."""
    R0 = 0.5 * shot["D0"]
    dx = R0 / cells_per_radius
    ny = math.ceil((RADIAL_EXTENT if radial is None else radial) * R0 / dx)
    overrides = {}
    if failure == "compression_aware":
        overrides = COMPRESSION_AWARE
    objects = {"rod": {"material": "al",
                       "geometry": {"type": "cylinder", "bottom": [0.0, 0.0, 0.0],
                                    "top": [shot["L0"], 0.0, 0.0], "radius": R0},
                       "velocity": [-shot["U0"], 0.0, 0.0], "temperature": shot["T0"],
                       "particles_per_cell": [PPC, PPC, PPC]}}
    planar = geometry == "axisymmetric"
    if planar:
        objects["rod"]["particles_per_cell"] = [PPC, PPC]
    materials = {"al": {"file": material_file, "overrides": overrides}}
    physics = {"artificial_viscosity": {"enabled": True}}
    if failure == "off":
        physics["erosion"] = "none"
    nx = math.ceil(shot["L0"] / dx) + 1
    t_end = end_time(shot)
    boundary = {"x-": "symmetric", "x+": "symmetric",
                "y-": "symmetric", "y+": "symmetric", "z-": "symmetric", "z+": "symmetric"}
    grid = {"lower": [0.0, 0.0, 0.0], "upper": [nx * dx, ny * dx, ny * dx],
            "cells": [nx, ny, ny], "boundary": boundary}
    if planar:
        # The r-z section: the y- face is the axis (symmetric, v_r = 0), no z faces.
        del boundary["z-"], boundary["z+"]
        grid = {"geometry": "axisymmetric", "lower": [0.0, 0.0], "upper": [nx * dx, ny * dx],
                "cells": [nx, ny], "boundary": boundary}
    if anvil[0] in ("wall", "wall_particles"):
        boundary["x-"] = "wall"
        grid["wall_friction"] = {"x-": anvil[1]}
        if anvil[0] == "wall_particles":
            grid["wall_contact"] = "particles"
    if anvil[0] in ("rigid", "rigid_particles"):
        # Two cells of rigid anvil below the impact face x = 0, as wide as the grid; its own
        # material (the density its contact normals read), multi-field contact with the rod.
        grid["lower"][0] = -2.0 * dx
        grid["cells"][0] = nx + 2
        boundary["x-"] = "free"
        materials["anvil"] = {"file": material_file}
        objects["anvil"] = {"material": "anvil", "rigid": True,
                            "geometry": {"type": "cylinder", "bottom": [-2.0 * dx, 0.0, 0.0],
                                         "top": [0.0, 0.0, 0.0],
                                         # the grid's radial extent; the quarter's corner too
                                         "radius": ny * dx * (1.0 if planar else 2 ** 0.5)},
                            "particles_per_cell": list(objects["rod"]["particles_per_cell"])}
        physics["contact"] = {"type": "friction", "mu": anvil[1]}
        if anvil[0] == "rigid_particles":
            physics["contact"]["rigid_contact"] = "particles"
    return {
        "description": f"Taylor impact, House et al. (1995) shot {shot['shot']}: "
                       f"{'axisymmetric model' if planar else 'quarter model'}, "
                       f"{cells_per_radius} cells per radius, failure {failure}",
        "materials": materials, "objects": objects,
        "grid": grid,
        "time": {"max_time": t_end, "multiplier": 0.5},
        "physics": physics,
        "output": {"interval": t_end / 40.0, "fields": ["plastic_strain", "temperature", "damage",
                                                  "failed", "failure_cause", "failed_in_tension",
                                                  "instability",
                                                  "object"]},
    }


def seed_offsets(shot, cells_per_radius, geometry="3d"):
    """How far inside the true rod the outermost seeded particles lie at t = 0 (axially, L0 minus
    the largest particle x; radially, R0 minus the largest particle radius): sub-cell centres
    (i + 1/2) h inside the cylinder, as mpm seeds them (docs/scenes.md). Adding these to the
    final extreme particles makes the measures exact at t = 0 (raw h/2 would read a 6-cells-per-
    radius rod 3 % too thick and a short rod up to 2 % too long). In the quarter model the rim is
    the farthest centre (y, z) of the staircase; in the r-z section the particles sit at z = 0,
    so it is the largest centre y <= R0 (R0 - h/2: R0 is a whole number of spacings)."""
    R0 = 0.5 * shot["D0"]
    h = R0 / cells_per_radius / PPC
    top = (math.floor(shot["L0"] / h - 0.5) + 0.5) * h
    centres = [(i + 0.5) * h for i in range(int(R0 / h) + 1)]
    if geometry == "axisymmetric":
        rim = max(a for a in centres if a <= R0)
    else:
        rim = max(math.hypot(a, b) for a in centres for b in centres if math.hypot(a, b) <= R0)
    return shot["L0"] - top, R0 - rim


def measure(x, plastic_strain, shot, cells_per_radius, face_lift=0.0, geometry="3d"):
    """Lf, Dm, Xf and the profile [(x, radius, mean plastic strain)] from final positions x, with
    the impact face `face_lift` above the anvil (a rod that bounced off a `wall` anvil). The
    radius is sqrt(y^2 + z^2) in the quarter model, y in the r-z section (z = 0 there)."""
    R0 = 0.5 * shot["D0"]
    h = R0 / cells_per_radius / PPC  # particle spacing
    axial, radial = seed_offsets(shot, cells_per_radius, geometry)
    x = x - [face_lift, 0.0, 0.0]
    r = x[:, 1] if geometry == "axisymmetric" else (x[:, 1] ** 2 + x[:, 2] ** 2) ** 0.5
    Lf = x[:, 0].max() + axial
    near = x[:, 0] < ANVIL_LAYER
    Dm = 2.0 * (r[near].max() + radial)
    nbins = max(1, int(math.ceil(Lf / h)))
    profile, edge = [], 0.0
    for b in range(nbins):
        inside = (x[:, 0] >= b * h) & (x[:, 0] < (b + 1) * h)
        if not inside.any():
            continue
        mean_ep = float(plastic_strain[inside].mean())
        profile.append(((b + 0.5) * h, r[inside].max() + radial, mean_ep))
        if mean_ep >= PLASTIC_EDGE:
            edge = (b + 1) * h
    # The last plastic bin's upper edge lies up to one bin beyond the rear end when the whole
    # rod yielded: the undeformed length is then 0, not a negative length.
    return Lf, Dm, Lf - min(edge, Lf), profile


def extract(run_dir, shot, cells_per_radius, geometry="3d"):
    """(Lf, Dm, Xf and the failure counts, the profile, the outer faces material reached) of a
    finished run (module docstring)."""
    snaps = results.snapshots(run_dir)
    first, last = results.read_points(snaps[0][1]), results.read_points(snaps[-1][1])
    # The rod's object index: the scene's objects in name order (an `anvil` before it).
    with open(f"{run_dir}/scene.json") as f:
        names = sorted(json.load(f)["objects"])
    rod0 = first["object"] == names.index("rod")
    X0, x = first["points"][rod0], last["points"][rod0]
    R0 = 0.5 * shot["D0"]
    with open(f"{run_dir}/scene.json") as f:
        as_run = json.load(f)
    wall = (as_run["grid"]["boundary"]["x-"] == "wall" or
            as_run["objects"].get("anvil", {}).get("rigid", False))
    # A wall or rigid anvil lets the rod bounce off (~10 m/s): the measures take its face where it was
    # while it touched, i.e. the rod's lowest particle at its lowest over the snapshots. The
    # mirror holds the face on the anvil (no lift).
    face_lift = 0.0
    if wall:
        lowest = min(results.read_points(f)["points"][rod0][:, 0].min() for _, f in snaps)
        face_lift = float(x[:, 0].min() - lowest)
    Lf, Dm, Xf, profile = measure(x, last["plastic_strain"][rod0], shot, cells_per_radius,
                                  face_lift, geometry)
    failed = last["failed"][rod0] > 0.5
    core = (X0[:, 1] ** 2 + X0[:, 2] ** 2) ** 0.5 <= 0.5 * R0
    causes = last["failure_cause"][rod0]
    with open(f"{run_dir}/summary.json") as f:
        summary = json.load(f)
    reached = summary.get("material_reached_faces") or []  # absent: no face reached
    header, rows = results.history_rows(run_dir)
    hist = [dict(zip(header, r)) for r in rows]
    e0 = float(hist[0]["total_energy [J]"])
    # At rest: the first history row with the kinetic energy below 3 % of the impact energy (what is left is elastic ringing).
    rest = next((float(h["time [s]"]) for h in hist if float(h["kinetic_energy [J]"]) < 0.03 * e0),
                float("nan"))
    out = {"Lf [m]": Lf, "Dm [m]": Dm, "Xf [m]": Xf, "face_lift [m]": face_lift,
           "particles": int(rod0.sum()), "failed": int(failed.sum()),
           "failed_core": int((failed & core).sum()), "core": int(core.sum()),
           "failed_core_under_pressure": int(
               (failed & core & (last["failed_in_tension"][rod0] < 0.5)).sum()),
           "reported_unstable": int((last["instability"][rod0] > 0).sum()),
           "kinetic_end_over_E0 [-]": float(hist[-1]["kinetic_energy [J]"]) / e0,
           "time_to_rest [s]": rest, "end_time [s]": float(hist[-1]["time [s]"]),
           "viscous_work_over_E0 [-]": float(hist[-1].get("viscous_work [J]", 0.0)) / e0,
           "friction_heat_over_E0 [-]": float(hist[-1].get("friction_heat [J]", 0.0)) / e0,
           "energy_error [-]": float(hist[-1]["energy_error [-]"]),
           "steps": summary["steps"], "wall_time [s]": summary["wall_time [s]"]}
    for i, c in enumerate(CAUSES[1:], start=1):
        out[f"failed_{c}"] = int((failed & (causes == i)).sum())
    return out, profile, reached


def material_digest(material):
    """SHA-256 of the material file's text: the scene names the file, and a re-fit rewrites it
    in place, so the content is part of what a finished run was a run of."""
    with open(material, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def finished(run_dir, the_scene, digest):
    """The row and profile of a run of this very scene and material that finished before
    (result.json), or None: a stopped campaign resumes, and a finished run is not repeated."""
    try:
        with open(os.path.join(run_dir, "result.json")) as f:
            done = json.load(f)
    except (OSError, ValueError):
        return None
    same = done.get("scene") == the_scene and done.get("material_sha256") == digest
    return done if same else None


def reached_text(reached):
    """'y+ (symmetric) at 21.3 us, 40 particles; ...' of summary.json "material_reached_faces",
    or '' when no material reached an outer face it did not start near."""
    return "; ".join(f"{f.get('face', '?')} ({f.get('condition', '?')}) at "
                     f"{1e6 * f.get('first_time [s]', float('nan')):.1f} us, "
                     f"{f.get('particles', '?')} particles" for f in reached)


def radial_faces(reached):
    """The faces of `reached` a larger radial extent moves away: y+ and z+ (the x faces are the
    anvil and the rear, which the rod only leaves)."""
    return [f for f in reached if f.get("face") in ("y+", "z+")]


def run_attempt(job, run_dir, radial):
    """One run of the job's shot with the grid `radial` R0 from the axis, or its result from an
    earlier invocation (result.json of this very scene and material): (row, profile, reached),
    profile None when mpm failed; reached is summary.json's "material_reached_faces" (absent:
    none)."""
    shot, set_name, material, failure, n, out_dir, runs_dir, mpm, threads, anvil, geometry = job
    tag = f"{set_name}_{failure}_n{n}"
    os.makedirs(run_dir, exist_ok=True)
    the_scene = scene(shot, material, failure, n, anvil, geometry, radial)
    digest = material_digest(material)
    done = finished(run_dir, the_scene, digest)
    if done is not None:
        print(f"taylor: {tag} {shot['shot']}: done before ({run_dir}/result.json)", flush=True)
        return done["row"], [tuple(p) for p in done["profile"]], done.get("reached", [])
    scene_file = os.path.join(run_dir, "scene_in.json")
    with open(scene_file, "w") as f:
        json.dump(the_scene, f, indent=1)
    start = time.time()
    proc = results.Launcher(mpm).run("run", scene_file, out=run_dir, threads=threads, check=False)
    row = {"set": set_name, "failure": failure, "cells_per_radius": n,
           "anvil": anvil[0] if anvil[0] == "mirror" else f"{anvil[0]}:{anvil[1]:g}",
           "geometry": geometry, "shot": shot["shot"],
           "L0_over_D0 [-]": shot["aspect"], "U0 [m/s]": shot["U0"], "L0 [m]": shot["L0"],
           "D0 [m]": shot["D0"], "Lf_exp [m]": shot["Lf"], "Dm_exp [m]": shot["Dm"],
           "Xf_exp [m]": shot["Xf"], "exit_code": proc.returncode,
           "elapsed [s]": time.time() - start, "radial_extent_over_R0 [-]": radial}
    if proc.returncode != 0:
        row["message"] = (proc.stderr.strip().splitlines() or ["?"])[-1]
        print(f"taylor: {tag} {shot['shot']} FAILED (exit {proc.returncode}): {row['message']}",
              flush=True)
        return row, None, []
    m, profile, reached = extract(run_dir, shot, n, geometry)
    row.update(m)
    record_shape(row, shot, profile, out_dir, tag)
    # Keep the last snapshot (the failure-cause figure); drop the others (tens of MB per run).
    snaps = results.snapshots(run_dir)
    for _, f in snaps[:-1]:
        os.remove(f)
    with open(os.path.join(run_dir, "particles.pvd"), "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n<Collection>\n'
                f'<DataSet timestep="{snaps[-1][0]!r}" part="0" '
                f'file="{os.path.relpath(snaps[-1][1], run_dir)}"/>\n</Collection>\n</VTKFile>\n')
    print(f"taylor: {tag} {shot['shot']}: {shape_text(row)}, failed {m['failed']} (core "
          f"{m['failed_core']}), grid {radial:.3g} R0, {row['elapsed [s]']:.0f} s", flush=True)
    row["last_snapshot"] = os.path.relpath(snaps[-1][1], out_dir)  # relative to OUT
    with open(os.path.join(run_dir, "result.json"), "w") as f:
        json.dump({"scene": the_scene, "material_sha256": digest, "row": row, "profile": profile,
                   "reached": reached}, f)
    return row, profile, reached


def run_one(job):
    """The job's shot on a grid wide enough for its mushroom: first RADIAL_EXTENT R0 from the
    axis; while material reaches the y+ or z+ face (summary.json "material_reached_faces"), again
    with the extent ENLARGEMENT times larger, at most MAX_ENLARGEMENTS times (each attempt in its
    own run directory, so that a stopped campaign resumes every one). The row of the last
    attempt, with the faces its material reached (empty: none) and the attempts before it;
    a run still confined is reported on stderr."""
    shot, set_name, material, failure, n, out_dir, runs_dir, mpm, threads, anvil, geometry = job
    tag = f"{set_name}_{failure}_n{n}"
    # Campaigns with different anvils or geometries may share --runs: each has its own run
    # directories.
    run_tag = tag if anvil[0] == "mirror" else f"{tag}_{anvil[0]}{anvil[1]:g}"
    if geometry != "3d":
        run_tag += f"_{geometry}"
    base = os.path.join(runs_dir, run_tag, shot["shot"])
    earlier = []
    for k in range(MAX_ENLARGEMENTS + 1):
        radial = round(RADIAL_EXTENT * ENLARGEMENT ** k, 9)  # 3.3, not 3.3000000000000003
        row, profile, reached = run_attempt(job, base if k == 0 else f"{base}_radial{radial:.4g}",
                                            radial)
        if profile is None:
            break
        confined = radial_faces(reached)
        if not confined or k == MAX_ENLARGEMENTS:
            break
        larger = radial * ENLARGEMENT
        print(f"taylor: warning: {tag} {shot['shot']}: with the grid {radial:.3g} R0 from the "
              f"axis, material reached its outer faces {reached_text(confined)}: running it "
              f"again at {larger:.3g} R0", file=sys.stderr, flush=True)
        earlier.append(f"{radial:.3g} R0: {reached_text(confined)}")
    row.setdefault("radial_extent_over_R0 [-]", radial)  # results of campaigns before it
    row["material_reached_faces"] = reached_text(reached) if profile is not None else ""
    row["confined_attempts"] = "; ".join(earlier)
    if profile is not None:
        record_shape(row, shot, profile, out_dir, tag)
        if reached:
            print(f"taylor: warning: {tag} {shot['shot']}: with the grid "
                  f"{row['radial_extent_over_R0 [-]']:.3g} R0 from the axis, material reached "
                  f"its outer faces {row['material_reached_faces']}: its Lf and Dm may be "
                  "confined (results.csv, material_reached_faces)", file=sys.stderr, flush=True)
    return row, profile


def shape_text(row):
    """Lf and Dm against the experiment, or the prediction where the shot has no measurement."""
    return ", ".join(f"{key} {row[f'{key}_error [%]']:+.2f} %" if row[f"{key}_error [%]"] != ""
                     else f"{key} {1e3 * row[f'{key} [m]']:.3f} mm (not measured)"
                     for key in ("Lf", "Dm"))


def record_shape(row, shot, profile, out_dir, tag):
    """Errors of Lf and Dm against the experiment into `row` (empty where the shot has no
    measurement: not judged; Xf is never judged); the profile into
    OUT/profiles/<tag>_<shot>.csv."""
    row.pop("Xf_error [%]", None)  # rows of campaigns before Xf was left unjudged
    for key in JUDGED:
        row[f"{key}_error [%]"] = ("" if shot[key] is None
                                   else 100.0 * (row[f"{key} [m]"] / shot[key] - 1.0))
    prof_dir = os.path.join(out_dir, "profiles")
    os.makedirs(prof_dir, exist_ok=True)
    with open(os.path.join(prof_dir, f"{tag}_{shot['shot']}.csv"), "w") as f:
        f.write("x [m],radius [m],mean_plastic_strain [-]\n")
        for p in profile:
            f.write(f"{p[0]:.6e},{p[1]:.6e},{p[2]:.6e}\n")


def reextract(out_dir, data=DATA):
    """Re-measures Lf, Dm, Xf and the profiles of OUT/results.csv from the runs' last snapshots
    (after a change of the measures; nothing is re-run)."""
    with open(os.path.join(out_dir, "results.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    shots = {s["shot"]: s for s in read_shots(data)}
    for row in rows:
        if row["exit_code"] != "0":
            continue
        shot, n = shots[row["shot"]], int(row["cells_per_radius"])
        last = results.read_points(os.path.join(out_dir, row["last_snapshot"]))
        rod = last["object"] == max(last["object"])
        Lf, Dm, Xf, profile = measure(last["points"][rod], last["plastic_strain"][rod], shot, n,
                                      float(row.get("face_lift [m]") or 0.0),
                                      row.get("geometry") or "3d")
        row.update({"Lf [m]": Lf, "Dm [m]": Dm, "Xf [m]": Xf})
        record_shape(row, shot, profile, out_dir, f"{row['set']}_{row['failure']}_n{n}")
    with open(os.path.join(out_dir, "results.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, list(rows[0].keys()), lineterminator="\n")
        w.writeheader()
        w.writerows(rows)
    print(f"taylor: re-measured {len(rows)} runs in {out_dir}/results.csv", flush=True)


class RunError(Exception):
    """A program the campaign runs failed before any shot (exit 3, one line)."""


def fit_material(name, out_dir, pointdriver):
    """Runs `pointdriver fit` for the set (stress-strain curves only) and returns its material."""
    fit_dir = os.path.join(out_dir, "fits", name)
    done = subprocess.run([pointdriver, "fit", os.path.join(REPO, FITS[name]), "--out", fit_dir,
                           "--no-figures"], capture_output=True, text=True, cwd=REPO)
    if done.returncode != 0:
        last = (done.stderr.strip().splitlines() or ["no message"])[-1]
        raise RunError(f"taylor: --sets {name}: pointdriver fit {FITS[name]} failed (exit "
                       f"{done.returncode}): {last}")
    files = [f for f in os.listdir(fit_dir) if f.endswith(".json") and f != "fit_report.json"]
    return os.path.join(fit_dir, files[0])


class Parser(argparse.ArgumentParser):
    def error(self, message):  # a usage error exits 1 (argparse's 2 is our input error)
        self.print_usage(sys.stderr)
        print(f"taylor: {message}", file=sys.stderr)
        sys.exit(1)


def main(argv=None):
    """Exit codes: 0 done, 1 usage error, 2 input error (the table of shots), 3 a run failed or an
    output could not be written, 130 interrupted (Ctrl-C)."""
    ap = Parser(prog="taylor.py", description=__doc__,
                formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out")
    ap.add_argument("--sets", default="table1,fit_all")
    ap.add_argument("--failure", default="off", help="comma list of off, shipped, compression_aware")
    ap.add_argument("--failure-sets", default=None,
                    help="sets run with the failure modes other than off (default: all --sets)")
    ap.add_argument("--cells-per-radius", default="4", help="comma list: a resolution ladder")
    ap.add_argument("--ladder-shots", default=None,
                    help="shots run at resolutions other than the first (default: all --shots)")
    ap.add_argument("--anvil", default="mirror",
                    help="mirror (default: symmetric x- face, frictionless), wall[:MU] (rigid "
                         "wall that never pulls, Coulomb friction MU), wall_particles[:MU] (that "
                         "wall met at the rod's particles), rigid[:MU] (a rigid body "
                         "at rest in contact, likewise) or rigid_particles (that body met at the "
                         "rod's particles, frictionless); one per OUT")
    ap.add_argument("--geometry", default="3d", choices=GEOMETRIES,
                    help="3d (default: the quarter model) or axisymmetric (the r-z section on a 2D "
                         "grid; one per OUT)")
    ap.add_argument("--data", default=DATA,
                    help="the table of shots, in the columns of data/experiments/taylor/"
                         "house1995.csv (the default); a measurement left empty is not judged")
    ap.add_argument("--shots", default=None, help="comma list of shot names (default: all 23)")
    ap.add_argument("--jobs", type=int, default=None, help="runs at a time (default: cores/threads)")
    ap.add_argument("--threads", type=int, default=1, help="OpenMP threads per run")
    ap.add_argument("--mpm", default=os.path.join(REPO, "build", "bin", "mpm"))
    ap.add_argument("--pointdriver", default=os.path.join(REPO, "build", "bin", "pointdriver"))
    ap.add_argument("--runs", default=None, help="directory of the runs (default: OUT/runs)")
    ap.add_argument("--no-plot", action="store_true")
    ap.add_argument("--reextract", action="store_true",
                    help="re-measure the runs of OUT/results.csv from their last snapshots, then "
                         "redo the report (no run)")
    a = ap.parse_args(argv)
    try:
        return campaign(a)
    except InputError as e:
        print(e, file=sys.stderr)
        return 2
    except RunError as e:
        print(e, file=sys.stderr)
        return 3
    except OSError as e:
        print(f"taylor: {e.filename or a.out}: cannot write: {e.strerror}", file=sys.stderr)
        return 3
    except KeyboardInterrupt:
        print("taylor: interrupted; run the same command again to resume (finished runs are "
              "kept)", file=sys.stderr)
        return 130


def campaign(a):
    """The campaign of the parsed options `a` (module docstring); its exit code."""
    out_dir = os.path.abspath(a.out)
    if a.reextract:
        reextract(out_dir, a.data)
        if not a.no_plot:
            sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
            import taylor_report  # noqa: E402
            taylor_report.report(out_dir)
        return 0
    os.makedirs(out_dir, exist_ok=True)
    runs_dir = os.path.abspath(a.runs) if a.runs else os.path.join(out_dir, "runs")
    shots = read_shots(a.data)
    if a.shots:
        wanted = a.shots.split(",")
        unknown = [s for s in wanted if s not in {x["shot"] for x in shots}]
        if unknown:
            sys.exit(f"taylor: --shots: unknown shot(s) {unknown}; the data file has "
                     f"{shots[0]['shot']}..{shots[-1]['shot']}")
        shots = [s for s in shots if s["shot"] in wanted]
    try:
        levels = [int(n) for n in a.cells_per_radius.split(",")]
    except ValueError:
        levels = []
    if not levels or min(levels) < 1:
        sys.exit(f"taylor: --cells-per-radius: expected whole numbers >= 1, comma separated "
                 f"(got '{a.cells_per_radius}')")
    ladder = set(a.ladder_shots.split(",")) if a.ladder_shots else None
    failures = a.failure.split(",")
    anvil = parse_anvil(a.anvil)
    sets = a.sets.split(",")
    failure_sets = a.failure_sets.split(",") if a.failure_sets else sets
    for f in failures:
        if f not in ("off", "shipped", "compression_aware"):
            sys.exit(f"taylor: --failure: unknown mode '{f}' (off, shipped, compression_aware)")
    for program, option in ((a.mpm, "--mpm"), (a.pointdriver, "--pointdriver")):
        if (option == "--mpm" or any(s in FITS for s in sets)) and not os.access(program,
                                                                                 os.X_OK):
            sys.exit(f"taylor: {option} {program}: not an executable (build it: cmake --build "
                     "build)")
    materials = {}
    for s in sets:
        if s in PUBLISHED:
            materials[s] = PUBLISHED[s]
        elif s in FITS:
            materials[s] = fit_material(s, out_dir, a.pointdriver)
        else:
            sys.exit(f"taylor: --sets: unknown set '{s}' ({', '.join([*PUBLISHED, *FITS])})")
    jobs = []
    for s in sets:
        for f in failures:
            if f != "off" and s not in failure_sets:
                continue
            for i, n in enumerate(levels):
                for shot in shots:
                    if i > 0 and ladder is not None and shot["shot"] not in ladder:
                        continue
                    jobs.append((shot, s, materials[s], f, n, out_dir, runs_dir, a.mpm,
                                 a.threads, anvil, a.geometry))
    # Longest first, so that the pool ends together.
    jobs.sort(key=lambda j: -(j[0]["L0"] * j[4] ** 4 / j[0]["U0"]))
    n_jobs = a.jobs or max(1, (os.cpu_count() or 1) // a.threads)
    print(f"taylor: {len(jobs)} runs, {n_jobs} at a time, {a.threads} thread(s) each", flush=True)
    start = time.time()
    rows = []
    with concurrent.futures.ThreadPoolExecutor(n_jobs) as pool:
        for row, _ in pool.map(run_one, jobs):
            rows.append(row)
    wall = time.time() - start
    order = {s["shot"]: i for i, s in enumerate(read_shots(a.data))}
    rows.sort(key=lambda r: (r["set"], r["failure"], r["cells_per_radius"], order[r["shot"]]))
    keys = []
    for r in rows:
        keys += [k for k in r if k not in keys]
    with open(os.path.join(out_dir, "results.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, keys, lineterminator="\n")
        w.writeheader()
        w.writerows(rows)
    with open(os.path.join(out_dir, "meta.json"), "w") as f:
        json.dump({"wall_time [s]": wall, "jobs": n_jobs, "threads": a.threads, "runs": len(rows),
                   "command": " ".join(sys.argv)}, f, indent=1)
    print(f"taylor: {len(rows)} runs in {wall:.0f} s; wrote {out_dir}/results.csv", flush=True)
    if not a.no_plot:
        sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
        import taylor_report  # noqa: E402  (matplotlib only when plotting)
        taylor_report.report(out_dir)
    return 3 if any(r["exit_code"] != 0 for r in rows) else 0


if __name__ == "__main__":
    sys.exit(main())
