"""Fit and check from Python: a Johnson-Cook set recovered from curves this module computed, and
a check report recomputed independently from the curves it returns."""
import numpy as np
import pytest

import impact

TRUE = {"A": 300e6, "B": 150e6, "n": 0.35, "C": 0.01}


def write_curve(directory, material, rate):
    """Uniaxial compression at `rate` [1/s], isothermal, to 20 % strain through run_path; written
    as an experiment file (docs/fitting.md) of true plastic strain and true stress."""
    path = {"material": {"file": material,
                         "overrides": {"constitutive_model": {"flow_stress": TRUE}}},
            "temperature": 294.0, "thermal": "isothermal",
            "legs": [{"duration": 0.2 / rate, "steps": 400, "velocity_gradient": {"xx": -rate},
                      "stress": {"yy": 0.0, "zz": 0.0}}]}
    r = impact.run_path(path)
    assert r.completed
    plastic = r["plastic_strain"] > 1e-3
    eps, sigma = r["plastic_strain"][plastic][::20], -r["stress_xx"][plastic][::20]
    name = directory / f"synthetic_{rate:g}per_s.csv"
    with open(name, "w") as f:
        f.write("# synthetic Johnson-Cook curve (python/tests/test_fit.py)\n"
                "# source: computed by run_path with the TRUE set\n"
                "# test_type: uniaxial_compression\n"
                f"# strain_rate [1/s]: {rate}\n# temperature [K]: 294\n"
                "# strain_measure: true_plastic\n# stress_measure: true\n"
                "true_plastic_strain [-],true_stress [Pa]\n")
        for e, s in zip(eps, sigma):
            f.write(f"{e:.17g},{s:.17g}\n")
    return name


def test_fit_recovers_johnson_cook_from_synthetic_curves(data, workdir):
    material = data("materials", "al6061_t6.json")
    files = [str(write_curve(workdir, material, rate)) for rate in (1e-3, 1.0, 1e3)]
    config = {"mode": "strength", "material": material,
              "adiabatic_above_rate": 1e9,  # the curves above are isothermal
              "data": files, "parameters": {"m": {"free": False}},
              "output": {"directory": "fit"}}
    report = impact.fit(config)
    assert report["converged"] and report["law"] == "johnson_cook"
    fitted = report["parameters"]
    for name, value in TRUE.items():
        assert fitted[name]["fitted"] == pytest.approx(value, rel=1e-2), name
    # The fitted material is a valid material document carrying the fitted values.
    m = impact.Material(report["fitted_material"])
    assert m.to_dict()["constitutive_model"]["flow_stress"]["B"] == fitted["B"]["fitted"]
    # Curves for plotting: the fitted model lies on the data.
    for c in report["series"]:
        model = np.interp(c["data"]["plastic_strain"], c["fitted"]["plastic_strain"],
                          c["fitted"]["stress"])
        assert np.max(np.abs(model / c["data"]["stress"] - 1.0)) < 2e-3


def interpolate(eps, sigma, x):
    """Linear in the plastic rows, extrapolated on the end segments (as the report's errors)."""
    keep = eps > 0.0
    e, s = eps[keep], sigma[keep]
    k = np.clip(np.searchsorted(e, x, side="right") - 1, 0, len(e) - 2)
    return s[k] + (x - e[k]) / (e[k + 1] - e[k]) * (s[k + 1] - s[k])


def test_check_report_matches_its_curves(data, workdir):
    config = {"material": data("materials", "al6061_t6.json"),
              "data": [{"file": data("experiments", "al6061_t6", "cad_298K_0.001per_s.csv")},
                       {"file": data("experiments", "al6061_t6", "gre_295K_0.002per_s.csv")}],
              "tolerance": {"rms_percent": 8.0, "max": 50e6}}
    report = impact.check(config)
    assert report["passed"] and report["exceeded"] == []
    assert len(report["curves"]) == 2 and len(report["series"]) == 2
    for row, series in zip(report["curves"], report["series"]):
        x = series["data"]["plastic_strain"]
        model = interpolate(series["material"]["plastic_strain"], series["material"]["stress"], x)
        rms = np.sqrt(np.mean((model - series["data"]["stress"]) ** 2))
        assert row["curve"] == series["data"]["name"]
        assert row["rms [Pa]"] == pytest.approx(rms, rel=1e-9)
    # A tolerance the set cannot meet: the report says which.
    strict = dict(config, tolerance={"rms": 1e6})
    failed = impact.check(strict)
    assert not failed["passed"] and "RMS" in failed["exceeded"][0]

