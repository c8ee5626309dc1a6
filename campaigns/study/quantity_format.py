"""How the campaign scripts print a quantity: one display unit per quantity, chosen for its size
(mm for lengths below a metre, GPa or MPa for pressures), and a ladder's range of converged values
as "7.61-8.07 mm for p in [1, 2]" (docs/accuracy.md#grid-convergence-ladders). Standard library
only: study_plot.py and ladder.py both print through it."""

import math

# SI unit -> [(factor, display unit)], largest first: the first factor not above the largest
# magnitude is used (so that the printed numbers are about 1 to 1000).
SCALES = {
    "m": [(1.0, "m"), (1e-3, "mm"), (1e-6, "um")],
    "Pa": [(1e9, "GPa"), (1e6, "MPa"), (1e3, "kPa"), (1.0, "Pa")],
    "s": [(1.0, "s"), (1e-3, "ms"), (1e-6, "us")],
    "J": [(1e6, "MJ"), (1e3, "kJ"), (1.0, "J")],
}


def display_unit(unit, values):
    """(factor, label) for printing `values` given in the SI `unit`: value / factor in label. A
    unit without scales (m/s, -) or no finite nonzero value keeps the unit as it is."""
    finite = [abs(v) for v in values if isinstance(v, (int, float)) and not isinstance(v, bool)
              and math.isfinite(v) and v != 0.0]
    scales = SCALES.get(unit)
    if not scales or not finite:
        return 1.0, unit
    largest = max(finite)
    for factor, label in scales:
        if largest >= factor:
            return factor, label
    return scales[-1]


def number(x, factor=1.0, digits=4):
    """x / factor to `digits` significant digits, or '-' when x is not a finite number."""
    if not isinstance(x, (int, float)) or isinstance(x, bool) or not math.isfinite(x):
        return "-"
    return f"{x / factor:.{digits}g}"


def with_unit(x, unit, digits=4):
    """'7.31 mm': x in the SI unit printed in its display unit ('-' when not a number)."""
    factor, label = display_unit(unit, [x])
    text = number(x, factor, digits)
    return text if text == "-" or label in ("", "-") else f"{text} {label}"


def order_text(p):
    return f"{p:.3g}"


def range_text(rng):
    """A ladder's range (the table's "range": low, high, unit, order_low, order_high) as
    '7.61-8.07 mm for p in [1, 2]' (Richardson over the plausible orders), or
    '15-53 mm over the finest 3 levels' (no power law behind the levels); 'low to high' where a
    value is negative. The ends carry the decimals that give the span two significant digits (a
    range of one value, to round-off: 4 significant digits). None or an incomplete range: '-'."""
    if not isinstance(rng, dict) or not all(isinstance(rng.get(k), (int, float))
                                            for k in ("low", "high")):
        return "-"
    unit = rng.get("unit", "")
    factor, label = display_unit(unit, [rng["low"], rng["high"]])
    span = abs(rng["high"] - rng["low"]) / factor
    size = max(abs(rng["high"]), abs(rng["low"])) / factor
    if span > 1e-6 * size and math.isfinite(span):  # else one value up to round-off
        decimals = max(0, 1 - math.floor(math.log10(span)))
        lo, hi = (f"{rng['low'] / factor:.{decimals}f}", f"{rng['high'] / factor:.{decimals}f}")
    else:
        lo = hi = number(rng["low"], factor)
    span = lo if lo == hi else (f"{lo} to {hi}" if rng["low"] < 0 or rng["high"] < 0
                                else f"{lo}-{hi}")
    text = span + ("" if label in ("", "-") else f" {label}")
    a, b = rng.get("order_low"), rng.get("order_high")
    if isinstance(a, (int, float)) and isinstance(b, (int, float)):
        a, b = order_text(a), order_text(b)
        return text + (f" for p = {a}" if a == b else f" for p in [{a}, {b}]")
    n = rng.get("levels", 3)
    return text + (" at the one level" if n == 1 else f" over the finest {n} levels")
