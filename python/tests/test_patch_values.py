"""What a notebook passes as patches and dicts: NumPy scalars and arrays are JSON numbers and
lists; NaN and infinities (which JSON has not) are refused naming the key; a history.csv that is
not a regular file is refused instead of read without end."""
import os

import numpy as np
import pytest

import impact


def test_numpy_values_in_a_patch_are_json_numbers(data):
    m = impact.Material(data("materials", "al6061_t6.json"), patches={"density": np.int64(2710)})
    assert m.density == 2710.0
    m = impact.Material(data("materials", "al6061_t6.json"),
                        patches=[{"density": np.float32(2720.0)}])
    assert m.density == 2720.0
    assert impact.Material(m.to_dict(), patches='{"density": 2730}').density == 2730.0


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), np.float64("-inf")])
def test_a_non_finite_number_is_refused_with_its_key(data, bad):
    with pytest.raises(impact.InputError, match=r"patches\[0\]: /density: expected a finite number"):
        impact.Material(data("materials", "al6061_t6.json"), patches={"density": bad})
    doc = impact.Material(data("materials", "al6061_t6.json")).to_dict()
    doc["constitutive_model"]["flow_stress"]["A"] = bad
    with pytest.raises(impact.InputError, match=r"/constitutive_model/flow_stress/A: expected a"):
        impact.Material(doc)


def test_a_history_that_is_a_device_is_refused(workdir):
    os.mkdir("run")
    os.symlink("/dev/zero", os.path.join("run", "history.csv"))
    with pytest.raises(impact.InputError, match=r"history.csv: expected the history.csv file"):
        impact.read_history("run")
