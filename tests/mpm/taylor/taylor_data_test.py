#!/usr/bin/env python3
"""The Taylor campaign's table of shots (--data) and its convergence estimate (docs/taylor.md).

  taylor_data_test.py WORK_DIR

campaigns/taylor/taylor.py reads any table in the columns of data/experiments/taylor/house1995.csv:
a measurement (Lf, Dm, Xf) left empty, or its column left out, is None: reported, not judged (no
error, out of the error statistics); L0_over_D0 follows from L0 and D0 when absent; a missing or
non-positive required value stops with the file, row and column. The House table reads as before
(23 shots, every measurement present). campaigns/taylor/taylor_report.py's Richardson estimate
recovers the order and the limit of f = f0 + C h^p from three levels with a constant and with a
non-constant refinement ratio, and refuses oscillating or non-shrinking differences. A run
directory whose result.json holds the same scene is finished (the campaign resumes); another scene
or no result is not.
"""
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "campaigns", "taylor"))
sys.path.insert(0, os.path.join(ROOT, "campaigns", "study"))
import taylor  # noqa: E402
import taylor_report  # noqa: E402

HEADER = "shot,L0_over_D0 [-],D0 [m],L0 [m],U0 [m/s],T0 [K],rho0 [kg/m^3],Lf [m],Dm [m],Xf [m]\n"


def write(work, name, text):
    path = os.path.join(work, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def refused(path):
    """The message with which read_shots stops, or None when it reads the file."""
    try:
        taylor.read_shots(path)
    except taylor.InputError as e:
        return str(e)
    return None


def main(work):
    os.makedirs(work, exist_ok=True)
    failures = []

    def check(ok, what):
        if not ok:
            failures.append(what)

    house = taylor.read_shots()
    check(len(house) == 23 and all(s[k] is not None for s in house for k in taylor.MEASURED),
          "the House table: 23 shots with every measurement")
    check(house[7]["shot"] == "H8" and house[7]["aspect"] == 2.0 and house[7]["Lf"] == 0.0114,
          f"H8 read as {house[7]}")

    # A table with an unmeasured diameter and an unmeasured length, without the aspect column.
    table = write(work, "partial.csv", "shot,D0 [m],L0 [m],U0 [m/s],T0 [K],Lf [m],Dm [m],Xf [m]\n"
                  "A1,0.0076,0.0152,300,294,0.0131,,\n"
                  "A2,0.0076,0.0380,250,294,,0.0120,0.0200\n")
    shots = taylor.read_shots(table)
    check([s["shot"] for s in shots] == ["A1", "A2"], f"shot names {shots}")
    check(shots[0]["Dm"] is None and shots[0]["Xf"] is None and shots[0]["Lf"] == 0.0131,
          f"A1's empty Dm and Xf: {shots[0]}")
    check(shots[1]["Lf"] is None and shots[1]["Dm"] == 0.0120, f"A2's empty Lf: {shots[1]}")
    check(abs(shots[0]["aspect"] - 2.0) < 1e-12, f"A1's aspect from L0/D0: {shots[0]['aspect']}")
    # Measurement columns left out altogether: nothing to judge.
    bare = taylor.read_shots(write(work, "bare.csv", "shot,D0 [m],L0 [m],U0 [m/s],T0 [K]\n"
                                   "B1,0.0076,0.0152,300,294\n"))
    check(all(bare[0][k] is None for k in taylor.MEASURED), f"no measurement columns: {bare}")

    # Not judged: no error where the measurement is empty; Xf never (A2 has a measured Xf).
    row = {"Lf [m]": 0.0130, "Dm [m]": 0.0125, "Xf [m]": 0.005}
    taylor.record_shape(row, shots[0], [(0.001, 0.004, 0.1)], work, "t")
    check(abs(row["Lf_error [%]"] - 100 * (0.0130 / 0.0131 - 1)) < 1e-12
          and row["Dm_error [%]"] == "" and "Xf_error [%]" not in row,
          f"errors of A1: {row}")
    row2 = {"Lf [m]": 0.0300, "Dm [m]": 0.0125, "Xf [m]": 0.0, "Xf_error [%]": -100.0}
    taylor.record_shape(row2, shots[1], [(0.001, 0.004, 0.1)], work, "t")
    check("Xf_error [%]" not in row2 and abs(row2["Dm_error [%]"] - 100 * (0.0125 / 0.0120 - 1))
          < 1e-12, f"errors of A2 (Xf measured, not judged): {row2}")
    check(taylor.shape_text(row) == f"Lf {row['Lf_error [%]']:+.2f} %, Dm 12.500 mm (not measured)",
          f"printed: {taylor.shape_text(row)}")
    check(taylor_report.error_stats([]) == "not measured"
          and taylor_report.error_stats([1.0, -3.0]) == "-1.00 / 2.00 / 3.00",
          "error statistics")

    # Xf = Lf - the axial position where the section's mean plastic strain falls below 0.2 %,
    # in bins of one particle spacing h: a rod yielded along its whole length has Xf = 0, though
    # the last plastic bin's upper edge lies beyond its rear end (it read -0.1 mm, "-101 %").
    import numpy as np
    h8 = house[7]
    h = 0.5 * h8["D0"] / 4 / taylor.PPC
    axial, _ = taylor.seed_offsets(h8, 4)
    # The last particle at 35.2 h, its bin's top at 36 h, Lf = 35.7 h: Xf read -0.35 h before.
    x = np.array([[(i + 0.5) * 0.89 * h, 0.0, 0.0] for i in range(40)])
    Lf, _, Xf, _ = taylor.measure(x, np.full(40, 0.01), h8, 4)
    check(abs(Lf - (39.5 * 0.89 * h + axial)) < 1e-15 and Xf == 0.0,
          f"Xf of a rod plastic all along: {Xf} (Lf {Lf})")
    strain = np.where(x[:, 0] < 5 * h, 0.01, 0.0)  # bins 0-4 plastic: the edge at 5 h
    _, _, Xf, _ = taylor.measure(x, strain, h8, 4)
    check(abs(Xf - (Lf - 5 * h)) < 1e-15, f"Xf of a rod plastic below 5 h: {Xf}")

    # Bad tables: the file, the row and the column.
    for name, text, expected in [
            ("no_speed.csv", HEADER + "H1,1.5,0.007595,0.01139,,294,2700,0.0102,0.0099,0.0052\n",
             "row 2 (H1), column 'U0 [m/s]': '' is not a number > 0"),
            ("bad_lf.csv", HEADER + "H1,1.5,0.007595,0.01139,227,294,2700,short,0.0099,0.0052\n",
             "row 2 (H1), column 'Lf [m]': 'short' is not a number > 0 or empty (not measured)"),
            ("negative.csv", HEADER + "H1,1.5,-0.007595,0.01139,227,294,2700,,,\n",
             "row 2 (H1), column 'D0 [m]': '-0.007595' is not a number > 0"),
            ("twice.csv", HEADER + "H1,1.5,0.0076,0.0114,227,294,2700,,,\n"
             "H1,1.5,0.0076,0.0114,227,294,2700,,,\n",
             "row 3: the column 'shot' needs a name, unique in the file (got 'H1')"),
            ("empty.csv", HEADER, "no shots")]:
        path = write(work, name, text)
        message = refused(path)
        check(message == f"taylor: {path}: {expected}", f"{name}: {message}")

    # Richardson: f = f0 + C h^p with h = 1 / n.
    def f(n, p=1.7):
        return 10.0 + 3.0 * (1.0 / n) ** p

    for levels in [(12, 16, 24), (6, 12, 24), (4, 6, 8)]:
        est = taylor_report.richardson(levels, [f(n) for n in levels])
        check(est is not None and abs(est[0] - 1.7) < 1e-8 and abs(est[1] - 10.0) < 1e-10,
              f"Richardson at {levels}: {est}")
    r = 2.0
    vals = [f(6), f(12), f(24)]
    closed = math.log((vals[0] - vals[1]) / (vals[1] - vals[2])) / math.log(r)
    check(abs(taylor_report.richardson((6, 12, 24), vals)[0] - closed) < 1e-12,
          "constant ratio: the closed form")
    check(taylor_report.equal_ratio_triple([4, 6, 8, 12, 16]) == (4, 8, 16)
          and taylor_report.equal_ratio_triple([4, 6, 8, 12, 16, 24]) == (6, 12, 24)
          and taylor_report.equal_ratio_triple([4, 6, 8, 12]) is None, "equal-ratio triples")
    check(taylor_report.richardson((12, 16, 24), [1.0, 1.1, 1.05]) is None, "oscillating")
    check(taylor_report.richardson((12, 16, 24), [1.0, 1.1, 1.3]) is None, "growing differences")
    check(taylor_report.richardson((12, 16, 24), [1.0, 1.0, 1.1]) is None, "no change, then one")

    # The report's tables render (GFM): each delimiter row has as many cells as its header,
    # on a committed ladder campaign (two sets, three resolutions: every table the report
    # writes but the failure table) and on the failure study; written without figures.
    sys.path.insert(0, os.path.join(ROOT, "tests", "mpm", "study"))
    import markdown_tables_test  # noqa: E402
    for campaign in ("taylor_ladder", "taylor_failure"):
        out = os.path.join(work, campaign)
        os.makedirs(out, exist_ok=True)
        with open(os.path.join(ROOT, "docs", "figures", campaign, "results.csv")) as f:
            text = f.read()
        write(out, "results.csv", text)
        taylor_report.report(out, draw=False)
        md = os.path.join(out, "results.md")
        with open(md) as f:
            tables = f.read().count("\n|---")
        bad = markdown_tables_test.problems(md)
        check(not bad and tables >= 4, f"{campaign}: results.md tables {tables}, delimiter rows "
              f"short (line, header, delimiter): {bad}")

    # The grid's radial extent follows the mushroom: while material reaches y+ or z+ (summary.json
    # "material_reached_faces"), the shot runs again 1.5 times wider, each attempt in its own
    # directory; the last attempt's faces and the earlier ones go into the row and onto stderr.
    # run_attempt stands in for mpm here: the mushroom reaches 3.8 R0 (the 600 m/s shot).
    import contextlib
    import io
    calls = []

    def fake_attempt(mushroom):
        def attempt(job, run_dir, radial):
            calls.append((os.path.basename(run_dir), round(radial, 6)))
            face = [{"face": "y+", "condition": "symmetric", "first_time [s]": 2.1e-5,
                     "particles": 40}] if mushroom >= radial - 0.2 else []
            return {"Lf [m]": 0.01, "Dm [m]": 0.02, "Xf [m]": 0.0,
                    "radial_extent_over_R0 [-]": radial}, [(0.0, 0.0, 0.0)], face
        return attempt

    real_attempt = taylor.run_attempt
    fast = dict(house[7], shot="U600", U0=600.0)
    job = (fast, "table1", taylor.MATERIAL, "off", 6, work, os.path.join(work, "runs"), "mpm", 1,
           ("mirror", 0.0), "3d")
    try:
        for mushroom, radials, still in ((3.8, [2.2, 3.3, 4.95], False), (1.7, [2.2], False),
                                         (9.0, [2.2, 3.3, 4.95, 7.425], True)):
            calls.clear()
            taylor.run_attempt = fake_attempt(mushroom)
            err = io.StringIO()
            with contextlib.redirect_stderr(err):
                row, _ = taylor.run_one(job)
            check([r for _, r in calls] == radials and calls[0][0] == "U600"
                  and all(d == f"U600_radial{r:.4g}" for d, r in calls[1:]),
                  f"mushroom {mushroom} R0: attempts {calls}")
            check(abs(row["radial_extent_over_R0 [-]"] - radials[-1]) < 1e-12
                  and (row["material_reached_faces"] != "") == still
                  and row["confined_attempts"].count(" R0: y+ (symmetric) at 21.0 us, 40 "
                                                     "particles") == len(radials) - 1,
                  f"mushroom {mushroom} R0: row {row}")
            lines = err.getvalue().splitlines()
            check(len(lines) == len(radials) - 1 + still
                  and all(line.startswith("taylor: warning: table1_off_n6 U600: with the grid ")
                          and " R0 from the axis, material reached its outer faces y+ (symmetric) "
                          "at 21.0 us, 40 particles: " in line for line in lines)
                  and (not still or lines[-1].endswith("its Lf and Dm may be confined "
                                                       "(results.csv, material_reached_faces)")),
                  f"mushroom {mushroom} R0: stderr {lines}")
    finally:
        taylor.run_attempt = real_attempt
    # The report flags a confined run: one row of the ladder campaign above, confined.
    import csv
    with open(os.path.join(work, "taylor_ladder", "results.csv"), newline="") as f:
        first = next(csv.DictReader(f))
    first.update({"material_reached_faces": "y+ (symmetric) at 21.0 us, 40 particles",
                  "confined_attempts": "", "radial_extent_over_R0 [-]": "7.425"})
    with open(os.path.join(work, "taylor_ladder", "results.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, list(first), lineterminator="\n")
        w.writeheader()
        w.writerow(first)
    taylor_report.report(os.path.join(work, "taylor_ladder"), draw=False)
    with open(os.path.join(work, "taylor_ladder", "results.md")) as f:
        report = f.read()
    check("CONFINED at 7.42 R0: y+ (symmetric) at 21.0 us, 40 particles" in report,
          "results.md does not flag the confined run")

    # Resuming: the result of this very scene and material content, or nothing.
    sc = taylor.scene(house[7], taylor.MATERIAL, "off", 6, geometry="axisymmetric")
    digest = taylor.material_digest(taylor.MATERIAL)
    run = os.path.join(work, "run")
    os.makedirs(run, exist_ok=True)
    if os.path.exists(os.path.join(run, "result.json")):
        os.remove(os.path.join(run, "result.json"))
    check(taylor.finished(run, sc, digest) is None, "no result.json: not finished")
    with open(os.path.join(run, "result.json"), "w") as f:
        json.dump({"scene": sc, "material_sha256": digest, "row": {"Lf [m]": 0.0114},
                   "profile": [[0.1, 0.2, 0.3]]}, f)
    done = taylor.finished(run, json.loads(json.dumps(sc)), digest)
    check(done is not None and done["row"] == {"Lf [m]": 0.0114}, f"finished: {done}")
    check(taylor.finished(run, taylor.scene(house[7], taylor.MATERIAL, "off", 8,
                                            geometry="axisymmetric"), digest) is None,
          "another scene in the same directory: not finished")
    # A material file rewritten in place (a re-fit) under the same name: not the same run.
    refit = os.path.join(work, "refit.json")
    with open(taylor.MATERIAL) as f:
        text = f.read()
    with open(refit, "w") as f:
        f.write(text)
    before = taylor.material_digest(refit)
    with open(refit, "w") as f:
        f.write(text.replace('"A": 324.0e6', '"A": 325.0e6'))
    check(taylor.material_digest(refit) != before, "the digest follows the file's content")
    check(taylor.finished(run, sc, taylor.material_digest(refit)) is None,
          "the same scene with another material content: not finished")

    for what in failures:
        print("FAILED:", what)
    if not failures:
        print("taylor data: all checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
