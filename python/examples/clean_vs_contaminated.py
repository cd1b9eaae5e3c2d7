"""Clean versus contaminated rotor blade section, as in the DLR gyroplane study.

The paper's airfoil analysis: NACA 8-H-12 and NACA 23012 at Re = 1.9e6, M = 0.41, clean
(free transition, e^n with N = 9) versus contaminated by insects (transition fixed at 7 %
chord on both surfaces). Its Table 5 reads the drag coefficient at Cl = 0.8: 8-H-12 0.006 →
0.012, 23012 0.008 → 0.012; for the 8-H-12 it notes the drag almost doubles for Cl ≈ 0.3 … 1.0
and the lift-curve slope falls by about 15 %.

This script computes the four polars, prints Cd at Cl = 0.8 (found on the interpolated
polar, the way the report reads Table 5), the lift-curve slopes (least squares over α −2…6°:
the README's numbers, computed from the same polars by tests/readme_numbers.rs) and the laminar extent of the
clean 8-H-12 at Cl = 0.8, and draws the comparison (Cl–α, drag polar, Cl/Cd, Cp at Cl = 0.8).

Run (headless, about ten seconds on two cores):

    python examples/clean_vs_contaminated.py [--out clean_vs_contaminated.png]
"""

from __future__ import annotations

import argparse

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import polargen as pg  # noqa: E402

RE, MACH, TRIP = 1.9e6, 0.41, 0.07
ALPHA = "-6:14:0.25"
PAPER_CD_AT_08 = {"naca8h12": (0.006, 0.012), "naca23012": (0.008, 0.012)}


def lift_slope(pol: pg.Polar, lo: float = -2.0, hi: float = 6.0) -> float:
    """dCl/dα [1/deg]: least squares over the usable points with lo ≤ α ≤ hi."""
    keep = pol.usable & (pol.alpha >= lo) & (pol.alpha <= hi)
    return float(np.polyfit(pol.alpha[keep], pol.cl[keep], 1)[0])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="clean_vs_contaminated.png", help="figure (PNG/SVG)")
    out = parser.parse_args().out

    cases = {}
    for foil in ("naca8h12", "naca23012"):
        for label, xtr in (("clean", 1.0), ("contaminated", TRIP)):
            table = pg.table(foil, re=[RE], mach=[MACH], alpha=ALPHA, xtr=xtr)
            cases[foil, label] = table

    print(f"Cd at Cl = 0.8, Re {RE:.2g}, M {MACH}   (paper Table 5: clean / contaminated)")
    for foil, (paper_clean, paper_dirty) in PAPER_CD_AT_08.items():
        cds = []
        for label in ("clean", "contaminated"):
            found = cases[foil, label].alpha_at_cl(0.8, RE, MACH)
            cds.append(found[1]["cd"] if found else float("nan"))
        print(f"  {foil:10s} {cds[0]:.5f} / {cds[1]:.5f}   ({paper_clean} / {paper_dirty})"
              f"   change {100 * (cds[1] / cds[0] - 1):+.0f} %")

    clean = cases["naca8h12", "clean"].polars()[0]
    dirty = cases["naca8h12", "contaminated"].polars()[0]
    slope_clean, slope_dirty = lift_slope(clean), lift_slope(dirty)
    print(f"8-H-12 lift-curve slope -2…6 deg: {slope_clean:.3f} → {slope_dirty:.3f} /deg "
          f"({100 * (slope_dirty / slope_clean - 1):+.1f} %; paper: about -15 %)")

    points = {label: pg.point("naca8h12", re=RE, mach=MACH, cl=0.8, xtr=xtr)
              for label, xtr in (("clean", 1.0), ("contaminated", TRIP))}
    p = points["clean"]
    print(f"clean 8-H-12 at Cl = 0.8: transition x/c {p.xtr_top:.2f} upper, "
          f"{p.xtr_bot:.2f} lower (paper: ≈ 0.5 upper, up to 1.0 lower)")

    fig, ax = plt.subplots(2, 2, figsize=(11, 8.5))
    styles = {"clean": "-", "contaminated": "--"}
    colours = {"naca8h12": "tab:blue", "naca23012": "tab:red"}
    for (foil, label), table in cases.items():
        pol = table.polars()[0]
        ok = pol.usable  # unconverged points and those in massive separation are not results
        kw = dict(ls=styles[label], color=colours[foil], label=f"{pol.meta['airfoil']} {label}")
        ax[0, 0].plot(pol.alpha[ok], pol.cl[ok], **kw)
        ax[0, 1].plot(pol.cd[ok], pol.cl[ok], **kw)
        ax[1, 0].plot(pol.alpha[ok], pol.cl[ok] / pol.cd[ok], **kw)
    for label, pt in points.items():
        for surface in (pt.upper, pt.lower):
            ax[1, 1].plot(surface.x, surface.cp, ls=styles[label], color="tab:blue",
                          label=f"NACA 8-H-12 {label}" if surface is pt.upper else None)
    ax[0, 1].axhline(0.8, color="grey", lw=0.8)
    ax[1, 1].invert_yaxis()
    for a, (xl, yl) in zip(ax.flat, [("α [deg]", "Cl"), ("Cd", "Cl"), ("α [deg]", "Cl/Cd"),
                                     ("x/c", "Cp at Cl = 0.8")]):
        a.set_xlabel(xl)
        a.set_ylabel(yl)
        a.grid(alpha=0.3)
        a.legend(fontsize=8)
    fig.suptitle(f"Clean vs contaminated (transition at {TRIP:.0%} chord), "
                 f"Re {RE:.2g}, M {MACH}")
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
