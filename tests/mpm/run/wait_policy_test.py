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


def policy(mpm, value, name=None):
    """The policy `mpm check` reports; `name`: argv[0] (as `exec -a NAME` sets it)."""
    env = dict(os.environ)
    env.pop("OMP_WAIT_POLICY", None)
    if value is not None:
        env["OMP_WAIT_POLICY"] = value
    done = subprocess.run([name or mpm, "check", SCENE], executable=mpm, capture_output=True,
                          text=True, env=env)
    assert done.returncode == 0, (value, done.returncode, done.stderr)
    text = done.stdout
    return json.loads(text)["report"]["omp_wait_policy"]


def main():
    mpm = sys.argv[1]
    got = {value: policy(mpm, value) for value in (None, "active", "passive")}
    assert got[None] == "passive", got  # not set: mpm chooses passive
    assert got["active"] == "active", got  # set: kept
    assert got["passive"] == "passive", got
    # Through a link to it the program still re-executes itself; under a name that is neither
    # (a tool's, `exec -a`) it does not, and libgomp's default stays: what every case above would
    # report without the re-execution.
    link = os.path.join(os.environ.get("TMPDIR", "/tmp"), f"mpm-link-{os.getpid()}")
    os.symlink(os.path.abspath(mpm), link)
    try:
        got["link"] = policy(link, None)
    finally:
        os.remove(link)
    got["other name"] = policy(mpm, None, name="not-mpm")
    assert got["link"] == "passive", got
    assert got["other name"] == "libgomp default", got
    print("ok:", got)


if __name__ == "__main__":
    main()
