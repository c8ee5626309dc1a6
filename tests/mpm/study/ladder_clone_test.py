#!/usr/bin/env python3
"""campaigns/study/ladder.py in a repository of its own (issue 52): the ladder's outputs are tracked
files, as the shipped tables are.

1. The table records the commit it was written from, clean: the outputs it writes are tracked, so
   a commit read after writing them would carry '-dirty' on a clean tree.
2. The same ladder in another clone (the repository moved to another folder) still finds its
   runs: each level's scene names the scene it extends relative to itself, so the text its run is
   matched by does not change with the folder.

A stand-in run (summary.json "completed" with the bar's peak pressure) of a scene that extends
data/scenes/verification/elastic_bar.json at level 1 stands for the real one: nothing is run.

  ladder_clone_test.py MPM"""

import json
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
STUDY = os.path.join(ROOT, "campaigns", "study")
SCENE = os.path.join(ROOT, "data", "scenes", "verification", "elastic_bar.json")
GIT = ["git", "-c", "user.name=ladder test", "-c", "user.email=test@example.invalid",
       "-c", "init.defaultBranch=main"]


def git(repo, *args):
    return subprocess.run(GIT + ["-C", repo] + list(args), capture_output=True, text=True,
                          check=True).stdout.strip()


def ladder(repo, mpm):
    """The ladder of the repository's scene at level 1, analysed from its stand-in run."""
    return subprocess.run(
        [sys.executable, os.path.join(repo, "campaigns", "study", "ladder.py"),
         os.path.join(repo, "scene.json"), "--levels", "1", "--analyse-only", "--no-plot",
         "--out", os.path.join(repo, "table"), "--runs", os.path.join(repo, "runs"),
         "--table", os.path.join(repo, "scene.ladder.json"), "--mpm", mpm],
        capture_output=True, text=True, timeout=120)


def main():
    mpm = sys.argv[1]
    if shutil.which("git") is None:
        print("ladder_clone_test: git is not installed; the test needs it")
        return 1
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        repo = os.path.join(tmp, "clone_a")
        os.makedirs(os.path.join(repo, "campaigns"))
        shutil.copytree(STUDY, os.path.join(repo, "campaigns", "study"),
                        ignore=shutil.ignore_patterns("__pycache__"))
        # ladder.py runs mpm and reads the runs through impact.results (<repo>/python).
        shutil.copytree(os.path.join(ROOT, "python", "impact"),
                        os.path.join(repo, "python", "impact"),
                        ignore=shutil.ignore_patterns("__pycache__"))
        with open(os.path.join(repo, "scene.json"), "w") as f:  # the shipped scene, from here
            json.dump({"extends": SCENE}, f, indent=1)
        # The outputs exist as tracked files before the ladder writes them, as the shipped ones do.
        done = ladder(repo, mpm)
        if done.returncode != 0:
            print(f"FAIL the ladder without runs: exit {done.returncode}, {done.stderr.strip()!r}")
            return 1
        with open(os.path.join(repo, "table", "scenes", "x1.json")) as f:
            level_text = f.read()
        extends = json.loads(level_text)["extends"]
        if os.path.isabs(extends) or os.path.normpath(os.path.join(
                repo, "table", "scenes", extends)) != os.path.join(repo, "scene.json"):
            failures.append(f"the level scene extends {extends!r}: expected ../../scene.json")
        run_dir = os.path.join(repo, "runs", "x1")
        os.makedirs(run_dir)
        with open(os.path.join(run_dir, "ladder_scene.json"), "w") as f:
            f.write(level_text)
        with open(os.path.join(run_dir, "summary.json"), "w") as f:
            json.dump({"status": "completed", "scene_fingerprint": "0123456789abcdef",
                       "particles": 1, "steps": 1, "final": {"energy_error [-]": 0.0},
                       "observables": {"objects": {n: {"mean_velocity [m/s]": [-1.0, 0.0, 0.0],
                                                       "max_pressure [Pa]": 1e6}
                                                   for n in ("bar",)}}}, f)
        with open(os.path.join(repo, ".gitignore"), "w") as f:
            f.write("runs/\n__pycache__/\n")
        git(repo, "init", "-q")
        git(repo, "add", "-A")
        git(repo, "commit", "-q", "-m", "the ladder's outputs as tracked files")
        head = git(repo, "rev-parse", "--short=12", "HEAD")
        done = ladder(repo, mpm)
        with open(os.path.join(repo, "scene.ladder.json")) as f:
            table = json.load(f)
        if done.returncode != 0 or table.get("commit") != head:
            failures.append(f"the table from a clean tree at {head}: commit "
                            f"{table.get('commit')!r}, exit {done.returncode}, "
                            f"{done.stderr.strip()!r}")
        if len(table.get("levels", [])) != 1:
            failures.append(f"the stand-in run was not read: levels {table.get('levels')}")
        if not git(repo, "status", "--porcelain", "--untracked-files=no"):
            failures.append("the ladder rewrote no tracked output: the test tests nothing")
        # The repository moved: another clone, the same runs.
        moved = os.path.join(tmp, "elsewhere", "clone_b")
        shutil.move(repo, moved)
        done = ladder(moved, mpm)
        with open(os.path.join(moved, "scene.ladder.json")) as f:
            table = json.load(f)
        if done.returncode != 0 or len(table.get("levels", [])) != 1:
            failures.append(f"the moved clone: exit {done.returncode}, levels "
                            f"{table.get('levels')}, {done.stderr.strip()!r}")
    if failures:
        print("\n".join(f"FAIL {x}" for x in failures))
        return 1
    print("ladder_clone_test: the table records a clean commit; a moved clone finds its runs")
    return 0


if __name__ == "__main__":
    sys.exit(main())
