#!/usr/bin/env python3
"""Result bounds for arithmetic changes (issue 41; docs/performance.md, "Result bounds for
arithmetic changes (issue 41)"): does a candidate `mpm` still give today's results?

  result_bounds.py REF_MPM NEW_MPM OUT_DIR [--set table2,recommended,taylor,verification]
                   [--jobs 1] [--threads 2] [--reuse-ref] [--halving [SETS]]
                   [--ensemble N [--ensemble-set table2]] [--new-shuffle K]

REF_MPM is today's main, NEW_MPM the candidate. Both run every scene of the chosen sets to its full
max_time, on the same thread count (results are bit-identical on any thread count, docs/mpm.md):
  table2        data/scenes/sphere_cylinder/case01.json ... case16.json (the report's Table 2);
  recommended   data/scenes/sphere_cylinder/recommended.json;
  taylor        data/scenes/taylor/h8_quarter.json (the 3D quarter rod, 6 cells per radius), the
                same at the Taylor campaign's default 4 cells per radius (its grid as
                campaigns/taylor/taylor.py lays it out) and h8_axisymmetric.json (the r-z twin);
  verification  data/scenes/verification/*.json that `mpm check` accepts (elastic_base.json is
                only a base the others extend).
Each scene runs from a scene file written to OUT_DIR/scenes/ that `extends` the original by
absolute path with `output.snapshots` off. The history interval is kept, because the history
rows are where `max_pressure` is sampled and where the energy error's maximum is read. The
Taylor scenes keep their snapshots (the `object` field only): Lf and Dm are measured on the last
one, as campaigns/taylor/taylor.py measures them.

The bounds (the issue's wording: "results may change in the last digits where the physics cannot
tell, if the books still close (momentum to 1e-12 of |p0|, energy error within 1e-4 of today's on
every Table 2 case and the recommended scene) and every observable of the recommended scene, the
Taylor H8 rod and the verification scenes stays within 1e-6 relative of today's (or within the
scatter of one time-step halving, where that is smaller: say which)"):
  momentum      max over the history rows of |momentum + outflow_momentum - p0 - boundary_impulse
                - external_impulse| / |p0| <= 1e-12 for NEW (REF's printed too). p0 is the t = 0
                row; where it is zero up to round-off, bodies meeting head-on are measured against
                one body's initial momentum sqrt(2 m KE0) (as the verification tests are), bodies
                starting at rest against the largest momentum of the run; the verdict says which;
  energy        energy_error at the end and max |energy_error| over the rows: |NEW - REF| <= 1e-4
                on the Table 2 cases and the recommended scene (reported on the others);
  observables   every number in summary.json (recursively: the final ledger row, mean velocities,
                peak pressures and their times, the crater, failed and converted counts, steps,
                ...), minus timing, memory, thread and host keys and the energy error (a book,
                above); the gauges' max, min and last value from history.csv; the Taylor rod's Lf
                and Dm. Passes by `1e-6` when |NEW - REF| <= 1e-6 |REF|; else by `halving` when
                REF was also run at half its time.multiplier (--halving SETS) and |NEW - REF| <=
                |REF_half - REF|; a momentum or impulse within 1e-12 |p0| of REF passes by
                `round-off` (the momentum bound: a component that is zero up to round-off), and
                so does a velocity, energy or stress within 1e-12 of the scene's scale for its
                unit (round_off_scales), and a peak's time where its peak did.
                A string (the status) must be equal, or with --ensemble one a member had.
The ensemble (issue 57: "a change of summation order is allowed where its results stay within
the method's own round-off sensitivity"): with --ensemble N (N >= 5), REF also runs the scenes of
--ensemble-set (default table2: erosion and failure, whose answer round-off can change) N - 1
more times with its particles stored in other orders (solver.shuffle_particles = 1 .. N - 1,
docs/scenes.md), the physics unchanged; with the seeded REF, N members. An observable, and the
energy error's end and max |.|, then also passes by `ensemble` when NEW lies within the members'
range widened by three of its widths on each side, [min - 3 w, max + 3 w], w = max - min: a
change of summation order is one more draw from the members' distribution, which is not normal:
erosion's discrete events make it heavy-tailed (docs/performance.md, the measured ensemble: a pure
reordering fell up to 2.3 widths beyond five members' range). --new-shuffle K runs NEW with
solver.shuffle_particles = K: a pure change of order, which must pass.

With --halving (on the scenes of SETS, a comma list; alone: every set run) the scatter |REF_half - REF| / |REF| of every observable is written too, and the
column `min bound` says whether NEW also holds the stricter reading (within the smaller of 1e-6
and the scatter).

Writes OUT_DIR/bounds.md (a table per scene: observable, REF, NEW, relative difference, halving
scatter, criterion, pass) and OUT_DIR/bounds.csv, prints one verdict line per scene and exits 1
if any bound fails (2 if a run could not be made).

Resumable: the runs go to OUT_DIR/runs/<scene>/{ref,new,ref_half,ref_order1..}; a run directory whose
summary.json exists and whose stamp (bounds_stamp.json: the extending scene and the binary's
SHA-256) matches is not run again. --reuse-ref relaxes the stamp of the REF runs (ref, ref_half)
to the scene alone, so that the REF results of one call serve later calls with other NEW binaries
(and a REF binary rebuilt from the same commit).

Only the standard library (with impact.results' launcher and plain readers, python/);
`mpm run SCENE --out DIR --threads N` and `mpm check SCENE` are used.
"""
import argparse
import concurrent.futures
import csv
import glob
import hashlib
import json
import math
import os
import re
import sys
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "python"))  # impact.results (pure Python)
from impact.results import Launcher, history_columns, read_points  # noqa: E402
SCENES = os.path.join(ROOT, "data", "scenes")
SETS = ("table2", "recommended", "taylor", "verification")

OBSERVABLE_BOUND = 1e-6      # relative, every observable
MOMENTUM_BOUND = 1e-12       # of |p0|, the momentum closure and round-off momenta
ENERGY_BOUND = 1e-4          # absolute on energy_error [-], Table 2 and recommended
ENERGY_SETS = ("table2", "recommended")
MIN_ENSEMBLE = 5             # members, the seeded REF included (issue 57)
ENSEMBLE_WIDTHS = 3.0        # NEW within the members' range widened by this many of its widths
CAMPAIGN_CELLS_PER_RADIUS = 4  # campaigns/taylor/taylor.py's default --cells-per-radius
ANVIL_LAYER = 0.5e-3         # Dm from the particles within this distance of the anvil [m] (taylor.py)

# summary.json keys that are not results: timing, memory, threads, host. Matched on the key's
# name without its unit, at any depth.
SKIPPED = {"wall_time", "phase_seconds", "particle_steps_per_second", "threads", "ranks",
           "omp_wait_policy", "available_memory", "memory", "memory_estimate",
           "memory_per_particle", "peak_resident_memory", "units", "host", "hostname",
           "version", "git", "date", "started", "energy_error"}


# ---------------------------------------------------------------------------------------------
# The comparison (pure functions: tests/mpm/benchmark/result_bounds_test.py feeds them synthetic
# summaries and histories).

def bare(key):
    """A key without its unit: 'wall_time [s]' -> 'wall_time'."""
    return key.split(" [")[0]


def flatten(node, prefix=""):
    """{path: value} of every number and string leaf of a summary, skipping SKIPPED keys. Lists
    are indexed: 'observables/objects/rod/mean_velocity [m/s]/0'. Booleans count as strings."""
    out = {}
    if isinstance(node, dict):
        for key, value in node.items():
            if bare(key) in SKIPPED:
                continue
            out.update(flatten(value, f"{prefix}/{key}" if prefix else key))
    elif isinstance(node, list):
        for i, value in enumerate(node):
            out.update(flatten(value, f"{prefix}/{i}"))
    elif isinstance(node, bool) or isinstance(node, str) or node is None:
        out[prefix] = str(node)
    elif isinstance(node, (int, float)):
        out[prefix] = float(node)
    return out


def per_body_units(cols):
    """The history's momentum and impulse columns under their 3D names: in plane strain they are
    per metre of thickness, "momentum_x [(kg m/s)/m]", and the books read them alike."""
    out = dict(cols)
    for k, v in cols.items():
        for plane, body in (("[(kg m/s)/m]", "[kg m/s]"), ("[(N s)/m]", "[N s]")):
            if k.endswith(plane):
                out.setdefault(k[: -len(plane)] + body, v)
    return out


def momentum_scale(cols, bodies=()):
    """(scale, how): what the momentum closure is measured against. |p0|, the first row's
    momentum, unless it is zero up to round-off (below 1e-9 of the largest body's): bodies meeting
    head-on are measured against one body's initial momentum sqrt(2 m KE) (bodies = [(m, KE0)]),
    as the verification tests measure them; bodies starting at rest against the largest term of
    the largest term of the balance over the rows, momentum or boundary or external impulse: the
    round-off of a sum scales with its largest term (a block resting on a wall under gravity keeps
    a round-off momentum while gravity's impulse and the wall's grow and cancel; on a ramp the
    wall's normal reaction cancels most of gravity's impulse)."""
    cols = per_body_units(cols)
    # A header-only history (a run stopped before its first row) has empty columns.
    p0 = math.sqrt(sum((cols.get(f"momentum_{c} [kg m/s]") or [0.0])[0] ** 2 for c in "xyz"))
    body = max((math.sqrt(2.0 * m * ke) for m, ke in bodies if m > 0.0 and ke > 0.0), default=0.0)
    if p0 > 1e-9 * body and p0 > 0.0:
        return p0, "|p0|"
    if body > 0.0:
        return body, "one body's initial momentum (p0 = 0)"
    rows = len(cols.get("time [s]", []))

    def largest(term, unit):
        return max((math.sqrt(sum(cols.get(f"{term}_{c} [{unit}]", [0.0] * rows)[i] ** 2
                                  for c in "xyz")) for i in range(rows)), default=0.0)
    term = max(largest("momentum", "kg m/s"), largest("boundary_impulse", "N s"),
               largest("external_impulse", "N s"))
    if term > 0.0:
        return term, "the largest momentum or impulse over the run (a start at rest)"
    return 1.0, "1 kg m/s (nothing moves)"


def momentum_closure(cols, scale):
    """max over rows of |momentum + outflow_momentum - p0 - boundary_impulse - external_impulse|
    / scale (docs/mpm.md, "Momentum closure")."""
    cols = per_body_units(cols)
    n = len(cols.get("time [s]", []))
    worst = 0.0
    for i in range(n):
        s = 0.0
        for c in "xyz":
            def at(name, unit):
                col = cols.get(f"{name}_{c} [{unit}]")
                return col[i] if col else 0.0
            p0 = cols.get(f"momentum_{c} [kg m/s]", [0.0])[0]
            r = (at("momentum", "kg m/s") + at("outflow_momentum", "kg m/s") - p0
                 - at("boundary_impulse", "N s") - at("external_impulse", "N s"))
            s += r * r
        worst = max(worst, math.sqrt(s) / scale)
    return worst


def energy_errors(cols):
    """(energy_error at the last row, max |energy_error| over the rows)."""
    e = cols.get("energy_error [-]", [])
    if not e:
        return float("nan"), float("nan")
    if any(math.isnan(v) for v in e):  # max() would skip a NaN or not, by where it lies
        return e[-1], float("nan")
    return e[-1], max(abs(v) for v in e)


def gauge_observables(cols):
    """The gauges' max, min and last value (their peaks), from history.csv's gauge columns."""
    out = {}
    for k, v in cols.items():
        if k.startswith("gauge_") and v:
            out[f"history/{k}/max"] = max(v)
            out[f"history/{k}/min"] = min(v)
            out[f"history/{k}/last"] = v[-1]
    return out


def relative(ref, new):
    """|new - ref| / |ref|; 0 when equal, inf when ref is 0 and new is not."""
    if new == ref:
        return 0.0
    if ref == 0.0 or not math.isfinite(ref) or not math.isfinite(new):
        return math.inf
    return abs(new - ref) / abs(ref)


def unit_of(name):
    """The unit of an observable: the bracket that ends its path, before a list index or a
    history column's max, min or last ('observables/objects/rod/mean_velocity [m/s]/2' -> 'm/s',
    'history/gauge_v [m/s]/max' -> 'm/s'; units hold '/' themselves:
    'final/momentum_y [(kg m/s)/m]'); '' without."""
    m = re.search(r" \[([^\[\]]*)\](?:/(?:\d+|max|min|last))?$", name)
    return m.group(1) if m else ""


def round_off_scale(name, p0, scales):
    """The scale a quantity of this name's unit is round-off against, or None: a momentum or
    impulse |p0|; with `scales` ({"velocity": V, "energy": E, "pressure": P}: the momentum scale
    over the total mass, the initial energy, that energy over the bodies' volume), a velocity V,
    an energy E and a stress P (a body in rigid translation has peak pressures of 1e-6 Pa). A body at rest in a symmetric scene
    has mean velocity components of 1e-15 m/s that any change of summation order moves."""
    unit = unit_of(name)
    if p0 is not None and unit in ("kg m/s", "N s", "(kg m/s)/m", "(N s)/m"):
        return p0
    if not scales:
        return None
    return {"m/s": scales.get("velocity"), "J": scales.get("energy"), "J/m": scales.get("energy"),
            "Pa": scales.get("pressure")}.get(unit)


def within_ensemble(new, members):
    """NEW within the members' range widened by ENSEMBLE_WIDTHS of its width on each side (module
    docstring)."""
    values = [m for m in members if isinstance(m, (int, float)) and math.isfinite(m)]
    if len(values) < len(members) or not values or not math.isfinite(new):
        return False
    lo, hi = min(values), max(values)
    w = ENSEMBLE_WIDTHS * (hi - lo)
    return lo - w <= new <= hi + w


def ensemble_width(ref, members):
    """The members' relative width (max - min) / |REF|; None without members or with a member
    that has no finite value."""
    if not members or any(isinstance(m, str) or not math.isfinite(m) for m in members):
        return None
    return relative(ref, ref + (max(members) - min(members)))


def judge(name, ref, new, half=None, p0=None, bound=OBSERVABLE_BOUND, members=None,
          scales=None):
    """One observable: a dict with rel, scatter (relative |REF_half - REF| / |REF|, None without a
    halving run), spread (the ensemble's relative width, None without one), criterion ('1e-6',
    'round-off', 'halving', 'ensemble', 'equal', or '' when it fails), ok, and strict (passes the
    stricter reading: within min(1e-6 |REF|, |REF_half - REF|); None without a halving run).
    `members`: the ensemble's values (REF's included)."""
    row = {"observable": name, "ref": ref, "new": new, "half": half, "rel": None, "scatter": None,
           "spread": None, "criterion": "", "ok": False, "strict": None}
    if isinstance(ref, str) or isinstance(new, str):
        row["ok"] = ref == new or (members is not None and new in members)
        row["criterion"] = "equal" if ref == new else ("ensemble" if row["ok"] else "")
        return row
    if math.isnan(new) and math.isnan(ref):  # NaN in both (a gauge with no member left): same
        row["rel"], row["criterion"], row["ok"] = 0.0, "equal", True
        return row
    diff = abs(new - ref) if math.isfinite(new) and math.isfinite(ref) else math.inf
    if new == ref:
        diff = 0.0
    row["rel"] = relative(ref, new) if diff > 0.0 else 0.0
    scatter = None  # |REF_half - REF|
    if half is not None and not isinstance(half, str):
        scatter = abs(half - ref)
        row["scatter"] = relative(ref, half)
    if diff <= bound * abs(ref):
        row["criterion"], row["ok"] = "1e-6", True
    elif (scale := round_off_scale(name, p0, scales)) is not None and diff <= MOMENTUM_BOUND * scale:
        row["criterion"], row["ok"] = "round-off", True
    elif scatter is not None and diff <= scatter:
        row["criterion"], row["ok"] = "halving", True
    elif members is not None and within_ensemble(new, members):
        row["criterion"], row["ok"] = "ensemble", True
    if members is not None:
        row["spread"] = ensemble_width(ref, members)
    if scatter is not None:
        row["strict"] = diff <= min(bound * abs(ref), scatter) or (
            row["criterion"] == "round-off")
    return row


def round_off_scales(summary, p_scale, cols=None):
    """{"velocity", "energy", "pressure"} from REF's summary.json and history (per metre of
    thickness in plane strain, as its momenta): a moving start's momentum scale over the total
    mass, its initial energy, and that energy over the bodies' particle volume. A start at rest
    takes the largest energy that entered instead, kinetic + strain or the external work over the
    rows, and the speed sqrt(2 E / M) (an impulse over the mass there is gravity's free fall over
    the run, which a resting body never has)."""
    def top(name):
        return next((v for k, v in summary.items() if bare(k) == name and
                     isinstance(v, (int, float))), 0.0)
    mass, energy = top("mass"), top("initial_energy")
    if not mass > 0.0:
        return None
    if energy > 0.0:
        v, e = p_scale / mass, energy
    else:
        e = max((abs(x) for k, col in (cols or {}).items()
                 if bare(k) in ("total_energy", "external_work") for x in col
                 if math.isfinite(x)), default=0.0)
        if not e > 0.0:
            return None
        v = math.sqrt(2.0 * e / mass)
    volume = sum(next((x for k, x in o.items() if bare(k) == "particle_volume"), 0.0)
                 for o in summary.get("objects", {}).values())
    return {"velocity": v, "energy": e, "pressure": e / volume if volume > 0.0 else None}


def compare_observables(ref, new, half=None, p0=None, ensemble=None, scales=None):
    """judge() for every observable of REF and NEW ({name: value}, e.g. flatten(summary)).
    `ensemble`: the other members' observables (a list of such dicts). One present in only one of
    REF and NEW fails (criterion 'missing'); one a member lacks is judged without the ensemble."""
    rows = []
    for name in sorted(set(ref) | set(new)):
        if name not in ref or name not in new:
            rows.append({"observable": name, "ref": ref.get(name), "new": new.get(name),
                         "half": None, "rel": None, "scatter": None, "spread": None,
                         "criterion": "missing", "ok": False, "strict": None})
            continue
        members = None
        if ensemble and all(name in m for m in ensemble):
            members = [ref[name]] + [m[name] for m in ensemble]
        rows.append(judge(name, ref[name], new[name], None if half is None else half.get(name),
                          p0, members=members, scales=scales))
    # A peak's time is the time of a round-off value where the peak itself passed as round-off.
    by_name = {r["observable"]: r for r in rows}
    for r in rows:
        name = r["observable"]
        if r["ok"] or not name.endswith("_time [s]"):
            continue
        head = name[: -len("_time [s]")] + " ["  # peak_time -> peak [, max_pressure_time -> ...
        peak = next((p for n, p in by_name.items() if n.startswith(head)), None)
        if peak is not None and peak["criterion"] == "round-off":
            r["criterion"], r["ok"] = "round-off", True
    return rows


def books(ref_cols, new_cols, scale, energy_judged, ensemble_cols=None):
    """The books: momentum closure of NEW (and REF) against MOMENTUM_BOUND x scale, and the energy
    error's end value and max |.| against ENERGY_BOUND (judged when energy_judged, else reported),
    or within the ensemble (ensemble_cols: the other members' histories; module docstring).
    A list of rows like judge()'s: observable, ref, new, criterion, ok."""
    rows = []
    m_ref, m_new = momentum_closure(ref_cols, scale), momentum_closure(new_cols, scale)
    rows.append({"observable": "books/momentum_closure [of the scale]", "ref": m_ref, "new": m_new,
                 "half": None, "rel": None, "scatter": None, "spread": None,
                 "criterion": f"<= {MOMENTUM_BOUND:g}", "ok": m_new <= MOMENTUM_BOUND,
                 "strict": None})
    (end_r, max_r), (end_n, max_n) = energy_errors(ref_cols), energy_errors(new_cols)
    others = [energy_errors(c) for c in ensemble_cols or []]
    for i, (what, r, n) in enumerate((("end", end_r, end_n), ("max_abs", max_r, max_n))):
        d = abs(n - r) if math.isfinite(n) and math.isfinite(r) else math.inf
        members = [r] + [o[i] for o in others] if others else None
        row = {"observable": f"books/energy_error_{what} [-]", "ref": r, "new": n, "half": None,
               "rel": d, "scatter": None, "spread": None, "strict": None,
               "criterion": f"abs <= {ENERGY_BOUND:g}" if energy_judged else "reported",
               "ok": d <= ENERGY_BOUND or not energy_judged}
        if members is not None:
            row["spread"] = max(members) - min(members)
            if energy_judged and not row["ok"] and within_ensemble(n, members):
                row["criterion"], row["ok"] = "ensemble", True
        rows.append(row)
    return rows


# ---------------------------------------------------------------------------------------------
# Runs.

def sha256(path):
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)
    return h.hexdigest()


def campaign_resolution(quarter, cells_per_radius=CAMPAIGN_CELLS_PER_RADIUS):
    """The grid patch that puts the quarter rod at the Taylor campaign's default resolution, laid
    out as campaigns/taylor/taylor.py's scene() lays it out: dx = R0 / cells, L0 / dx + 1 cells
    along the rod, 2.2 R0 / dx across (the mushroom's room)."""
    with open(quarter) as f:
        rod = json.load(f)["objects"]["rod"]["geometry"]
    r0, l0 = rod["radius"], rod["top"][0] - rod["bottom"][0]
    dx = r0 / cells_per_radius
    nx, ny = math.ceil(l0 / dx) + 1, math.ceil(2.2 * r0 / dx)
    return {"grid": {"upper": [nx * dx, ny * dx, ny * dx], "cells": [nx, ny, ny]}}


def scenes_of(sets, mpm):
    """[(name, set, original path, patch or None)] of the chosen sets."""
    out = []
    sc = os.path.join(SCENES, "sphere_cylinder")
    if "table2" in sets:
        out += [(os.path.basename(p)[:-5], "table2", p, None)
                for p in sorted(glob.glob(os.path.join(sc, "case*.json")))]
    if "recommended" in sets:
        out.append(("recommended", "recommended", os.path.join(sc, "recommended.json"), None))
    if "taylor" in sets:
        quarter = os.path.join(SCENES, "taylor", "h8_quarter.json")
        out += [("taylor_h8_quarter", "taylor", quarter, None),
                ("taylor_h8_quarter_cpr4", "taylor", quarter, campaign_resolution(quarter)),
                ("taylor_h8_axisymmetric", "taylor",
                 os.path.join(SCENES, "taylor", "h8_axisymmetric.json"), None)]
    if "verification" in sets:
        for p in sorted(glob.glob(os.path.join(SCENES, "verification", "*.json"))):
            # A base scene without a grid or objects (elastic_base.json) is not a scene to run.
            if Launcher(mpm).run("check", p, check=False).returncode == 0:
                out.append((f"verification_{os.path.basename(p)[:-5]}", "verification", p, None))
    return out


def extending_scene(original, kind, patch=None, multiplier=None, shuffle=0):
    """The scene a run reads: the original by absolute path (and patch), without snapshots (the
    Taylor rod keeps them, with the object field, for Lf and Dm); half the multiplier for a
    halving run; its particles stored in the order of seed `shuffle` (0: seed order)."""
    doc = {"extends": os.path.abspath(original)}
    doc.update(patch or {})
    if shuffle:
        doc["solver"] = dict(doc.get("solver", {}), shuffle_particles=shuffle)
    if kind == "taylor":
        doc["output"] = {"snapshots": True, "fields": ["object"]}
    else:
        doc["output"] = {"snapshots": False}
    if multiplier is not None:
        doc["time"] = {"multiplier": multiplier}
    return doc


def finished(run_dir, stamp, scene_only):
    """A run of this stamp finished in run_dir (summary.json and a matching bounds_stamp.json)."""
    try:
        with open(os.path.join(run_dir, "bounds_stamp.json")) as f:
            old = json.load(f)
        if not os.path.exists(os.path.join(run_dir, "summary.json")):
            return False
    except (OSError, ValueError):
        return False
    if scene_only:
        return old.get("scene") == stamp["scene"]
    return all(old.get(k) == v for k, v in stamp.items())


def run(mpm, scene_doc, run_dir, threads, scene_only):
    """Runs mpm on scene_doc into run_dir unless finished; (wall seconds or None if reused,
    error message or None)."""
    stamp = {"scene": scene_doc, "binary_sha256": sha256(mpm)}
    if finished(run_dir, stamp, scene_only):
        return None, None
    os.makedirs(run_dir, exist_ok=True)
    stamp_path = os.path.join(run_dir, "bounds_stamp.json")
    if os.path.exists(stamp_path):
        os.remove(stamp_path)
    scene_path = run_dir + ".scene.json"
    with open(scene_path, "w") as f:
        json.dump(scene_doc, f, indent=1)
    start = time.perf_counter()
    done = Launcher(mpm).run("run", scene_path, out=run_dir, threads=threads, check=False)
    wall = time.perf_counter() - start
    with open(os.path.join(run_dir, "bounds_stderr.txt"), "w") as f:
        f.write(done.stderr)
    if not os.path.exists(os.path.join(run_dir, "summary.json")):
        return wall, f"{mpm} exited {done.returncode} without summary.json: {done.stderr[-500:]}"
    # A run that stopped (status failed) still has its summary: the status is compared.
    with open(stamp_path, "w") as f:
        json.dump(dict(stamp, exit_code=done.returncode, wall_seconds=wall), f, indent=1)
    return wall, None


def read_run(run_dir):
    with open(os.path.join(run_dir, "summary.json")) as f:
        summary = json.load(f)
    return summary, history_columns(run_dir)


def rod_measures(run_dir):
    """Lf and Dm of the Taylor rod (campaigns/taylor/taylor.py's measures, mirror anvil at the
    grid's x- face): the largest particle x, and twice the largest radius among the particles
    within 0.5 mm of the anvil, each plus the distance by which the seeded extreme particle lay
    inside the rod at t = 0 (read from the first snapshot, so the measures are exact there)."""
    with open(os.path.join(run_dir, "scene.json")) as f:
        scene = json.load(f)
    with open(os.path.join(run_dir, "particles.pvd")) as f:
        files = re.findall(r'file="([^"]+)"', f.read())
    first = read_points(os.path.join(run_dir, files[0]), numpy=False)
    last = read_points(os.path.join(run_dir, files[-1]), numpy=False)
    rod = scene["objects"]["rod"]["geometry"]
    axisymmetric = scene["grid"].get("geometry") == "axisymmetric"
    anvil = scene["grid"]["lower"][0]

    def radius(p):
        return abs(p[1]) if axisymmetric else math.hypot(p[1], p[2])
    axial = rod["top"][0] - max(p[0] for p in first["points"])
    radial = rod["radius"] - max(radius(p) for p in first["points"])
    pts = last["points"]
    lf = max(p[0] for p in pts) - anvil + axial
    dm = 2.0 * (max(radius(p) for p in pts if p[0] - anvil < ANVIL_LAYER) + radial)
    return {"taylor/Lf [m]": lf, "taylor/Dm [m]": dm}


def observables(run_dir, kind):
    summary, cols = read_run(run_dir)
    obs = flatten(summary)
    obs.update(gauge_observables(cols))
    if kind == "taylor":
        obs.update(rod_measures(run_dir))
    return summary, cols, obs


# ---------------------------------------------------------------------------------------------
# Report.

def fmt(v):
    if v is None:
        return ""
    if isinstance(v, str):
        return v
    return f"{v:.17g}"


def fmt_rel(v):
    return "" if v is None else f"{v:.3g}"


def verdict(name, rows, scale_how):
    failed = [r for r in rows if not r["ok"]]
    by = {}
    for r in rows:
        if r["ok"]:
            by[r["criterion"]] = by.get(r["criterion"], 0) + 1
    mom = next(r for r in rows if r["observable"].startswith("books/momentum"))
    ee = next(r for r in rows if r["observable"] == "books/energy_error_end [-]")
    nonzero = sum(1 for r in rows if r["rel"] not in (None, 0.0) and not
                  r["observable"].startswith("books/"))
    text = (f"{name}: {'PASS' if not failed else 'FAIL'}: {len(rows)} checks "
            f"({', '.join(f'{v} by {k}' for k, v in sorted(by.items()))}); "
            f"{nonzero} observables differ; momentum closure NEW {mom['new']:.2g} REF "
            f"{mom['ref']:.2g} of {scale_how}; energy_error end NEW - REF {ee['rel']:.2g}")
    if failed:
        text += "; failing: " + ", ".join(
            f"{r['observable']} (REF {fmt(r['ref'])}, NEW {fmt(r['new'])})" for r in failed)
    return text


def write_reports(out, results, args):
    with open(os.path.join(out, "bounds.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["scene", "set", "observable", "ref", "new", "ref_half", "rel_diff",
                    "halving_scatter", "ensemble_spread", "criterion", "pass", "min_bound_pass"])
        for name, kind, rows, _, _ in results:
            for r in rows:
                w.writerow([name, kind, r["observable"], fmt(r["ref"]), fmt(r["new"]),
                            fmt(r["half"]), fmt_rel(r["rel"]), fmt_rel(r["scatter"]),
                            fmt_rel(r.get("spread")), r["criterion"], int(r["ok"]),
                            "" if r["strict"] is None else int(r["strict"])])
    with open(os.path.join(out, "bounds.md"), "w") as f:
        f.write("# Result bounds (issue 41)\n\n")
        f.write(f"REF `{args.ref}`, NEW `{args.new}`, {args.threads} thread(s); "
                f"campaigns/benchmark/result_bounds.py, docs/performance.md.\n\n")
        f.write("Criteria: books (momentum closure <= 1e-12 of the scale, energy_error NEW - REF "
                "<= 1e-4 on Table 2 and recommended); observables |NEW - REF| <= 1e-6 |REF| "
                "(`1e-6`), else <= |REF_half - REF| (`halving`); momenta within 1e-12 |p0| "
                "(`round-off`); with --ensemble, within the members' range widened by three of its widths "
                "(`ensemble`; spread: the width, relative for observables, absolute for the "
                "energy error). `min bound`: within the smaller of 1e-6 and the halving scatter "
                "(needs --halving).\n\n")
        if args.ensemble:
            f.write(f"Ensemble: {args.ensemble} members of REF (particle orders 0 .. "
                    f"{args.ensemble - 1}) on {args.ensemble_set}; NEW's particle order "
                    f"{args.new_shuffle}.\n\n")
        for name, kind, rows, line, _ in results:
            f.write(f"## {name} ({kind})\n\n{line}\n\n")
            f.write("| observable | REF | NEW | rel diff | halving scatter | ensemble spread | "
                    "criterion | pass | min bound |\n|---|---|---|---|---|---|---|---|---|\n")
            for r in rows:
                strict = "" if r["strict"] is None else ("yes" if r["strict"] else "no")
                f.write(f"| {r['observable']} | {fmt(r['ref'])} | {fmt(r['new'])} | "
                        f"{fmt_rel(r['rel'])} | {fmt_rel(r['scatter'])} | "
                        f"{fmt_rel(r.get('spread'))} | {r['criterion']} | "
                        f"{'yes' if r['ok'] else '**no**'} | {strict} |\n")
            f.write("\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("ref", help="today's mpm (main)")
    ap.add_argument("new", help="the candidate mpm")
    ap.add_argument("out")
    ap.add_argument("--set", default=",".join(SETS), help=f"comma list of {', '.join(SETS)}")
    ap.add_argument("--jobs", type=int, default=1, help="runs at a time")
    ap.add_argument("--threads", type=int, default=2, help="threads per run (REF and NEW alike)")
    ap.add_argument("--reuse-ref", action="store_true",
                    help="reuse REF runs whose scene matches whatever the REF binary")
    ap.add_argument("--halving", nargs="?", const="all", default="",
                    help="also run REF at half its time.multiplier, on the scenes of these sets "
                         "(comma list; alone: every set run): the scatter of each observable")
    ap.add_argument("--ensemble", type=int, default=0,
                    help=f"members (>= {MIN_ENSEMBLE}, the seeded REF included) of REF's ensemble "
                         "of particle orders on the scenes of --ensemble-set (0: none)")
    ap.add_argument("--ensemble-set", default="table2",
                    help="comma list of the sets judged by the ensemble (default table2)")
    ap.add_argument("--new-shuffle", type=int, default=0,
                    help="run NEW with solver.shuffle_particles = K (a pure change of order)")
    args = ap.parse_args()
    args.ref, args.new = os.path.abspath(args.ref), os.path.abspath(args.new)
    for what, path in (("REF_MPM", args.ref), ("NEW_MPM", args.new)):
        if not (os.path.isfile(path) and os.access(path, os.X_OK)):
            sys.exit(f"result_bounds.py: {what}: {path} is not an executable file (an mpm binary)")
    if args.jobs < 1 or args.threads < 1:
        sys.exit("result_bounds.py: --jobs and --threads: expected integers >= 1")
    if args.ensemble != 0 and args.ensemble < MIN_ENSEMBLE:
        sys.exit(f"result_bounds.py: --ensemble: expected 0 (none) or at least {MIN_ENSEMBLE} "
                 f"members, got {args.ensemble}")
    if args.new_shuffle < 0 or 0 < args.new_shuffle < args.ensemble:
        sys.exit(f"result_bounds.py: --new-shuffle: expected 0 (seed order) or a seed that is no "
                 f"member's (>= {max(1, args.ensemble)}), got {args.new_shuffle}")
    sets = [s for s in args.set.split(",") if s]
    for s in sets:
        if s not in SETS:
            sys.exit(f"result_bounds.py: --set: unknown set '{s}' (known: {', '.join(SETS)})")
    out = os.path.abspath(args.out)
    os.makedirs(out, exist_ok=True)
    scenes = scenes_of(sets, args.ref)
    halving = sets if args.halving == "all" else [s for s in args.halving.split(",") if s]
    for s in halving:
        if s not in sets:
            sys.exit(f"result_bounds.py: --halving: '{s}' is not one of the sets run ({args.set})")
    ensemble_sets = [s for s in args.ensemble_set.split(",") if s] if args.ensemble else []
    for s in ensemble_sets:
        if s not in sets:
            sys.exit(f"result_bounds.py: --ensemble-set: '{s}' is not one of the sets run "
                     f"({args.set})")
    # The members beside the seeded REF: REF with its particles in other orders.
    shuffles = range(1, args.ensemble)

    # REF first (the halving run needs REF's multiplier), then NEW and REF_half.
    jobs = []
    for name, kind, path, patch in scenes:
        base = os.path.join(out, "runs", name)
        doc = extending_scene(path, kind, patch)
        jobs.append((name, "ref", args.ref, doc, base + "/ref", True))
        new_doc = extending_scene(path, kind, patch, shuffle=args.new_shuffle)
        jobs.append((name, "new", args.new, new_doc, base + "/new", False))
        if kind in ensemble_sets:
            for k in shuffles:
                jobs.append((name, f"ref_order{k}", args.ref,
                             extending_scene(path, kind, patch, shuffle=k),
                             f"{base}/ref_order{k}", True))
    started = time.perf_counter()
    walls, errors = {}, []

    def go(job):
        name, role, mpm, doc, run_dir, is_ref = job
        return job, run(mpm, doc, run_dir, args.threads, is_ref and args.reuse_ref)

    def execute(batch):
        with concurrent.futures.ThreadPoolExecutor(max(1, args.jobs)) as pool:
            for job, (wall, err) in pool.map(go, batch):
                walls[(job[0], job[1])] = wall
                tag = "reused" if wall is None else f"{wall:.1f} s"
                print(f"  {job[0]} {job[1]}: {tag}{' ERROR ' + err if err else ''}", flush=True)
                if err:
                    errors.append(f"{job[0]} {job[1]}: {err}")

    execute(jobs)
    if args.halving:
        halves = []
        for name, kind, path, patch in scenes:
            if kind not in halving:
                continue
            ref_dir = os.path.join(out, "runs", name, "ref")
            if not os.path.exists(os.path.join(ref_dir, "scene.json")):
                continue
            with open(os.path.join(ref_dir, "scene.json")) as f:
                m = json.load(f).get("time", {}).get("multiplier", 0.5)  # docs/scenes.md default
            halves.append((name, "ref_half", args.ref, extending_scene(path, kind, patch, 0.5 * m),
                           os.path.join(out, "runs", name, "ref_half"), True))
        execute(halves)
    if errors:
        print("result_bounds.py: runs that could not be made:\n  " + "\n  ".join(errors))
        sys.exit(2)

    results, any_failed = [], False
    for name, kind, _, _ in scenes:
        base = os.path.join(out, "runs", name)
        ref_summary, ref_cols, ref_obs = observables(base + "/ref", kind)
        _, new_cols, new_obs = observables(base + "/new", kind)
        if args.new_shuffle:  # the scene NEW read differs by its order key: its fingerprint too
            for obs in (ref_obs, new_obs):
                obs.pop("scene_fingerprint", None)
        half_obs = None
        if kind in halving and os.path.exists(base + "/ref_half/summary.json"):
            half_obs = observables(base + "/ref_half", kind)[2]
        members = [observables(f"{base}/ref_order{k}", kind) for k in shuffles
                   if kind in ensemble_sets]
        bodies = [(o.get("mass [kg]", o.get("mass [kg/m]", 0.0)),
                   o.get("kinetic_energy [J]", o.get("kinetic_energy [J/m]", 0.0)))
                  for o in ref_summary.get("objects", {}).values()]
        scale, how = momentum_scale(ref_cols, bodies)
        rows = books(ref_cols, new_cols, scale, kind in ENERGY_SETS, [m[1] for m in members])
        rows += compare_observables(ref_obs, new_obs, half_obs, scale, [m[2] for m in members],
                                    round_off_scales(ref_summary, scale, ref_cols))
        line = verdict(name, rows, how)
        any_failed |= any(not r["ok"] for r in rows)
        print(line, flush=True)
        results.append((name, kind, rows, line, how))
    write_reports(out, results, args)
    print(f"result_bounds.py: {len(results)} scenes, {time.perf_counter() - started:.0f} s; "
          f"{'ALL PASS' if not any_failed else 'SOME BOUNDS FAIL'}; {out}/bounds.md, bounds.csv")
    sys.exit(1 if any_failed else 0)


if __name__ == "__main__":
    main()
