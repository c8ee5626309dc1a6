"""The batch state is validated before the update: a value no material point can hold, an
unknown key or a wrong shape is refused naming the key (or argument), the first point and the
expected value or shape. A single point works without the leading dimension."""
import numpy as np
import pytest

import impact

L = np.diag([1e4, -5e3, -5e3])  # [1/s]
DT = 1e-7  # [s]


@pytest.fixture
def al(data):
    return impact.Material(data("materials", "al6061_t6.json"))


@pytest.mark.parametrize("key, values, message", [
    ("temperature", [294.0, np.nan, 300.0],
     r"state\['temperature'\]\[1\]: expected a temperature > 0 \[K\], got nan \(1 of 3 points\)"),
    ("temperature", [-5.0, 294.0, -1.0],
     r"state\['temperature'\]\[0\]: expected a temperature > 0 \[K\], got -5 \(2 of 3 points\)"),
    ("plastic_strain", [0.0, 0.1, -0.01],
     r"state\['plastic_strain'\]\[2\]: expected a plastic strain >= 0 \[-\], got -0.01"),
    ("plastic_strain_rate", [0.0, np.inf, 0.0],
     r"state\['plastic_strain_rate'\]\[1\]: expected a plastic strain rate >= 0 \[1/s\], got inf"),
    ("damage", [0.0, -0.5, 0.0], r"state\['damage'\]\[1\]: expected a damage >= 0 \[-\]"),
    ("porosity", [1.0, 0.0, 0.0], r"state\['porosity'\]\[0\]: expected a porosity in \[0, 1\)"),
    ("internal_energy", [0.0, 0.0, np.nan],
     r"state\['internal_energy'\]\[2\]: expected a finite specific internal energy"),
    ("failed", [0, 2, 1], r"state\['failed'\]\[1\]: expected 0 or 1 \(False or True\), got 2"),
    ("failure_cause", [0, 1.5, 0], r"state\['failure_cause'\]\[1\]: expected codes 0-4"),
    ("instability", [0, 4, 0], r"state\['instability'\]\[1\]: expected bits 0-3"),
])
def test_inadmissible_values_are_refused_with_key_and_point(al, key, values, message):
    state = al.initial_state(n=3)
    state[key] = np.array(values)
    with pytest.raises(impact.InputError, match=message):
        impact.update(al, state, np.stack([L] * 3), DT)


def test_inadmissible_tensors_are_refused(al):
    state = al.initial_state(n=2)
    state["F"][1] = np.diag([-1.0, 1.0, 1.0])  # det F < 0: an inverted point
    with pytest.raises(impact.InputError, match=r"state\['F'\]\[1\]: expected a deformation "
                                                r"gradient with det F > 0, got \[\[-1, 0, 0\]"):
        impact.update(al, state, np.stack([L] * 2), DT)
    state = al.initial_state(n=2)
    state["stress"][0, 0, 0] = np.nan
    with pytest.raises(impact.InputError, match=r"state\['stress'\]\[0\]: expected a finite "):
        impact.update(al, state, np.stack([L] * 2), DT)
    state = al.initial_state(n=2)
    state["R"][0] = 2.0 * np.eye(3)  # not a rotation
    with pytest.raises(impact.InputError, match=r"state\['R'\]\[0\]: expected a rotation"):
        impact.update(al, state, np.stack([L] * 2), DT)
    bad_L = np.stack([L, L * np.nan])
    with pytest.raises(impact.InputError, match=r"^L\[1\]: expected a finite velocity gradient"):
        impact.update(al, al.initial_state(n=2), bad_L, DT)
    with pytest.raises(impact.InputError, match=r"^F1\[0\]: expected a deformation gradient "
                                                r"with det F1 > 0"):
        impact.update(al, al.initial_state(n=2), np.stack([L] * 2), DT, F1=np.zeros((2, 3, 3)))
    with pytest.raises(impact.InputError, match=r"^dt: expected a time step > 0 \[s\], got nan"):
        impact.update(al, al.initial_state(n=2), np.stack([L] * 2), float("nan"))


def test_unknown_key_is_refused_with_the_nearest_known_one(al):
    state = al.initial_state(n=1)
    state["stres"] = state.pop("stress")
    with pytest.raises(impact.InputError, match=r"^state\['stres'\]: unknown key \(did you mean "
                                                r"stress\?\); known: stress, F, R, "):
        impact.update(al, state, L[None], DT)


def test_shape_errors_name_the_argument_and_the_expected_shape(al):
    with pytest.raises(impact.InputError, match=r"^state\['temperature'\]: expected an array of "
                                                r"shape \(2,\), got \(3,\)"):
        impact.update(al, {"temperature": np.full(3, 300.0)}, np.stack([L] * 2), DT)
    with pytest.raises(impact.InputError, match=r"^L: expected velocity gradients of shape "
                                                r"\(N, 3, 3\), or \(3, 3\) for one point \[1/s\], "
                                                r"got \(3,\)"):
        impact.update(al, al.initial_state(), np.zeros(3), DT)
    with pytest.raises(impact.InputError, match=r"^F1: expected an array of shape \(2, 3, 3\), "
                                                r"got \(3, 3, 3\)"):
        impact.update(al, al.initial_state(n=2), np.stack([L] * 2), DT,
                      F1=np.stack([np.eye(3)] * 3))


def test_a_single_point_needs_no_leading_dimension(al):
    """docs/python.md: L (3, 3) with a state of one point, given with or without its leading
    dimension, is the batch of one, bit for bit, and comes back without the dimension."""
    batch, batch_report = impact.update(al, al.initial_state(n=1), L[None], DT)
    for state in (al.initial_state(),                                   # arrays (1, ...)
                  {k: v[0] for k, v in al.initial_state().items()},     # one point's own shapes
                  {"temperature": al.room_temperature}):                # scalars alone
        one, report = impact.update(al, state, L, DT)
        assert one["stress"].shape == (3, 3) and np.ndim(one["temperature"]) == 0
        for key, value in batch.items():
            assert np.array_equal(one[key], value[0]), key
        assert report["status"] == batch_report["status"][0] == "ok"


def test_the_flow_stress_internal_variable_is_carried(data):
    """Mechanical Threshold Stress keeps its structure stress sigma_e in the state
    (`flow_internal` [Pa]): it grows from 0 at a plastic step, and a second step from the
    returned state differs from one that would restart it at 0."""
    m = impact.Material(data("materials", "ofhc_copper_mts.json"))
    state = m.initial_state(n=1)
    for _ in range(200):
        state, _ = impact.update(m, state, L[None], DT)
    assert state["flow_internal"][0] > 0.0
    carried, _ = impact.update(m, state, L[None], DT)
    restarted, _ = impact.update(m, dict(state, flow_internal=np.zeros(1)), L[None], DT)
    assert carried["stress"][0, 0, 0] != restarted["stress"][0, 0, 0]
