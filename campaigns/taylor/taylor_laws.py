#!/usr/bin/env python3
"""Which flow-stress law predicts the Taylor shots best: campaigns of several parameter sets on
several anvils, compared per set, anvil and aspect ratio.

  python3 campaigns/taylor/taylor_laws.py OUT CAMPAIGN [CAMPAIGN ...]

Each CAMPAIGN is the OUT of a campaigns/taylor/taylor.py run (one anvil each) with several
`--sets` at one resolution, failure off. Writes OUT/laws.md and OUT/laws.csv (per set and anvil:
runs, Lf and Dm error mean / mean abs / worst abs, shots within 3 % (Lf) and 5 % (Dm), and the
mean errors per aspect-ratio group) and OUT/laws.png (Lf and Dm error against L0/D0, a panel per
anvil and measure, a marker per set). Errors are (predicted - measured) / measured [%]. Nothing
is run.
"""

import argparse
import csv
import os
import sys
from collections import defaultdict

# The House et al. (1995) rods fall in three families of aspect ratio.
ASPECT_GROUPS = (("1.5-2", 1.0, 2.5), ("3-5", 2.5, 6.0), ("7.5-10", 6.0, 11.0))
SET_ORDER = ("table1", "fit_all", "fit_room", "scg", "fit_za", "fit_ptw")
SET_LABELS = {"table1": "JC, Table 1 (published)", "fit_all": "JC, fitted",
              "fit_room": "JC, fitted (room temperature)", "scg": "SCG, Steinberg (published)",
              "fit_za": "ZA fcc, fitted", "fit_ptw": "PTW, fitted"}
REQUIRED = ("set", "failure", "cells_per_radius", "shot", "exit_code", "L0_over_D0 [-]",
            "Lf_error [%]", "Dm_error [%]")
MARKERS = {"table1": "s", "fit_all": "o", "fit_room": "^", "scg": "D", "fit_za": "v",
           "fit_ptw": "P"}


def number(text):
    return float(text) if text not in (None, "") else None


def anvil_of(row):
    friction = number(row.get("anvil_friction"))
    name = row.get("anvil") or "mirror"
    return f"{name}, mu = {friction:g}" if friction is not None else name


def load(campaign):
    path = os.path.join(campaign, "results.csv")
    if not os.path.isfile(path):
        sys.exit(f"taylor_laws: {path}: not found (run campaigns/taylor/taylor.py first)")
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        missing = [c for c in REQUIRED if c not in (reader.fieldnames or [])]
        if missing:
            sys.exit(f"taylor_laws: {path}: not a taylor.py results table (no column "
                     f"{', '.join(missing)})")
        rows = [r for r in reader if r["failure"] == "off"]
    if not rows:
        sys.exit(f"taylor_laws: {path}: no run with failure off")
    for r in rows:
        r["ok"] = r["exit_code"] == "0"
        r["aspect"] = float(r["L0_over_D0 [-]"])
        for key in ("Lf_error [%]", "Dm_error [%]"):
            r[key] = number(r.get(key))
        r["anvil_label"] = anvil_of(r)
    return rows


def stats(errors, bound):
    if not errors:
        return None
    return {"mean": sum(errors) / len(errors), "mean_abs": sum(map(abs, errors)) / len(errors),
            "worst": max(errors, key=abs), "within": sum(abs(e) <= bound for e in errors),
            "n": len(errors)}


def summarise(rows):
    out = []
    keyed = defaultdict(list)
    for r in rows:
        keyed[(r["anvil_label"], r["set"])].append(r)
    order = {s: i for i, s in enumerate(SET_ORDER)}
    for (anvil, s), rs in sorted(keyed.items(), key=lambda k: (k[0][0], order.get(k[0][1], 99))):
        ok = [r for r in rs if r["ok"]]
        entry = {"anvil": anvil, "set": s, "runs": len(rs), "ok": len(ok),
                 "Lf": stats([r["Lf_error [%]"] for r in ok if r["Lf_error [%]"] is not None], 3.0),
                 "Dm": stats([r["Dm_error [%]"] for r in ok if r["Dm_error [%]"] is not None], 5.0)}
        for name, lo, hi in ASPECT_GROUPS:
            group = [r for r in ok if lo <= r["aspect"] < hi]
            for key in ("Lf", "Dm"):
                e = [r[f"{key}_error [%]"] for r in group if r[f"{key}_error [%]"] is not None]
                entry[f"{key} {name}"] = sum(e) / len(e) if e else None
        out.append(entry)
    return out


def write(out, summary):
    groups = [g[0] for g in ASPECT_GROUPS]
    head = ["anvil", "set", "runs", "completed"]
    for key in ("Lf", "Dm"):
        head += [f"{key} error mean [%]", f"{key} error mean abs [%]", f"{key} error worst [%]",
                 f"{key} within {'3' if key == 'Lf' else '5'} %"]
        head += [f"{key} error mean, L0/D0 {g} [%]" for g in groups]
    with open(os.path.join(out, "laws.csv"), "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(head)
        for e in summary:
            row = [e["anvil"], e["set"], e["runs"], e["ok"]]
            for key in ("Lf", "Dm"):
                s = e[key] or {}
                row += [s.get("mean"), s.get("mean_abs"), s.get("worst"), s.get("within")]
                row += [e[f"{key} {g}"] for g in groups]
            w.writerow(row)

    def fmt(v):
        return "-" if v is None else f"{v:+.2f}"

    lines = ["| anvil | set | Lf mean / mean abs / worst [%] | Lf within 3 % [shots] | "
             "Lf mean by L0/D0 " + " / ".join(groups) + " [%] | Dm mean / mean abs / worst [%] | "
             "Dm within 5 % [shots] | Dm mean by L0/D0 " + " / ".join(groups) + " [%] |",
             "|---|---|---|---|---|---|---|---|"]
    for e in summary:
        cells = [e["anvil"], f"`{e['set']}` ({SET_LABELS.get(e['set'], e['set'])})"]
        for key in ("Lf", "Dm"):
            s = e[key]
            if s is None:
                cells += ["not measured", "-", "-"]
                continue
            cells += [f"{s['mean']:+.2f} / {s['mean_abs']:.2f} / {s['worst']:+.2f}",
                      f"{s['within']} of {s['n']}",
                      " / ".join(fmt(e[f"{key} {g}"]) for g in groups)]
        if e["ok"] < e["runs"]:
            cells[1] += f" ({e['runs'] - e['ok']} runs failed)"
        lines.append("| " + " | ".join(cells) + " |")
    with open(os.path.join(out, "laws.md"), "w") as f:
        f.write("Taylor impact of 6061-T6 (House et al. 1995), failure off: prediction error per "
                "flow-stress law and anvil (campaigns/taylor/taylor_laws.py).\n\n")
        f.write("\n".join(lines) + "\n")


def figure(out, rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    anvils = sorted({r["anvil_label"] for r in rows})
    sets = sorted({r["set"] for r in rows}, key=lambda s: SET_ORDER.index(s)
                  if s in SET_ORDER else 99)
    fig, axes = plt.subplots(2, len(anvils), figsize=(6 * len(anvils), 8), squeeze=False)
    for j, anvil in enumerate(anvils):
        for i, (key, band) in enumerate((("Lf", 3.0), ("Dm", 5.0))):
            ax = axes[i][j]
            for k, s in enumerate(sets):
                pts = sorted((r["aspect"], r[f"{key}_error [%]"]) for r in rows
                             if r["anvil_label"] == anvil and r["set"] == s and r["ok"]
                             and r[f"{key}_error [%]"] is not None)
                # A small horizontal offset per set, so that the markers of one rod do not hide
                # each other.
                dx = 0.08 * (k - (len(sets) - 1) / 2)
                ax.plot([a + dx for a, _ in pts], [e for _, e in pts], MARKERS.get(s, "d"),
                        mfc="none", label=SET_LABELS.get(s, s))
            ax.axhspan(-band, band, color="0.9", zorder=0)
            ax.axhline(0.0, color="k", lw=0.6)
            ax.set_xlabel("L0 / D0 [-]")
            ax.set_ylabel(f"{key} error [%]")
            ax.set_title(f"{key}, anvil: {anvil}", fontsize=10)
            ax.grid(alpha=0.3)
    axes[0][0].legend(fontsize=8)
    geometry = ", ".join(sorted({r.get("geometry") or "3d" for r in rows}))
    cells = ", ".join(sorted({r["cells_per_radius"] for r in rows}))
    fig.suptitle(f"Taylor impact of 6061-T6 (House et al. 1995), {geometry}, {cells} cells per "
                 "radius, failure off: error per law (grey: +-3 % Lf, +-5 % Dm)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "laws.png"), dpi=110)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out")
    ap.add_argument("campaigns", nargs="+")
    ap.add_argument("--no-plot", action="store_true")
    a = ap.parse_args()
    rows = [r for c in a.campaigns for r in load(c)]
    os.makedirs(a.out, exist_ok=True)
    write(a.out, summarise(rows))
    if not a.no_plot:
        figure(a.out, rows)
    print(f"taylor_laws: wrote {a.out}/laws.md, laws.csv" + ("" if a.no_plot else ", laws.png"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
