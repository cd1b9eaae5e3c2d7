"""OpenFAST's own derivation of the unsteady-aero coefficients from an airfoil table, written
again in Python from the equations of OpenFAST's AirfoilInfo (modules/aerodyn/src/
AirfoilInfo.f90: CalculateUACoeffs, Calculate_C_alpha, ComputeUA360_AttachedFlow,
ComputeUA360_updateSeparationF, ComputeUA360_CnOffset) and NWTC_Num.f90 (kernelSmoothing with
the triweight kernel, fZeros, InterpStp), for the Cn-based models (UA_Mod 2, 3, 5, 7; 3 is
AeroDyn's default). It gives what OpenFAST computes for a table read with InclUAdata False:
alpha0, C_nalpha, alpha1, alpha2, Cn1, Cn2 and the attached range it found. Not carried over:
the reverse-flow correction of f near +-180 deg (it does not reach the stall angles) and
OpenFAST's single precision. Used only by the tests, to compare polargen's block with it.
"""

import math

import numpy as np

LIMIT = math.radians(20.0)  # the range the slope analysis is limited to (not for UA_Mod 8)
SLOPE_DROP = 0.90  # CnSlopeThreshold
F_STALL = 0.7  # fAtCriticalCn


def _smooth_triweight(x, f, radius):
    """Kernel smoothing with the triweight kernel (35/32)(1 - u^2)^3, u clipped to [-1, 1]."""
    out = np.empty_like(f)
    for j, xj in enumerate(x):
        u = np.clip((x - xj) / radius, -1.0, 1.0)
        k = 35.0 / 32.0 * (1.0 - np.abs(u) ** 2) ** 3
        out[j] = (k * f).sum() / k.sum() if k.sum() > 0 else 0.0
    return out


def _interp_clamped(x, xs, ys):
    """Linear interpolation, the end values outside (InterpStp)."""
    return float(np.interp(x, xs, ys))


def _interp_extrap(x, xs, ys):
    """Linear interpolation, extrapolated from the end intervals outside."""
    if x <= xs[0]:
        k = 0
    elif x >= xs[-1]:
        k = len(xs) - 2
    else:
        k = int(np.searchsorted(xs, x)) - 1
    t = (x - xs[k]) / (xs[k + 1] - xs[k])
    return ys[k] + t * (ys[k + 1] - ys[k])


def _zeros(x, f, period=None):
    """Sign changes of f (f(j-1) < 0 <= f(j) or the reverse), linear between points."""
    roots = []
    for j in range(1, len(f)):
        if (f[j - 1] < 0 <= f[j]) or (f[j - 1] >= 0 > f[j]):
            roots.append(x[j] - f[j] * (x[j] - x[j - 1]) / (f[j] - f[j - 1]))
    if period is not None and ((f[-1] < 0 <= f[0]) or (f[-1] >= 0 > f[0])):
        roots.append(x[0] - f[0] * (x[0] - x[-1] + period) / (f[0] - f[-1]))
    return roots


def derive(alpha_deg, cl, cd):
    """OpenFAST's coefficients of one table (rows from -180 to 180 deg): a dict with alpha0,
    alpha1, alpha2 (deg), C_nalpha (1/rad), Cn1, Cn2, Cd0, alphaLower, alphaUpper (deg)."""
    a = np.radians(np.asarray(alpha_deg, float))
    cl, cd = np.asarray(cl, float), np.asarray(cd, float)
    n = len(a)
    near = np.abs(a) <= LIMIT
    i_cd_min = int(np.flatnonzero(near)[np.argmin(cd[near])])  # first minimum
    cd0 = cd[i_cd_min]
    alpha_at_cd_min = a[i_cd_min]
    cn = cl * np.cos(a) + (cd - cd0) * np.sin(a)
    slope_raw = np.diff(cn) / np.diff(a)
    mid = 0.5 * (a[1:] + a[:-1])
    slope = _smooth_triweight(mid, slope_raw, math.radians(2.0))
    slope_at_cd_min = _interp_clamped(alpha_at_cd_min, mid, slope)
    # 0-based indices below; the Fortran code's are 1-based.
    below = np.flatnonzero(mid < LIMIT)
    above = np.flatnonzero(mid > -LIMIT)
    i_high_limit = min(int(below[-1]) + 1, n - 2)
    i_low_limit = max(int(above[0]) - 1, 0)
    if i_high_limit - i_low_limit < 3:
        i_high_limit = min(i_low_limit + 2, n - 2)
    if i_high_limit - i_low_limit < 3:
        i_low_limit = max(i_high_limit - 2, 0)
    # alphaUpper: walk up from the minimum-drag row while the smoothed slope keeps above 90 %
    # of its largest value so far.
    i_high = i_high_limit if i_high_limit >= i_cd_min else n - 2
    largest = slope_at_cd_min
    i_high2 = i_cd_min
    for row in range(i_cd_min, i_high + 1):
        i_high2 = row
        if slope[row] > largest:
            largest = slope[row]
        elif slope[row] < SLOPE_DROP * largest:
            break
    if i_high2 == i_cd_min:
        alpha_upper = alpha_at_cd_min
    else:
        i_high2 = min(max(0, i_high2 - 1), n - 2)
        alpha_upper = mid[i_high2]
    # alphaLower: the same walking down.
    largest = slope_at_cd_min
    i_low = i_low_limit
    i_top = max(0, min(i_high2, i_cd_min, n - 2))
    if i_top < i_low:
        i_low = 0
    i_low2 = i_top
    for row in range(i_top, i_low - 1, -1):
        i_low2 = row
        if slope[row] > largest:
            largest = slope[row]
        elif slope[row] < SLOPE_DROP * largest:
            break
    if i_low2 == i_cd_min:
        alpha_lower = alpha_at_cd_min
    else:
        i_low2 = min(max(0, i_low2 + 1), n - 2)
        alpha_lower = mid[i_low2]
    # C_nalpha and alpha0: least squares on the rows inside the range less 20 % margins.
    margin = 0.2 * (alpha_upper - alpha_lower)
    lo = i_low_limit
    while lo < i_high_limit - 1 and a[lo] < alpha_lower + margin:
        lo += 1
    hi = i_high_limit
    while hi > lo + 1 and a[hi] > alpha_upper - margin:
        hi -= 1
    c_nalpha, intercept = np.polyfit(a[lo:hi + 1], cn[lo:hi + 1], 1)
    alpha0 = -intercept / c_nalpha
    # The fully attached line and the separation point f (ComputeUA360_*).
    i_lower = int(np.flatnonzero(a >= alpha_lower)[0]) if (a >= alpha_lower).any() else 0
    i_upper = int(np.flatnonzero(a <= alpha_upper)[-1]) if (a <= alpha_upper).any() else n - 1
    i_lower = max(0, min(n - 2, i_lower))
    i_upper = max(1, min(n - 1, i_upper))
    alpha_lower, alpha_upper = a[i_lower], a[i_upper]
    s_up = (cn[i_upper - 1] - cn[i_upper]) / (a[i_upper - 1] - a[i_upper])
    a0_up = a[i_upper] - cn[i_upper] / s_up if s_up != 0 else a[i_upper]
    s_lo = (cn[i_lower] - cn[i_lower + 1]) / (a[i_lower] - a[i_lower + 1])
    a0_lo = a[i_lower] - cn[i_lower] / s_lo if s_lo != 0 else a[i_lower]
    roots = _zeros(a, cn, period=2 * math.pi)
    a0_rev = a[0]
    far = [r for r in roots if abs(r) >= math.radians(45.0)]
    if far:
        a0_rev = max(far, key=abs)
        if a0_rev < -math.pi / 2:
            a0_rev += 2 * math.pi
    s_rev = -2 * math.pi
    break_up = (s_rev * a0_rev - s_up * a0_up) / (s_rev - s_up)
    cn_break_up = s_up * (break_up - a0_up)
    break_lo = (s_rev * (a0_rev - 2 * math.pi) - s_lo * a0_lo) / (s_rev - s_lo)
    cn_break_lo = s_lo * (break_lo - a0_lo)
    attached = cn.copy()
    for row in range(0, i_lower):
        attached[row] = _interp_extrap(a[row], [a0_rev - 2 * math.pi, break_lo, a[i_lower]],
                                       [0.0, cn_break_lo, cn[i_lower]])
    for row in range(i_upper + 1, n):
        attached[row] = _interp_extrap(a[row], [a[i_upper], break_up, a0_rev],
                                       [cn[i_upper], cn_break_up, 0.0])
    cn_offset = cn[i_lower] + 0.05 if cn[i_lower] > -0.05 else 0.0
    scale = 0.1 * 180.0 / math.pi
    offset = cn_offset * (np.tanh(scale * (a + math.pi / 2)) - np.tanh(scale * (a - math.pi / 2))) / 2
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(attached == offset, 1.0, (cn - offset) / (attached - offset))
    ratio = np.maximum(0.25, ratio)
    f = np.clip((2 * np.sqrt(ratio) - 1) ** 2, 0.0, 1.0)
    f[i_lower:i_upper + 1] = 1.0

    def stall(rows, guess_rows):
        roots = _zeros(a[rows], F_STALL - f[rows])
        guess = a[guess_rows[0]] if len(guess_rows) else a[0]
        if len(roots) == 1:
            return roots[0]
        if roots:
            return min(roots, key=lambda r: abs(r - guess))
        return guess

    up_guess = np.flatnonzero((a >= alpha_upper) & (f <= F_STALL))
    low_guess = np.flatnonzero((a <= alpha_lower) & (f <= F_STALL))[::-1]
    alpha1 = stall(slice(i_upper, n), up_guess)
    alpha2 = stall(slice(0, i_lower + 1), low_guess)
    return {
        "alpha0": math.degrees(alpha0),
        "C_nalpha": float(c_nalpha),
        "alpha1": math.degrees(alpha1),
        "alpha2": math.degrees(alpha2),
        "Cn1": _interp_clamped(alpha1, a, cn),
        "Cn2": _interp_clamped(alpha2, a, cn),
        "Cd0": float(cd0),
        "alphaLower": math.degrees(alpha_lower),
        "alphaUpper": math.degrees(alpha_upper),
    }
