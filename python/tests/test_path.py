"""Point-driver paths from Python: named columns with units, against closed forms."""
import numpy as np
import pytest

import impact


def test_uniaxial_stress_columns_units_and_physics(data, jc_flow_stress):
    r = impact.run_path(data("paths", "uniaxial_stress_1000.json"))
    assert r.completed and r.error == "" and r.steps == 2000
    assert r.units["time"] == "s" and r.units["stress_xx"] == "Pa"
    assert r.units["plastic_strain"] == "-"
    assert len(r["time"]) == 2001 and r["time"][-1] == pytest.approx(2e-4)
    # Lateral stress free to the driver's tolerance.
    assert np.max(np.abs(r["stress_yy"])) < 1.0 and np.max(np.abs(r["stress_zz"])) < 1.0
    # Elastic: the first step's slope is Young's modulus E = 9 K mu / (3 K + mu).
    doc = impact.Material(data("materials", "al6061_t6.json")).to_dict()
    K, mu = doc["bulk_modulus"], doc["shear_modulus"]
    E = 9 * K * mu / (3 * K + mu)
    eps = np.log(r["F_xx"])
    assert r["stress_xx"][1] / eps[1] == pytest.approx(E, rel=1e-3)
    # Plastic, isothermal: the end stress is Johnson-Cook's at the end's eps_p and rate.
    expected = jc_flow_stress(doc["constitutive_model"]["flow_stress"], r["plastic_strain"][-1],
                              1000.0, 294.0, doc["room_temperature"], doc["melt_temperature"])
    assert r["stress_xx"][-1] == pytest.approx(expected, rel=2e-3)


def test_path_as_dict_with_patch_and_bad_key(data, workdir):
    path = {"material": data("materials", "al6061_t6.json"), "temperature": 294.0,
            "legs": [{"duration": 1e-4, "steps": 200, "velocity_gradient": {"xx": 1000.0},
                      "stress": {"yy": 0.0, "zz": 0.0}}]}
    base = impact.run_path(path)
    # A merge patch raising A by 10 MPa raises the plastic stress by 10 MPa times the rate
    # factor (1 + C ln 1000) of Johnson-Cook's multiplicative form.
    patched = impact.run_path(path, patches={"material": {
        "file": data("materials", "al6061_t6.json"),
        "overrides": {"constitutive_model": {"flow_stress": {"A": 334e6}}}}})
    C = impact.Material(data("materials", "al6061_t6.json")).to_dict()[
        "constitutive_model"]["flow_stress"]["C"]
    factor = 1.0 + C * np.log(1000.0)
    # The same strain, different plastic strain split: compare at the end with B eps_p^n equal.
    assert base["plastic_strain"][-1] > 0.0
    diff = patched["stress_xx"][-1] - base["stress_xx"][-1]
    assert diff == pytest.approx(10e6 * factor, rel=2e-2)
    bad = dict(path, legs=[{"duration": -1.0, "steps": 10}])
    with pytest.raises(impact.InputError, match=r"<path dict>: /legs/0/duration"):
        impact.run_path(bad)
