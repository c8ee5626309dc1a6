#!/usr/bin/env python3
"""How idle OpenMP threads wait (support/omp_wait_policy.hpp, docs/performance.md#threads): `mpm`
started without OMP_WAIT_POLICY runs with it "passive" (libgomp reads it only at load, so the
program executes itself again with it set), and keeps a policy the user set. Read back from
`mpm check`'s report, which names the policy its process ran with.

  wait_policy_test.py MPM
"""
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
SCENE = os.path.join(ROOT, "data", "scenes", "verification", "rigid_translation.json")


def policy(mpm, value):
    env = dict(os.environ)
    env.pop("OMP_WAIT_POLICY", None)
    if value is not None:
        env["OMP_WAIT_POLICY"] = value
    done = subprocess.run([mpm, "check", SCENE], capture_output=True, text=True, env=env)
    assert done.returncode == 0, (value, done.returncode, done.stderr)
    text = done.stdout
    return json.loads(text[text.rindex("\n{") + 1:] if "\n{" in text else text)["omp_wait_policy"]


def main():
    mpm = sys.argv[1]
    got = {value: policy(mpm, value) for value in (None, "active", "passive")}
    assert got[None] == "passive", got  # not set: mpm chooses passive
    assert got["active"] == "active", got  # set: kept
    assert got["passive"] == "passive", got
    print("ok:", got)


if __name__ == "__main__":
    main()
