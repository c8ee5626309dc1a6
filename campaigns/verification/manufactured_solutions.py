#!/usr/bin/env python3
"""The manufactured solutions of docs/verification.md, derived with sympy (Debian's python3-sympy).

Wallstedt & Guilkey (2008, J. Comput. Phys. 227:9628, sec. 4) verify explicit GIMP against a
displacement field chosen in advance: the body force that makes it a solution of the momentum
equation, b = u_tt - Div P / rho0 (reference configuration, per unit mass), is applied to the
particles. The material is compressible neo-Hookean,
    P = mu (F - F^-T) + lambda ln(J) F^-T,            (first Piola-Kirchhoff stress)
with F = I + Grad u and J = det F. Three fields, each with constants A [m] (amplitude), L [m]
(wavelength) and c [m/s] (the wave speed sqrt(mu / rho0) sets the time scale as in the paper):
  axis_aligned (3D):    u_i = A sin(2 pi X_i / L) sin(pi c t / L), i = x, y, z
  plane_strain:         u_x, u_y as above, u_z = 0
  axisymmetric:         u_x = A sin(2 pi X / L) sin(pi c t / L), u_R = A sin(2 pi R / L)
                        sin(pi c t / L) with R = Y (it vanishes on the axis); the divergence in
                        cylindrical coordinates has the hoop term (P_RR - P_TT) / R.

Usage:
  manufactured_solutions.py            print each field's scene keys (objects.<name>.velocity,
                                       objects.<name>.body_force, output.exact_displacement) as
                                       JSON, expressions in muParser's syntax (docs/scenes.md)
  manufactured_solutions.py --check    compare every body force with an independent evaluation
                                       (central differences of u and of P in numpy, no sympy) at
                                       random points and times; exit 1 beyond 1e-6 relative
  manufactured_solutions.py --scenes DIR
                                       write the verification scenes mms_<field>.json into DIR
                                       (data/scenes/verification/, committed): the body fills
                                       [0, L] per axis, every face `symmetric` (each field is odd
                                       about X = 0 and X = L, the mirror's own symmetry), the
                                       neo-Hookean material of data/materials/neo_hookean_soft.json
"""
import json
import sys

import numpy as np
import sympy as sp
from sympy.printing.str import StrPrinter

X, Y, Z, t = sp.symbols("X Y Z t", real=True)
A, L, c, mu, lam, rho0 = sp.symbols("A L c mu lam rho0", positive=True)
FIELDS = ("axis_aligned", "plane_strain", "axisymmetric")


def displacement(field):
    """u(X, t) as a sympy 3-vector (x, y, z; on the axisymmetric grid y is the radius R)."""
    s = lambda q: A * sp.sin(2 * sp.pi * q / L) * sp.sin(sp.pi * c * t / L)  # noqa: E731
    if field == "axis_aligned":
        return sp.Matrix([s(X), s(Y), s(Z)])
    return sp.Matrix([s(X), s(Y), 0])  # plane strain, and axisymmetric with Y = R


def piola(F):
    """Neo-Hookean first Piola-Kirchhoff stress of deformation gradient F."""
    Finv_T = F.inv().T
    return mu * (F - Finv_T) + lam * sp.log(F.det()) * Finv_T


def body_force(field):
    """b = u_tt - Div P / rho0 (not simplified: sympy's simplify takes minutes here)."""
    u = displacement(field)
    coords = [X, Y, Z]
    if field == "axisymmetric":
        # F in (x, R, theta): diag(1 + u_x,x, 1 + u_R,R, 1 + u_R / R), off-diagonals
        # u_x,R and u_R,x (zero for this separable field, kept for generality).
        F = sp.Matrix([[1 + sp.diff(u[0], X), sp.diff(u[0], Y), 0],
                       [sp.diff(u[1], X), 1 + sp.diff(u[1], Y), 0],
                       [0, 0, 1 + u[1] / Y]])
        P = piola(F)
        div = sp.Matrix([
            sp.diff(P[0, 0], X) + sp.diff(P[0, 1], Y) + P[0, 1] / Y,
            sp.diff(P[1, 0], X) + sp.diff(P[1, 1], Y) + (P[1, 1] - P[2, 2]) / Y,
            0])
    else:
        F = sp.eye(3) + u.jacobian(coords)
        P = piola(F)
        div = sp.Matrix([sum(sp.diff(P[i, j], coords[j]) for j in range(3)) for i in range(3)])
    return sp.diff(u, t, 2) - div / rho0


class MuParserPrinter(StrPrinter):
    """sympy to muParser: ^ for powers (parenthesised: -2^2 is -4 there), pi, ln."""

    def _print_Pow(self, expr):
        base, exp = expr.as_base_exp()
        if exp == sp.Rational(1, 2):
            return f"sqrt({self._print(base)})"
        if exp == -1:
            return f"1/({self._print(base)})"
        return f"({self._print(base)})^({self._print(exp)})"

    def _print_log(self, expr):
        return f"ln({self._print(expr.args[0])})"

    def _print_Pi(self, expr):
        return "pi"

    def _print_Exp1(self, expr):
        return "_e"


def muparser(expr):
    text = MuParserPrinter().doprint(expr)
    return text.replace("lam", "lambda_").replace("**", "^")


def scene_keys(field):
    u = displacement(field)
    v0 = sp.diff(u, t).subs(t, 0)
    b = body_force(field)
    return {
        "field": field,
        "constants": ["A", "L", "c", "mu", "lambda_", "rho0"],
        "velocity": [muparser(sp.simplify(e)) if e != 0 else 0 for e in v0],
        "body_force": [muparser(e) if e != 0 else 0 for e in b],
        "exact_displacement": [muparser(e) if e != 0 else 0 for e in u],
    }


def numeric_body_force(field, point, time, values, h=1e-5):
    """b at one point by central differences in numpy: u_tt, Grad u, P, Div P (no sympy)."""
    a, ell, cc, m, la, r0 = (values[k] for k in ("A", "L", "c", "mu", "lam", "rho0"))

    def u(x, tt):
        s = lambda q: a * np.sin(2 * np.pi * q / ell) * np.sin(np.pi * cc * tt / ell)  # noqa
        if field == "axis_aligned":
            return np.array([s(x[0]), s(x[1]), s(x[2])])
        return np.array([s(x[0]), s(x[1]), 0.0])

    def grad_u(x):
        g = np.zeros((3, 3))
        for j in range(3):
            dx = np.zeros(3)
            dx[j] = h
            g[:, j] = (u(x + dx, time) - u(x - dx, time)) / (2 * h)
        return g

    def stress(x):
        F = np.eye(3) + grad_u(x)
        if field == "axisymmetric":
            F[2, :] = 0.0
            F[:, 2] = 0.0
            F[2, 2] = 1.0 + u(x, time)[1] / x[1]
        Finv_T = np.linalg.inv(F).T
        return m * (F - Finv_T) + la * np.log(np.linalg.det(F)) * Finv_T

    div = np.zeros(3)
    for j in range(2 if field != "axis_aligned" else 3):
        dx = np.zeros(3)
        dx[j] = h
        div += (stress(point + dx)[:, j] - stress(point - dx)[:, j]) / (2 * h)
    if field == "axisymmetric":
        P = stress(point)
        div[0] += P[0, 1] / point[1]
        div[1] += (P[1, 1] - P[2, 2]) / point[1]
        div[2] = 0.0
    u_tt = (u(point, time + h) - 2 * u(point, time) + u(point, time - h)) / h**2
    return u_tt - div / r0


def check():
    rng = np.random.default_rng(55)
    values = {"A": 0.02, "L": 1.0, "c": 20.0, "mu": 4.0e5, "lam": 6.0e5, "rho0": 1000.0}
    subs = {A: values["A"], L: values["L"], c: values["c"], mu: values["mu"],
            lam: values["lam"], rho0: values["rho0"]}
    worst = 0.0
    for field in FIELDS:
        b = sp.lambdify((X, Y, Z, t), body_force(field).subs(subs), "numpy")
        scale = 0.0
        errors = []
        for _ in range(20):
            point = rng.uniform(0.05, 0.95, 3)
            time = rng.uniform(0.0, 0.1)
            exact = np.array(b(*point, time), dtype=float).reshape(3)
            numeric = numeric_body_force(field, point, time, values)
            scale = max(scale, np.abs(exact).max())
            errors.append(np.abs(exact - numeric).max())
        relative = max(errors) / scale
        worst = max(worst, relative)
        print(f"{field}: body force from sympy against central differences at 20 points: "
              f"largest difference {relative:.2e} of the largest component {scale:.3e} m/s^2")
    return 0 if worst <= 1e-6 else 1


# The scenes' numbers: the soft solid of data/materials/neo_hookean_soft.json (E = 1e7 Pa, nu = 0.3,
# rho0 = 1000 kg/m^3), a body L = 1 m wide and an amplitude A = 0.05 m: |Grad u| up to
# 2 pi A / L = 0.31, J from 0.33 to 2.2 at the peak, large deformation. c = sqrt(mu / rho0), so the
# displacement peaks at t = L / (2 c) = 8.06 ms, the scenes' end.
SOFT = {"A": 0.05, "L": 1.0, "mu": 1.0e7 / 2.6, "lambda_": 1.0e7 * 0.3 / (1.3 * 0.4),
        "rho0": 1000.0}
SOFT["c"] = (SOFT["mu"] / SOFT["rho0"]) ** 0.5
GEOMETRY = {
    "axis_aligned": ({"lower": [0, 0, 0], "upper": [1, 1, 1], "cells": [8, 8, 8]},
                     {"type": "box", "lower": [0, 0, 0], "upper": [1, 1, 1]}),
    "plane_strain": ({"geometry": "plane_strain", "lower": [0, 0], "upper": [1, 1],
                      "cells": [16, 16]},
                     {"type": "box", "lower": [0, 0, -0.5], "upper": [1, 1, 0.5]}),
    "axisymmetric": ({"geometry": "axisymmetric", "lower": [0, 0], "upper": [1, 1],
                      "cells": [16, 16]},
                     {"type": "cylinder", "bottom": [0, 0, 0], "top": [1, 0, 0], "radius": 1}),
}


def write_scenes(directory):
    import os
    for field in FIELDS:
        keys = scene_keys(field)
        grid, geometry = GEOMETRY[field]
        scene = {
            "description": (
                f"Manufactured solution '{field}' (campaigns/verification/manufactured_solutions.py, "
                "docs/verification.md#manufactured-solutions; Wallstedt & Guilkey 2008, J. Comput. "
                "Phys. 227:9628, sec. 4): u = A sin(2 pi X / L) sin(pi c t / L) per axis, held by "
                "the body force sympy derives for the compressible neo-Hookean solid; every face "
                "symmetric. Written by `manufactured_solutions.py --scenes`: edit the script, not "
                "this file. The history's displacement_error_rms/max [m] are the error; "
                "`mpm study --ladder` refines the grid."),
            "constants": {k: SOFT[k] for k in ("A", "L", "c", "mu", "lambda_", "rho0")},
            "materials": {"soft": {"file": "../../materials/neo_hookean_soft.json"}},
            "objects": {"body": {"material": "soft", "geometry": geometry,
                                 "velocity": keys["velocity"],
                                 "body_force": keys["body_force"]}},
            "grid": grid,
            "time": {"max_time": SOFT["L"] / (2.0 * SOFT["c"]), "multiplier": 0.4},
            "solver": {"interpolation": "gimp", "scheme": "musl"},
            "output": {"snapshots": False, "exact_displacement": keys["exact_displacement"]},
        }
        path = os.path.join(directory, f"mms_{field}.json")
        with open(path, "w") as out:
            json.dump(scene, out, indent=1)
            out.write("\n")
        print(path)


if __name__ == "__main__":
    if sys.argv[1:] == ["--check"]:
        sys.exit(check())
    if len(sys.argv) == 3 and sys.argv[1] == "--scenes":
        write_scenes(sys.argv[2])
        sys.exit(0)
    if sys.argv[1:]:
        sys.exit(__doc__)
    print(json.dumps([scene_keys(f) for f in FIELDS], indent=1))
