"""Errors as exceptions, warnings through `warnings`: what a notebook, which never shows the C++
side's stderr, gets from a failed, refused or badly placed run and from a likely unit slip."""
import os
import subprocess
import sys

import numpy as np
import pytest

import impact


def test_failed_run_raises_run_error_with_the_reason(data, workdir):
    """A body force of 1e14 m/s^2 switched on after 1 us: its step, sqrt(0.5 x 5 mm / 1e14) =
    5e-9 s, falls below time.min_dt = 1e-8 s during the run, which stops (mpm run exits 3) with
    the solver's message. (A min_dt above the step at the start is refused before the run, exit 4.)"""
    scene = {"extends": data("scenes", "verification", "rigid_translation.json"),
             "objects": {"block": {"body_force": ["t > 1e-6 ? 1e14 : 0", 0, 0]}},
             "time": {"max_time": 2e-5, "min_dt": 1e-8}}
    with pytest.raises(impact.RunError) as caught:
        impact.run_scene(scene, out="failed", threads=1)
    e = caught.value
    assert e.exit_code == 3 and e.directory == "failed"
    assert "below time.min_dt = 1e-08 s: the body-force step" in e.reason and e.reason in str(e)
    # What the run wrote up to the failure comes with it: the row at t = 0 of a run at rest.
    assert e.result["status"]["status"] == "failed"
    assert e.result["status"]["message"] == e.reason
    assert e.result["history"]["time"][0] == 0.0


def test_refused_run_raises_run_error_and_writes_nothing(test_data, workdir):
    """1200^3 cells: the memory estimate refuses the scene (exit 4) before anything is seeded,
    allocated or written; not even the output directory (and its missing parents) is left (an
    empty one was, before)."""
    with pytest.raises(impact.RunError, match=r"^refusing to start: estimated memory") as caught:
        impact.run_scene(test_data("mpm_runs", "huge_grid.json"), out="runs/huge", threads=1)
    assert caught.value.exit_code == 4
    assert os.listdir(".") == []


def test_full_disk_during_a_run_raises_output_error(data, workdir):
    """A file-size limit of 20 kB (RLIMIT_FSIZE, as `ulimit -f`; a full disk's ENOSPC takes the
    same path) lets scene.json (1.5 kB) through and stops the run at its first snapshot (76 kB):
    impact.OutputError, an OSError naming the file and the system's reason, as `mpm run` exits 3
    with it (RunError, before). In a child process: the limit would stop pytest's own files."""
    child = f"""
import resource, impact
resource.setrlimit(resource.RLIMIT_FSIZE, (20000, resource.RLIM_INFINITY))
scene = {{"extends": {data("scenes", "verification", "rigid_translation.json")!r},
          "time": {{"max_time": 2e-5}}, "output": {{"snapshots": True}}}}
try:
    impact.run_scene(scene, out="full", threads=1)
except impact.OutputError as e:
    print(type(e).__name__, isinstance(e, OSError), e)
except impact.RunError as e:
    print("RunError", e)
"""
    done = subprocess.run([sys.executable, "-c", child], capture_output=True, text=True,
                          env=dict(os.environ), timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stdout.startswith("OutputError True cannot write full/particles/step_"), \
        done.stdout
    assert done.stdout.rstrip().endswith("(File too large)"), done.stdout
    assert os.path.getsize(os.path.join("full", "scene.json")) > 1000


def test_unwritable_out_raises_input_error_naming_it(data, workdir):
    (workdir / "a_file").write_text("not a directory\n")
    out = os.path.join("a_file", "run")
    with pytest.raises(impact.InputError, match=r"^out: a_file/run: expected a directory the "
                                                r"run can write into, got "):
        impact.run_scene(data("scenes", "verification", "rigid_translation.json"), out=out)
    with pytest.raises(impact.InputError, match=r"^out: a_file: expected a directory the run can "
                                                r"write into, got a file \(.*a_file\), not a "
                                                r"directory$"):
        impact.run_scene(data("scenes", "verification", "rigid_translation.json"), out="a_file")
    # /dev/full, a device, said "got File exists".
    with pytest.raises(impact.InputError, match=r"^out: /dev/full: expected a directory the run "
                                                r"can write into, got a file \(/dev/full\), not "
                                                r"a directory$"):
        impact.run_scene(data("scenes", "verification", "rigid_translation.json"), out="/dev/full")


def test_a_thread_count_out_of_range_is_refused(data, workdir):
    """threads=-3 ran silently on all the cores; 0 (all) and 1 to 256 are mpm's --threads."""
    scene = data("scenes", "verification", "rigid_translation.json")
    for bad in (-3, 257, 1.5, True, "2"):
        with pytest.raises(impact.InputError, match=r"^threads: expected 0 \(all the cores\) or a "
                                                    r"whole number from 1 to 256, got "):
            impact.run_scene(scene, out="run", threads=bad)
        with pytest.raises(impact.InputError, match=r"^threads: "):
            impact.check_scene(scene, threads=bad)
    assert not os.path.exists("run")


def test_unit_slips_are_warnings_at_the_callers_line(test_data, workdir):
    with pytest.warns(impact.InputWarning, match=r"/density: 2.7 looks like g/cm\^3") as record:
        m = impact.Material(test_data("unit_warnings", "materials", "density_in_g_per_cc.json"))
    assert record[0].filename == __file__ and m.warnings  # the list is kept too
    with pytest.warns(impact.InputWarning, match=r"/objects/block/velocity/0: 1.47e\+06 looks "
                                                 r"like mm/s") as record:
        impact.check_scene(test_data("unit_warnings", "scenes", "velocity_in_mm_per_s.json"))
    assert record[0].filename == __file__
    with pytest.warns(impact.InputWarning, match=r"/temperature: 21 looks like degC") as record:
        impact.run_path(test_data("unit_warnings", "paths", "temperature_in_celsius.json"))
    assert record[0].filename == __file__
    with pytest.warns(impact.InputWarning, match=r"/tolerance/max: 50 looks like MPa"):
        impact.check(test_data("unit_warnings", "fits", "check_tolerance_in_mpa.json"))
    # As errors on request, as Python's warnings go.
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error", impact.InputWarning)
        with pytest.raises(impact.InputWarning):
            impact.Material(test_data("unit_warnings", "materials", "modulus_in_gpa.json"))


def test_unsolvable_path_raises_run_error_with_what_it_computed(data):
    """One Newton iteration with the elastic Jacobian and no cut-back cannot solve a plastic
    stress-controlled step (tests/pointdriver/driver/replay_test.cpp): pointdriver run exits 3."""
    path = {"material": data("materials", "al6061_t6.json"), "temperature": 294.0,
            "legs": [{"type": "uniaxial_stress", "strain": 0.02, "strain_rate": 1000.0,
                      "steps": 20}],
            "solver": {"max_iterations": 1, "max_cutbacks": 0, "jacobian": "elastic"}}
    with pytest.raises(impact.RunError, match="did not converge") as caught:
        impact.run_path(path)
    e = caught.value
    assert e.exit_code == 3 and e.directory is None
    table = e.result
    assert not table.completed and table.error == e.reason
    # The rows up to the failed step: elastic (eps_p = 0), time increasing from 0.
    assert len(table["time"]) == table.steps + 1 and table.steps >= 1
    assert table["time"][0] == 0.0 and np.all(np.diff(table["time"]) > 0.0)
    assert np.all(table["plastic_strain"] == 0.0)
    # The replay path repeats the failed step and fails the same way.
    assert table.replay is not None
    with pytest.raises(impact.RunError, match="did not converge"):
        impact.run_path(table.replay)


def test_input_error_is_documented_and_a_value_error():
    assert issubclass(impact.InputError, ValueError)
    assert "JSON key path" in impact.InputError.__doc__
    assert issubclass(impact.RunError, RuntimeError)
