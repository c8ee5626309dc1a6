#!/usr/bin/env python3
"""campaigns/study/ladder.py on a graded grid (grid.refine, issue 56): a level keeps the base cells
and scales the box's refine.factor, so the coarse cells and the box's nodes are the same at every
level and only the box refines. Checked against the reader itself: for each level of a Taylor rod
whose box ends off the base nodes, at factors that are and are not whole (2 x 1, 1.5, 2.2), the
level scene the ladder writes gets from `mpm check` the base cells as given and a smallest cell
per axis equal (to 1e-12, relative) to the box's cell size the ladder computes (ladder.fine_cells),
and the ladder's representative h is the geometric mean of those; level 1 has the scene's own
fingerprint (mpm run of the scene finds its error bar); a --set that deletes grid.refine reaches
the level file (the level runs uniform); the levels' narrowed uGIMP boxes and a body's seeded
volume that differs by more than 1 % between levels are warned of. A level that would take the
factor past 64 is a usage error before anything runs.

  ladder_graded_test.py MPM"""

import contextlib
import io
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "campaigns", "study"))
import ladder  # noqa: E402

ROD = os.path.join(ROOT, "data", "scenes", "verification", "taylor_rod.json")
BOX = {"lower": [0.0, 0.0, 0.0], "upper": [0.0041, 0.0052, 0.0052], "factor": 2,
       "growth": 1.3}


def main():
    mpm = sys.argv[1]
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        scene_file = os.path.join(tmp, "graded_rod.json")
        with open(scene_file, "w") as f:
            json.dump({"extends": ROD, "grid": {"refine": BOX}}, f)
        scene = json.load(open(ROD))
        scene["grid"]["refine"] = dict(BOX)
        for level in (1.0, 1.5, 2.2):
            path = os.path.join(tmp, ladder.run_name(level) + ".json")
            ladder.write_level_scene(path, scene_file, scene, level, None, 200, None)
            done = subprocess.run([mpm, "check", path, "--threads", "1"], capture_output=True,
                                  text=True, timeout=300)
            if done.returncode != 0:
                failures.append(f"level {level:g}: mpm check exit {done.returncode}: "
                                f"{done.stderr.strip()}")
                continue
            grid = json.loads(done.stdout)["report"]["grid"]
            expected = ladder.fine_cells(scene, BOX["factor"] * level)
            print(f"level {level:g}: factor {BOX['factor'] * level:g}, cells {grid['cells']}, "
                  f"smallest {grid['smallest_cell [m]']} m, ladder {expected} m")
            if grid["base_cells"] != scene["grid"]["cells"]:
                failures.append(f"level {level:g}: base cells {grid['base_cells']}, expected "
                                f"{scene['grid']['cells']}")
            for d, (got, want) in enumerate(zip(grid["smallest_cell [m]"], expected)):
                if abs(got - want) > 1e-12 * want:
                    failures.append(f"level {level:g}, axis {d}: smallest cell {got!r} m, the "
                                    f"ladder's box cell {want!r} m")
            h = ladder.representative_h(scene, ladder.level_cells(scene, level),
                                        ladder.level_factor(scene, level))
            mean = (expected[0] * expected[1] * expected[2]) ** (1.0 / 3.0)
            if abs(h - mean) > 1e-12 * mean:
                failures.append(f"level {level:g}: representative h {h!r} m, expected {mean!r} m")
        # Level 1 is the scene itself: the same fingerprint, so mpm run of the scene finds its
        # level in the ladder table (the scene writes 2, and 2 x 1.0 would write 2.0).
        prints = [subprocess.run([mpm, "check", "--fingerprint", p], capture_output=True,
                                 text=True, timeout=300).stdout.strip()
                  for p in (scene_file, os.path.join(tmp, "x1.json"))]
        print(f"fingerprints: scene {prints[0]}, level 1 {prints[1]}")
        if prints[0] != prints[1] or len(prints[0]) != 16:
            failures.append(f"level 1's fingerprint {prints[1]!r}, the scene's {prints[0]!r}")
        # A --set that deletes the box reaches the level file as a null (composed, not applied
        # to {}, which dropped it: every level of such a "uniform" ladder ran graded).
        path = os.path.join(tmp, "deleted.json")
        sets = [{"grid": {"refine": None}}, {"time": {"max_time": 1e-6}}]
        patched = scene
        for one in sets:  # as read_patched_scene resolves it
            patched = ladder.merge_patch(patched, one)
        ladder.write_level_scene(path, scene_file, patched, 1.5, None, 200, None, sets)
        level = json.load(open(path))
        done = subprocess.run([mpm, "check", path, "--threads", "1"], capture_output=True,
                              text=True, timeout=300)
        graded_run = (json.loads(done.stdout)["report"]["grid"].get("graded")
                      if done.returncode == 0 else None)
        print(f"--set refine null: level file grid {level.get('grid')}, graded {graded_run}")
        if level["grid"].get("refine", "absent") is not None or graded_run:
            failures.append(f"--set '{{\"grid\": {{\"refine\": null}}}}': level file grid "
                            f"{level.get('grid')}, mpm check graded {graded_run}")
        if level.get("time", {}).get("max_time") != 1e-6:
            failures.append(f"a second --set lost: {level.get('time')}")
        # The levels' seeding and narrowing are said on stderr.
        runs = [{"name": f"x{lv}", "ppc": None,
                 "data": {"narrowed": n, "volume_ratio": {"block": v}}}
                for lv, n, v in ((1, 0, 1.0), (1.5, 0, 0.934), (2, 112863, 0.962))]
        err = io.StringIO()
        with contextlib.redirect_stderr(err):
            ladder.seeding_warnings(runs)
        print(err.getvalue().strip())
        if ("x2: 112863 particle-steps had their uGIMP box narrowed" not in err.getvalue()
                or "seeded volume of block differs by 7.1 %" not in err.getvalue()):
            failures.append(f"seeding warnings: {err.getvalue()!r}")
        done = subprocess.run([sys.executable, os.path.join(ROOT, "campaigns", "study",
                                                            "ladder.py"),
                               scene_file, "--levels", "1,40", "--out", os.path.join(tmp, "out"),
                               "--mpm", mpm, "--no-plot"], capture_output=True, text=True,
                              timeout=300)
        print(f"levels 1,40: exit {done.returncode}: {done.stderr.strip()}")
        if done.returncode != 1 or "/grid/refine/factor 80" not in done.stderr:
            failures.append(f"levels 1,40 (factor 80): exit {done.returncode}, "
                            f"{done.stderr.strip()!r}; expected exit 1 naming the factor")
        if os.path.exists(os.path.join(tmp, "out", "runs", "x1")):
            failures.append("levels 1,40: level 1 ran before the refusal")
    for f in failures:
        print("FAIL " + f)
    print("OK" if not failures else f"{len(failures)} failure(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
