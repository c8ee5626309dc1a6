"""Ctrl-C during run_scene: the run stops after the step under way, writes its checkpoint and
raises KeyboardInterrupt; resume_scene continues it to the end. In a child process, which sends
itself SIGINT as a terminal or a notebook's interrupt button would (pytest must not get it)."""
import json
import os
import shutil
import subprocess
import sys

import numpy as np
import pytest

import impact

CHILD = r"""
import json, os, signal, sys, threading, time
import impact
scene, out = json.loads(sys.argv[1]), sys.argv[2]

def interrupt():  # once the run has started (status.json of step 0 written): Ctrl-C
    while not os.path.exists(os.path.join(out, "status.json")):
        time.sleep(0.005)
    os.kill(os.getpid(), signal.SIGINT)

threading.Thread(target=interrupt, daemon=True).start()
try:
    impact.run_scene(scene, out=out, threads=1)
except KeyboardInterrupt as e:
    print(json.dumps({"interrupted": str(e)}))
    sys.exit(0)
print(json.dumps({"completed": True}))
"""


def test_ctrl_c_checkpoints_raises_and_resumes(data, workdir):
    """The shipped rigid translation slowed to V = (3, -2, 1) m/s (3 mm in 1e-3 s, inside the
    grid; 2449 steps, about 1.2 s on one thread): interrupted as it starts (the run looks at
    Python's signals every 50 ms), then continued to the end by resume_scene."""
    scene = {"extends": data("scenes", "verification", "rigid_translation.json"),
             "objects": {"block": {"velocity": [3.0, -2.0, 1.0]}},
             "time": {"max_time": 1e-3}, "output": {"interval": 1e-5, "snapshots": False}}
    # The child imports the module this test imports, wherever PYTHONPATH pointed.
    package_root = os.path.dirname(os.path.dirname(os.path.abspath(impact.__file__)))
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(
        [package_root] + [p for p in [os.environ.get("PYTHONPATH")] if p]))
    child = subprocess.run([sys.executable, "-c", CHILD, json.dumps(scene), "run"],
                           capture_output=True, text=True, timeout=120, env=env)
    assert child.returncode == 0, child.stderr
    said = json.loads(child.stdout.splitlines()[-1])
    assert "interrupted" in said, said
    message = said["interrupted"]
    assert message.startswith("interrupted by SIGINT after step ")
    assert "checkpoint run/checkpoint.bin" in message
    assert "impact.resume_scene('run')" in message
    with open(os.path.join("run", "status.json")) as f:
        status = json.load(f)
    assert status["status"] == "interrupted" and 1 <= status["step"] < 2000
    assert status["checkpoint"]["step"] == status["step"]
    assert os.path.exists(os.path.join("run", "checkpoint.bin"))
    # A new run into the unfinished one's directory is refused with the remedies in Python's
    # words (it suggested mpm's --overwrite); overwrite=True starts one over a copy of it.
    shutil.copytree("run", "copy")
    with pytest.raises(impact.InputError) as refused:
        impact.run_scene(scene, out="run", threads=1)
    text = str(refused.value)
    assert "impact.resume_scene('run')" in text and "run_scene(..., overwrite=True)" in text, text
    assert "--overwrite" not in text and "mpm run --restart" not in text, text
    short = dict(scene, time={"max_time": 1e-5})
    over = impact.run_scene(short, out="copy", threads=1, overwrite=True)
    assert over["status"]["status"] == "completed" and over["history"]["time"][-1] == 1e-5
    # Continued to the end: a history row every 1e-5 s and at the end, no row twice, the kinetic
    # energy of the rigid translation kept (KE = M |V|^2 / 2).
    done = impact.resume_scene("run", threads=1)
    assert done["status"]["status"] == "completed" and done["summary"]["steps"] == 2449
    h = done["history"]
    assert h["time"][-1] == 1e-3 and np.all(np.diff(h["time"]) > 0.0)
    assert len(h["time"]) == 101 or len(h["time"]) == 102, len(h["time"])
    mass = done["summary"]["mass [kg]"]
    np.testing.assert_allclose(h["kinetic_energy"], 0.5 * mass * (3**2 + 2**2 + 1**2),
                               rtol=1e-12)
