"""MPM scenes from Python: a rigid translation (energy and momentum of the closed form) and the
scene checks."""
import numpy as np
import pytest

import impact


def test_rigid_translation_keeps_its_energy_and_momentum(data, workdir):
    """The shipped block (20 mm cube of 6061-T6, rho = 2700 kg/m^3) translating at (30, -20, 10)
    m/s, as a dict extending the shipped scene: KE = rho V |v|^2 / 2 = 15.12 J and p = rho V v
    at every history row."""
    scene = {"extends": data("scenes", "verification", "rigid_translation.json"),
             "time": {"max_time": 2e-5}}
    r = impact.run_scene(scene, out="translation", threads=1)
    assert r["exit_code"] == 0 and r["summary"]["status"] == "completed"
    h = r["history"]
    assert h.units["kinetic_energy"] == "J" and h.units["momentum_x"] == "kg m/s"
    mass = 2700.0 * 0.02 ** 3
    assert r["summary"]["mass [kg]"] == pytest.approx(mass, rel=1e-12)
    np.testing.assert_allclose(h["kinetic_energy"], 0.5 * mass * (30**2 + 20**2 + 10**2),
                               rtol=1e-12)
    np.testing.assert_allclose(h["momentum_x"], 30.0 * mass, rtol=1e-12)
    np.testing.assert_allclose(h["momentum_y"], -20.0 * mass, rtol=1e-12)
    assert h["time"][-1] == pytest.approx(2e-5)


def test_patches_and_check(data, workdir):
    scene = data("scenes", "verification", "rigid_translation.json")
    checked = impact.check_scene(scene, patches={"grid": {"cells": [24, 24, 24]}})
    assert checked["resolved"]["grid"]["cells"] == [24, 24, 24]
    assert checked["refusal"] == "" and checked["report"]["particles"] > 0
    with pytest.raises(impact.InputError,
                       match=r"^patches\[0\] \(over .*rigid_translation.json\): /time/max_time"):
        impact.check_scene(scene, patches={"time": {"max_time": -1.0}})


def test_an_output_that_cannot_be_written_is_refused_before_the_run(data, workdir):
    """run_scene into a place no directory can be made: refused before the run starts, as an
    InputError naming `out` (docs/python.md); a file that cannot be written during a run is an
    impact.OutputError, an OSError."""
    scene = data("scenes", "verification", "rigid_translation.json")
    with pytest.raises(impact.InputError, match=r"out: /proc/x/run: expected a directory"):
        impact.run_scene(scene, out="/proc/x/run", threads=1)
    assert issubclass(impact.OutputError, OSError)
