"""Materials and the constitutive update from Python, against closed forms."""
import math

import numpy as np
import pytest

import impact


def test_material_from_file_dict_and_patch(data):
    m = impact.Material(data("materials", "al6061_t6.json"))
    doc = m.to_dict()
    assert m.name == "6061-T6 aluminium"
    assert doc["density"] == pytest.approx(2700.0)
    # The same document as a dict, and a merge patch changing A.
    assert impact.Material(doc).to_dict() == doc
    patched = impact.Material(data("materials", "al6061_t6.json"),
                              patches={"constitutive_model": {"flow_stress": {"A": 300e6}}})
    assert patched.to_dict()["constitutive_model"]["flow_stress"]["A"] == 300e6


def test_bad_material_names_key_path_and_range(data):
    with pytest.raises(impact.InputError) as e:
        impact.Material(data("materials", "al6061_t6.json"), patches={"density": -1.0})
    assert str(e.value).startswith("patches[0] (over ")
    assert "al6061_t6.json): /density:" in str(e.value)
    assert "(0, 30000]" in str(e.value)
    assert isinstance(e.value, ValueError)


def test_elastic_shear_step_is_two_mu_d_dt(data):
    """An isochoric pure stretch (symmetric traceless L, no spin): F = exp(D dt) is symmetric, so
    R = I and the hypoelastic update gives s = 2 mu D dt exactly, with no pressure."""
    m = impact.Material(data("materials", "al6061_t6.json"))
    mu = m.to_dict()["shear_modulus"]
    d = 100.0  # [1/s]
    L = np.array([[0.0, d, 0.0], [d, 0.0, 0.0], [0.0, 0.0, 0.0]])
    dt = 1e-7
    state, report = impact.update(m, m.initial_state(n=1), L[None], dt)
    assert report["status"][0] == "ok" and not report["plastic"][0]
    assert state["stress"][0, 0, 1] == pytest.approx(2.0 * mu * d * dt, rel=1e-9)
    assert state["stress"][0, 1, 0] == pytest.approx(2.0 * mu * d * dt, rel=1e-9)
    assert abs(np.trace(state["stress"][0])) < 1e-9 * mu * d * dt


def test_plastic_point_sits_on_the_johnson_cook_surface(data, jc_flow_stress):
    """Uniaxial strain at 1e4 /s, isothermal (heating off): once plastic, the von Mises stress
    equals sigma_y(eps_p, rate, T) of Johnson & Cook (1983) eq. 1 to the return's tolerance."""
    m = impact.Material(data("materials", "al6061_t6.json"),
                        patches={"constitutive_model": {"adiabatic_heating": {"enabled": False}}})
    doc = m.to_dict()
    rate, dt = 1e4, 1e-7
    L = np.diag([rate, 0.0, 0.0])
    state = {k: v[0] for k, v in m.initial_state().items()}
    for _ in range(300):
        state, report = impact.update(m, state, L, dt)
    assert report["status"] == "ok" and report["plastic"]
    s = state["stress"] - np.trace(state["stress"]) / 3.0 * np.eye(3)
    von_mises = math.sqrt(1.5 * np.sum(s * s))
    expected = jc_flow_stress(doc["constitutive_model"]["flow_stress"], state["plastic_strain"],
                              state["plastic_strain_rate"], state["temperature"],
                              doc["room_temperature"], doc["melt_temperature"])
    assert state["plastic_strain"] > 0.02
    assert von_mises == pytest.approx(expected, rel=1e-6)


def test_batch_matches_one_point_updates_bit_for_bit(data):
    """A batch of mixed elastic and plastic points (the solver's batched kernels) gives exactly
    the bits of one-point calls."""
    m = impact.Material(data("materials", "al6061_t6.json"))
    rng = np.random.default_rng(7)
    n = 37  # not a multiple of the lane count
    L = rng.normal(scale=2e4, size=(n, 3, 3))
    state = m.initial_state(n=n)
    state["plastic_strain"] = rng.uniform(0.0, 0.3, n)
    state["stress"] = rng.normal(scale=1e8, size=(n, 3, 3))
    state["stress"] = 0.5 * (state["stress"] + state["stress"].transpose(0, 2, 1))
    batch, report = impact.update(m, state, L, 2e-7)
    assert report["plastic"].any() and not report["plastic"].all()
    for i in range(n):
        one, _ = impact.update(m, {k: v[i] for k, v in state.items()}, L[i], 2e-7)
        for key in ("stress", "plastic_strain", "temperature", "F", "R"):
            assert np.array_equal(one[key], batch[key][i]), (key, i)


def test_shape_errors_name_the_argument(data):
    m = impact.Material(data("materials", "al6061_t6.json"))
    with pytest.raises(ValueError, match=r"state\['stress'\]: expected an array of shape \(2, 3, 3\)"):
        impact.update(m, {"stress": np.zeros((3, 3, 3))}, np.zeros((2, 3, 3)), 1e-7)
    with pytest.raises(ValueError, match=r"state\['failure_cause'\]\[0\]: expected codes 0-4"):
        impact.update(m, {"failure_cause": np.array([9])}, np.zeros((1, 3, 3)), 1e-7)
    assert impact.failure_causes[0] == "none" and impact.update_statuses[0] == "ok"
    with pytest.raises(ValueError, match="dt: expected a time step > 0"):
        impact.update(m, m.initial_state(), np.zeros((1, 3, 3)), 0.0)


def test_a_number_no_double_holds_is_an_input_error(data, workdir):
    """A Python int beyond the double range (10**400) in a patch or a document: impact.InputError
    naming the patch and the key (it was a RuntimeError from the JSON parser)."""
    material = data("materials", "al6061_t6.json")
    with pytest.raises(impact.InputError,
                       match=r"^patches\[1\]: /density: the number 1000000000000000\.\.\. "
                             r"\(401 characters\) is beyond the range of a double") as e:
        impact.Material(material, patches=[{"name": "x"}, {"density": 10**400}])
    assert isinstance(e.value, ValueError)
    doc = impact.Material(material).to_dict()
    with pytest.raises(impact.InputError, match=r"^patches\[0\]: /density: the number"):
        impact.Material(doc, patches={"density": -10**400})
    doc["density"] = 10**400
    with pytest.raises(impact.InputError, match=r"<material dict>: /density: the number"):
        impact.Material(doc)
    with pytest.raises(impact.InputError, match=r"^patches\[0\]: /temperature: the number"):
        impact.run_path(data("paths", "uniaxial_stress_1000.json"),
                        patches={"temperature": 10**400})
