#!/usr/bin/env python3
"""`pointdriver cards MATERIAL --units mm-ms-kg` writes cards holding the material in mm-ms-kg
(Johnson-Cook as shipped, then with Swift x Cowper-Symonds hardening, below).

  cards_cli_test.py POINTDRIVER OUT_DIR

The conversions, from the units alone: with length 1 mm = 1e-3 m, time 1 ms = 1e-3 s and mass
1 kg, a stress of 1 kg / (mm ms^2) is 1 / (1e-3 x 1e-6) = 1e9 Pa (GPa), a density of 1 kg/mm^3 is
1e9 kg/m^3, a rate of 1 /ms is 1e3 /s, and a specific heat of 1 mm^2 / (ms^2 K) is
1e-6 / 1e-6 = 1 J/(kg K). So data/materials/al6061_t6.json (rho 2700 kg/m^3, G 26e9 Pa,
K 66.4e9 Pa, A 324e6 Pa, B 114e6 Pa, reference rate 1 /s, cp 896 J/(kg K)) must appear as
rho 2.7e-6, G 26, K 66.4, A 0.324, B 0.114, EPSO 0.001, cp 896, with E = 9 K G / (3 K + G) and
nu = (3 K - 2 G) / (2 (3 K + G)) from the moduli, and the dimensionless n, C, m, D1..D5, the
Taylor-Quinney coefficient and the temperatures in K unchanged. Every such value is read back
from the written LS-DYNA .k (10-column fields, named by the `$#` line above them) and Abaqus .inp
(the data line after each keyword) and compared with the material file's value converted here,
to 1e-6 relative (the cards' printed digits); zeros exactly.
"""
import json
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
MATERIAL = os.path.join(ROOT, "data", "materials", "al6061_t6.json")
STRESS, DENSITY, RATE, SPECIFIC_HEAT = 1e-9, 1e-9, 1e-3, 1.0  # SI -> mm-ms-kg, derived above


def ls_dyna_fields(text, keyword):
    """{name: value} of the cards after `keyword` up to the next keyword: each `$#` line names
    the 10-column fields of the line below it."""
    lines = text.split(keyword + "\n", 1)[1].splitlines()
    out = {}
    for names, values in zip(lines, lines[1:]):
        if names.startswith("*"):
            break
        if names.startswith("$#"):
            keys = names[2:].split()
            fields = [values[10 * i:10 * i + 10] for i in range(len(keys))]
            out.update({k: float(v) for k, v in zip(keys, fields)})
    return out


def abaqus_lines(text):
    """{keyword line: [numbers of the data line after it]}."""
    lines = [line for line in text.splitlines() if not line.startswith("**")]
    return {k: [float(x) for x in v.split(",")] for k, v in zip(lines, lines[1:])
            if k.startswith("*") and not v.startswith("*")}


def same(got, want, what):
    ok = got == want if want == 0 else abs(got - want) <= 1e-6 * abs(want)
    assert ok, f"{what}: the card has {got}, expected {want}"


def main(pointdriver, out):
    shutil.rmtree(out, ignore_errors=True)
    done = subprocess.run([pointdriver, "cards", MATERIAL, "--units", "mm-ms-kg", "--out", out],
                          capture_output=True, text=True)
    assert done.returncode == 0, (done.returncode, done.stderr)
    with open(MATERIAL) as f:
        m = json.load(f)
    cm = m["constitutive_model"]
    fs, dmg = cm["flow_stress"], cm["damage"]
    K, G = m["bulk_modulus"] * STRESS, m["shear_modulus"] * STRESS
    E, nu = 9 * K * G / (3 * K + G), (3 * K - 2 * G) / (2 * (3 * K + G))
    print(f"expected: rho {m['density'] * DENSITY:g} kg/mm^3, G {G:g}, K {K:g}, E {E:.8g} GPa, "
          f"nu {nu:.8g}, A {fs['A'] * STRESS:g}, B {fs['B'] * STRESS:g} GPa, "
          f"EPSO {fs['reference_strain_rate'] * RATE:g} /ms")

    with open(os.path.join(out, "al6061_t6.k")) as f:
        k = f.read()
    assert "units mm-ms-kg" in k, k
    mat = ls_dyna_fields(k, "*MAT_JOHNSON_COOK")
    expected = {"ro": m["density"] * DENSITY, "g": G, "e": E, "pr": nu, "a": fs["A"] * STRESS,
                "b": fs["B"] * STRESS, "n": fs["n"], "c": fs["C"], "m": fs["m"],
                "tm": m["melt_temperature"], "tr": m["room_temperature"],
                "epso": fs["reference_strain_rate"] * RATE,
                "cp": m["specific_heat"] * SPECIFIC_HEAT,
                **{f"d{i}": dmg[f"D{i}"] for i in range(1, 6)}}
    for name, want in expected.items():
        same(mat[name], want, f"LS-DYNA *MAT_JOHNSON_COOK {name}")
    eos = ls_dyna_fields(k, "*EOS_LINEAR_POLYNOMIAL")
    same(eos["c1"], K, "LS-DYNA *EOS_LINEAR_POLYNOMIAL c1 (the bulk modulus)")
    for c in ("c0", "c2", "c3", "c4", "c5", "c6"):
        same(eos[c], 0.0, f"LS-DYNA *EOS_LINEAR_POLYNOMIAL {c}")

    with open(os.path.join(out, "al6061_t6.inp")) as f:
        inp = f.read()
    assert "units mm-ms-kg" in inp, inp
    a = abaqus_lines(inp)
    checks = {"*DENSITY": [m["density"] * DENSITY], "*ELASTIC": [E, nu],
              "*PLASTIC, HARDENING=JOHNSON COOK": [fs["A"] * STRESS, fs["B"] * STRESS, fs["n"],
                                                   fs["m"], m["melt_temperature"],
                                                   m["room_temperature"]],
              "*RATE DEPENDENT, TYPE=JOHNSON COOK": [fs["C"], fs["reference_strain_rate"] * RATE],
              "*SPECIFIC HEAT": [m["specific_heat"] * SPECIFIC_HEAT],
              "*INELASTIC HEAT FRACTION": [cm["adiabatic_heating"]["taylor_quinney"]]}
    for keyword, want in checks.items():
        assert keyword in a and len(a[keyword]) == len(want), (keyword, a.get(keyword))
        for i, (g, w) in enumerate(zip(a[keyword], want)):
            same(g, w, f"Abaqus {keyword} [{i}]")
    print(f"LS-DYNA: {len(expected) + 7} values, Abaqus: "
          f"{sum(len(w) for w in checks.values())} values as converted here")
    swift_cowper_symonds(pointdriver, out, m, E, nu)
    print("OK")


# The same material with Swift hardening and Cowper-Symonds rate scaling (Bodner & Symonds'
# aluminium D = 6500 /s, q = 4 on an illustrative Swift K = 420 MPa, eps0 = 0.005, n = 0.08), as
# LS-DYNA's *MAT_POWER_LAW_PLASTICITY: sigma_y = k (eps_yp + ep)^N [1 + (rate / SRC)^(1/SRP)],
# SIGY < 0.02 being eps_yp itself. So k = K, N = n, SRC = D, SRP = q and SIGY = eps0 (a strain,
# unconverted), VP = 1; Abaqus: *PLASTIC's first row (K eps0^n, 0) and *RATE DEPENDENT,
# TYPE=POWER LAW (D, q).
SWIFT = {"type": "cowper_symonds", "K": 420e6, "eps0": 0.005, "n": 0.08, "D": 6500.0, "q": 4.0}


def swift_cowper_symonds(pointdriver, out, m, E, nu):
    fs = m["constitutive_model"]["flow_stress"]
    patch = {k: None for k in fs if k not in SWIFT}
    patch.update(SWIFT)
    done = subprocess.run([pointdriver, "cards", MATERIAL, "--units", "mm-ms-kg", "--out", out,
                           "--set", json.dumps({"constitutive_model": {"flow_stress": patch}})],
                          capture_output=True, text=True)
    assert done.returncode == 0, (done.returncode, done.stderr)
    with open(os.path.join(out, "al6061_t6.k")) as f:
        k = f.read()
    mat = ls_dyna_fields(k, "*MAT_POWER_LAW_PLASTICITY")
    expected = {"ro": m["density"] * DENSITY, "e": E, "pr": nu, "k": SWIFT["K"] * STRESS,
                "n": SWIFT["n"], "src": SWIFT["D"] * RATE, "srp": SWIFT["q"],
                "sigy": SWIFT["eps0"], "vp": 1.0}
    for name, want in expected.items():
        same(mat[name], want, f"LS-DYNA *MAT_POWER_LAW_PLASTICITY {name}")
    assert "*EOS" not in k, k
    with open(os.path.join(out, "al6061_t6.inp")) as f:
        a = abaqus_lines(f.read())
    first_yield = SWIFT["K"] * SWIFT["eps0"] ** SWIFT["n"] * STRESS
    checks = {"*PLASTIC": [first_yield, 0.0],
              "*RATE DEPENDENT, TYPE=POWER LAW": [SWIFT["D"] * RATE, SWIFT["q"]]}
    for keyword, want in checks.items():
        assert keyword in a and len(a[keyword]) == len(want), (keyword, a.get(keyword))
        for i, (g, w) in enumerate(zip(a[keyword], want)):
            same(g, w, f"Abaqus {keyword} [{i}]")
    print(f"Swift x Cowper-Symonds: LS-DYNA {len(expected)} values, Abaqus 4 values as converted "
          "here")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
