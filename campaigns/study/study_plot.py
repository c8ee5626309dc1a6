#!/usr/bin/env python3
"""Figures and table of an `mpm study` (the report's Table 2 study; docs/mpm.md).

  study_plot.py OUT [--no-figures]

OUT holds one directory per case (history.csv, summary.json, scene.json, as `mpm run` writes them).
Writes
  OUT/<case>/energy.png  left: kinetic, strain and total energy [J] vs time [us] of the case (solid)
                         and of case01 (dashed), plus any further ledger energy terms (thin lines);
                         right: the momentum components [kg m/s], the case and case01, and per
                         component the case's balance p - boundary impulse - body-force impulse
                         (dotted; conserved: a flat line).
  OUT/summary.csv        one row per case, header cells `name [unit]`, full precision.
  OUT/summary.md         the same as a markdown table, 4 significant digits.
--no-figures writes the table only (needs no matplotlib).
history.csv columns are read by name, so ledger columns added later are picked up: every `[J]`
column between boundary_impulse_z and energy_error is drawn and tabulated at the end time.

Exit codes: 0 done, 1 usage error, 2 input error, 3 an output could not be written, 4 matplotlib
missing, 130 interrupted (Ctrl-C).
`mpm study` runs this script; it can also be run directly.
"""

import argparse
import csv
import json
import math
import os
import re
import sys
import textwrap

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import quantity_format  # noqa: E402
from impact.results import history_rows  # noqa: E402

MISSING_MATPLOTLIB = 4
REFERENCE = "case01"


class InputError(Exception):
    pass


def strip_unit(name):
    return re.sub(r"\s*\[[^\]]*\]\s*$", "", name).strip()


def unit_of(name):
    m = re.search(r"\[([^\]]*)\]\s*$", name)
    return m.group(1) if m else ""


class History:
    """history.csv by column name (the header cell without its unit)."""

    def __init__(self, path):
        # A run killed mid-write leaves a short or broken last line: history_rows skips it.
        head, data = history_rows(os.path.dirname(path))
        if not head:
            raise InputError(f"{path}: empty file")
        self.header = [h.strip() for h in head]
        self.names = [strip_unit(h) for h in self.header]
        # A plane-strain run's extensive columns are per metre of thickness (J/m, ...).
        self.units = {strip_unit(h): unit_of(h) for h in self.header}
        self.columns = {n: [r[i] for r in data] for i, n in enumerate(self.names)}
        self.rows = len(data)

    def has(self, name):
        return name in self.columns

    def col(self, name):
        return self.columns[name]

    def last(self, name, default=0.0):
        c = self.columns.get(name)
        return c[-1] if c else default

    def energy_terms(self):
        """The further ledger terms: `[J]` columns between boundary_impulse_z and energy_error
        (sinks such as viscous_work, friction_heat; outflow_kinetic_energy; external_work with
        gravity)."""
        if "boundary_impulse_z" not in self.names or "energy_error" not in self.names:
            return []
        lo = self.names.index("boundary_impulse_z")
        hi = self.names.index("energy_error")
        energy = self.units.get("total_energy", "J")
        return [self.names[i] for i in range(lo + 1, hi) if unit_of(self.header[i]) == energy]


def read_json(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def summary_entry(summary, name):
    """(value, unit) of summary.json's `name [unit]` entry, whatever its unit: a plane-strain
    run's extensive entries are per metre of thickness ("initial_energy [J/m]")."""
    for key, value in summary.items():
        if strip_unit(key) == name:
            return value, unit_of(key)
    return None, ""


def case_order(name):
    return (name == "recommended", name)


class Case:
    def __init__(self, out, name):
        self.name = name
        self.dir = os.path.join(out, name)
        self.summary = read_json(os.path.join(self.dir, "summary.json")) or {}
        scene = read_json(os.path.join(self.dir, "scene.json")) or {}
        self.description = scene.get("description", "") if isinstance(scene, dict) else ""
        self.history = None
        path = os.path.join(self.dir, "history.csv")
        if os.path.isfile(path):
            try:
                self.history = History(path)
            except (OSError, InputError) as e:
                sys.stderr.write(f"study_plot.py: {e}\n")
        if self.history is not None and self.history.rows == 0:
            self.history = None
        # No summary.json next to a history: the run was interrupted.
        self.status = self.summary.get("status", "incomplete")
        self.message = self.summary.get("message", "")


def find_cases(out):
    if not os.path.isdir(out):
        raise InputError(f"{out}: not a directory")
    names = [
        n
        for n in os.listdir(out)
        if os.path.isfile(os.path.join(out, n, "summary.json"))
        or os.path.isfile(os.path.join(out, n, "history.csv"))
    ]
    if not names:
        raise InputError(f"{out}: no case directories (with summary.json or history.csv)")
    return [Case(out, n) for n in sorted(names, key=case_order)]


# ---- table -------------------------------------------------------------------------------------

# {E}: the energy unit of the study's runs (J, or J/m in plane strain).
COLUMNS = [
    ("case", "case"),
    ("status", "status"),
    ("particles", "particles [-]"),
    ("e0", "initial_kinetic_energy [{E}]"),
    ("final_total", "final_total_energy [{E}]"),
    ("max_total", "max_total_energy [{E}]"),
    ("drift", "relative_drift [-]"),
    ("ledger_end", "ledger_error_end [-]"),
    ("ledger_max", "max_abs_ledger_error [-]"),
    ("momentum_error", "momentum_balance_error [-]"),
    ("steps", "steps [-]"),
    ("wall", "wall_time [s]"),
    ("rate", "particle_steps_per_second [1/s]"),
]


def number(x):
    return x if isinstance(x, (int, float)) and not isinstance(x, bool) else None


def table_row(case, terms):
    s, h = case.summary, case.history
    r = {
        "case": case.name,
        "status": case.status,
        "particles": number(s.get("particles")),
        "e0": number(summary_entry(s, "initial_energy")[0]),
        "steps": number(s.get("steps")),
        "wall": number(s.get("wall_time [s]")),
        "rate": number(s.get("particle_steps_per_second")),
        "message": case.message,
    }
    if h is None:
        return r
    total = h.col("total_energy")
    r["final_total"] = total[-1]
    r["max_total"] = max(total)
    if r["e0"]:
        r["drift"] = (total[-1] - r["e0"]) / r["e0"]
    err = h.col("energy_error")
    r["ledger_end"] = err[-1]
    r["ledger_max"] = max(abs(e) for e in err)
    # p_end - p0 - boundary impulse (- body-force impulse): zero to round-off for the solver.
    p0 = summary_entry(s, "initial_momentum")[0]
    if not (isinstance(p0, list) and len(p0) == 3):
        p0 = [h.col(f"momentum_{a}")[0] for a in "xyz"]
    residual = [
        h.last(f"momentum_{a}")
        - p0[i]
        - h.last(f"boundary_impulse_{a}")
        - h.last(f"external_impulse_{a}")
        for i, a in enumerate("xyz")
    ]
    scale = math.sqrt(sum(p * p for p in p0))
    # Bodies whose momenta cancel (head-on) leave round-off in p0: then relative to
    # sqrt(2 M E0), the largest |p| the kinetic energy allows; absolute (kg m/s) if that is 0 too.
    mass, e0 = number(summary_entry(s, "mass")[0]), r["e0"]
    reference = math.sqrt(2.0 * mass * e0) if mass and e0 and e0 > 0 else 0.0
    if scale <= 1e-9 * reference:
        scale = reference
    r["momentum_error"] = math.sqrt(sum(d * d for d in residual)) / (scale if scale > 0 else 1.0)
    for t in terms:
        if h.has(t):
            r["term:" + t] = h.last(t)
    return r


def write_tables(out, cases):
    terms = []
    for c in cases:
        for t in c.history.energy_terms() if c.history else []:
            if t not in terms:
                terms.append(t)
    rows = [table_row(c, terms) for c in cases]
    energy, momentum = study_units(cases)
    keys = [k for k, _ in COLUMNS] + ["term:" + t for t in terms] + ["message"]
    heads = ([h.replace("{E}", energy) for _, h in COLUMNS] + [f"{t}_end [{energy}]" for t in terms]
             + ["message"])

    with open(os.path.join(out, "summary.csv"), "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(heads)
        for r in rows:
            w.writerow(["" if r.get(k) is None else r[k] for k in keys])

    def md(v):
        if v is None:
            return ""
        if isinstance(v, float):
            return f"{v:.4g}"
        return str(v).replace("|", "\\|").replace("\n", " ")

    lines = [
        f"# Study {os.path.basename(os.path.abspath(out))}: energy and momentum balance per case",
        "",
        "| " + " | ".join(heads) + " |",
        "|" + "---|" * len(heads),
    ]
    lines += ["| " + " | ".join(md(r.get(k)) for k in keys) + " |" for r in rows]
    lines += [
        "",
        "initial_kinetic_energy: the discretized sum 1/2 m_p v_p^2 at t = 0 (summary.json "
        "initial_energy); relative_drift = (final total - initial) / initial; ledger_error: the "
        "ledger's energy_error (docs/mpm.md#ledger); momentum_balance_error = "
        "abs(p_end - p0 - boundary_impulse - external_impulse) / abs(p0) (/ sqrt(2 M E0) when "
        "the bodies' momenta cancel, abs(p0) < 1e-9 sqrt(2 M E0); "
        f"absolute in {momentum} if both are 0). Columns `*_end [{energy}]`: further ledger "
        "energy terms at the end time (docs/mpm.md)."
        + (" Energies and momenta are per metre of thickness (plane strain)." if "/m" in energy
           else ""),
        "",
    ]
    for c in cases:
        lines += discretization_error_lines(c)
    with open(os.path.join(out, "summary.md"), "w") as f:
        f.write("\n".join(lines))


def study_units(cases):
    """The energy and momentum units of the cases' histories: J and kg m/s, or per metre of
    thickness (J/m, (kg m/s)/m) when the runs are plane strain."""
    for c in cases:
        if c.history is not None and "total_energy" in c.history.units:
            return c.history.units["total_energy"], c.history.units.get("momentum_x", "kg m/s")
    return "J", "kg m/s"


def entry_unit(entry):
    """The SI unit of a discretization_error entry: its range's, else the one its JSON pointer
    into summary.json names ('/observables/crater/depth [m]'; '~1' is '/')."""
    rng = entry.get("range")
    if isinstance(rng, dict) and isinstance(rng.get("unit"), str):
        return rng["unit"]
    m = re.search(r"\[([^\]]*)\]", entry.get("path") or "")
    return m.group(1).replace("~1", "/") if m else ""


def discretization_error_lines(case):
    """The error bar of a run whose scene has a grid-convergence ladder table (summary.json
    "discretization_error", written by mpm run; docs/accuracy.md#grid-convergence-ladders). One
    extrapolated value, this run's signed error against it and GCI_fine only where the ladder
    calls the observable quotable ("quotable": true); elsewhere the verdict and the range of
    converged values, never a percentage against one extrapolated number."""
    d = case.summary.get("discretization_error")
    if not isinstance(d, dict):
        return []
    head = [f"## {case.name}: discretization error (grid-convergence ladder)", ""]
    if "observables" not in d:
        return head + [f"Ladder table {d.get('table', '?')}: {d.get('status', '?')}.", ""]

    def num(x):
        return isinstance(x, (int, float)) and not isinstance(x, bool)

    lines = head + [
        f"This run is level x{quantity_format.number(d.get('level'))} of the ladder in "
        f"{d.get('table')} (made at commit {d.get('ladder_commit', '?')}). Where the ladder's "
        "finest triple is quotable (monotonic convergence, an order within the plausible "
        "[0.5, 2], in the asymptotic range), the extrapolated value is Richardson's from its "
        "three finest levels, error = (this run - extrapolated) / abs(extrapolated), GCI_fine the "
        "uncertainty band of the finest level's value (Celik et al. 2008, safety factor 1.25; "
        "not this run's) and p the observed order. Elsewhere no single converged value can be "
        "quoted: the verdict and the range of converged values that the levels and the "
        "plausible orders bound (docs/accuracy.md#grid-convergence-ladders)."
        + (f" The ladder refined {d['scope']}." if isinstance(d.get("scope"), str) else ""),
        "",
        "| observable [unit] | this run | extrapolated | error [%] | GCI_fine of the finest level "
        "[%] | order p [-] | verdict and range of converged values |",
        "|---|---|---|---|---|---|---|",
    ]
    for name, o in d["observables"].items():
        if not isinstance(o, dict):
            continue
        unit = entry_unit(o)
        rng = o.get("range") if isinstance(o.get("range"), dict) else None
        shown = [o.get("value"), o.get("extrapolated")] + (
            [rng.get("low"), rng.get("high")] if rng else [])
        factor, label = quantity_format.display_unit(unit, shown)

        def cell(x):
            text = quantity_format.number(x, factor)
            return text if text == "-" or label in ("", "-") else f"{text} {label}"

        if o.get("quotable") is True and num(o.get("extrapolated")):
            error = (f"{100 * o['error [-]']:+.1f}" if num(o.get("error [-]")) else "-")
            gci_fine = (f"{100 * o['gci_fine [-]']:.2g}" if num(o.get("gci_fine [-]")) else "-")
            order = quantity_format.number(o.get("order"), 1.0, 3)
            lines.append(f"| {name} [{label}] | {cell(o.get('value'))} | "
                         f"{cell(o['extrapolated'])} | {error} | {gci_fine} | {order} | "
                         f"quotable: {o.get('verdict', 'in the asymptotic range')} |")
            continue
        verdict = o.get("verdict") or o.get("status") or "not quotable"
        where = (quantity_format.range_text(rng) if rng else
                 "no range in the ladder table (re-analyse it: campaigns/study/ladder.py "
                 "--analyse-only)")
        lines.append(f"| {name} [{label}] | {cell(o.get('value'))} | - | - | - | - | "
                     f"{verdict}: {where} |")
    return lines + [""]


# ---- figures -----------------------------------------------------------------------------------


def import_pyplot():
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.stderr.write(
            "study_plot.py: matplotlib is not installed; install it with:\n"
            "  apt-get install -y python3-matplotlib\n"
            "or write the table only with --no-figures\n"
        )
        sys.exit(MISSING_MATPLOTLIB)
    return plt


def short(text, limit=150):
    text = " ".join(text.split())
    return text if len(text) <= limit else text[: limit - 3].rstrip() + "..."


def momentum_balances(history):
    """{axis: [p - boundary impulse - body-force impulse per row]} for x, y and z (the axes whose
    boundary impulse the history has): each is constant where momentum is conserved."""
    out = {}
    for axis in "xyz":
        if not (history.has(f"momentum_{axis}") and history.has(f"boundary_impulse_{axis}")):
            continue
        external = (history.col(f"external_impulse_{axis}")
                    if history.has(f"external_impulse_{axis}") else [0.0] * history.rows)
        out[axis] = [p - j - e for p, j, e in zip(history.col(f"momentum_{axis}"),
                                                  history.col(f"boundary_impulse_{axis}"),
                                                  external)]
    return out


def draw_case(plt, case, reference):
    fig, (ax_e, ax_p) = plt.subplots(1, 2, figsize=(13, 5))
    runs = [(case, "-")]
    if reference is not None and reference is not case and reference.history is not None:
        runs.append((reference, "--"))
    energy = [("kinetic_energy", "C0"), ("strain_energy", "C1"), ("total_energy", "k")]
    for c, style in runs:
        h = c.history
        t = [x * 1e6 for x in h.col("time")]
        for name, color in energy:
            ax_e.plot(t, h.col(name), style, color=color, lw=1.5, label=f"{name} ({c.name})")
        for i, name in enumerate(h.energy_terms()):
            ax_e.plot(t, h.col(name), style, color=f"C{i + 2}", lw=0.8, label=f"{name} ({c.name})")
        for name, color in [("momentum_x", "C0"), ("momentum_y", "C1"), ("momentum_z", "C2")]:
            ax_p.plot(t, h.col(name), style, color=color, lw=1.5, label=f"{name} ({c.name})")
        # The conserved quantities, one per component: momentum minus what the faces (and body
        # forces) exerted. The far end of the cylinder lies on the x+ face, whose reaction turns
        # p_x around after ~18 us; the y and z faces take up the sideways momentum likewise, so
        # p_y and p_z move without any drift: their balances are drawn too.
        # y and z are often both zero: z dash-dotted and thinner, so that neither hides.
        styles = {"x": (":", 2.0, "C0"), "y": (":", 2.6, "C1"), "z": ("-.", 1.2, "C2")}
        for axis, balance in (momentum_balances(h) if c is case else {}).items():
            line, width, color = styles[axis]
            ax_p.plot(t, balance, line, color=color, lw=width,
                      label=f"momentum_{axis} - impulses_{axis} ({c.name}, conserved)")
    ax_e.set_xlabel("time [µs]")
    energy_unit, momentum_unit = study_units([case])
    ax_e.set_ylabel(f"energy [{energy_unit}]")
    ax_e.set_title("energy (this case solid" + (f", {REFERENCE} dashed)" if len(runs) > 1 else ")"))
    ax_p.set_xlabel("time [µs]")
    ax_p.set_ylabel(f"momentum [{momentum_unit}]")
    ax_p.set_title("momentum (dotted, dash-dotted: minus the faces' and body forces' impulses: "
                   "conserved)", fontsize=9)
    for ax in (ax_e, ax_p):
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7)
    title = case.name + ("" if case.status == "completed" else f" ({case.status})")
    if case.description:
        title += ": " + short(case.description)
    fig.suptitle("\n".join(textwrap.wrap(title, 120)), fontsize=10)
    fig.tight_layout()
    path = os.path.join(case.dir, "energy.png")
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


class Parser(argparse.ArgumentParser):
    def error(self, message):  # a usage error exits 1 (argparse's 2 is our input error)
        self.print_usage(sys.stderr)
        sys.stderr.write(f"study_plot.py: {message}\n")
        sys.exit(1)


def main():
    p = Parser(description="Figures and table of an `mpm study`.")
    p.add_argument("out", help="the study output directory (mpm study --out)")
    p.add_argument("--no-figures", action="store_true", help="write the table only")
    args = p.parse_args()
    try:
        cases = find_cases(args.out)
        write_tables(args.out, cases)
        print(f"study_plot.py: wrote {os.path.join(args.out, 'summary.csv')} and summary.md")
        if args.no_figures:
            return 0
        plt = import_pyplot()
        reference = next((c for c in cases if c.name == REFERENCE), None)
        for c in cases:
            if c.history is not None:
                draw_case(plt, c, reference)
        print(f"study_plot.py: wrote {sum(c.history is not None for c in cases)} figures")
    except InputError as e:
        sys.stderr.write(f"study_plot.py: {e}\n")
        return 2
    except OSError as e:  # an output that cannot be written (read-only, full, a special file)
        sys.stderr.write(f"study_plot.py: {e.filename or args.out}: cannot be written: "
                         f"{e.strerror or e}\n")
        return 3
    except KeyboardInterrupt:
        sys.stderr.write("study_plot.py: interrupted\n")
        return 130
    return 0


if __name__ == "__main__":
    sys.exit(main())
