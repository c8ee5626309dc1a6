"""Grid convergence arithmetic: observed order, Richardson extrapolation and the grid convergence
index of three solutions on systematically refined grids, as the ASME V&V 20 procedure states it
in Celik, Ghia, Roache, Freitas, Coleman & Raad (2008), "Procedure for estimation and reporting of
uncertainty due to discretization in CFD applications", J. Fluids Eng. 130, 078001 (the GCI of
Roache 1994, J. Fluids Eng. 116, 405). Standard library only
(docs/accuracy.md#grid-convergence-ladders).

Notation as in Celik et al. (2008), grid 1 the finest:
  h_i        representative cell size, h = (volume / cells)^(1/D)  (their eq. 1)
  r21, r32   refinement ratios h2/h1, h3/h2 (need not be equal)
  e21, e32   phi2 - phi1, phi3 - phi2
  p          observed order, their eqs. 3a-3c:
               p = |ln|e32/e21| + q(p)| / ln r21,  q(p) = ln((r21^p - s) / (r32^p - s)),
               s = sign(e32/e21); solved without the absolute value for s = 1 (observed_order)
  phi_ext    (r21^p phi1 - phi2) / (r21^p - 1)  (eq. 4)
  e_a        |(phi1 - phi2) / phi1|, e_ext = |(phi_ext - phi1) / phi_ext|  (eq. 5)
  GCI_fine   Fs e_a / (r21^p - 1), Fs = 1.25 for three grids  (eq. 6)
The convergence condition follows the ratio R = e21/e32 of Stern, Wilson, Coleman & Paterson
(2001, J. Fluids Eng. 123, 793), taken per unit log-ratio for unequal refinement,
R* = (e21 / ln r21) / (e32 / ln r32) (= R for equal ratios): 0 < R* < 1 monotonic convergence
(exactly when a power law phi0 + C h^p, p > 0, passes through the three points), -1 < R* < 0
oscillatory convergence (Celik et al. flag it by e32/e21 < 0 and keep s = -1 in q; no power
law is behind it, and Stern et al. bound its error by half the range of the three solutions),
|R*| >= 1 divergence (no order, no extrapolation, no GCI), e21 = 0 or e32 = 0 none either.
The monotonic order is the power law's (observed_order); the conservative GCI of Oberkampf & Roy
(2010) is given beside Celik's (conservative_gci).

What a ladder lets a reader quote (docs/accuracy.md#grid-convergence-ladders): one extrapolated
value with its GCI only when the finest triple is quotable (monotonic, its order within
PLAUSIBLE_ORDER, and in the asymptotic range); otherwise the range that the levels and the
plausible orders bound (converged_range), never an error against one extrapolated number.
"""

import math

SAFETY_FACTOR = 1.25  # Fs for three or more grids (Roache 1998; Celik et al. 2008, eq. 6)
# Observed orders a first-order method can plausibly show; outside, an extrapolation is not quoted.
PLAUSIBLE_ORDER = (0.5, 2.0)


def representative_h(volume, cells, dimension):
    """h = (volume / cells)^(1/D) (Celik et al. 2008, eq. 1, for cells of equal size)."""
    return (volume / cells) ** (1.0 / dimension)


def convergence_condition(phi1, phi2, phi3, r21=None, r32=None):
    """'monotonic', 'oscillatory', 'monotonic divergence', 'oscillatory divergence' or
    'no difference' (e21 or e32 zero), from R* = (e21 / ln r21) / (e32 / ln r32) (module
    docstring). With equal ratios (or none given) R* is Stern et al.'s R = e21/e32; with unequal
    ones 0 < R* < 1 is exactly the condition that a power law phi0 + C h^p with p > 0 passes
    through the three points (e32/e21 > ln r32 / ln r21)."""
    e21, e32 = phi2 - phi1, phi3 - phi2
    if e21 == 0.0 or e32 == 0.0:
        return "no difference"
    ratio = e21 / e32
    if r21 is not None and r32 is not None:
        ratio *= math.log(r32) / math.log(r21)
    if 0.0 < ratio < 1.0:
        return "monotonic"
    if -1.0 < ratio < 0.0:
        return "oscillatory"
    return "monotonic divergence" if ratio > 0.0 else "oscillatory divergence"


def observed_order(phi1, phi2, phi3, r21, r32, tolerance=1e-14, iterations=200):
    """p of Celik et al. (2008) eqs. 3a-3c for a converging triple, else None.

    Monotonic (s = 1): the root of p ln r21 = ln|e32/e21| + q(p), which is the power law
    phi = phi0 + C h^p through the three points. The right side minus the left rises strictly
    with p from ln(e32/e21) - ln(ln r32 / ln r21), so the root is unique and exists exactly when
    the condition is monotonic (convergence_condition with the ratios); it is bracketed by a scan
    of p in [1e-4, 50] and bisected. Celik's fixed-point form, with the absolute value, can
    settle on a spurious root where ln|e32/e21| + q(p) < 0, or cycle, when r21 and r32 differ
    much.
    Oscillatory (s = -1): Celik's fixed point from q = 0, the same scan and bisection where it
    does not settle."""
    e21, e32 = phi2 - phi1, phi3 - phi2
    if convergence_condition(phi1, phi2, phi3, r21, r32) not in ("monotonic", "oscillatory"):
        return None
    s = 1.0 if e32 / e21 > 0 else -1.0
    log_ratio = math.log(abs(e32 / e21))

    def q(p):
        return math.log((r21 ** p - s) / (r32 ** p - s))

    def update(p):
        return abs(log_ratio + q(p)) / math.log(r21)

    def residual(p):
        if s > 0:
            return p * math.log(r21) - (log_ratio + q(p))
        return p - update(p)

    if s < 0:
        p = abs(log_ratio) / math.log(r21)  # the first guess q = 0 (Celik et al. 2008)
        for _ in range(iterations):
            try:
                nxt = update(p)
            except (ValueError, ZeroDivisionError, OverflowError):
                break
            if abs(nxt - p) <= tolerance * max(1.0, abs(p)):
                return nxt
            p = nxt

    grid = [1e-4 * (5e5 ** (i / 800.0)) for i in range(801)]  # 1e-4 to 50, geometric
    previous = None
    for hi in grid:
        try:
            fhi = residual(hi)
        except (ValueError, ZeroDivisionError, OverflowError):
            previous = None
            continue
        if fhi == 0.0:
            return hi
        if previous is not None and (previous[1] > 0) != (fhi > 0):
            lo, flo = previous
            for _ in range(200):
                mid = 0.5 * (lo + hi)
                fm = residual(mid)
                if (fm > 0) == (flo > 0):
                    lo, flo = mid, fm
                else:
                    hi = mid
                if hi - lo <= tolerance * hi:
                    break
            return 0.5 * (lo + hi)
        previous = (hi, fhi)
    return None


def gci_triple(phi, h, safety_factor=SAFETY_FACTOR):
    """The whole procedure on phi = (phi1, phi2, phi3), h = (h1, h2, h3), grid 1 the finest.
    Returns a dict: r21, r32, condition, order p, extrapolated phi_ext21, e_a, e_ext, gci_fine
    (relative, as fractions), gci_medium (GCI_32 with the same p, for the asymptotic check);
    order and what follows are None when the triple does not converge."""
    (phi1, phi2, phi3), (h1, h2, h3) = phi, h
    if not h1 < h2 < h3:
        raise ValueError(f"gci_triple: h must grow from the finest grid: {h}")
    r21, r32 = h2 / h1, h3 / h2
    out = {"r21": r21, "r32": r32,
           "condition": convergence_condition(phi1, phi2, phi3, r21, r32),
           "order": None, "extrapolated": None, "e_a": None, "e_ext": None, "gci_fine": None,
           "gci_medium": None, "gci_conservative": None, "phi1": phi1,
           # Oscillatory: no power law behind it; Stern et al. (2001) bound the error by half the
           # range of the three solutions, relative to phi1.
           "oscillation_band": (0.5 * (max(phi) - min(phi)) / abs(phi1)
                                if phi1 != 0.0 else None)}
    p = observed_order(phi1, phi2, phi3, r21, r32)
    if p is None or p <= 0.0:
        return out
    rp21 = r21 ** p
    ext = (rp21 * phi1 - phi2) / (rp21 - 1.0)
    out["order"], out["extrapolated"] = p, ext
    if phi1 != 0.0:
        out["e_a"] = abs((phi1 - phi2) / phi1)
        out["gci_fine"] = safety_factor * out["e_a"] / (rp21 - 1.0)
    if ext != 0.0:
        out["e_ext"] = abs((ext - phi1) / ext)
    if phi2 != 0.0:
        out["gci_medium"] = safety_factor * abs((phi2 - phi3) / phi2) / (r32 ** p - 1.0)
    if phi1 != 0.0:
        out["gci_conservative"] = conservative_gci(out["e_a"], r21, p)
    return out


FORMAL_ORDER = 1.0  # explicit MPM on shocks, contact and plasticity: first order at best


def conservative_gci(e_a, r21, p, formal_order=FORMAL_ORDER):
    """The GCI of Roache (1998) as Oberkampf & Roy (2010, sec. 8.7) recommend it when the observed
    order p is more than 10 % from the formal one: safety factor 3 and the order limited to
    min(max(0.5, p), formal), and never below Celik's; within 10 % it is Celik's GCI_fine with
    Fs = 1.25."""
    celik = SAFETY_FACTOR * e_a / (r21 ** p - 1.0)
    if abs(p - formal_order) <= 0.1 * formal_order:
        return celik
    used = min(max(0.5, p), formal_order)
    # Never below Celik's: with p < 0.5 the limited order would give the smaller band.
    return max(celik, 3.0 * e_a / (r21 ** used - 1.0))


def ladder(values, h, safety_factor=SAFETY_FACTOR):
    """Every consecutive triple of a ladder (values and h ordered from the finest grid), finest
    triple first: gci_triple(...) plus 'h', the triple's three cell sizes. Levels whose value is
    None are skipped (a failed run)."""
    pairs = [(v, x) for v, x in zip(values, h) if v is not None and math.isfinite(v)]
    out = []
    for i in range(len(pairs) - 2):
        (v1, x1), (v2, x2), (v3, x3) = pairs[i], pairs[i + 1], pairs[i + 2]
        t = gci_triple((v1, v2, v3), (x1, x2, x3), safety_factor)
        t["h"] = (x1, x2, x3)
        out.append(t)
    return out


def asymptotic_check(finest, next_coarser):
    """A consistency test of the finest triple against the next coarser one (which shares its two
    coarser grids, so this is not independent evidence): both converge monotonically, their
    orders agree within 25 % (a heuristic of this project, not from the literature), and the
    coarser triple's extrapolation lies within the finest triple's band phi1 +- GCI_fine |phi1|.
    (Within one monotonic triple Roache's ratio GCI_32 / (r21^p GCI_21) equals |phi1/phi2|
    identically, so it cannot tell; two triples can.) Returns (bool or None, reason)."""
    if next_coarser is None:
        return None, "one triple only: a fourth level is needed to tell"
    a, b = finest, next_coarser
    if a["condition"] != "monotonic" or b["condition"] != "monotonic":
        return False, f"convergence {b['condition']} then {a['condition']}"
    if a["order"] is None or b["order"] is None:
        return False, "no observed order"
    if abs(a["order"] - b["order"]) > 0.25 * max(a["order"], b["order"]):
        return False, f"orders {b['order']:.2f} then {a['order']:.2f} differ by more than 25 %"
    if a["gci_fine"] is None or a.get("phi1") is None:
        return False, "no GCI band"
    band = a["gci_fine"] * abs(a["phi1"])
    if abs(b["extrapolated"] - a["phi1"]) > band:
        return False, (f"the coarser triple's extrapolation {b['extrapolated']:.6g} lies outside "
                       f"the band {a['phi1']:.6g} +- {band:.3g}")
    return True, "orders agree within 25 % and the coarser extrapolation lies in the GCI band"


def richardson(phi1, phi2, r21, p):
    """Richardson's extrapolation of the two finest values with order p (Celik et al. 2008,
    eq. 4): phi1 + (phi1 - phi2) / (r21^p - 1)."""
    return phi1 + (phi1 - phi2) / (r21 ** p - 1.0)


def plausible_orders(observed, formal=FORMAL_ORDER, band=PLAUSIBLE_ORDER):
    """(low, high, clamped): the orders from the formal one to the observed one, each end limited
    to the plausible band; clamped tells that the observed order lay outside the band."""
    lo, hi = sorted((observed, formal))
    clamp = lambda p: min(max(p, band[0]), band[1])  # noqa: E731
    return clamp(lo), clamp(hi), not band[0] <= observed <= band[1]


def converged_range(phi, h, formal=FORMAL_ORDER, band=PLAUSIBLE_ORDER):
    """The range of converged values that the finest triple phi = (phi1, phi2, phi3) on
    h = (h1, h2, h3) (grid 1 the finest) and the plausible orders bound:
    - monotonic convergence with observed order p: from the finest value phi1 (where the
      converged value lies if the convergence stalls beyond the finest level) to Richardson's
      extrapolation (richardson) for every order between the formal order and p, each end
      limited to the plausible band (plausible_orders): low and high span phi1 and its values at
      the two ends of that interval (it is monotonic in the order). Without phi1 the range could
      lie wholly beyond every level (issue 52: a residual velocity of +3 to +14 m/s while every
      level was negative);
    - anything else (oscillatory, divergent, no difference): no power law bounds the converged
      value; the band of the three values.
    Returns {"low", "high", "order_low", "order_high" (None unless monotonic), "observed_order",
    "clamped", "condition", "sign_determined" (False when the range spans 0: the converged
    value's sign is then not known)}."""
    t = gci_triple(phi, h)
    out = {"condition": t["condition"], "observed_order": t["order"], "order_low": None,
           "order_high": None, "clamped": False}
    if t["condition"] == "monotonic" and t["order"]:
        lo, hi, clamped = plausible_orders(t["order"], formal, band)
        ends = [richardson(phi[0], phi[1], t["r21"], q) for q in (lo, hi)] + [phi[0]]
        out.update(low=min(ends), high=max(ends), order_low=lo, order_high=hi, clamped=clamped)
    else:
        out.update(low=min(phi), high=max(phi))
    out["sign_determined"] = not out["low"] < 0.0 < out["high"]
    return out


def quotable(triple, asymptotic, band=PLAUSIBLE_ORDER):
    """May the finest triple's one extrapolated value and its GCI be quoted: it converges
    monotonically, its order lies within the plausible band, and the asymptotic check
    (asymptotic_check) passed (True; None, untested, is not enough)."""
    return bool(triple and triple["condition"] == "monotonic" and triple["order"]
                and band[0] <= triple["order"] <= band[1] and asymptotic is True)
