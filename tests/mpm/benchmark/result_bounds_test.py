#!/usr/bin/env python3
"""The comparison of campaigns/benchmark/result_bounds.py (issue 41's result bounds;
docs/performance.md), on synthetic summaries and histories: no mpm run.

  result_bounds_test.py

An observable passes within 1e-6 relative of REF (the bound itself included), else within the
scatter |REF_half - REF| of a time-step halving, else fails; a momentum passes within 1e-12 |p0|
(round-off); `min bound` is the stricter reading (within the smaller of the two). The books: the
momentum closure momentum - p0 - boundary_impulse (+ outflow, - external) against 1e-12 of |p0|,
or, where p0 is round-off, of one body's sqrt(2 m KE0) (head-on) or the largest term of the
balance, |p| or an impulse (from rest); energy_error's end and max |.| within 1e-4 of REF where judged,
reported elsewhere. summary.json is read recursively without timing, memory, thread keys and
the energy error; a missing observable or a different status fails. With an ensemble of REF's
particle orders, an observable or the energy error also passes within the members' range widened
by three of its widths on each side, and a status a member had. A run directory is reused
when its stamp matches (scene and binary; --reuse-ref: the REF runs' scene alone).
"""
import json
import math
import os
import shutil
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "campaigns", "benchmark"))
import result_bounds as rb  # noqa: E402


def history(momentum_x, impulse_x, energy_error, gauge=None):
    cols = {"time [s]": [i * 1e-6 for i in range(len(momentum_x))],
            "momentum_x [kg m/s]": momentum_x, "momentum_y [kg m/s]": [0.0] * len(momentum_x),
            "momentum_z [kg m/s]": [0.0] * len(momentum_x),
            "boundary_impulse_x [N s]": impulse_x,
            "boundary_impulse_y [N s]": [0.0] * len(momentum_x),
            "boundary_impulse_z [N s]": [0.0] * len(momentum_x),
            "energy_error [-]": energy_error}
    if gauge is not None:
        cols["gauge_probe [m/s]"] = gauge
    return cols


def main():
    failures = []

    def check(ok, what):
        if not ok:
            failures.append(what)

    # --- summary.json read recursively, timing and host keys and the energy error left out.
    summary = {"wall_time [s]": 3.0, "phase_seconds [s]": {"stress": 1.0}, "threads": 2,
               "particle_steps_per_second": 1e6, "peak_resident_memory [MB]": 9.0,
               "memory_estimate": {"total [MB]": 16.0}, "omp_wait_policy": "passive",
               "status": "completed", "steps": 284, "failed_particles": 270,
               "final": {"energy_error [-]": 1e-3, "kinetic_energy [J]": 10.0},
               "observables": {"objects": {"sphere": {"mean_velocity [m/s]": [1.0, 2.0, 0.0]}},
                               "crater": {"depth [m]": 0.004, "half_depth_diameter [m]": 0.01}}}
    flat = rb.flatten(summary)
    check(set(flat) == {"status", "steps", "failed_particles", "final/kinetic_energy [J]",
                        "observables/objects/sphere/mean_velocity [m/s]/0",
                        "observables/objects/sphere/mean_velocity [m/s]/1",
                        "observables/objects/sphere/mean_velocity [m/s]/2",
                        "observables/crater/depth [m]", "observables/crater/half_depth_diameter [m]"},
          f"flatten keeps the results only: {sorted(flat)}")
    check(flat["status"] == "completed" and flat["observables/crater/depth [m]"] == 0.004,
          f"flatten values: {flat}")

    # --- 1e-6 relative, the bound included; beyond it, fails without a halving run.
    ok = rb.judge("crater/depth [m]", 1.0, 1.0 + 1e-6)
    check(ok["ok"] and ok["criterion"] == "1e-6", f"1e-6 exactly passes: {ok}")
    ok = rb.judge("crater/depth [m]", -4.0, -4.0 - 3.9e-6)
    check(ok["ok"] and ok["criterion"] == "1e-6", f"a negative value within 1e-6: {ok}")
    bad = rb.judge("crater/depth [m]", 1.0, 1.0 + 2e-6)
    check(not bad["ok"] and bad["criterion"] == "" and abs(bad["rel"] - 2e-6) < 1e-12,
          f"2e-6 fails without halving: {bad}")
    check(bad["strict"] is None, "no halving run: no strict reading")
    zero = rb.judge("failed_particles", 0.0, 1.0)
    check(not zero["ok"] and zero["rel"] == math.inf, f"REF 0, NEW 1: fails: {zero}")
    same = rb.judge("failed_particles", 0.0, 0.0)
    check(same["ok"] and same["rel"] == 0.0, f"0 and 0: {same}")

    # --- the halving scatter: passes within |REF_half - REF| when 1e-6 is exceeded.
    by_half = rb.judge("taylor/Lf [m]", 1.0, 1.0 + 1e-4, half=1.0 - 3e-4)
    check(by_half["ok"] and by_half["criterion"] == "halving" and
          abs(by_half["scatter"] - 3e-4) < 1e-12, f"within the halving scatter: {by_half}")
    check(by_half["strict"] is False, f"the stricter reading min(1e-6, scatter) fails: {by_half}")
    beyond = rb.judge("taylor/Lf [m]", 1.0, 1.0 + 4e-4, half=1.0 - 3e-4)
    check(not beyond["ok"], f"beyond the halving scatter fails: {beyond}")
    tight = rb.judge("taylor/Lf [m]", 1.0, 1.0 + 5e-7, half=1.0 + 1e-7)
    check(tight["ok"] and tight["criterion"] == "1e-6" and tight["strict"] is False,
          f"within 1e-6 but beyond a smaller scatter: passes, strict reading fails: {tight}")
    both = rb.judge("taylor/Lf [m]", 1.0, 1.0 + 5e-7, half=1.0 + 1e-5)
    check(both["ok"] and both["strict"] is True, f"within both: {both}")

    # --- a momentum that is round-off: within 1e-12 |p0|; not for other quantities.
    mom = rb.judge("final/momentum_y [kg m/s]", 1e-17, 4e-17, p0=0.6)
    check(mom["ok"] and mom["criterion"] == "round-off", f"momentum round-off: {mom}")
    imp = rb.judge("final/boundary_impulse_z [N s]", 0.0, 5e-13, p0=0.6)
    check(imp["ok"] and imp["criterion"] == "round-off", f"impulse round-off: {imp}")
    big = rb.judge("final/momentum_y [kg m/s]", 1e-17, 1e-12, p0=0.6)
    check(not big["ok"], f"momentum beyond 1e-12 |p0|: {big}")
    energy = rb.judge("final/kinetic_energy [J]", 1e-17, 4e-17, p0=0.6)
    check(not energy["ok"], f"without the scene's scales round-off is for momenta only: {energy}")

    # --- strings equal; an observable in only one run fails.
    rows = rb.compare_observables({"status": "completed", "steps": 10.0, "a": 1.0},
                                  {"status": "failed", "steps": 10.0, "b": 1.0})
    by_name = {r["observable"]: r for r in rows}
    check(not by_name["status"]["ok"], f"status differs: {by_name['status']}")
    check(by_name["steps"]["ok"], f"steps equal: {by_name['steps']}")
    check(not by_name["a"]["ok"] and by_name["a"]["criterion"] == "missing" and
          not by_name["b"]["ok"], f"missing observables: {rows}")
    rows = rb.compare_observables({"x": 2.0}, {"x": 2.0 + 1e-5}, half={"x": 2.0 + 1e-4})
    check(rows[0]["ok"] and rows[0]["criterion"] == "halving", f"halving by name: {rows}")

    # --- the books. The rod hits the wall: momentum - p0 - impulse = 0 exactly.
    p0 = -0.6
    ref = history([p0, -0.5, -0.25], [0.0, 0.1, 0.35], [0.0, 2e-3, 1e-3])
    scale, how = rb.momentum_scale(ref)
    check(scale == 0.6 and how == "|p0|", f"scale |p0|: {scale} {how}")
    check(rb.momentum_closure(ref, scale) < 1e-15, "closed books: 0 to round-off")
    leak = history([p0, -0.5, -0.25 + 6e-12], [0.0, 0.1, 0.35], [0.0, 2e-3, 1e-3])
    check(abs(rb.momentum_closure(leak, scale) - 1e-11) < 1e-14,
          f"a leak of 6e-12 on |p0| 0.6: {rb.momentum_closure(leak, scale)}")
    rows = rb.books(ref, leak, scale, True)
    check(not rows[0]["ok"] and rows[0]["observable"].startswith("books/momentum"),
          f"NEW's leak fails the momentum book: {rows[0]}")
    ok_rows = rb.books(ref, ref, scale, True)
    check(all(r["ok"] for r in ok_rows) and len(ok_rows) == 3, f"REF against itself: {ok_rows}")
    outflow = dict(ref)
    outflow["momentum_x [kg m/s]"] = [p0, -0.3, -0.05]          # 0.2 left through the x- face
    outflow["outflow_momentum_x [kg m/s]"] = [0.0, -0.2, -0.2]
    check(rb.momentum_closure(outflow, scale) < 1e-15, "outflow momentum is booked")
    gravity = history([0.0, 0.1, 0.2], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0])
    gravity["external_impulse_x [N s]"] = [0.0, 0.1, 0.2]
    check(rb.momentum_closure(gravity, 1.0) < 1e-15, "external impulse is booked")
    check(rb.momentum_scale(ref, [(1.0, 0.18)])[0] == 0.6, "one body moving: |p0|")
    head_on = history([1e-18, 1e-18, 2e-18], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0])
    scale0, how0 = rb.momentum_scale(head_on, [(2.0, 4.0), (2.0, 1.0)])
    check(scale0 == 4.0 and "p0 = 0" in how0,
          f"p0 round-off (head-on): the larger body's sqrt(2 m KE0): {scale0} {how0}")
    at_rest = history([0.0, 0.3, -0.5], [0.0, 0.3, -0.5], [0.0, 0.0, 0.0])
    scale1, how1 = rb.momentum_scale(at_rest, [(2.0, 0.0)])
    check(scale1 == 0.5 and "rest" in how1, f"a start at rest: the largest |p|: {scale1} {how1}")
    # A body resting on a wall under gravity: its momentum stays round-off, gravity's impulse
    # and the wall's grow and cancel; the scale is the largest term of the balance.
    resting = history([0.0, 1e-17, -2e-17], [0.0, 0.4, 0.8], [0.0, 0.0, 0.0])
    resting["external_impulse_x [N s]"] = [0.0, -0.4, -0.8]
    scale2, _ = rb.momentum_scale(resting, [(2.0, 0.0)])
    check(scale2 == 0.8, f"resting: the largest impulse: {scale2}")
    falling = dict(resting)
    falling["momentum_x [kg m/s]"] = [0.0, 1.0, 2.0]              # set moving: its momentum
    scale3, _ = rb.momentum_scale(falling, [(2.0, 0.0)])
    check(scale3 == 2.0, f"a body set moving: its largest momentum, the largest term: {scale3}")
    # Plane strain: the columns per metre of thickness are read alike.
    plane = {k.replace("[kg m/s]", "[(kg m/s)/m]").replace("[N s]", "[(N s)/m]"): v
             for k, v in leak.items()}
    check(abs(rb.momentum_closure(plane, scale) - 1e-11) < 1e-14,
          f"plane strain's leak is seen: {rb.momentum_closure(plane, scale)}")
    check(rb.judge("final/momentum_y [(kg m/s)/m]", 1e-17, 4e-17, p0=0.6)["criterion"] ==
          "round-off", "a plane-strain momentum is a momentum")
    # The unit is the last one on the path: an object named "rod [J]" does not make its
    # velocities energies.
    check(rb.unit_of("observables/objects/rod [J]/mean_velocity [m/s]/2") == "m/s" and
          rb.unit_of("final/momentum_y [(kg m/s)/m]") == "(kg m/s)/m" and
          rb.unit_of("history/gauge_v [m/s]/last") == "m/s" and
          rb.unit_of("observables/objects/rod [J]/particles") == "" and
          rb.unit_of("steps") == "", "the unit of an observable")
    e = rb.judge("observables/objects/rod [J]/max_pressure_time [s]", 1.0, 2.0,
                 scales={"velocity": 10.0, "energy": 1e9, "pressure": 1e9})
    check(not e["ok"], f"a time is no energy, whatever its object's name: {e}")
    v = rb.judge("observables/objects/b/mean_velocity [m/s]/2", 1.7e-15, 1.5e-15,
                 scales={"velocity": 10.0, "energy": 1.0})
    check(v["ok"] and v["criterion"] == "round-off", f"a round-off velocity of a 10 m/s body: {v}")
    v = rb.judge("observables/objects/b/mean_velocity [m/s]/2", 1.7e-15, 2e-10,
                 scales={"velocity": 10.0, "energy": 1.0})
    check(not v["ok"], f"2e-10 m/s is beyond round-off of 10 m/s: {v}")
    rows = {r["observable"]: r for r in rb.compare_observables(
        {"gauges/g/peak [m/s]": 3e-14, "gauges/g/peak_time [s]": 0.5},
        {"gauges/g/peak [m/s]": -3e-14, "gauges/g/peak_time [s]": 0.9},
        scales={"velocity": 1.0, "energy": 1.0})}
    check(rows["gauges/g/peak_time [s]"]["ok"] and
          rows["gauges/g/peak_time [s]"]["criterion"] == "round-off",
          f"a round-off peak's time: {rows}")
    rows = {r["observable"]: r for r in rb.compare_observables(
        {"o/b/max_pressure [Pa]": 4.8e-6, "o/b/max_pressure_time [s]": 1.7e-4},
        {"o/b/max_pressure [Pa]": 4.3e-6, "o/b/max_pressure_time [s]": 1.8e-4},
        scales={"velocity": 1.0, "energy": 1.0, "pressure": 1e6})}
    check(all(r["ok"] and r["criterion"] == "round-off" for r in rows.values()),
          f"a round-off pressure of a body in rigid translation, and its time: {rows}")
    scales = rb.round_off_scales({"mass [kg]": 2.0, "initial_energy [J]": 4.0, "objects": {
        "a": {"particle_volume [m^3]": 1e-3}, "b": {"particle_volume [m^3]": 3e-3}}}, 6.0)
    check(scales == {"velocity": 3.0, "energy": 4.0, "pressure": 1000.0},
          f"scales from a summary: {scales}")
    # A start at rest (plane strain): the largest energy that entered, not gravity's free fall
    # over the run (its impulse over the mass).
    rest = {"mass [kg/m]": 2.0, "initial_energy [J/m]": 0.0,
            "objects": {"a": {"particle_volume [m^3/m]": 1e-3}}}
    scales = rb.round_off_scales(rest, 1e3, {"total_energy [J/m]": [0.0, 0.25, 0.09],
                                             "external_work [J/m]": [0.0, 0.16, 0.2]})
    check(scales == {"velocity": 0.5, "energy": 0.25, "pressure": 250.0},
          f"a start at rest's scales: {scales}")
    e = rb.judge("final/kinetic_energy [J/m]", 0.08, 0.0808, scales=scales)
    check(not e["ok"], f"a 1 % change of a resting body's energy is no round-off: {e}")
    rows = {r["observable"]: r for r in rb.compare_observables(
        {"gauges/g/peak [m/s]": 3.0, "gauges/g/peak_time [s]": 0.5},
        {"gauges/g/peak [m/s]": 3.0, "gauges/g/peak_time [s]": 0.9},
        scales={"velocity": 1.0, "energy": 1.0})}
    check(not rows["gauges/g/peak_time [s]"]["ok"],
          f"a real peak's time is judged on its own: {rows}")

    # Energy error: end and max |.| within 1e-4 where judged (Table 2, recommended).
    near = history([p0, -0.5, -0.25], [0.0, 0.1, 0.35], [0.0, 2e-3 + 9e-5, 1e-3 - 9e-5])
    far = history([p0, -0.5, -0.25], [0.0, 0.1, 0.35], [0.0, 2e-3, 1e-3 + 2e-4])
    check(all(r["ok"] for r in rb.books(ref, near, scale, True)), "energy within 1e-4 passes")
    rows = {r["observable"]: r for r in rb.books(ref, far, scale, True)}
    check(not rows["books/energy_error_end [-]"]["ok"] and
          rows["books/energy_error_max_abs [-]"]["ok"],
          f"end 2e-4 off fails, max abs unchanged passes: {rows}")
    peak = history([p0, -0.5, -0.25], [0.0, 0.1, 0.35], [0.0, -2.2e-3, 1e-3])
    rows = {r["observable"]: r for r in rb.books(ref, peak, scale, True)}
    check(not rows["books/energy_error_max_abs [-]"]["ok"] and
          abs(rows["books/energy_error_max_abs [-]"]["new"] - 2.2e-3) < 1e-15,
          f"max |energy_error| read over the rows, sign ignored: {rows}")
    rows = rb.books(ref, far, scale, False)
    check(all(r["ok"] for r in rows[1:]) and rows[1]["criterion"] == "reported",
          f"energy reported, not judged, outside Table 2 and recommended: {rows}")

    # --- the ensemble of particle orders (issue 57): within the members' range widened by three
    # of its widths on each side; REF is a member.
    check(rb.ENSEMBLE_WIDTHS == 3.0, "three widths (docs/performance.md)")
    members = [10.0, 10.4, 9.8, 10.1, 10.2]                      # range [9.8, 10.4], width 0.6
    e = rb.judge("failed_particles", 10.0, 12.1, members=members)
    check(e["ok"] and e["criterion"] == "ensemble" and abs(e["spread"] - 0.06) < 1e-12,
          f"within [8.0, 12.2]: passes by the ensemble: {e}")
    edge = [10.0, 10.5, 9.75, 10.25, 10.0]                        # 9.75 - 3 x 0.75 = 7.5
    e = rb.judge("failed_particles", 10.0, 7.5, members=edge)
    check(e["ok"] and e["criterion"] == "ensemble", f"the widened range's edge passes: {e}")
    e = rb.judge("failed_particles", 10.0, 7.49, members=edge)
    check(not e["ok"], f"just beyond the edge fails: {e}")
    nan = float("nan")
    e = rb.judge("history/gauge_probe [m/s]/min", nan, nan)
    check(e["ok"] and e["criterion"] == "equal", f"NaN in REF and NEW is the same: {e}")
    check(math.isnan(rb.energy_errors({"energy_error [-]": [0.0, nan, 1e-3]})[1]),
          "a NaN energy error is no maximum")
    e = rb.judge("failed_particles", 10.0, 12.25, members=members)
    check(not e["ok"], f"beyond the widened range fails: {e}")
    e = rb.judge("failed_particles", 10.0, 10.0 + 5e-5, members=[10.0] * 5)
    check(not e["ok"], f"an ensemble without spread admits nothing beyond 1e-6: {e}")
    e = rb.judge("failed_particles", 10.0, 10.15, members=[10.0, 10.1, float("nan"), 10.2, 10.0])
    check(not e["ok"], f"a member without a finite value admits nothing: {e}")
    e = rb.judge("status", "completed", "failed", members=["completed", "failed", "completed"])
    check(e["ok"] and e["criterion"] == "ensemble", f"a status a member had: {e}")
    e = rb.judge("status", "completed", "failed", members=["completed"] * 5)
    check(not e["ok"], f"a status no member had: {e}")
    rows = {r["observable"]: r for r in rb.compare_observables(
        {"x": 1.0, "y": 2.0}, {"x": 1.5, "y": 2.5},
        ensemble=[{"x": 1.2, "y": 2.0}, {"x": 0.9, "y": 2.0}, {"x": 1.1}, {"x": 1.0}])}
    check(rows["x"]["ok"] and rows["x"]["criterion"] == "ensemble",
          f"x within [0.0, 2.1]: {rows['x']}")
    check(not rows["y"]["ok"], f"y: a member lacks it, judged without the ensemble: {rows['y']}")
    # The energy error: within 1e-4 of REF, or within the ensemble's widened range.
    others = [history([p0, -0.5, -0.25], [0.0, 0.1, 0.35], [0.0, 2e-3, 1e-3 + d])
              for d in (1e-4, -0.5e-4, 0.5e-4, 0.0)]       # end in [0.95e-3, 1.1e-3], w 1.5e-4
    rows = {r["observable"]: r for r in rb.books(ref, far, scale, True, others)}
    check(rows["books/energy_error_end [-]"]["ok"] and
          rows["books/energy_error_end [-]"]["criterion"] == "ensemble",
          f"end 2e-4 off, within the ensemble: {rows}")
    beyond = history([p0, -0.5, -0.25], [0.0, 0.1, 0.35], [0.0, 2e-3, 1e-3 + 6e-4])
    rows = {r["observable"]: r for r in rb.books(ref, beyond, scale, True, others)}
    check(not rows["books/energy_error_end [-]"]["ok"],
          f"end 6e-4 off, beyond [0.5e-3, 1.55e-3]: fails: {rows}")
    doc = rb.extending_scene("/a/case01.json", "table2", shuffle=3)
    check(doc["solver"] == {"shuffle_particles": 3} and doc["output"] == {"snapshots": False},
          f"a member's scene: {doc}")
    check("solver" not in rb.extending_scene("/a/case01.json", "table2"),
          "the seeded REF's scene sets no order")

    # Gauges: max, min and last of each gauge column.
    g = rb.gauge_observables(history([p0] * 3, [0.0] * 3, [0.0] * 3, gauge=[0.0, -3.0, -1.0]))
    check(g == {"history/gauge_probe [m/s]/max": 0.0, "history/gauge_probe [m/s]/min": -3.0,
                "history/gauge_probe [m/s]/last": -1.0}, f"gauge peaks: {g}")

    # Resumption: a run directory is reused when its stamp matches (the REF runs with
    # --reuse-ref: the scene alone), and only with its summary.json.
    work = tempfile.mkdtemp()
    stamp = {"scene": {"extends": "/a.json"}, "binary_sha256": "1"}
    with open(os.path.join(work, "bounds_stamp.json"), "w") as f:
        json.dump(dict(stamp, exit_code=0, wall_seconds=1.5), f)
    check(not rb.finished(work, stamp, False), "no summary.json: not finished")
    with open(os.path.join(work, "summary.json"), "w") as f:
        f.write("{}")
    check(rb.finished(work, stamp, False), "same scene and binary: finished")
    other = dict(stamp, binary_sha256="2")
    check(not rb.finished(work, other, False), "another binary: run again")
    check(rb.finished(work, other, True), "another binary, scene only (--reuse-ref): reused")
    check(not rb.finished(work, dict(stamp, scene={"extends": "/b.json"}), True),
          "another scene: run again")
    shutil.rmtree(work)

    for what in failures:
        print("FAILED:", what)
    if not failures:
        print("result bounds: all checks passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
