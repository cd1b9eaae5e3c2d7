#!/usr/bin/env python3
"""pg.aero against NeuralFoil on the same inputs: accuracy (against polargen's solver and the
XFOIL 6.99 polars in tests/data/xfoil) and wall time. Prints the tables of docs/python.md.

Needs the polargen package and NeuralFoil (``pip install neuralfoil``; its network weights ship
with the package). Run from the repository root:

    python tools/aero_vs_neuralfoil.py [--model xlarge] [--repeat 3]

The sample: the NACA 8-H-12 and 23012 at Re 1.9e6, free transition and transition fixed at 7 %
chord, α −4…8° in 0.5° steps (the α of the XFOIL files), at M 0.41 (the paper's condition;
NeuralFoil has no Mach input, so it answers for M 0) and at M 0 (where both are incompressible).
Timing: the same 100 points, and 200 scattered points (α −4…8°, Re 5e5…3e6, M 0; every point
its own condition, the worst case for polargen's warm starts), on all cores.
"""

from __future__ import annotations

import argparse
import csv
import time
from pathlib import Path

import numpy as np

import polargen as pg

REPO = Path(__file__).resolve().parents[1]
RE = 1.9e6
CASES = [("naca8h12", "free", 1.0), ("naca8h12", "xtr0.07", 0.07),
         ("naca23012", "free", 1.0), ("naca23012", "xtr0.07", 0.07)]


def xfoil(foil: str, trip: str):
    """The XFOIL 6.99 polar at Re 1.9e6, M 0.41 from tests/data/xfoil: α → (cl, cd)."""
    path = REPO / "tests" / "data" / "xfoil" / f"{foil}_Re1.9e6_M0.41_{trip}.csv"
    with path.open() as f:
        return {float(r["alpha"]): (float(r["cl"]), float(r["cd"])) for r in csv.DictReader(f)}


def neuralfoil(foil: str, alpha, re, xtr: float, model: str):
    import neuralfoil as nf

    coordinates = pg.Airfoil.named(foil).coordinates
    out = nf.get_aero_from_coordinates(coordinates, alpha=alpha, Re=re, xtr_upper=xtr,
                                       xtr_lower=xtr, model_size=model)
    return np.asarray(out["CL"]).ravel(), np.asarray(out["CD"]).ravel(), \
        np.asarray(out["analysis_confidence"]).ravel()


def stats(ref_cd, cd, ref_cl, cl):
    rel = np.abs(cd / ref_cd - 1.0) * 100.0
    return (f"{np.median(rel):.1f} % / {rel.max():.1f} %",
            f"{np.median(np.abs(cl - ref_cl)):.3f} / {np.abs(cl - ref_cl).max():.3f}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--model", default="xlarge", help="NeuralFoil model size")
    parser.add_argument("--repeat", type=int, default=3, help="timing runs (best is taken)")
    args = parser.parse_args()

    print(f"NeuralFoil model {args.model}; sample: {len(CASES)} polars x α -4…8 step 0.5")
    print()
    print("| case | NeuralFoil vs XFOIL M 0.41: median / max |ΔCd|/Cd | median / max |ΔCl| "
          "| NeuralFoil vs polargen M 0 | polargen M 0.41 vs XFOIL |")
    print("|---|---|---|---|---|")
    for foil, trip, xtr in CASES:
        ref = xfoil(foil, trip)
        alpha = np.array(sorted(a for a in ref if -4.0 <= a <= 8.0))
        x_cl = np.array([ref[a][0] for a in alpha])
        x_cd = np.array([ref[a][1] for a in alpha])
        ours = pg.aero(foil, alpha=alpha, re=RE, mach=0.41, xtr=xtr)
        ours0 = pg.aero(foil, alpha=alpha, re=RE, mach=0.0, xtr=xtr)
        n_cl, n_cd, _ = neuralfoil(foil, alpha, RE, xtr, args.model)
        ok = ours.converged & ours0.converged
        nf_x = stats(x_cd[ok], n_cd[ok], x_cl[ok], n_cl[ok])
        nf_0 = stats(ours0.cd[ok], n_cd[ok], ours0.cl[ok], n_cl[ok])
        pg_x = stats(x_cd[ok], ours.cd[ok], x_cl[ok], ours.cl[ok])
        print(f"| {foil} {trip} ({int(ok.sum())} points) | {nf_x[0]} | {nf_x[1]} | "
              f"Cd {nf_0[0]}, Cl {nf_0[1]} | Cd {pg_x[0]}, Cl {pg_x[1]} |")

    def best(f):
        times = []
        for _ in range(args.repeat):
            t0 = time.perf_counter()
            f()
            times.append(time.perf_counter() - t0)
        return min(times)

    alpha = np.arange(-4.0, 8.0 + 1e-9, 0.5)
    sample = [(foil, xtr) for foil, _, xtr in CASES]
    t_pg = best(lambda: [pg.aero(f, alpha=alpha, re=RE, mach=0.41, xtr=x) for f, x in sample])
    t_nf = best(lambda: [neuralfoil(f, alpha, RE, x, args.model) for f, x in sample])
    rng = np.random.default_rng(1)
    a_s, re_s = rng.uniform(-4.0, 8.0, 200), rng.uniform(5e5, 3e6, 200)
    t_pg_s = best(lambda: pg.aero("naca2412", alpha=a_s, re=re_s))
    t_nf_s = best(lambda: neuralfoil("naca2412", a_s, re_s, 1.0, args.model))
    scattered = pg.aero("naca2412", alpha=a_s, re=re_s)
    print()
    print("| sample | pg.aero | NeuralFoil |")
    print("|---|---|---|")
    print(f"| 4 polars x {len(alpha)} α (warm-started sweeps) | {t_pg:.2f} s | {t_nf:.3f} s |")
    print(f"| 200 scattered points, NACA 2412 ({int(scattered.converged.sum())} converged) "
          f"| {t_pg_s:.2f} s | {t_nf_s:.3f} s |")


if __name__ == "__main__":
    main()
