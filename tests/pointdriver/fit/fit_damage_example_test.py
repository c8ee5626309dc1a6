#!/usr/bin/env python3
"""`pointdriver fit` on the damage example writes fitted D1..D5 that reproduce its data.

  fit_damage_example_test.py POINTDRIVER OUT_DIR

data/fits/al6061_t6_damage_synthetic.json fits D1..D5 of eq. 7 to 19 synthetic fracture strains
(made from the material's set -0.77, 1.45, -0.47, 0, 1.6 with 3 % scatter; docs/fitting.md).
Asserted, with eq. 7 evaluated here from the CSV and the material file
(eps_f = [D1 + D2 exp(D3 eta)] [1 + D4 ln max(rate / rate0, 1)] [1 + D5 T*], T* clamped to
[0, 1], eps_f floored at 1e-3):
- the fitted material file holds the report's fitted D1..D5 and, apart from its damage block,
  description and sources, the material it was fitted from;
- the RMS of the fitted set over the data, computed here, equals the report's (1e-9 relative),
  as does the material set's;
- least squares: the fitted set reproduces the data no worse than the set the data were made
  with (the material's), and within the 3 % scatter (RMS below 3 % of the data's RMS);
- the set the data were made with lies within 3 standard errors of the fitted D4 and D5, the
  two parameters docs/fitting.md calls well determined, and the docs' figures (RMS 0.014,
  D4 = -0.004 +- 0.003, D5 = 1.48 +- 0.06) are the run's to their printed digits.
"""
import json
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
CONFIG = os.path.join(ROOT, "data", "fits", "al6061_t6_damage_synthetic.json")


def fracture_strain(d, material, eta, rate, temperature):
    jc = material["constitutive_model"]["damage"]
    rate0 = jc.get("reference_strain_rate", 1.0)
    room, melt = material["room_temperature"], material["melt_temperature"]
    t_star = min(max((temperature - room) / (melt - room), 0.0), 1.0)
    e = ((d[0] + d[1] * math.exp(d[2] * eta)) * (1 + d[3] * math.log(max(rate / rate0, 1.0)))
         * (1 + d[4] * t_star))
    return max(e, 1e-3)


def rms(d, material, rows):
    return math.sqrt(sum((fracture_strain(d, material, *r[:3]) - r[3]) ** 2 for r in rows)
                     / len(rows))


def main(pointdriver, out):
    done = subprocess.run([pointdriver, "fit", CONFIG, "--out", out], capture_output=True,
                          text=True)
    assert done.returncode == 0, (done.returncode, done.stderr)
    with open(CONFIG) as f:
        config = json.load(f)
    with open(os.path.join(ROOT, config["material"])) as f:
        material = json.load(f)
    with open(os.path.join(ROOT, config["data"][0]["file"])) as f:
        lines = [line for line in f if line.strip() and not line.startswith("#")]
    assert lines[0].startswith("triaxiality [-],strain_rate [1/s],temperature [K]"), lines[0]
    rows = [[float(x) for x in line.split(",")] for line in lines[1:]]
    assert len(rows) == 19, len(rows)
    with open(os.path.join(out, "damage_fit_report.json")) as f:
        report = json.load(f)
    with open(os.path.join(out, config["output"]["material"])) as f:
        fitted_material = json.load(f)
    names = ["D1", "D2", "D3", "D4", "D5"]
    fitted = [report["parameters"][n]["fitted"] for n in names]
    errors = [report["parameters"][n]["std_error"] for n in names]
    made_with = [material["constitutive_model"]["damage"][n] for n in names]
    print("fitted " + ", ".join(f"{n} {v:.4g} +- {e:.2g}"
                                for n, v, e in zip(names, fitted, errors)))

    damage = fitted_material["constitutive_model"]["damage"]
    assert [damage[n] for n in names] == fitted, (damage, fitted)
    assert damage["type"] == "johnson_cook", damage
    strip = lambda m: {k: ({**v, "damage": None} if k == "constitutive_model" else v)
                       for k, v in m.items() if k not in ("description", "sources")}
    assert strip(fitted_material) == strip(material), "the fitted material changed more than D1..D5"

    fit_rms, set_rms = rms(fitted, material, rows), rms(made_with, material, rows)
    data_rms = math.sqrt(sum(r[3] ** 2 for r in rows) / len(rows))
    print(f"RMS here: fitted {fit_rms:.6g}, material's set {set_rms:.6g}; report "
          f"{report['rms']['fitted']:.6g}, {report['rms']['material']:.6g}; 3 % of the data's "
          f"RMS {0.03 * data_rms:.4g}")
    assert abs(fit_rms - report["rms"]["fitted"]) <= 1e-9 * fit_rms, (fit_rms, report["rms"])
    assert abs(set_rms - report["rms"]["material"]) <= 1e-9 * set_rms, (set_rms, report["rms"])
    assert fit_rms <= set_rms, (fit_rms, set_rms)
    assert fit_rms < 0.03 * data_rms, (fit_rms, data_rms)
    for i in (3, 4):
        assert abs(made_with[i] - fitted[i]) <= 3 * errors[i], (names[i], fitted[i], errors[i])
    assert (round(fit_rms, 3), round(fitted[3], 3), round(errors[3], 3), round(fitted[4], 2),
            round(errors[4], 2)) == (0.014, -0.004, 0.003, 1.48, 0.06), "docs/fitting.md's figures"
    print("OK")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
