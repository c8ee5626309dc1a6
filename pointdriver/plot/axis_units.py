"""An axis' unit with an SI prefix, so that its numbers read as they are (300 MPa, not 3.0 with
"1e8" above the axis), for the plot scripts (plot.py, run_plot.py). Standard library only.

Only units a reader quotes with a prefix are scaled: stresses and pressures (Pa: kPa, MPa, GPa)
and energies (J: kJ, MJ). Others (K, -, m/s, /s) keep their unit, and an axis never shows an
offset (set by the scripts: `useOffset=False`).
"""
import math

PREFIXED = {"Pa": [(1e9, "GPa"), (1e6, "MPa"), (1e3, "kPa")],
            "J": [(1e6, "MJ"), (1e3, "kJ")]}


def scaled_unit(unit, values):
    """(factor, label): divide the values by `factor` and label the axis with `label`, the
    largest prefix of `unit` under the largest finite magnitude among `values` (the unit itself
    when none fits or the unit takes no prefix)."""
    largest = max((abs(v) for v in values if math.isfinite(v)), default=0.0)
    for factor, label in PREFIXED.get(unit, []):
        if largest >= factor:
            return factor, label
    return 1.0, unit
