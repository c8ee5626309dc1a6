#!/usr/bin/env python3
"""Stability map of the sphere-cylinder impact (docs/accuracy.md#stability-map).

  stability_map.py --out OUT [--mpm build/bin/mpm] [--max-time 10e-6] [--threads 2]
                   [--base case01|recommended] [--multipliers 0.1,0.8,1.2]
                   [--interpolations gimp,linear] [--contacts single_velocity,friction]
                   [--av on,off] [--velocities 1470,700] [--schemes musl]
                   [--no-report-cases] [--no-run]

Writes one variant scene per grid point, OUT/scenes/caseNNN.json, each `extends` the base scene
(data/scenes/sphere_cylinder/case01.json by default, absolute path) with a JSON merge patch
(multiplier, interpolation, contact type, artificial viscosity on/off, sphere velocity, max_time;
with --schemes also the update scheme: the base's MUSL by default, `usl` adds USL rows),
plus the report's observations as named cases (below); runs

  mpm study OUT/scenes --out OUT/runs --threads N --no-plot

reads OUT/runs/summary.csv and classifies every run:

  unstable          the run was stopped (summary status `failed`): the energy-growth check
                    (time.max_energy_growth) or any other solver failure (NaN, a particle leaving
                    the grid, a failed constitutive update, dt < min_dt); the reason is the
                    `field` the message names (energy, stress, velocity, position, time step);
  energy-drifting   completed, but abs(energy_error) at the end > DRIFT (5 %);
  stable            completed with abs(energy_error) at the end <= DRIFT.

Outputs: OUT/stability_map.csv (one row per run), OUT/stability_map.md (the map as a table, one
row per combination, one column per multiplier, and the report's observations) and
OUT/stability_map.png (multiplier on x, one row per (interpolation, contact, AV, velocity)
combination, marker by class; needs matplotlib, skipped with a warning otherwise).

The report's observations (Banerjee 2004, sec. 5) as named rows/cases:
  case02  initial dt 1e-11 s ("below delt_min 5e-8 s the run became unstable"): an extra row,
          gimp / friction / AV on / 1470 m/s with time.initial_dt = 1e-11 s, at every multiplier;
  case12  8-node interpolation "unstable at large deformation": linear / friction / AV on / 1470
          at multiplier 0.8 (a grid point; flagged in the table);
  case14  friction contact gaining energy at a low multiplier: gimp / friction / AV on / 1470 at
          multiplier 0.1 (a grid point; flagged).

Exit codes: 0 map written, 1 usage error, 2 input error (e.g. no mpm program), 3 mpm study failed
to produce a table.
"""

import argparse
import csv
import itertools
import json
import os
import re
import shutil
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "python"))  # impact.results (pure Python)
from impact.results import Launcher  # noqa: E402
SCENES = os.path.join(ROOT, "data", "scenes", "sphere_cylinder")

DRIFT = 0.05  # abs(energy_error) at the end above which a completed run is "energy-drifting"
MULTIPLIERS = [0.05, 0.1, 0.2, 0.4, 0.8, 1.0, 1.2]
INTERPOLATIONS = ["gimp", "linear"]
CONTACTS = ["single_velocity", "friction"]
AV = ["on", "off"]
VELOCITIES = [1470.0, 700.0]
SCHEMES = ["musl", "usl"]
CLASSES = ["stable", "energy-drifting", "unstable"]


class UsageError(Exception):
    pass


class InputError(Exception):
    pass


def floats(text):
    try:
        values = [float(x) for x in text.split(",") if x.strip()]
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected comma-separated numbers, got '{text}'")
    if not values:
        raise argparse.ArgumentTypeError("expected at least one number")
    return values


def names(allowed):
    def parse(text):
        values = [x.strip() for x in text.split(",") if x.strip()]
        bad = [v for v in values if v not in allowed]
        if bad or not values:
            raise argparse.ArgumentTypeError(
                f"expected a comma-separated subset of {','.join(allowed)}, got '{text}'"
            )
        return values

    return parse


def fmt_multiplier(m):
    return f"{m:g}"


class Variant:
    """One run: a grid point, or a named report case (`tag` non-empty)."""

    def __init__(self, multiplier, interpolation, contact, av, velocity, tag="", initial_dt=None,
                 scheme="musl"):
        self.multiplier = multiplier
        self.scheme = scheme
        self.interpolation = interpolation
        self.contact = contact
        self.av = av
        self.velocity = velocity
        self.tag = tag  # e.g. "report case02: initial dt 1e-11 s"
        self.initial_dt = initial_dt
        self.name = ""
        self.observation = ""

    def row_label(self):
        label = f"{self.interpolation} / {self.contact} / AV {self.av} / {self.velocity:g} m/s"
        if self.scheme != "musl":
            label += f" / {self.scheme.upper()}"
        if self.initial_dt is not None:
            label += f" / dt0 {self.initial_dt:g} s"
        return label

    def patch(self, base, max_time):
        p = {
            "extends": base,
            "description": f"Stability map: {self.row_label()}, multiplier "
            f"{fmt_multiplier(self.multiplier)}" + (f" ({self.tag})" if self.tag else ""),
            "time": {"multiplier": self.multiplier, "max_time": max_time},
            "solver": {"interpolation": self.interpolation, "scheme": self.scheme},
            "physics": {
                # single_velocity reads no mu: the base's (case01's) is removed (null).
                "contact": {"type": self.contact,
                            **({"mu": None} if self.contact == "single_velocity" else {})},
                "artificial_viscosity": {"enabled": self.av == "on"},
            },
            "objects": {"sphere": {"velocity": [self.velocity, 0.0, 0.0]}},
            "output": {"interval": max_time / 20.0, "snapshots": False},
        }
        if self.initial_dt is not None:
            p["time"]["initial_dt"] = self.initial_dt
        return p

    def as_dict(self):
        return {
            "case": self.name,
            "multiplier": self.multiplier,
            "interpolation": self.interpolation,
            "scheme": self.scheme,
            "contact": self.contact,
            "artificial_viscosity": self.av,
            "velocity [m/s]": self.velocity,
            "initial_dt [s]": self.initial_dt,
            "observation": self.observation,
        }


# The report's observations that are grid points: (interpolation, contact, AV, velocity,
# multiplier) -> what the report said.
REPORT_POINTS = {
    ("linear", "friction", "on", 1470.0, 0.8): "report case12: 8-node unstable at large deformation",
    ("gimp", "friction", "on", 1470.0, 0.1): "report case14: friction gains energy at low multiplier",
    ("gimp", "friction", "on", 1470.0, 0.8): "report case01 (Appendix I)",
}


def make_variants(args):
    variants = []
    for scheme, interp, contact, av, vel in itertools.product(
        args.schemes, args.interpolations, args.contacts, args.av, args.velocities
    ):
        for m in args.multipliers:
            v = Variant(m, interp, contact, av, vel, scheme=scheme)
            if scheme == "musl":
                v.observation = REPORT_POINTS.get((interp, contact, av, vel, m), "")
            variants.append(v)
    if args.report_cases:
        # Report case 2: the tiny first step, on the report's deck (friction, AV on, 1470 m/s).
        interp = "gimp" if "gimp" in args.interpolations else args.interpolations[0]
        for m in args.multipliers:
            v = Variant(m, interp, "friction", "on", 1470.0, tag="report case02", initial_dt=1e-11)
            v.observation = "report case02: initial dt 1e-11 s (report: unstable below 5e-8 s)"
            variants.append(v)
    for i, v in enumerate(variants, 1):
        v.name = f"case{i:03d}"
    return variants


def write_scenes(out, variants, base, max_time):
    scenes = os.path.join(out, "scenes")
    os.makedirs(scenes, exist_ok=True)
    for f in os.listdir(scenes):  # a smaller map must not run a larger map's leftovers
        if re.fullmatch(r"case.*\.json", f):
            os.remove(os.path.join(scenes, f))
    for v in variants:
        with open(os.path.join(scenes, v.name + ".json"), "w") as f:
            json.dump(v.patch(base, max_time), f, indent=1)
            f.write("\n")
    with open(os.path.join(out, "stability_cases.json"), "w") as f:
        json.dump(
            {"base": base, "max_time [s]": max_time, "cases": [v.as_dict() for v in variants]},
            f,
            indent=1,
        )
        f.write("\n")
    return scenes


def run_study(mpm, scenes, runs, threads):
    # Leftover case directories of an earlier, larger map would otherwise enter summary.csv.
    if os.path.isdir(runs):
        shutil.rmtree(runs)
    launcher = Launcher(mpm)
    cmd = launcher.command("study", scenes, out=runs, threads=threads, extra=["--no-plot"])
    print("stability_map.py: " + " ".join(cmd), flush=True)
    t0 = time.monotonic()
    code = launcher.run("study", scenes, out=runs, threads=threads, extra=["--no-plot"],
                        check=False, capture=False).returncode
    wall = time.monotonic() - t0
    if code not in (0, 3):  # 3: some case failed, which is what the map is looking for
        raise InputError(f"mpm study exited with code {code}")
    return wall


def read_summary(runs):
    path = os.path.join(runs, "summary.csv")
    if not os.path.isfile(path):
        raise InputError(f"{path}: missing (mpm study writes it with python3; see its warnings)")
    with open(path, newline="") as f:
        return {r["case"]: r for r in csv.DictReader(f)}


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def failure_reason(message):
    """The failure's field as the solver names it: '...: particle N (...): FIELD: why'."""
    m = re.search(r"\): (energy|stress|velocity|position): ", message or "")
    if m:
        return m.group(1)
    if "below min_dt" in (message or ""):
        return "time step"
    return "other"


def classify(row):
    """(class, reason, energy_error at the end or None)."""
    if row is None:
        return "not run", "", None
    err = number(row.get("ledger_error_end [-]"))
    if row.get("status") != "completed":
        return "unstable", failure_reason(row.get("message", "")), err
    if err is None:
        return "not run", "no history", None
    return ("energy-drifting" if abs(err) > DRIFT else "stable"), "", err


def failed_step(message):
    m = re.match(r"step (\d+), time ([0-9.eE+-]+) s", message or "")
    return (int(m.group(1)), float(m.group(2))) if m else (None, None)


def results(variants, summary):
    rows = []
    for v in variants:
        r = summary.get(v.name)
        cls, reason, err = classify(r)
        step, t_fail = failed_step(r.get("message", "") if r else "")
        d = v.as_dict()
        d.update(
            {
                "row": v.row_label(),
                "class": cls,
                "reason": reason,
                "energy_error_end [-]": err,
                "max_abs_energy_error [-]": number(r.get("max_abs_ledger_error [-]")) if r else None,
                "relative_drift [-]": number(r.get("relative_drift [-]")) if r else None,
                "steps [-]": number(r.get("steps [-]")) if r else None,
                "failed_step [-]": step,
                "failed_time [s]": t_fail,
                "wall_time [s]": number(r.get("wall_time [s]")) if r else None,
                "message": (r.get("message", "") if r else ""),
            }
        )
        rows.append(d)
    return rows


CSV_KEYS = [
    "case",
    "row",
    "multiplier",
    "interpolation",
    "scheme",
    "contact",
    "artificial_viscosity",
    "velocity [m/s]",
    "initial_dt [s]",
    "class",
    "reason",
    "energy_error_end [-]",
    "max_abs_energy_error [-]",
    "relative_drift [-]",
    "steps [-]",
    "failed_step [-]",
    "failed_time [s]",
    "wall_time [s]",
    "observation",
    "message",
]


def write_csv(out, rows):
    with open(os.path.join(out, "stability_map.csv"), "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(CSV_KEYS)
        for r in rows:
            w.writerow(["" if r.get(k) is None else r[k] for k in CSV_KEYS])


def cell_text(r):
    if r["class"] == "unstable":
        where = f" step {r['failed_step [-]']}" if r["failed_step [-]"] is not None else ""
        t = r["failed_time [s]"]
        return f"**unstable** ({r['reason']}{where}" + (f", {t * 1e6:.3g} us)" if t else ")")
    if r["class"] == "not run":
        return "not run"
    err = r["energy_error_end [-]"]
    tag = "stable" if r["class"] == "stable" else "*drifting*"
    return f"{tag} {err * 100:+.2f} %"


def ordered_rows(rows):
    labels, mults = [], []
    for r in rows:
        if r["row"] not in labels:
            labels.append(r["row"])
        if r["multiplier"] not in mults:
            mults.append(r["multiplier"])
    return labels, sorted(mults)


def write_markdown(out, rows, meta):
    labels, mults = ordered_rows(rows)
    by = {(r["row"], r["multiplier"]): r for r in rows}
    lines = [
        "# Stability map: sphere-cylinder variants",
        "",
        f"Base scene `{os.path.relpath(meta['base'], ROOT)}`, max_time {meta['max_time'] * 1e6:g} us, "
        f"{len(rows)} runs, `mpm study` wall time {meta['wall']:.0f} s "
        f"({meta['threads']} threads). Classes: **unstable** = stopped by the solver (status "
        f"failed; reason = the failure's field: `energy` is the energy-growth check, "
        f"time.max_energy_growth), *drifting* = completed with abs(energy_error) at the end > "
        f"{DRIFT * 100:g} %, stable = completed within {DRIFT * 100:g} %; the number is "
        f"energy_error at the end (docs/mpm.md#ledger).",
        "",
        "| interpolation / contact / AV / velocity | "
        + " | ".join(f"x{fmt_multiplier(m)}" for m in mults)
        + " |",
        "|---|" + "---|" * len(mults),
    ]
    for label in labels:
        cells = [cell_text(by[(label, m)]) if (label, m) in by else "" for m in mults]
        lines.append(f"| {label} | " + " | ".join(cells) + " |")
    notes = [r for r in rows if r["observation"]]
    if notes:
        lines += ["", "The report's observations:", ""]
        for r in notes:
            lines.append(
                f"- {r['observation']}: {r['row']}, multiplier {fmt_multiplier(r['multiplier'])}: "
                f"{cell_text(r).replace('**', '').replace('*', '')} ({r['case']})"
            )
    counts = {c: sum(r["class"] == c for r in rows) for c in CLASSES + ["not run"]}
    lines += [
        "",
        "Counts: " + ", ".join(f"{c} {n}" for c, n in counts.items() if n),
        "",
        "Messages of the unstable runs:",
        "",
    ]
    for r in rows:
        if r["class"] == "unstable":
            lines.append(f"- {r['case']} ({r['row']}, x{fmt_multiplier(r['multiplier'])}): "
                         f"{r['message']}")
    lines.append("")
    with open(os.path.join(out, "stability_map.md"), "w") as f:
        f.write("\n".join(lines))


MARKERS = {
    "stable": ("o", "tab:green"),
    "energy-drifting": ("^", "tab:orange"),
    "unstable": ("X", "tab:red"),
    "not run": (".", "0.6"),
}


def draw(out, rows, meta):
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.stderr.write(
            "stability_map.py: warning: no matplotlib (apt-get install -y python3-matplotlib): "
            "no stability_map.png; the csv and md tables are written\n"
        )
        return False
    labels, mults = ordered_rows(rows)
    fig, ax = plt.subplots(figsize=(10, 0.42 * len(labels) + 1.8))
    for r in rows:
        y = len(labels) - 1 - labels.index(r["row"])
        marker, color = MARKERS[r["class"]]
        ax.scatter(r["multiplier"], y, marker=marker, s=90, color=color, edgecolors="k",
                   linewidths=0.5, zorder=3)
        if r["class"] in ("stable", "energy-drifting"):
            text = f"{r['energy_error_end [-]'] * 100:+.1f}%"
        elif r["class"] == "unstable":
            text = r["reason"]
        else:
            text = ""
        ax.annotate(text, (r["multiplier"], y), xytext=(0, 11), textcoords="offset points",
                    ha="center", fontsize=6)
        if r["observation"]:
            ax.scatter(r["multiplier"], y, marker="s", s=220, facecolors="none",
                       edgecolors="tab:blue", linewidths=1.0, zorder=2)
    ax.set_xscale("log")
    ax.set_xticks(mults)
    ax.set_xticklabels([fmt_multiplier(m) for m in mults])
    ax.minorticks_off()
    ax.set_xlim(min(mults) / 1.35, max(mults) * 1.35)
    ax.set_yticks(range(len(labels)))
    ax.set_yticklabels(list(reversed(labels)), fontsize=7)
    ax.set_ylim(-0.7, len(labels) - 0.3)
    ax.axvline(1.0, color="0.5", lw=0.8, ls="--")
    ax.set_xlabel("time-step multiplier (CFL number) [-]")
    ax.set_title(
        f"Sphere-cylinder stability map, {meta['max_time'] * 1e6:g} us "
        f"(drifting: abs(energy_error) > {DRIFT * 100:g} % at the end)",
        fontsize=9,
    )
    ax.grid(True, axis="x", color="0.9")
    # Every class in the legend, present or not: maps compare at a glance.
    from matplotlib.lines import Line2D

    handles = [
        Line2D([], [], ls="none", marker=MARKERS[c][0], color=MARKERS[c][1], mec="k", mew=0.5,
               ms=8, label=c + (f" (> {DRIFT * 100:g} %)" if c == "energy-drifting" else ""))
        for c in CLASSES
    ]
    if any(r["observation"] for r in rows):
        handles.append(Line2D([], [], ls="none", marker="s", mfc="none", mec="tab:blue", ms=12,
                              label="report observation"))
    ax.legend(handles=handles, loc="upper left", bbox_to_anchor=(1.01, 1.0), fontsize=7,
              frameon=False)
    fig.tight_layout()
    fig.savefig(os.path.join(out, "stability_map.png"), dpi=130)
    plt.close(fig)
    return True


class Parser(argparse.ArgumentParser):
    def error(self, message):  # a usage error exits 1 (2 is an input error here)
        self.print_usage(sys.stderr)
        sys.stderr.write(f"stability_map.py: error: {message}\n")
        sys.exit(1)


def main():
    p = Parser(description=__doc__.split("\n\n")[0],
               formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--out", required=True, help="output directory")
    p.add_argument("--mpm", default=os.path.join(ROOT, "build", "bin", "mpm"),
                   help="the mpm program (default: build/bin/mpm)")
    p.add_argument("--max-time", type=float, default=10e-6, help="end time [s] (default 10e-6)")
    p.add_argument("--threads", type=int, default=2, help="threads per run (default 2)")
    p.add_argument("--base", choices=["case01", "recommended"], default="case01",
                   help="base scene in data/scenes/sphere_cylinder (default case01, the report's "
                   "deck: friction mu 1e-4, AV 0.07/1.6, AllowNoTension, create_new_particles)")
    p.add_argument("--multipliers", type=floats, default=MULTIPLIERS)
    p.add_argument("--interpolations", type=names(INTERPOLATIONS), default=INTERPOLATIONS)
    p.add_argument("--contacts", type=names(CONTACTS), default=CONTACTS)
    p.add_argument("--av", type=names(AV), default=AV, help="artificial viscosity: on,off")
    p.add_argument("--velocities", type=floats, default=VELOCITIES, help="sphere speed [m/s]")
    p.add_argument("--schemes", type=names(SCHEMES), default=["musl"],
                   help="update schemes (default musl, the base's; usl adds rows)")
    p.add_argument("--no-report-cases", dest="report_cases", action="store_false",
                   help="leave out the extra row of the report's case 2 (initial dt 1e-11 s)")
    p.add_argument("--no-run", action="store_true",
                   help="classify and draw an existing OUT/runs without running")
    args = p.parse_args()
    if not (args.max_time > 0):
        p.error("--max-time must be positive")
    if args.threads < 1:
        p.error("--threads must be >= 1")
    if any(not (0 < m <= 1.5) for m in args.multipliers):
        p.error("--multipliers must lie in (0, 1.5] (time.multiplier's range)")

    out = os.path.abspath(args.out)
    base = os.path.join(SCENES, args.base + ".json")
    variants = make_variants(args)
    try:
        if not os.path.isfile(base):
            raise InputError(f"{base}: base scene not found")
        if not args.no_run and not (os.path.isfile(args.mpm) and os.access(args.mpm, os.X_OK)):
            raise InputError(f"{args.mpm}: no mpm program (build first, or pass --mpm)")
        os.makedirs(out, exist_ok=True)
        scenes = write_scenes(out, variants, base, args.max_time)
        runs = os.path.join(out, "runs")
        wall = 0.0
        if args.no_run:
            meta_path = os.path.join(out, "stability_meta.json")
            if os.path.isfile(meta_path):
                with open(meta_path) as f:
                    wall = json.load(f).get("study_wall_time [s]", 0.0)
        else:
            wall = run_study(args.mpm, scenes, runs, args.threads)
            with open(os.path.join(out, "stability_meta.json"), "w") as f:
                json.dump({"study_wall_time [s]": wall, "threads": args.threads,
                           "runs": len(variants)}, f, indent=1)
        summary = read_summary(runs)
    except InputError as e:
        sys.stderr.write(f"stability_map.py: {e}\n")
        return 2
    rows = results(variants, summary)
    meta = {"base": base, "max_time": args.max_time, "wall": wall, "threads": args.threads}
    write_csv(out, rows)
    write_markdown(out, rows, meta)
    drawn = draw(out, rows, meta)
    counts = {c: sum(r["class"] == c for r in rows) for c in CLASSES + ["not run"]}
    print(
        f"stability_map.py: {len(rows)} runs in {wall:.0f} s: "
        + ", ".join(f"{c} {n}" for c, n in counts.items() if n)
        + f"; wrote {os.path.join(out, 'stability_map.csv')}, stability_map.md"
        + (", stability_map.png" if drawn else "")
    )
    return 0


if __name__ == "__main__":
    sys.exit(main())
