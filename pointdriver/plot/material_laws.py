#!/usr/bin/env python3
"""Where the flow-stress laws of one material disagree: true stress against plastic strain in
uniaxial compression computed by `pointdriver run` with each shipped law file of the material,
at 1e-3 and 1e3 /s and 294 and 600 K (isothermal, so the laws are compared, not the heating),
one panel per rate and temperature, every law in each panel.

  material_laws.py POINTDRIVER OUT_DIR

Writes OUT_DIR/materials_<material>.png and OUT_DIR/materials_<material>.csv (columns:
law, temperature [K], strain_rate [1/s], plastic_strain [-], stress [Pa]) for copper (Johnson-
Cook, Zerilli-Armstrong, Steinberg-Cochran-Guinan, Mechanical Threshold Stress, Preston-Tonks-
Wallace), tantalum (Preston-Tonks-Wallace, Steinberg-Cochran-Guinan), Ti-6Al-4V (Johnson-Cook,
Steinberg-Cochran-Guinan), 6061-T6 aluminium (the report's Table 1 Johnson-Cook, Steinberg-
Cochran-Guinan), 4340 steel (Johnson-Cook, Mechanical Threshold Stress at four hardnesses), HY-100
steel (Mechanical Threshold Stress) and Armco iron (Johnson-Cook). The files in OPTIONAL are
plotted when they are in data/materials/ (they land separately); a material with none of its
files present is skipped.
"""
import csv
import json
import os
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
MATERIALS = {
    "copper": [("Johnson-Cook (1983)", "ofhc_copper_jc"),
               ("Zerilli-Armstrong (1987)", "ofhc_copper_za"),
               ("Steinberg-Cochran-Guinan (1996)", "ofhc_copper_scg"),
               ("Mechanical Threshold Stress (1988)", "ofhc_copper_mts"),
               ("Preston-Tonks-Wallace (2003)", "ofhc_copper_ptw")],
    "tantalum": [("Preston-Tonks-Wallace (2003)", "tantalum_ptw"),
                 ("Steinberg-Cochran-Guinan (1996)", "tantalum_scg")],
    "ti6al4v": [("Johnson-Cook (Lesuer 2000)", "ti6al4v_jc"),
                ("Steinberg-Cochran-Guinan (1996)", "ti6al4v_scg")],
    "al6061_t6": [("Johnson-Cook (the report's Table 1)", "al6061_t6"),
                  ("Steinberg-Cochran-Guinan (1996)", "al6061_t6_scg")],
    "steel_4340": [("Johnson-Cook (1983)", "steel_4340_jc"),
                   ("Mechanical Threshold Stress, Rc 30 (Banerjee 2007)", "steel_4340_mts_rc30"),
                   ("Mechanical Threshold Stress, Rc 38 (Banerjee 2007)", "steel_4340_mts_rc38"),
                   ("Mechanical Threshold Stress, Rc 45 (Banerjee 2007)", "steel_4340_mts_rc45"),
                   ("Mechanical Threshold Stress, Rc 49 (Banerjee 2007)", "steel_4340_mts_rc49")],
    "steel_hy100": [("Mechanical Threshold Stress (Goto et al. 2000)", "steel_hy100_mts")],
    "armco_iron": [("Johnson-Cook (1983)", "armco_iron_jc")],
}
# Written on other branches: plotted once they are in data/materials/.
OPTIONAL = {"al6061_t6_scg", "steel_4340_mts_rc30", "steel_4340_mts_rc38", "steel_4340_mts_rc45",
            "steel_4340_mts_rc49", "steel_hy100_mts"}
RATES = (1e-3, 1e3)
TEMPERATURES = (294.0, 600.0)
STRAIN = 0.5


def curve(pointdriver, material_file, T, rate, work):
    path = os.path.join(work, f"{os.path.basename(material_file)}_{T:.0f}K_{rate:g}.json")
    with open(path, "w") as f:
        json.dump({"material": material_file, "temperature": T, "thermal": "isothermal",
                   "legs": [{"duration": STRAIN / rate, "steps": 200,
                             "velocity_gradient": {"xx": -rate},
                             "stress": {"yy": 0.0, "zz": 0.0}}]}, f)
    out = path.replace(".json", ".csv")
    done = subprocess.run([pointdriver, "run", path, "-o", out], capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"material_laws.py: pointdriver run {path} exited {done.returncode}\n"
                 f"{done.stderr}")
    rows = list(csv.DictReader(open(out)))
    return ([float(r["plastic_strain [-]"]) for r in rows],
            [float(r["von_mises [Pa]"]) for r in rows])


def main(pointdriver, out_dir):
    os.makedirs(out_dir, exist_ok=True)
    with tempfile.TemporaryDirectory() as work:  # the path files and runs
        for material, laws in MATERIALS.items():
            present = [(label, name) for label, name in laws
                       if name not in OPTIONAL or os.path.exists(material_file(name))]
            if present:
                plot(pointdriver, material, present, out_dir, work)
            else:
                print(f"skipped {material}: none of its files is in data/materials/ yet")


def material_file(name):
    return os.path.join(ROOT, "data", "materials", name + ".json")


def plot(pointdriver, material, laws, out_dir, work):
    fig, axes = plt.subplots(1, len(RATES) * len(TEMPERATURES), figsize=(16, 4.2),
                             sharey=True)
    table = os.path.join(out_dir, f"materials_{material}.csv")
    with open(table, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["law", "temperature [K]", "strain_rate [1/s]", "plastic_strain [-]",
                    "stress [Pa]"])
        k = 0
        for T in TEMPERATURES:
            for rate in RATES:
                ax = axes[k]
                k += 1
                for label, name in laws:
                    ep, s = curve(pointdriver, material_file(name), T, rate, work)
                    ax.plot(ep, [x / 1e6 for x in s], label=label)
                    for e, x in zip(ep, s):
                        w.writerow([label, T, rate, e, x])
                ax.set_title(f"{T:.0f} K, {rate:g} /s")
                ax.set_xlabel("plastic strain [-]")
                ax.grid(alpha=0.3)
    axes[0].set_ylabel("true stress, von Mises [MPa]")
    axes[0].legend(fontsize=8)
    fig.suptitle(f"{material}: uniaxial compression, isothermal (pointdriver run, "
                 "data/materials/)")
    fig.tight_layout()
    png = os.path.join(out_dir, f"materials_{material}.png")
    fig.savefig(png, dpi=110)
    print(f"wrote {png} and {table}")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
