#!/usr/bin/env python3
"""Every flow-stress law from a material file, in both programs.

  laws_in_programs_test.py POINTDRIVER MPM WORK_DIR

The 6061-T6 material with its flow_stress replaced (a merge patch on the material, as a user
writes it) by Zerilli-Armstrong (fcc, Zerilli & Armstrong 1987 copper constants), Steinberg-
Cochran-Guinan (Steinberg 1996, 6061-T6), Preston-Tonks-Wallace (Preston, Tonks & Wallace
2003, copper) and Mechanical Threshold Stress (Follansbee & Kocks 1988 in Banerjee's 2007 form,
an illustrative set; its structure stress sigma_e integrated here along the run's own rows with
the law's update, sigma_e += theta(sigma_e, rate, T) d_ep), Swift hardening with Cowper-
Symonds rate scaling (Bodner & Symonds' aluminium D = 6500 /s, q = 4; an illustrative Swift set),
and Johnson-Cook as shipped:
  - `pointdriver run`: uniaxial stress at 1000 /s to 20 % strain, isothermal. At the last step
    the axial stress equals the law's flow stress at the step's plastic strain and rate, start
    temperature and pressure and end density, computed here from the papers' equations
    independently of the library, to 1e-6 relative.
  - `mpm run`: the Taylor rod verification scene for 5 us completes with the energy books as
    closed as Johnson-Cook's (2 % of E0 on this coarse rod in its first microseconds: the error
    is the scheme's, not the law's), and each law leaves a different kinetic energy (the law is
    the one the solver used).
"""
import csv
import json
import math
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
MATERIAL = os.path.join(ROOT, "data", "materials", "al6061_t6.json")
JC_KEYS = ["A", "B", "n", "C", "m", "reference_strain_rate", "rate_form"]
NA = 6.02214076e23

LAWS = {
    "zerilli_armstrong": {"type": "zerilli_armstrong", "form": "fcc", "C0": 46.5e6,
                          "C2": 890e6, "C3": 0.0028, "C4": 0.000115},
    "steinberg_cochran_guinan": {"type": "steinberg_cochran_guinan", "Y0": 0.29e9,
                                 "Y_max": 0.68e9, "beta": 125.0, "n": 0.10, "G0": 27.6e9,
                                 "dG_dp": 65.0e-12 * 27.6e9, "dG_dT": -0.62e-3 * 27.6e9},
    "preston_tonks_wallace": {"type": "preston_tonks_wallace", "theta": 0.025, "p": 2.0,
                              "s0": 0.0085, "s_inf": 0.00055, "kappa": 0.11, "gamma": 1e-5,
                              "y0": 0.0001, "y_inf": 0.0001, "y1": 0.094, "y2": 0.575,
                              "beta": 0.25, "G0": 51.8e9, "alpha": 0.2, "molar_mass": 63.546e-3},
    "mechanical_threshold_stress": json.load(open(os.path.join(
        ROOT, "tests", "data", "flow_stress", "mts_illustrative.json")))["flow_stress"],
    "cowper_symonds": {"type": "cowper_symonds", "K": 420e6, "eps0": 0.005, "n": 0.08,
                       "D": 6500.0, "q": 4.0},
    "johnson_cook": None,  # as shipped
}
KB = 1.380649e-23


def nadal_le_poac(block, mu0, T, p, rho, rho0, Tm):
    """Nadal & Le Poac (2003), J. Appl. Phys. 93:2472, eq. (9)-(10): mu(p, T) with T^ = T / T_m,
    J(T^) = 1 + exp(-(1 + 1/zeta) / (1 + zeta / (1 - T^))), floored at 0 (none above 1 + zeta)."""
    Th = T / Tm
    if Th >= 1 + block["zeta"]:
        return 0.0
    J = 1 + math.exp(-(1 + 1 / block["zeta"]) / (1 + block["zeta"] / (1 - Th)))
    atom = block["molar_mass"] / NA
    mu = ((mu0 + block["dG_dp"] * p / (rho / rho0) ** (1 / 3)) * (1 - Th)
          + rho * KB * T / (block["C"] * atom)) / J
    return max(mu, 0.0)


def mts_law_at(law, T):
    """Above T_c, the set of an "above_critical_temperature" block in place of the law's
    (Banerjee 2007: 4340's austenite set above 1040 K)."""
    above = law.get("above_critical_temperature")
    if above is None or not T > above["T_c"]:
        return law
    return {**law, **{k: v for k, v in above.items() if k != "T_c"}}


def mts(law, rate, T, p=0.0, rho=0.0, material=None):
    """MTS pieces at one rate and T: mu/mu0, S_i, S_e, and theta(sigma_e) (Banerjee 2007), at
    pressure p and density rho where the modulus reads them (Nadal-Le Poac, as Banerjee 2007)."""
    law = mts_law_at(law, T)
    rate = max(rate, 1e-6)
    block = law.get("shear_modulus")
    if block is None:  # the law's own Varshni modulus (Banerjee eq. 10)
        mu = law["mu0"] - law["D"] / (math.exp(law["T0"] / T) - 1)
    elif block["type"] == "nadal_le_poac":
        mu = nadal_le_poac(block, law["mu0"], T, p, rho, material["density"],
                           material["melt_temperature"])
    else:
        raise ValueError(block["type"])
    b3 = law["burgers"] ** 3

    def S(g0, eps0, p, q):
        x = KB * T / (g0 * b3 * mu) * math.log(eps0 / rate)
        if x <= 0:
            return 1.0
        y = 1 - x ** (1 / q)
        return 0.0 if y <= 0 else y ** (1 / p)
    ses = law["sigma_es0"] * (rate / law["eps0_es"]) ** (KB * T / (law["g0_es"] * b3 * mu))

    def fit(c0, c1, c2, c3):  # a hardening rate >= 0: a negative fit is held at 0
        return max(c0 + c1 * math.log(rate) + c2 * math.sqrt(rate) - c3 * T, 0.0)
    theta0 = fit(law["a0"], law["a1"], law["a2"], law["a3"])
    theta_iv = fit(*(law.get(k, 0.0) for k in ("aIV0", "aIV1", "aIV2", "aIV3")))

    def theta(se):  # stage III to IV (Banerjee 2007 eq. 8; Goto et al. 2000)
        F = math.tanh(law["alpha"] * se / ses) / math.tanh(law["alpha"])
        return theta0 * (1 - F) + theta_iv * F
    # No intrinsic barrier (sigma_i = 0, an fcc metal): its activation keys need not be given.
    Si = S(law["g0_i"], law["eps0_i"], law["p_i"], law["q_i"]) if law["sigma_i"] > 0 else 0.0
    return (mu / law["mu0"], Si, S(law["g0_e"], law["eps0_e"], law["p_e"], law["q_e"]), theta)


def structure_update(law, sigma_e, d_ep, rate, T, p, rho, material):
    """sigma_e after d_ep, held >= 0 (a stress the dislocation density carries)."""
    theta = mts(law, rate, T, p, rho, material)[3]
    return max(sigma_e + theta(sigma_e) * d_ep, 0.0)


def flow_stress(law, ep, rate, T, p, rho, material, sigma_e=0.0):
    """The papers' equations, written out again (not the library's code)."""
    if law is None:
        jc = material["constitutive_model"]["flow_stress"]
        t_star = (T - material.get("room_temperature", 294.0)) / (
            material["melt_temperature"] - material.get("room_temperature", 294.0))
        rate_factor = 1 + jc["C"] * math.log(max(rate / jc.get("reference_strain_rate", 1.0), 1))
        return (jc["A"] + jc["B"] * ep ** jc["n"]) * rate_factor * (1 - max(t_star, 0) ** jc["m"])
    if law["type"] == "zerilli_armstrong":
        r = max(rate, 1e-6)
        return law["C0"] + law["C2"] * math.sqrt(ep) * math.exp(-law["C3"] * T +
                                                               law["C4"] * T * math.log(r))
    if law["type"] == "steinberg_cochran_guinan":
        y = min(law["Y0"] * (1 + law["beta"] * ep) ** law["n"], law["Y_max"])
        eta = rho / material["density"]
        return y * (1 + law["dG_dp"] / law["G0"] * p / eta ** (1 / 3) +
                    law["dG_dT"] / law["G0"] * (T - 300))
    if law["type"] == "preston_tonks_wallace":
        Th = T / material["melt_temperature"]
        G = law["G0"] * (1 - law["alpha"] * Th)
        xi = 0.5 * (4 * math.pi * rho * NA / law["molar_mass"] / 3) ** (1 / 3) * math.sqrt(G / rho)
        r = max(rate, 1e-6) / (law["gamma"] * xi)
        e = math.erf(law["kappa"] * Th * math.log(1 / r))
        s0 = law["s0"]
        ts = max(s0 - (s0 - law["s_inf"]) * e, s0 * r ** law["beta"])
        ty = max(law["y0"] - (law["y0"] - law["y_inf"]) * e,
                 min(law["y1"] * r ** law["y2"], s0 * r ** law["beta"]))
        a, pp = s0 - ty, law["p"]
        if pp == 0:  # the Voce limit of eq. (14) as p -> 0
            return 2 * G * (ts - (ts - ty) * math.exp(-law["theta"] * ep / (ts - ty)))
        x = pp * (ts - ty) / a
        tau = ts + a / pp * math.log(1 - (1 - math.exp(-x)) * math.exp(
            -pp * law["theta"] * ep / (a * (math.exp(x) - 1))))
        return 2 * G * tau
    if law["type"] == "cowper_symonds":  # Swift (1952) x Cowper & Symonds (1957)
        r = max(rate, 1e-6)
        return law["K"] * (law["eps0"] + ep) ** law["n"] * (1 + (r / law["D"]) ** (1 / law["q"]))
    if law["type"] == "mechanical_threshold_stress":
        ratio, Si, Se, _ = mts(law, rate, T, p, rho, material)
        return law["sigma_a"] + (Si * mts_law_at(law, T)["sigma_i"] + Se * sigma_e) * ratio
    raise ValueError(law["type"])


def run(cmd):
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"FAIL: {' '.join(cmd)} exited {done.returncode}\n{done.stderr}")


def main(pointdriver, mpm, work):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    material = json.load(open(MATERIAL))
    kinetic = []
    for name, law in LAWS.items():
        overrides = {}
        if law is not None:
            patch = {k: None for k in JC_KEYS}
            patch.update(law)
            overrides = {"constitutive_model": {"flow_stress": patch}}
        # Point driver: uniaxial stress, 1000 /s, 20 %, isothermal at 294 K.
        path = os.path.join(work, name + ".path.json")
        with open(path, "w") as f:
            json.dump({"material": {"file": MATERIAL, "overrides": overrides},
                       "temperature": 294.0, "thermal": "isothermal",
                       "legs": [{"duration": 2e-4, "steps": 2000,
                                 "velocity_gradient": {"xx": 1000.0},
                                 "stress": {"yy": 0.0, "zz": 0.0}}]}, f)
        out = os.path.join(work, name + ".csv")
        run([pointdriver, "run", path, "-o", out])
        rows = list(csv.DictReader(open(out)))
        last, before = rows[-1], rows[-2]
        ep = float(last["plastic_strain [-]"])
        rate = float(last["plastic_strain_rate [1/s]"])
        sigma_e = 0.0
        if law is not None and law["type"] == "mechanical_threshold_stress":
            for prev, row in zip(rows[:-1], rows[1:]):  # the law's update, step by step
                d_ep = float(row["plastic_strain [-]"]) - float(prev["plastic_strain [-]"])
                if d_ep > 0:
                    sigma_e = structure_update(law, sigma_e, d_ep,
                                               float(row["plastic_strain_rate [1/s]"]),
                                               float(prev["temperature [K]"]),
                                               float(prev["pressure [Pa]"]),
                                               float(row["density [kg/m^3]"]), material)
        expected = flow_stress(law, ep, rate, float(before["temperature [K]"]),
                               float(before["pressure [Pa]"]), float(last["density [kg/m^3]"]),
                               material, sigma_e)
        got = float(last["von_mises [Pa]"])
        print(f"{name}: pointdriver ep {ep:.4f}, rate {rate:.1f} /s: von Mises {got:.6e} Pa, "
              f"the law {expected:.6e} Pa")
        assert ep > 0.15, ep
        assert abs(got - expected) <= 1e-6 * expected, (name, got, expected)
        # MPM: the Taylor rod for 5 us with this law.
        scene = os.path.join(work, name + ".scene.json")
        # The whole scene, not "extends": a merge patch drops the nulls of a key its base lacks,
        # and the nulls are what take Johnson-Cook's keys out.
        doc = json.load(open(os.path.join(ROOT, "data/scenes/verification/taylor_rod.json")))
        doc["materials"]["al"] = {"file": MATERIAL, "overrides": overrides}
        doc["time"]["max_time"] = 5e-6
        doc.setdefault("output", {})["snapshots"] = False
        with open(scene, "w") as f:
            json.dump(doc, f)
        rod = os.path.join(work, name + ".mpm")
        run([mpm, "run", scene, "--out", rod, "--threads", "1"])
        summary = json.load(open(os.path.join(rod, "summary.json")))
        final = summary["final"]
        print(f"{name}: mpm {summary['status']}, {summary['steps']} steps, energy error "
              f"{final['energy_error [-]']:.2e}, kinetic energy {final['kinetic_energy [J]']:.4f} J")
        assert summary["status"] == "completed", summary["status"]
        assert abs(final["energy_error [-]"]) < 3e-2, final["energy_error [-]"]
        kinetic.append(final["kinetic_energy [J]"])
    assert len(set(round(k, 6) for k in kinetic)) == len(kinetic), kinetic
    print("OK")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], sys.argv[3])
