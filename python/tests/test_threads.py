"""Idle OpenMP threads wait passively unless the caller chose otherwise (docs/performance.md#threads):
importing impact sets OMP_WAIT_POLICY to "passive" before the extension (and libgomp) load, and
keeps a value the caller set. In a child process: libgomp reads the variable once, when loaded."""
import os
import subprocess
import sys

import pytest

CHILD = "import os, impact; print(os.environ['OMP_WAIT_POLICY'])"


@pytest.mark.parametrize("given, expected", [(None, "passive"), ("active", "active"),
                                             ("passive", "passive")])
def test_import_waits_passively_unless_asked(given, expected):
    env = dict(os.environ)
    env.pop("OMP_WAIT_POLICY", None)
    if given is not None:
        env["OMP_WAIT_POLICY"] = given
    done = subprocess.run([sys.executable, "-c", CHILD], capture_output=True, text=True, env=env,
                          check=True)
    assert done.stdout.strip() == expected
