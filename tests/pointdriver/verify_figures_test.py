#!/usr/bin/env python3
"""The figures of `pointdriver verify` (the committed docs/figures/verification/*.png) as drawn:

  verify_figures_test.py POINTDRIVER WORK_DIR

Runs the four cases that draw figures and reads what plot.py prints per panel (its axis label,
then its lines as the legend names them). Asserted: stresses and pressures in MPa or GPa (Pa with
"1e8" and "1e11" over the axes, before), one quantity per y axis (the axis listed every column
and was clipped, before), every coincident pair said so in the legend (Dienes on Green-Naghdi,
mu sin(gamma) on Jaumann, the reference temperature on the driver's, the Johnson-Cook curves at
0.001 /s and 1 /s, equal below the reference rate of 1 /s: one was hidden, before), the
measured Hugoniot as points, and each PNG's size in pixels (6.4 x 4.6 in at 130 dpi; 9.6 in wide
with the legend beside the 12 flow curves).
Without matplotlib: exit 77 (CTest: skipped).
"""
import os
import shutil
import struct
import subprocess
import sys

CASES = ["johnson_cook_uniaxial_stress", "adiabatic_compression_4000", "simple_shear_gamma5",
         "mie_gruneisen_uniaxial_strain"]
RATES = ["0.001", "1", "1000", "100000"]
FLOW_CURVES = ", ".join(
    f"driver_{r}_per_s_{t}K" + (f" (coincides with driver_0.001_per_s_{t}K)" if r == "1" else "")
    for t in (294, 500, 800) for r in RATES)
EXPECTED = {
    "johnson_cook_flow_curves.png": (f"  axial stress sigma_xx [MPa]: {FLOW_CURVES}", (1248, 598)),
    "adiabatic_compression_stress.png": ("  von Mises stress [MPa]: von_mises", (832, 598)),
    "adiabatic_compression_temperature.png": (
        "  temperature [K]: temperature, temperature_reference (coincides with temperature)",
        (832, 598)),
    "simple_shear.png": (
        "  shear stress sigma_xy [GPa]: green_naghdi_xy, dienes_xy (coincides with "
        "green_naghdi_xy), jaumann_xy, mu_sin_gamma (coincides with jaumann_xy)", (832, 598)),
    "mie_gruneisen_hugoniot.png": (
        "  pressure [GPa]: driver path, Hugoniot (closed form), experiments (McQueen, Mitchell, "
        "Vaidya)", (832, 598)),
}


def main(exe, work):
    shutil.rmtree(work, ignore_errors=True)
    cmd = [exe, "verify", "--out", work]
    for case in CASES:
        cmd += ["--case", case]
    done = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, f"exit {done.returncode}\n{done.stdout[-3000:]}\n{done.stderr}"
    if "figures skipped" in done.stdout:
        print("no python3/matplotlib: no figures; skipped")
        sys.exit(77)
    lines = done.stdout.splitlines()
    for png, (panel, size) in EXPECTED.items():
        figure = os.path.join(work, png)
        at = lines.index(f"wrote {figure}")
        assert lines[at + 1] == panel, f"{png}:\n  got      {lines[at + 1]}\n  expected {panel}"
        with open(figure, "rb") as f:
            head = f.read(24)
        assert head[:8] == b"\x89PNG\r\n\x1a\n", head
        assert struct.unpack(">II", head[16:24]) == size, (png, struct.unpack(">II", head[16:24]))
    print(f"OK: {len(EXPECTED)} figures, their panels and sizes")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
