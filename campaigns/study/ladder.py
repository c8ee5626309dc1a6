#!/usr/bin/env python3
"""A grid-convergence ladder of any scene (docs/accuracy.md#grid-convergence-ladders).

  ladder.py SCENE.json --out OUT [--levels 1,1.5,2.25] [--ratio 1.5 --count 3]
            [--particles-per-cell N,... --ppc-levels L,...] [--threads 2] [--ranks 1]
            [--set JSON ...] [--mpm build/bin/mpm] [--mpirun mpirun] [--checkpoint-steps 200]
            [--runs DIR] [--table PATH] [--analyse-only [--refingerprint]] [--no-plot]
  (also `mpm study --ladder LEVELS SCENE.json --out OUT [...]`, which runs this script)

1. Writes OUT/scenes/<run>.json for every level: a scene that `extends` SCENE with the grid's cells
   times the level on every axis (rounded; the domain stays as it is, so cells and particle spacing
   shrink together: particles per cell are kept), snapshots off (the first and last only when a
   Taylor rod is measured), checkpoints every --checkpoint-steps steps. On a graded grid
   (grid.refine) a level keeps the base cells and multiplies refine.factor by the level instead:
   the box refines (with its strips and their grading), the base cells elsewhere stay, and h is
   the box's cell (a local h: the GCI is the error of the box's cells only). --particles-per-cell 1,2,3
   adds, at each of --ppc-levels, runs with that many particles per cell per axis on every object
   (quadrature error apart from grid error).
2. Runs them one after another, coarsest first, `mpm run` with --threads (or under
   `mpirun -np RANKS` with --ranks > 1). A run that finished (summary.json "completed") for the same
   scene file is not run again; one that stopped with a checkpoint resumes from it (`mpm run
   --restart`): a ladder can be stopped (Ctrl-C writes a checkpoint) and resumed, and extended one
   level at a time into the same OUT.
3. Reads the observables the scene names (definitions in docs/accuracy.md#grid-convergence-ladders):
   the crater's depth, half-depth and surface diameters (output.crater), each gauge's peak over
   the history rows (output.gauges; the signed reading of largest magnitude), each object's
   largest pressure and the fastest object's (the projectile's) final mean velocity along its
   impact direction, for a
   Taylor rod (one cylinder along x moving along -x) its final length Lf and mushroom diameter Dm,
   and with output.exact_displacement the displacement error (rms and max) of the last history row.
4. For every observable: the values per level, then per consecutive triple of levels the
   convergence condition, observed order, Richardson extrapolation and fine-grid GCI of Celik et
   al. (2008) (campaigns/study/gci.py), and whether the finest triple is in the asymptotic range
   (against the next coarser triple). Writes OUT/ladder.csv (one row per run and observable),
   OUT/ladder.md, OUT/ladder.json (the ladder table) and OUT/ladder_<observable>.png (value against
   h with the extrapolated value and its GCI band). --table PATH also writes the ladder table there
   (e.g. data/scenes/sphere_cylinder/recommended.ladder.json, which `mpm run` of that scene reads
   to put the error bar into its summary).
A Taylor rod whose shape cannot be measured (its anvil layer all failed: the shipped failure stack)
has no Lf and Dm; the table's verdict and a warning on stderr say why and how to measure them
(failure off: --set '{"physics": {"erosion": "none"}}').
--analyse-only without --levels (and without --ratio/--count) re-analyses the levels already run:
those of OUT/ladder.json, else of the run folders runs/x<level>; with none it is a usage error.
--analyse-only --refingerprint labels each level with the fingerprint the scene has today (`mpm
check --fingerprint`) rather than the one its run recorded, naming every level whose fingerprint
changed: for a scene edited in keys that change no number (a key removed because the model never
read it). `mpm run` still marks such a table stale if its value differs from the run's.
Exit codes: 0 done, 1 usage error, 2 input error (the scene), 3 a run failed (analysed without it)
or an output could not be written (one line naming the path and the reason), 130 Ctrl-C (a level
being run writes its checkpoint; the same command resumes).
"""

import argparse
import csv
import datetime
import json
import math
import re
import os
import shlex
import signal
import subprocess
import sys
import textwrap

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
# impact.results (pure Python): <src>/python, or share/impact/python of an install.
sys.path.insert(0, os.path.join(ROOT, "python"))
import gci  # noqa: E402
import quantity_format  # noqa: E402
from impact import results  # noqa: E402

ANVIL_LAYER = 0.5e-3  # Dm: particles within this distance of the anvil [m] (campaigns/taylor)


# --- the scene -----------------------------------------------------------------------------------

def load_resolved(path):
    """The scene after its `extends` chain (RFC 7396 merge patches, material paths made relative
    to the working directory), as mpm/input/scene_reader.cpp resolves it."""
    with open(path) as f:
        doc = json.load(f)
    here = os.path.dirname(path)
    for m in doc.get("materials", {}).values():
        if isinstance(m, dict) and isinstance(m.get("file"), str) and not os.path.isabs(m["file"]):
            m["file"] = os.path.normpath(os.path.join(here, m["file"]))
    if "extends" not in doc:
        return doc
    base = load_resolved(os.path.normpath(os.path.join(here, doc.pop("extends"))))
    return merge_patch(base, doc)


def merge_patch(target, patch):
    if not isinstance(patch, dict):
        return patch
    out = dict(target) if isinstance(target, dict) else {}
    for k, v in patch.items():
        if v is None:
            out.pop(k, None)
        else:
            out[k] = merge_patch(out.get(k), v)
    return out


def taylor_rod(scene):
    """(name, object) of the scene's Taylor rod: its only cylinder, axis along x, moving along -x;
    else None."""
    rods = [(n, o) for n, o in scene.get("objects", {}).items()
            if o.get("geometry", {}).get("type") == "cylinder"]
    if len(rods) != 1:
        return None
    name, rod = rods[0]
    g, v = rod["geometry"], rod.get("velocity", [0.0])
    axis_along_x = all(abs(a - b) < 1e-12 for a, b in zip(g["bottom"][1:], g["top"][1:]))
    return (name, rod) if axis_along_x and v[0] < 0 and all(c == 0 for c in v[1:]) else None


def dimension(scene):
    return len(scene["grid"]["cells"])


THIN_AXIS = 3  # an axis of fewer cells is a slice's thickness (a 1-D bar, a plate): not refined


def refined_axes(scene):
    """The axes a ladder refines: those of at least THIN_AXIS cells (all, if none is)."""
    cells = scene["grid"]["cells"]
    axes = [i for i, c in enumerate(cells) if c >= THIN_AXIS]
    return axes or list(range(len(cells)))


def graded(scene):
    """True for a scene whose grid has a refined box (grid.refine, docs/scenes.md#graded-grids)."""
    return scene["grid"].get("refine") is not None


GRADED_SCOPE = ("the refined box of a graded grid (grid.refine): the levels multiply its factor "
                "and keep the base cells, so the GCI is the error of the box's cells alone, not "
                "of the cells that do not refine (docs/accuracy.md#grid-convergence-ladders)")


def level_factor(scene, level):
    """A graded scene's refine.factor at LEVEL: the box's cells refine with the level, the base
    cells stay (so the coarse cells, their particles and the box's nodes are the same at every
    level); None for a uniform grid."""
    if not graded(scene):
        return None
    base = scene["grid"]["refine"]["factor"]
    # Level 1 writes the scene's own number: the scene fingerprint reads 2 and 2.0 as different
    # texts, and level 1 must match the scene itself (mpm run's error bar).
    return base if level == 1 else base * level


def fine_cells(scene, factor):
    """The box's cell size [m] per axis at FACTOR, as the reader makes it
    (mpm/scene/graded_axis.cpp): the box widened to the base nodes, then round(span / (h0 / F))
    equal cells, at least one."""
    g, box = scene["grid"], scene["grid"]["refine"]
    sizes = []
    for d, n in enumerate(g["cells"]):
        lo, up = g["lower"][d], g["upper"][d]
        h0 = (up - lo) / n

        def base_node(x, upward):  # graded_axis.cpp's, step for step
            x = min(max(x, lo), up)
            c = (x - lo) / h0
            if abs(c - round(c)) <= 1e-9:  # on a node already: as given, or the face
                return lo if round(c) <= 0 else up if round(c) >= n else x
            return min(max(lo + (math.ceil(c) if upward else math.floor(c)) * h0, lo), up)
        a, b = base_node(box["lower"][d], False), base_node(box["upper"][d], True)
        if not (factor > 1.0 and b > a):
            sizes.append(h0)
            continue
        sizes.append((b - a) / max(1, int(math.floor((b - a) / (h0 / factor) + 0.5))))
    return sizes


def representative_h(scene, cells, factor=None):
    """(cell volume)^(1/D) [m] over the refined axes (Celik et al. 2008, eq. 1; cells of one
    size): a thin axis that keeps its cells does not enter the refinement. On a graded grid
    (FACTOR given) the cells are those of the refined box, where the ladder refines."""
    lo, up = scene["grid"]["lower"], scene["grid"]["upper"]
    axes = refined_axes(scene)
    sizes = (fine_cells(scene, factor) if factor is not None
             else [(up[i] - lo[i]) / cells[i] for i in range(len(cells))])
    vol = 1.0
    for i in axes:
        vol *= sizes[i]
    return vol ** (1.0 / len(axes))


def level_cells(scene, level):
    """grid.cells at LEVEL: scaled on a uniform grid; a graded grid's base cells as they are."""
    if graded(scene):
        return list(scene["grid"]["cells"])
    axes = refined_axes(scene)
    return [max(1, int(math.floor(c * level + 0.5))) if i in axes else c
            for i, c in enumerate(scene["grid"]["cells"])]


def run_name(level, ppc=None):
    return f"x{level:g}" + (f"_p{ppc}" if ppc is not None else "")


def overlay(base, top):
    """top over base, key by key, keeping top's nulls (they are merge-patch deletions for mpm)."""
    if not isinstance(base, dict) or not isinstance(top, dict):
        return top
    out = dict(top)
    for k, v in base.items():
        out[k] = overlay(v, top[k]) if k in top else v
    return {k: out[k] for k in list(top) + [k for k in base if k not in top]}


def write_level_scene(path, scene_file, scene, level, ppc, checkpoint_steps, rod, sets=()):
    """The level's scene file: `extends` SCENE, the --set patches (SETS, parsed) merged into the
    file itself, and the level's own keys over them (so a --set cannot change a level's cells,
    snapshots or particles per cell, and the file, which is the resume marker, records the
    patches). Returns its text."""
    cells, factor = level_cells(scene, level), level_factor(scene, level)
    output = {"snapshots": False, "checkpoint_interval_steps": checkpoint_steps,
              "directory": None}
    if rod is not None:  # Lf and Dm come from the first and last snapshots (at the scene's
        output["snapshots"] = True  # output.interval, which also sets the history rows)
    # Relative to the level scene's own folder (mpm resolves `extends` from there): the level's
    # text, the marker its run is matched by, is then the same in every clone of the repository.
    patch = {"extends": os.path.relpath(os.path.abspath(scene_file),
                                        os.path.dirname(os.path.abspath(path))),
             "description": (f"{os.path.basename(scene_file)} at {level:g} x the cells per axis "
                             + (f"of the refined box (factor {factor:g})" if factor is not None
                                else f"({' x '.join(map(str, cells))})")
                             + (f", {ppc} particles per cell per axis" if ppc is not None else "")
                             + " (campaigns/study/ladder.py)"),
             "grid": {"cells": cells}, "output": output}
    if factor is not None:
        patch["grid"]["refine"] = {"factor": factor}
    if ppc is not None:
        patch["objects"] = {n: {"particles_per_cell": [ppc] * dimension(scene)}
                            for n in scene["objects"]}
    combined = {}
    for one in sets:  # composed, not applied: a null (a deletion) must reach the level file
        combined = overlay(combined, one)
    combined.pop("extends", None)
    if combined:
        patch = overlay(combined, patch)
    text = json.dumps(patch, indent=1) + "\n"
    old = open(path).read() if os.path.exists(path) else None
    if old != text:
        with open(path, "w") as f:
            f.write(text)
    return text


# --- running -------------------------------------------------------------------------------------

def finished(run_dir, scene_text):
    try:
        with open(os.path.join(run_dir, "ladder_scene.json")) as f:
            same = f.read() == scene_text
        with open(os.path.join(run_dir, "summary.json")) as f:
            return same and json.load(f).get("status") == "completed"
    except (OSError, ValueError):
        return False


def run_level(args, scene_path, scene_text, run_dir):
    """Runs (or resumes) one level; returns mpm's exit code. A checkpoint is resumed only when
    the marker (the level scene's text, written before the run starts and after the previous
    run's checkpoint and summary are gone) matches this level's scene."""
    os.makedirs(run_dir, exist_ok=True)
    marker = os.path.join(run_dir, "ladder_scene.json")
    resumable = (os.path.exists(os.path.join(run_dir, "checkpoint.bin"))
                 and os.path.exists(marker) and open(marker).read() == scene_text)
    launcher = results.Launcher(args.mpm, args.mpirun)
    if resumable:
        cmd = launcher.command("run", options=["--restart", run_dir], threads=args.threads,
                               ranks=args.ranks, extra=["-q"])
    else:
        for stale in ("ladder_scene.json", "checkpoint.bin", "summary.json"):
            if os.path.exists(os.path.join(run_dir, stale)):
                os.remove(os.path.join(run_dir, stale))
        with open(marker, "w") as f:
            f.write(scene_text)
        cmd = launcher.command("run", scene_path, out=run_dir, options=["--overwrite"],
                               threads=args.threads, ranks=args.ranks, extra=["-q"])
    print(f"ladder: {'resuming' if resumable else 'running'} {os.path.basename(run_dir)}: "
          f"{shlex.join(cmd)}", flush=True)
    with open(os.path.join(run_dir, "ladder.log"), "a") as log:
        # Its own session: Ctrl-C reaches the ladder only, which passes on exactly one SIGINT
        # (mpm then writes its checkpoint; a second one would kill it outright).
        proc = launcher.popen(cmd, stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
        try:
            return proc.wait()
        except KeyboardInterrupt:
            proc.send_signal(signal.SIGINT)
            proc.wait()
            raise


def fingerprint_of(args, scene_path):
    """The scene fingerprint `mpm check --fingerprint` gives (what `mpm run` writes into
    summary.json), from --mpm or else this tree's build; None when neither knows the option."""
    for mpm in (args.mpm, os.path.join(ROOT, "build", "bin", "mpm")):
        try:
            done = results.Launcher(mpm).run("check", scene_path, options=["--fingerprint"],
                                             check=False, timeout=600)
        except results.LaunchError:  # not an executable
            continue
        text = done.stdout.strip()
        if done.returncode == 0 and len(text) == 16:
            return text
    return None


# --- observables ---------------------------------------------------------------------------------

def pointer_get(doc, pointer):
    node = doc
    for part in pointer.split("/")[1:]:
        part = part.replace("~1", "/").replace("~0", "~")
        if isinstance(node, list):
            node = node[int(part)] if part.isdigit() and int(part) < len(node) else None
        elif isinstance(node, dict):
            node = node.get(part)
        else:
            return None
        if node is None:
            return None
    return float(node) if isinstance(node, (int, float)) and not isinstance(node, bool) else None


def gauge_peaks(run_dir):
    """{gauge name: (unit, peak)}: per history.csv column gauge_<name> [unit], the signed reading
    of largest magnitude over the rows (the first of equal magnitudes)."""
    try:
        head, rows = results.history_rows(run_dir)
    except (OSError, ValueError):  # no history.csv (InputError is a ValueError)
        return {}
    if not rows:
        return {}
    out = {}
    for i, col in enumerate(head):
        if not col.startswith("gauge_"):
            continue
        name, _, unit = col[len("gauge_"):].partition(" [")
        values = [r[i] for r in rows]
        peak = max(values, key=abs) if values else None  # max keeps the first of equal magnitudes
        out[name] = (unit.rstrip("]"), peak)
    return out


NO_FAILURE = '{"physics": {"erosion": "none"}}'  # how the Taylor campaign measures shapes


class NotMeasured(Exception):
    """Why a run's Lf and Dm could not be measured, and how they can be (one line)."""


def taylor_measures(run_dir, scene, rod):
    """(Lf, Dm [m], note) of the rod from the first and last snapshots (campaigns/taylor/
    taylor.py's measures, with the seed offsets read from the first snapshot: exact at t = 0);
    note tells how many particles failed (debris, not measured), or is None. NotMeasured when
    no intact particle lies within 0.5 mm of the anvil."""
    import numpy as np
    name, obj = rod
    snaps = results.snapshots(run_dir)
    first, last = results.read_points(snaps[0][1]), results.read_points(snaps[-1][1])
    ids = first["object"]
    index = sorted(scene["objects"]).index(name) if len(set(ids.tolist())) > 1 else ids[0]
    mine = ids == index
    g = obj["geometry"]
    axis = g["bottom"]
    planar = dimension(scene) == 2

    def radius(p):
        return abs(p[:, 1] - axis[1]) if planar else ((p[:, 1] - axis[1]) ** 2
                                                      + (p[:, 2] - axis[2]) ** 2) ** 0.5

    # The particles' order (and on several ranks their grouping) differs between snapshots:
    # each snapshot is masked by its own object ids.
    mine_last = last["object"] == index
    X0, x = first["points"][mine], last["points"][mine_last]
    # The anvil is the grid's x- face; a rod that bounced off a `wall` anvil is measured from
    # its impact face where it lay at its lowest over the snapshots (taylor.py's face_lift).
    anvil = scene["grid"]["lower"][0]
    face_lift = 0.0
    if scene["grid"].get("boundary", {}).get("x-") == "wall":
        lowest = min(snap["points"][snap["object"] == index][:, 0].min()
                     for snap in (results.read_points(f) for _, f in snaps))
        face_lift = float(x[:, 0].min() - lowest)
    x = x - np.array([anvil + face_lift, 0.0, 0.0])
    # Failed particles are debris, not the rod's shape (with erosion off there are none).
    intact = (last["failed"][mine_last] < 0.5) if "failed" in last else np.ones(len(x), bool)
    axial = g["top"][0] - X0[:, 0].max()
    radial = g["radius"] - radius(X0).max()
    failed = int(len(x) - intact.sum())
    note = (f"{failed} of {len(x)} particles of the rod failed (debris, not measured)"
            if failed else None)
    near = (x[:, 0] < ANVIL_LAYER) & intact
    if not near.any():
        raise NotMeasured(f"{failed} of {len(x)} particles of the rod failed and none intact "
                          "lies within 0.5 mm of the anvil; measure the shape with failure off, "
                          f"as the Taylor campaign does: --set '{NO_FAILURE}'"
                          if failed else "no particle of the rod lies within 0.5 mm of the anvil")
    Lf = x[intact, 0].max() + axial
    Dm = 2.0 * (radius(x[near]).max() + radial)
    return float(Lf), float(Dm), note


def observables_of(scene, rod):
    """[(name, JSON pointer into summary.json or None, unit)] the scene names (module docstring)."""
    out = []
    crater = scene.get("output", {}).get("crater")
    if crater:
        out += [("crater depth", "/observables/crater/depth [m]", "m"),
                ("crater half-depth diameter", "/observables/crater/half_depth_diameter [m]", "m"),
                ("crater surface diameter", "/observables/crater/surface_diameter [m]", "m")]
    objects = scene.get("objects", {})
    # A velocity component written as an expression (docs/scenes.md#expressions) counts as 0 here.
    speeds = {n: max((abs(c) if isinstance(c, (int, float)) else 0.0
                      for c in o.get("velocity", [0.0])), default=0.0)
              for n, o in objects.items()}
    fastest = max(speeds, key=speeds.get) if speeds else None
    if fastest is not None and speeds[fastest] > 0 and rod is None:
        v = objects[fastest]["velocity"]
        c = max(range(len(v)), key=lambda i: abs(v[i]))
        out.append((f"{fastest} residual velocity",
                    f"/observables/objects/{fastest}/mean_velocity [m~1s]/{c}", "m/s"))
    # Peak pressures, sampled at the history rows; not for a Taylor rod, whose observables are its
    # shape (its scenes write few rows: the rows are also its snapshots).
    for n in sorted(objects) if rod is None else []:
        out.append((f"{n} peak pressure", f"/observables/objects/{n}/max_pressure [Pa]", "Pa"))
    units = {"velocity": "m/s", "strain": "-", "pressure": "Pa"}
    for g, spec in sorted(scene.get("output", {}).get("gauges", {}).items()):
        unit = units.get(spec.get("type"), "?")
        out.append((f"gauge {g} peak", f"/gauges/{g}/peak [{unit.replace('/', '~1')}]", unit))
    if rod is not None:
        out += [("Lf", None, "m"), ("Dm", None, "m")]
    # A manufactured solution's error at the end of the run (output.exact_displacement).
    if "exact_displacement" in scene.get("output", {}):
        out += [(f"displacement error {k}", None, "m") for k in ("rms", "max")]
    return out


def final_history_value(run_dir, column):
    """The last history.csv row's value in the column whose name is `column` (unit aside), or
    None when the run wrote no such column."""
    try:
        head, rows = results.history_rows(run_dir)
    except (OSError, ValueError):  # no history.csv (InputError is a ValueError)
        return None
    names = [c.partition(" [")[0] for c in head]
    if column not in names or not rows:
        return None
    return rows[-1][names.index(column)]


def read_run(run_dir, scene_text, scene, rod, observables):
    """The level's observables, or None unless its run completed for this very level scene."""
    if not finished(run_dir, scene_text):
        return None
    with open(os.path.join(run_dir, "summary.json")) as f:
        s = json.load(f)
    peaks = gauge_peaks(run_dir)
    values, notes = {}, {}
    for name, pointer, unit in observables:
        v = None
        if name.startswith("gauge "):
            v = peaks.get(name[len("gauge "):-len(" peak")], (None, None))[1]
        elif name.startswith("displacement error "):
            v = final_history_value(run_dir, "displacement_error_" + name.split()[-1])
        elif name in ("Lf", "Dm"):
            if "Lf" in values or "Lf" in notes:
                continue
            try:
                values["Lf"], values["Dm"], note = taylor_measures(run_dir, scene, rod)
                if note:
                    notes["Lf"] = notes["Dm"] = note
            except NotMeasured as e:
                notes["Lf"] = notes["Dm"] = f"not measured: {e}"
            except (OSError, ValueError, IndexError, KeyError) as e:
                notes["Lf"] = notes["Dm"] = (f"not measured: the snapshots of {run_dir} could "
                                             f"not be read ({type(e).__name__}: {e})")
            continue
        else:
            v = pointer_get(s, pointer)
        values[name] = v
    return {"values": values, "notes": notes, "particles": s.get("particles"),
            "steps": s.get("steps"),
            "wall": s.get("wall_time [s]"), "threads": s.get("threads"), "ranks": s.get("ranks"),
            "fingerprint": s.get("scene_fingerprint"),
            "energy_error": s.get("final", {}).get("energy_error [-]"),
            # A graded grid's cells (the base cells are the level's grid.cells) and the
            # particle-steps whose uGIMP box was narrowed (docs/scenes.md#graded-grids).
            "graded_cells": s.get("grid", {}).get("cells") if s.get("grid", {}).get("graded")
            else None, "narrowed": s.get("narrowed_particle_steps"),
            "volume_ratio": {n: o.get("volume_ratio") for n, o in s.get("objects", {}).items()
                             if isinstance(o, dict)}}


# --- analysis ------------------------------------------------------------------------------------

def fmt(x, digits=4):
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "-"
    return f"{x:.{digits}g}"


def verdict(finest, asym, count, band=gci.PLAUSIBLE_ORDER):
    """Why the finest triple's extrapolation may or may not be quoted, short: 'in the asymptotic
    range' when it may (gci.quotable), else every reason that applies, joined by '; '."""
    if finest is None:
        return f"{count} level{'s' if count != 1 else ''}: fewer than three"
    reasons = []
    if finest["condition"] != "monotonic":
        reasons.append({"oscillatory": "oscillatory convergence",
                        "no difference": "no difference between levels"}.get(
                            finest["condition"], finest["condition"]))
    elif finest["order"] is None:
        reasons.append("no observed order")
    elif not band[0] <= finest["order"] <= band[1]:
        reasons.append(f"order {finest['order']:.3g} outside the plausible "
                       f"[{band[0]:g}, {band[1]:g}]")
    reasons.append({True: "in the asymptotic range", False: "not in the asymptotic range",
                    None: "asymptotic range not tested (a fourth level is needed)"}[asym])
    if asym is True and reasons[:-1]:
        reasons.pop()  # two agreeing triples do not make an oscillation or an odd order quotable
    return "; ".join(reasons)


def range_of(values, hs, unit):
    """The ladder table's "range" of an observable (gci.converged_range on the finest triple; the
    levels' values with fewer than three): low, high [unit], the orders it spans (null unless
    monotonic), the number of levels behind it and its basis in words; None without a value."""
    pairs = [(v, x) for v, x in zip(values, hs) if v is not None and math.isfinite(v)]
    if not pairs:
        return None
    if len(pairs) < 3:
        vals = [v for v, _ in pairs]
        return {"low": min(vals), "high": max(vals), "unit": unit, "order_low": None,
                "order_high": None, "levels": len(vals),
                "sign_determined": not min(vals) < 0.0 < max(vals),
                "basis": "fewer than three levels: the band of the levels' values"}
    phi, h = [v for v, _ in pairs[:3]], [x for _, x in pairs[:3]]
    r = gci.converged_range(phi, h)
    out = {"low": r["low"], "high": r["high"], "unit": unit, "order_low": r["order_low"],
           "order_high": r["order_high"], "levels": 3, "sign_determined": r["sign_determined"]}
    if r["order_low"] is not None:
        out["basis"] = (f"from the finest level's value to Richardson's extrapolation of the "
                        f"finest triple for every order from the formal {gci.FORMAL_ORDER:g} to "
                        f"the observed {r['observed_order']:.3g}"
                        + (f", limited to the plausible [{gci.PLAUSIBLE_ORDER[0]:g}, "
                           f"{gci.PLAUSIBLE_ORDER[1]:g}]" if r["clamped"] else ""))
    else:
        out["basis"] = (f"{r['condition']}: no power law bounds the converged value; the band "
                        "of the finest three levels' values")
    if not r["sign_determined"]:
        out["basis"] += "; the converged value's sign is not determined"
    return out


def level_notes(ladder_runs, name):
    """['at x1, x2: NOTE', ...]: what the runs say about an observable's measurement (failed
    particles, or why it is not measured), the levels with the same note grouped."""
    grouped = {}
    for r in ladder_runs:
        note = r["data"].get("notes", {}).get(name)
        if note:
            grouped.setdefault(note, []).append(f"x{r['level']:g}")
    return [f"at {', '.join(levels)}: {note}" for note, levels in grouped.items()]


def analyse(runs, observables):
    """Per observable: the Celik triples of the main ladder (finest first) and the answer: the
    finest triple's extrapolation, whether it may be quoted, and the range of converged values
    (docs/accuracy.md#grid-convergence-ladders)."""
    ladder_runs = sorted([r for r in runs if r["ppc"] is None and r["data"]],
                         key=lambda r: r["h"])
    result = {}
    for name, pointer, unit in observables:
        vals = [r["data"]["values"].get(name) for r in ladder_runs]
        hs = [r["h"] for r in ladder_runs]
        triples = gci.ladder(vals, hs)
        finest = triples[0] if triples else None
        asym, why = (gci.asymptotic_check(finest, triples[1] if len(triples) > 1 else None)
                     if finest else (None, "fewer than three levels"))
        status = (finest["condition"] if finest else "fewer than three levels")
        monotonic = bool(finest and finest["condition"] == "monotonic" and finest["order"])
        band = gci.PLAUSIBLE_ORDER
        if monotonic:
            p = finest["order"]
            status = "extrapolated" if band[0] <= p <= band[1] else (
                f"extrapolated with an implausible order {p:.2g} (outside "
                f"[{band[0]:g}, {band[1]:g}]): read the conservative GCI")
        elif finest and finest["condition"] == "oscillatory":
            status = (f"oscillatory convergence: no extrapolation; error bounded by half the "
                      f"range, +-{100 * finest['oscillation_band']:.2g} %"
                      if finest["oscillation_band"] is not None else "oscillatory convergence")
        # The verdict on the asymptotic range goes into the status, which mpm run's error bar
        # carries into summary.json: an extrapolation outside it is an estimate, not an answer.
        status += {True: "; in the asymptotic range (two triples agree)",
                   False: f"; not in the asymptotic range ({why})",
                   None: f"; asymptotic range not tested ({why})"}[asym]
        count = sum(v is not None for v in vals)
        notes = level_notes(ladder_runs, name)
        if notes:
            status += "; " + "; ".join(notes)
        why_not = verdict(finest, asym, count)
        if finest is None and any("not measured" in n for n in notes):
            why_not = "; ".join(notes)
        bounds = range_of(vals, hs, unit)
        if bounds and bounds.get("sign_determined") is False:
            why_not += "; the converged value's sign is not determined"
        result[name] = {"name": name, "path": pointer, "unit": unit,
                        "levels": [r["level"] for r in ladder_runs], "h [m]": hs, "values": vals,
                        "triples": triples, "status": status,
                        "extrapolated": finest["extrapolated"] if monotonic else None,
                        "order": finest["order"] if monotonic else None,
                        "gci_fine [-]": finest["gci_fine"] if monotonic else None,
                        "gci_conservative [-]": finest["gci_conservative"] if monotonic else None,
                        "asymptotic": asym, "asymptotic_reason": why,
                        "quotable": gci.quotable(finest, asym),
                        "verdict": why_not, "notes": notes,
                        "range": bounds}
    return result


def git_commit():
    try:
        rev = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short=12", "HEAD"],
                             capture_output=True, text=True, check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", ROOT, "status", "--porcelain", "--untracked-files=no"],
                               capture_output=True, text=True).stdout.strip()
        return rev + ("-dirty" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def write_csv(out, runs, observables):
    """ladder.csv: a row per run and observable, with the run's cost."""
    with open(os.path.join(out, "ladder.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["run", "level [-]", "particles_per_cell [-]", "h [m]", "observable", "unit",
                    "value", "particles [-]", "steps [-]", "particle_steps [-]", "wall_time [s]",
                    "threads [-]", "ranks [-]"])
        for r in runs:
            if not r["data"]:
                continue
            d = r["data"]
            for name, _, unit in observables:
                w.writerow([r["name"], r["level"], r["ppc"] if r["ppc"] else "", r["h"], name,
                            unit, d["values"].get(name, ""), d["particles"], d["steps"],
                            (d["particles"] or 0) * (d["steps"] or 0), d["wall"], d["threads"],
                            d["ranks"]])


def ladder_table(args, scene_file, runs, result, commit):
    """ladder.json's document: the scene, the command, the levels and the observables."""
    ladder_runs = sorted([r for r in runs if r["ppc"] is None and r["data"]], key=lambda r: r["h"])
    table = {
        "scene": (os.path.relpath(os.path.abspath(scene_file), ROOT)
                  if os.path.abspath(scene_file).startswith(ROOT + os.sep)
                  else os.path.abspath(scene_file)),
        "command": args.command_line, "commit": commit,
        "date": datetime.date.today().isoformat(),
        "definitions": "docs/accuracy.md#grid-convergence-ladders",
        "safety_factor": gci.SAFETY_FACTOR,
        # The keys without a unit in their name: counts and ratios.
        "units": {k: "-" for k in ("safety_factor", "level", "cells", "refine_factor",
                                   "graded_cells", "narrowed_particle_steps", "particles",
                                   "steps", "particle_steps", "threads", "ranks")},
        "levels": [{"level": r["level"], "cells": r["cells"],
                    **({"refine_factor": r["refine_factor"],
                        "graded_cells": r["data"].get("graded_cells"),
                        "narrowed_particle_steps": r["data"].get("narrowed")}
                       if r.get("refine_factor") else {}),
                    "h [m]": r["h"],
                    "fingerprint": r["data"]["fingerprint"], "particles": r["data"]["particles"],
                    "steps": r["data"]["steps"],
                    "particle_steps": (r["data"]["particles"] or 0) * (r["data"]["steps"] or 0),
                    "wall_time [s]": r["data"]["wall"], "threads": r["data"]["threads"],
                    "ranks": r["data"]["ranks"], "energy_error [-]": r["data"]["energy_error"]}
                   for r in ladder_runs],
        "observables": [{k: v for k, v in res.items() if k not in ("levels", "h [m]")}
                        for res in result.values()],
    }
    for o in table["observables"]:
        o["triples"] = [{k: v for k, v in t.items()} for t in o["triples"]]
    if any(r.get("refine_factor") for r in ladder_runs):  # said again by mpm run's error bar
        table["scope"] = GRADED_SCOPE
    return table


def write_table(args, table):
    """ladder.json (and --table, the same text)."""
    text = json.dumps(table, indent=1, allow_nan=False,
                      default=lambda x: None) + "\n"
    with open(os.path.join(args.out, "ladder.json"), "w") as f:
        f.write(text)
    if args.table:
        with open(args.table, "w") as f:
            f.write(text)


def pct(x, signed=False):
    return "-" if x is None else (f"{100 * x:+.2g}" if signed else f"{100 * x:.2g}")


def summary_lines(args, table, result):
    """ladder.md's head: the command and definitions, the levels' table and the observables'."""
    lines = [f"# Grid-convergence ladder: {table['scene']}", "",
             f"Command: `{args.command_line}` (commit {table['commit']}, {table['date']}). "
             "Definitions: docs/accuracy.md#grid-convergence-ladders. An extrapolated value, its "
             "GCI and the error of level x1 against it are given only where the finest triple is "
             "quotable (monotonic, an order within the plausible "
             f"[{gci.PLAUSIBLE_ORDER[0]:g}, {gci.PLAUSIBLE_ORDER[1]:g}] and in the asymptotic "
             "range); elsewhere the verdict and the range of converged values that the levels "
             "and the plausible orders bound. GCI_fine: Celik et al. "
             f"(2008), safety factor {gci.SAFETY_FACTOR}, a band about the finest level's value; "
             "conservative GCI: Oberkampf & Roy (2010), safety factor 3 and the order limited to "
             f"[0.5, {gci.FORMAL_ORDER:g}] when it is more than 10 % from the formal order "
             f"{gci.FORMAL_ORDER:g}.", "",
             "| level [-] | cells [-] | h [mm] | particles [-] | steps [-] | particle-steps [-] "
             "| wall [s] | threads x ranks [-] | energy_error [-] |",
             "|---|---|---|---|---|---|---|---|---|"]
    for lv in table["levels"]:
        cells = " x ".join(map(str, lv["cells"]))
        if lv.get("refine_factor"):  # graded: the base cells, the box's factor, the graded cells
            cells += (f" refined {lv['refine_factor']:g} x: "
                      f"{' x '.join(map(str, (lv.get('graded_cells') or [])[:len(lv['cells'])]))}"
                      + (f", {lv['narrowed_particle_steps']} narrowed particle-steps"
                         if lv.get("narrowed_particle_steps") else ""))
        lines.append(f"| x{lv['level']:g} | {cells} | "
                     f"{fmt(1e3 * lv['h [m]'])} | {lv['particles']} | {lv['steps']} | "
                     f"{fmt(float(lv['particle_steps']), 3)} | {fmt(lv['wall_time [s]'], 4)} | "
                     f"{lv['threads']} x {lv['ranks']} | {fmt(lv['energy_error [-]'], 3)} |")
    lines += ["", "| observable [unit] | " + " | ".join(f"x{lv['level']:g}"
                                                       for lv in table["levels"])
              + " | verdict | range of converged values | extrapolated | observed order p [-] | "
              "GCI_fine (finest) [%] | conservative GCI [%] | x1 error vs extrapolated [%] |",
              "|---|" + "---|" * len(table["levels"]) + "---|---|---|---|---|---|---|"]

    for res in result.values():
        factor, label = quantity_format.display_unit(res["unit"], res["values"])
        ext = res["extrapolated"] if res["quotable"] else None
        x1 = next((v for v, lv in zip(res["values"], res["levels"]) if lv == 1.0), None)
        err = (x1 - ext) / abs(ext) if (x1 is not None and ext) else None
        lines.append(f"| {res['name']} [{label}] | "
                     + " | ".join(quantity_format.number(v, factor) for v in res["values"])
                     + f" | {res['verdict']} | {quantity_format.range_text(res['range'])} | "
                     f"{quantity_format.number(ext, factor)} | "
                     f"{fmt(res['order'], 3)} | "
                     f"{pct(res['gci_fine [-]'] if ext is not None else None)} | "
                     f"{pct(res['gci_conservative [-]'] if ext is not None else None)} | "
                     f"{pct(err, signed=True)} |")
    return lines


def triple_lines(result):
    """ladder.md's list of every consecutive triple per observable."""
    lines = ["", "Every consecutive triple (finest first): its cell sizes, condition, observed "
              "order, Richardson's extrapolation with that order and GCI_fine (a triple's own "
              "figures: quote none of them unless the table above calls the observable "
              "quotable).", ""]
    for res in result.values():
        factor, label = quantity_format.display_unit(res["unit"], res["values"])
        parts = [f"({', '.join(fmt(1e3 * x, 3) for x in t['h'])}) mm: {t['condition']}, "
                 f"p {fmt(t['order'], 3)}, "
                 + (quantity_format.number(t["extrapolated"], factor)
                    + ("" if label == "-" else f" {label}")
                    if t["extrapolated"] is not None else "-") + ", "
                 + (f"GCI_fine {100 * t['gci_fine']:.2g} %" if t["gci_fine"] is not None
                    else "-")
                 for t in res["triples"]]
        lines.append(f"- **{res['name']}**: " + ("; ".join(parts) if parts else "no triple"))
    return lines


def write_outputs(args, scene_file, runs, observables, result, plot, scene_objects=None):
    out = args.out
    # Before anything is written: the outputs are tracked files, and writing them dirties the tree.
    commit = git_commit()
    write_csv(out, runs, observables)
    table = ladder_table(args, scene_file, runs, result, commit)
    write_table(args, table)
    lines = summary_lines(args, table, result) + triple_lines(result)
    first = next(iter(scene_objects.values()), {}) if scene_objects else {}
    lines += ppc_lines(runs, observables, (first.get("particles_per_cell") or [2])[0])
    with open(os.path.join(out, "ladder.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    if plot:
        draw(out, result)
        draw_cost(out, table, result)


def ppc_lines(runs, observables, base_ppc=2):
    """Particles per cell apart from cells: at each level with --particles-per-cell runs, each
    observable per particle count, its spread over the counts (max - min, relative to the main
    ladder's value there), the change from the scene's count to the next larger one, and beside
    them its change from the next coarser grid (relative likewise)."""
    ppc_runs = [r for r in runs if r["ppc"] is not None and r["data"]]
    if not ppc_runs:
        return []
    counts = sorted({r["ppc"] for r in ppc_runs})
    main = sorted([r for r in runs if r["ppc"] is None and r["data"]], key=lambda r: r["level"])
    lines = ["", "Particles per cell per axis at fixed grids (quadrature against grid error): "
             "values per particle count; spread = (max - min) / |value at the scene's count|; "
             "next count = |value at the next larger count - value at the scene's| / |value at the "
             "scene's|; grid = |value - value one level coarser| / |value|, at the scene's count.",
             "", "| level [-] | observable [unit] | " + " | ".join(f"{p} per axis" for p in counts)
             + " | scene's | spread over particle counts [%] | next count [%] | grid change [%] |",
             "|---|---|" + "---|" * (len(counts) + 4)]

    def rel(a, b):
        return f"{100 * abs(a - b) / abs(b):.1f}" if (a is not None and b) else "-"

    for level in sorted({r["level"] for r in ppc_runs}):
        here = {r["ppc"]: r for r in ppc_runs if r["level"] == level}
        ref = next((r for r in main if r["level"] == level), None)
        coarser = [r for r in main if r["level"] < level]
        coarser = coarser[-1] if coarser else None
        for name, _, unit in observables:
            vals = [here[p]["data"]["values"].get(name) if p in here else None for p in counts]
            v_ref = ref["data"]["values"].get(name) if ref else None
            known = [v for v in vals + [v_ref] if v is not None]
            factor, label = quantity_format.display_unit(unit, known)
            spread = ((max(known) - min(known)) / abs(v_ref)
                      if v_ref and len(known) > 1 else None)
            larger = next((v for p, v in zip(counts, vals) if v is not None and p > base_ppc),
                          None)
            v_c = coarser["data"]["values"].get(name) if coarser else None
            lines.append(f"| x{level:g} | {name} [{label}] | "
                         + " | ".join(quantity_format.number(v, factor) for v in vals)
                         + f" | {quantity_format.number(v_ref, factor)} | "
                         + (f"{100 * spread:.1f}" if spread is not None else "-") + " | "
                         + rel(larger, v_ref) + " | " + rel(v_c, v_ref) + " |")
    return lines


def draw_cost(out, table, result):
    """Speed against accuracy: each level's |value - extrapolated| / |extrapolated| against its
    particle-steps and wall time, one curve per quotable observable (an extrapolation that may
    not be quoted is no reference to measure an error against). Without one, no chart (and a
    stale one from an earlier analysis of OUT is removed)."""
    path = os.path.join(out, "ladder_cost.png")
    curves = [r for r in result.values() if r["quotable"] and r["extrapolated"]]
    if not curves:
        if os.path.exists(path):
            os.remove(path)
        return
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    cost = {lv["level"]: (lv["particle_steps"], lv["wall_time [s]"]) for lv in table["levels"]}
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), sharey=True)
    for res in curves:
        pts = [(cost[lv], abs(v - res["extrapolated"]) / abs(res["extrapolated"]))
               for lv, v in zip(res["levels"], res["values"]) if v is not None and lv in cost]
        pts = [(c, e) for c, e in pts if e > 0]
        if not pts:
            continue
        for i, ax in enumerate(axes):
            ax.loglog([c[i] for c, _ in pts], [e for _, e in pts], "o-", label=res["name"])
    axes[0].set_xlabel("particle-steps [-]")
    axes[1].set_xlabel("wall time [s]")
    axes[0].set_ylabel("|value - extrapolated| / |extrapolated| [-]")
    axes[1].legend(fontsize=7)
    for ax in axes:
        ax.grid(True, which="both", alpha=0.3)
    fig.suptitle(f"{table['scene']}: error against the ladder's extrapolated value "
                 "(quotable observables)", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def draw(out, result):
    """OUT/ladder_<observable>.png: the levels' values against h, in one display unit per figure
    (quantity_format), with, at h = 0, the extrapolated value and the finest level's GCI_fine band
    where the observable is quotable, else the range of converged values; the axes hold every
    point and band drawn."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("ladder: matplotlib missing: no figures (apt-get install python3-matplotlib)")
        return
    for res in result.values():
        pts = [(1e3 * h, v) for h, v in zip(res["h [m]"], res["values"]) if v is not None]
        if not pts:
            continue
        rng = res["range"]
        shown = [v for _, v in pts] + ([rng["low"], rng["high"]] if rng else [])
        factor, label = quantity_format.display_unit(res["unit"], shown)
        fig, ax = plt.subplots(figsize=(5.8, 4.2))
        ax.plot([h for h, _ in pts], [v / factor for _, v in pts], "o-", label="levels")
        ys = [v / factor for _, v in pts]
        x_max = max(h for h, _ in pts)
        width = 0.035 * x_max
        if res["quotable"]:
            ext, finest = res["extrapolated"] / factor, pts[0]
            # GCI_fine is the band about the finest level's value (Celik et al. 2008, eq. 6).
            band = (res["gci_fine [-]"] or 0.0) * abs(finest[1]) / factor
            ax.plot([0.0], [ext], "k*", ms=11, label=f"extrapolated, p = {res['order']:.3g}")
            ax.plot([0.0, finest[0]], [ext, finest[1] / factor], "k--", lw=0.8)
            ax.errorbar([finest[0]], [finest[1] / factor], yerr=[band], color="C3", capsize=4,
                        fmt="none", label="finest level +- GCI_fine")
            ys += [ext, finest[1] / factor - band, finest[1] / factor + band]
        elif rng:
            lo, hi = rng["low"] / factor, rng["high"] / factor
            if rng["order_low"] is not None and len(pts) >= 2:
                # The power laws through the two finest levels with the range's end orders.
                (h1, v1), (h2, v2) = pts[0], pts[1]
                for q, style in ((rng["order_low"], ":"), (rng["order_high"], "--")):
                    ext = gci.richardson(v1, v2, h2 / h1, q)
                    hs = [h1 * i / 40.0 for i in range(41)]
                    ax.plot(hs, [(ext + (v1 - ext) * (x / h1) ** q) / factor for x in hs],
                            style, color="C2", lw=0.9, label=f"power law, p = {q:.3g}")
            ax.fill_between([-width, width], [lo, lo], [max(hi, lo), max(hi, lo)], color="C2",
                            alpha=0.35, lw=0)
            ax.plot([0.0, 0.0], [lo, hi], "-", color="C2", lw=3,
                    label="range: " + quantity_format.range_text(rng))
            ys += [lo, hi]
        span = (max(ys) - min(ys)) or max(abs(max(ys)), 1e-300)
        ax.set_ylim(min(ys) - 0.08 * span, max(ys) + 0.08 * span)
        ax.set_xlim(-2 * width, 1.05 * x_max)
        ax.axvline(0.0, color="0.7", lw=0.6)
        ax.set_xlabel("representative cell size h [mm]")
        ax.set_ylabel(f"{res['name']} [{label}]")
        ax.set_title("\n".join(textwrap.wrap(f"{res['name']}: {res['verdict']}", 70)),
                     fontsize=8)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7, loc="best")
        fig.tight_layout()
        safe = "".join(c if c.isalnum() else "_" for c in res["name"])
        fig.savefig(os.path.join(out, f"ladder_{safe}.png"), dpi=110)
        plt.close(fig)


# --- main ----------------------------------------------------------------------------------------

def number_list(text):
    try:
        out = [float(x) for x in text.split(",") if x.strip()]
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected comma-separated numbers, got '{text}'")
    if not out or any(not (x > 0 and math.isfinite(x)) for x in out):
        raise argparse.ArgumentTypeError(f"expected positive numbers, got '{text}'")
    return out


class Parser(argparse.ArgumentParser):
    def error(self, message):  # a usage error exits 1 (argparse's 2 is our input error)
        self.print_usage(sys.stderr)
        print(f"ladder: {message}", file=sys.stderr)
        sys.exit(1)


class OutputError(Exception):
    """An output (directory or file) that could not be written: exit 3, one line."""


def writing(what):
    """A context that turns an OSError while writing `what` into an OutputError naming the path
    and the reason."""
    class Guard:
        def __enter__(self):
            return self

        def __exit__(self, kind, error, tb):
            if kind is not None and issubclass(kind, OSError):
                path = error.filename or what
                raise OutputError(f"{path}: cannot be written ({what}): "
                                  f"{error.strerror or error}") from None
            return False
    return Guard()


def main(argv):
    """Exit codes: module docstring; an output that cannot be written 3, Ctrl-C 130, each with
    one line on stderr."""
    try:
        return ladder_main(argv)
    except OutputError as e:
        print(f"ladder: {e}", file=sys.stderr)
        return 3
    except KeyboardInterrupt:
        print("ladder: interrupted; run the same command again to resume (finished levels are "
              "kept)", file=sys.stderr)
        return 130
    except BrokenPipeError:  # stdout closed (e.g. piped into head): nothing more to say
        try:
            sys.stdout = open(os.devnull, "w")
        except OSError:
            pass
        return 3


def parse_arguments(argv):
    """(parser, args) of the command line, with args.levels worked out and the options checked
    on their own (a bad one exits through the parser)."""
    ap = Parser(prog="ladder.py", description=__doc__.split("\n")[0])
    ap.add_argument("scene")
    ap.add_argument("--out", required=True)
    ap.add_argument("--levels", type=number_list, default=None,
                    help="multipliers of the scene's cells per axis (default: --ratio, --count)")
    ap.add_argument("--ratio", type=float, default=1.5)
    ap.add_argument("--count", type=int, default=3)
    ap.add_argument("--particles-per-cell", type=number_list, default=[])
    ap.add_argument("--ppc-levels", type=number_list, default=[])
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--ranks", type=int, default=1)
    ap.add_argument("--set", action="append", default=[], help="JSON merge patch over the scene")
    ap.add_argument("--mpm", default=os.path.join(ROOT, "build", "bin", "mpm"))
    ap.add_argument("--mpirun", default="mpirun",
                    help="the MPI launcher with its options, e.g. 'mpirun --oversubscribe'")
    ap.add_argument("--checkpoint-steps", type=int, default=200)
    ap.add_argument("--runs", default=None, help="where the runs go (default OUT/runs)")
    ap.add_argument("--table", default=None)
    ap.add_argument("--analyse-only", action="store_true")
    ap.add_argument("--refingerprint", action="store_true",
                    help="with --analyse-only: today's scene fingerprints, not the runs' own")
    ap.add_argument("--no-plot", action="store_true")
    args = ap.parse_args(argv)
    args.command_line = shlex.join(["campaigns/study/ladder.py"] + argv)
    if args.levels is None and args.analyse_only and not {"--ratio", "--count"} & set(argv):
        # Re-analysing: the levels already run, not the default ladder (which would write an
        # empty analysis over a good one).
        args.levels = levels_already_run(args)
        if not args.levels:
            ap.error(f"--analyse-only: no --levels given and none found in "
                     f"{os.path.join(args.out, 'ladder.json')} or its runs")
    if args.levels is None:
        if not (args.ratio > 1 and args.count >= 1):
            ap.error("--ratio must exceed 1 and --count be at least 1")
        args.levels = [args.ratio ** i for i in range(args.count)]
        args.levels = [float(f"{x:.6g}") for x in args.levels]
    if len(set(args.levels)) != len(args.levels):
        ap.error(f"--levels: a level is repeated: {args.levels}")
    if any(p != int(p) or p < 1 for p in args.particles_per_cell):
        ap.error("--particles-per-cell: expected whole numbers >= 1")
    if args.threads < 1 or args.ranks < 1 or args.checkpoint_steps < 1:
        ap.error("--threads, --ranks and --checkpoint-steps must be at least 1")
    return ap, args


def read_patched_scene(args):
    """(scene resolved with the --set patches, the patches), or the exit code after saying on
    stderr why not (1: a --set that is not a JSON object; 2: a scene without a usable grid)."""
    if not os.path.isfile(args.scene):
        print(f"ladder: {args.scene}: expected a scene file (JSON), "
              f"{'got a directory' if os.path.isdir(args.scene) else 'no such file'}",
              file=sys.stderr)
        return 2
    try:
        sets = [json.loads(s) for s in args.set]
        if any(not isinstance(x, dict) for x in sets):
            print("ladder: --set: expected a JSON object (a merge patch), e.g. "
                  "'{\"time\": {\"max_time\": 1e-5}}'", file=sys.stderr)
            return 1
    except ValueError as e:
        print(f"ladder: --set: not JSON: {e}", file=sys.stderr)
        return 1
    try:
        scene = load_resolved(args.scene)
        for x in sets:
            scene = merge_patch(scene, x)
        g = scene["grid"]
        if not (isinstance(g["cells"], list) and all(isinstance(c, int) and c >= 1
                                                    for c in g["cells"])
                and len(g["lower"]) == len(g["upper"]) == len(g["cells"]) in (2, 3)
                and all(isinstance(a, (int, float)) and isinstance(b, (int, float)) and b > a
                        for a, b in zip(g["lower"], g["upper"]))
                and isinstance(scene["time"]["max_time"], (int, float))):
            raise ValueError("expected /grid/cells whole numbers >= 1, /grid/lower and /grid/upper "
                             "numbers (upper > lower) of the same length 2 or 3, and a number "
                             "/time/max_time")
        box = g.get("refine")
        if isinstance(box, list):  # several boxes: no one box whose cells the levels refine
            raise ValueError("/grid/refine is a list of boxes: a ladder refines one box (its "
                             "cells are the level's h); give one box that holds them all "
                             "(docs/scenes.md#graded-grids)")
        if box is not None and not (
                isinstance(box, dict) and isinstance(box.get("factor"), (int, float))
                and all(isinstance(box.get(k), list) and len(box[k]) == len(g["cells"])
                        and all(isinstance(x, (int, float)) for x in box[k])
                        for k in ("lower", "upper"))):
            raise ValueError("expected /grid/refine an object with a number factor and lower and "
                             "upper of as many numbers as /grid/cells (docs/scenes.md#graded-grids)")
    except (OSError, ValueError, KeyError, TypeError, AttributeError, IndexError) as e:
        print(f"ladder: {args.scene}: cannot read the scene's grid (/grid/cells, /grid/lower, "
              f"/grid/upper) and /time/max_time: {e}", file=sys.stderr)
        return 2
    return scene, sets


def check_destinations(ap, args):
    """The output options against the file system; 1 (after a line on stderr) for an --mpm that
    cannot run, else None. A bad --out, --runs or --table exits through the parser."""
    for path, what in ((args.out, "--out"), (args.runs, "--runs")):
        if path and os.path.exists(path) and not os.path.isdir(path):
            ap.error(f"{what} {path}: exists and is not a directory")
    if args.table and (os.path.isdir(args.table) or not os.path.isdir(
            os.path.dirname(os.path.abspath(args.table)))):
        ap.error(f"--table {args.table}: expected a file path in an existing directory")
    if args.refingerprint and not args.analyse_only:
        ap.error("--refingerprint goes with --analyse-only (a run records its own fingerprint)")
    if not args.analyse_only and not os.access(args.mpm, os.X_OK):
        print(f"ladder: --mpm {args.mpm}: not an executable (build it: cmake --build build)",
              file=sys.stderr)
        return 1
    return None


def levels_already_run(args):
    """The levels of OUT/ladder.json, else those of the run folders (runs/x<level>), ascending;
    [] when there are none."""
    try:
        with open(os.path.join(args.out, "ladder.json")) as f:
            levels = [float(lv["level"]) for lv in json.load(f).get("levels", [])]
        if levels:
            return sorted(set(levels))
    except (OSError, ValueError, KeyError, TypeError):
        pass
    runs_root = args.runs or os.path.join(args.out, "runs")
    found = set()
    for name in os.listdir(runs_root) if os.path.isdir(runs_root) else []:
        match = re.fullmatch(r"x([0-9.eE+-]+)", name)
        if match:
            try:
                found.add(float(match.group(1)))
            except ValueError:
                pass
    return sorted(found)


def plan_levels(ap, args, scene):
    """[(level, particles per cell or None)]: the grid levels, then the --ppc-levels per
    --particles-per-cell. Two levels with the same cells exit through the parser; a level whose
    whole cells refine the axes unevenly is a warning."""
    seen = {}
    for lv in sorted(args.levels):
        cells, factor = tuple(level_cells(scene, lv)), level_factor(scene, lv)
        if factor is not None and not 1.0 <= factor <= 64.0:
            ap.error(f"--levels: {lv:g} gives /grid/refine/factor {factor:g} "
                     f"({scene['grid']['refine']['factor']:g} x {lv:g}); expected levels that "
                     "keep it within [1, 64]")
        key = (cells, tuple(fine_cells(scene, factor)) if factor is not None else None)
        if key in seen:
            ap.error(f"--levels: {seen[key]:g} and {lv:g} give the same cells {list(cells)}"
                     + (" and the same refined box" if factor is not None else ""))
        seen[key] = lv
        if factor is None:
            ratios = [c / c0 for c, c0 in zip(cells, scene["grid"]["cells"])]
        else:
            ratios = [a / b for a, b in zip(fine_cells(scene, scene["grid"]["refine"]["factor"]),
                                            fine_cells(scene, factor))]
        if any(abs(r / lv - 1.0) > 0.02 for r in ratios):
            print(f"ladder: warning: level {lv:g} refines the axes by "
                  f"{', '.join(f'{r:.3f}' for r in ratios)} (whole cells): the representative h "
                  "takes it into account, but the refinement is not uniform", file=sys.stderr)
    plan = [(lv, None) for lv in sorted(args.levels)]
    return plan + [(lv, int(p)) for lv in sorted(args.ppc_levels) for p in args.particles_per_cell]


def check_level_scenes(args, scene, plan, rod, sets):
    """Writes every level's scene and has `mpm check` read it before anything runs: 2 (after the
    refusals on stderr) when one is refused, else 0."""
    problems = []
    for level, ppc in plan:
        path = os.path.join(args.out, "scenes", run_name(level, ppc) + ".json")
        with writing("a level's scene"):
            write_level_scene(path, args.scene, scene, level, ppc, args.checkpoint_steps, rod,
                              sets)
        done = results.Launcher(args.mpm).run("check", path, threads=1, check=False)
        if done.returncode != 0:
            problems.append(f"level {run_name(level, ppc)} (exit {done.returncode}): "
                            + (done.stderr.strip() or done.stdout.strip()))
            continue
        try:  # what mpm check warns of (elongated graded cells, ...) is said before the runs
            warnings = json.loads(done.stdout).get("warnings", [])
        except ValueError:
            warnings = []
        for w in warnings:
            print(f"ladder: warning: level {run_name(level, ppc)}: {w}", file=sys.stderr)
    if problems:
        print("ladder: a level's scene is refused; nothing was run:\n" + "\n".join(problems),
              file=sys.stderr)
        return 2
    return 0


def run_plan(args, scene, plan, rod, sets, observables, runs_root):
    """(runs, failed): each level run (unless finished, or --analyse-only) and read back, the
    failed ones named with their log; None (after a line on stderr) when the user stops a run."""
    runs, failed = [], []
    for level, ppc in plan:
        name = run_name(level, ppc)
        scene_path = os.path.join(args.out, "scenes", name + ".json")
        with writing("a level's scene"):
            text = write_level_scene(scene_path, args.scene, scene, level, ppc,
                                     args.checkpoint_steps, rod, sets)
        run_dir = os.path.join(runs_root, name)
        if not args.analyse_only and not finished(run_dir, text):
            try:
                with writing("--runs" if args.runs else "--out"):
                    code = run_level(args, scene_path, text, run_dir)
            except KeyboardInterrupt:
                print("ladder: interrupted; run the same command again to resume", file=sys.stderr)
                return None
            if code != 0:
                failed.append(f"{name} (exit {code}; {run_dir}/ladder.log)")
                print(f"ladder: {name} failed with exit {code}", file=sys.stderr)
        cells, factor = level_cells(scene, level), level_factor(scene, level)
        runs.append({"name": name, "level": level, "ppc": ppc, "cells": cells,
                     "refine_factor": factor, "scene_path": scene_path,
                     "h": representative_h(scene, cells, factor),
                     "data": read_run(run_dir, text, scene, rod, observables)})
    return runs, failed


def fill_fingerprints(args, runs):
    """Runs made before summary.json carried the fingerprint, and with --refingerprint every
    run: the fingerprint `mpm check` gives the level's scene today."""
    for r in runs:
        if not r["data"]:
            continue
        if not r["data"]["fingerprint"]:
            r["data"]["fingerprint"] = fingerprint_of(args, r["scene_path"])
        elif args.refingerprint:
            today = fingerprint_of(args, r["scene_path"])
            if today and today != r["data"]["fingerprint"]:
                print(f"ladder: {r['name']}: fingerprint {r['data']['fingerprint']} of the run, "
                      f"{today} of the scene today (--refingerprint): the table takes today's",
                      file=sys.stderr)
                r["data"]["fingerprint"] = today


SEEDING_SPREAD = 0.01  # a body's seeded volume that differs more between levels is said


def seeding_warnings(runs):
    """Warnings on stderr for what the levels' differences hold besides the cells: uGIMP boxes
    narrowed on a graded grid (docs/scenes.md#graded-grids), and a body whose seeded volume
    (volume_ratio: particle volume over the geometry's) differs between levels by more than 1 %
    (its mass then differs as much, and the GCI counts it as discretization error)."""
    ladder_runs = [r for r in runs if r["ppc"] is None and r["data"]]
    for r in ladder_runs:
        if r["data"].get("narrowed"):
            print(f"ladder: warning: level {r['name']}: {r['data']['narrowed']} particle-steps had "
                  "their uGIMP box narrowed (coarse particles among fine cells; "
                  "docs/scenes.md#graded-grids)", file=sys.stderr)
    names = sorted({n for r in ladder_runs for n in (r["data"].get("volume_ratio") or {})})
    for n in names:
        ratios = [(r["name"], r["data"]["volume_ratio"].get(n)) for r in ladder_runs
                  if isinstance(r["data"].get("volume_ratio", {}).get(n), (int, float))]
        if len(ratios) >= 2:
            lo, hi = min(v for _, v in ratios), max(v for _, v in ratios)
            if hi - lo > SEEDING_SPREAD * lo:
                print(f"ladder: warning: the seeded volume of {n} differs by "
                      f"{100 * (hi / lo - 1):.2g} % between levels (volume_ratio "
                      + ", ".join(f"{name} {v:.4f}" for name, v in ratios)
                      + "): its mass differs as much, and the GCI counts that as discretization "
                      "error; put its faces on the nodes of every level", file=sys.stderr)


def report(args, scene, runs, observables):
    """Analyses the runs and writes ladder.md, the table and the figure; the measures that could
    not be taken are warnings, Lf and Dm sharing one line."""
    result = analyse(runs, observables)
    seeding_warnings(runs)
    said = {}
    for res in result.values():
        for note in res["notes"]:
            if "not measured" in note:
                said.setdefault(note, []).append(res["name"])
    for note, names in said.items():
        print(f"ladder: warning: {' and '.join(names)} {note}", file=sys.stderr)
    with writing("the ladder's outputs"):
        write_outputs(args, args.scene, runs, observables, result, not args.no_plot,
                      scene.get("objects", {}))
    print(f"ladder: {os.path.join(args.out, 'ladder.md')}" + (f", table {args.table}"
                                                                if args.table else ""))


def ladder_main(argv):
    ap, args = parse_arguments(argv)
    patched = read_patched_scene(args)
    if isinstance(patched, int):
        return patched
    scene, sets = patched
    code = check_destinations(ap, args)
    if code:
        return code
    rod = taylor_rod(scene)
    observables = observables_of(scene, rod)
    runs_root = args.runs or os.path.join(args.out, "runs")
    with writing("--out"):
        os.makedirs(os.path.join(args.out, "scenes"), exist_ok=True)
    with writing("--runs" if args.runs else "--out"):
        os.makedirs(runs_root, exist_ok=True)
    plan = plan_levels(ap, args, scene)
    if not args.analyse_only:  # every level's scene is checked before anything runs
        code = check_level_scenes(args, scene, plan, rod, sets)
        if code:
            return code
    ran = run_plan(args, scene, plan, rod, sets, observables, runs_root)
    if ran is None:
        return 130
    runs, failed = ran
    fill_fingerprints(args, runs)
    report(args, scene, runs, observables)
    if failed:
        print("ladder: failed: " + ", ".join(failed), file=sys.stderr)
        return 3
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
