"""pytest setup for the Python module's tests: CTest puts the build tree's python/ on PYTHONPATH
(tests/CMakeLists.txt); the relocation test imports the installed copy instead."""
import os

import pytest

import impact


@pytest.fixture
def data():
    """data_path of the shipped files (source tree or install)."""
    return impact.data_path


def johnson_cook(jc, plastic_strain, rate, temperature, room, melt):
    """Johnson & Cook (1983) eq. 1 with the 'clamped' rate form: below the reference rate the
    rate factor is 1. An independent transcription for the tests."""
    import math
    rate_factor = 1.0 + jc["C"] * math.log(max(rate / jc["reference_strain_rate"], 1.0))
    homologous = (temperature - room) / (melt - room)
    thermal = 1.0 - max(homologous, 0.0) ** jc["m"]
    return (jc["A"] + jc["B"] * plastic_strain ** jc["n"]) * rate_factor * thermal


@pytest.fixture
def jc_flow_stress():
    return johnson_cook


@pytest.fixture
def workdir(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    return tmp_path


def pytest_report_header(config):
    return f"impact {impact.__version__} from {os.path.dirname(impact.__file__)}"


@pytest.fixture
def test_data():
    """A file of the repository's tests/data (hostile and suspicious inputs)."""
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests", "data")
    return lambda *relative: os.path.normpath(os.path.join(root, *relative))
