#!/usr/bin/env python3
"""Upper-surface separation location x_sep/c from XFOIL 6.99 boundary-layer dumps.

Usage: separation_from_dump.py RE DUMP_DIR > rows.csv

Reads every DUMP_DIR/bl_a<alpha>.txt (XFOIL's DUMP: s x y Ue/Vinf Dstar Theta Cf H ...,
starting at the upper trailing edge, around the leading edge, along the lower surface and
into the wake) and prints `re,alpha,xsep_top`: the x/c where the reversed flow (Cf < 0) that
reaches the upper trailing edge begins, interpolated linearly in x where Cf changes sign;
1 when Cf >= 0 at the trailing edge (a bubble that reattaches does not count). The same rule
as polargen's `xsep_top` (src/viscous/forces.rs, `separation_x`).
"""
import glob
import os
import re
import sys


def xsep_upper(rows):
    # Upper surface: from the trailing edge (first row) to the leading edge (smallest x).
    x = [r[1] for r in rows]
    le = min(range(len(rows)), key=lambda i: x[i])
    upper = rows[: le + 1]
    if upper[0][6] >= 0.0:
        return 1.0
    k = 0
    while k + 1 < len(upper) and upper[k + 1][6] < 0.0:
        k += 1
    if k + 1 == len(upper):
        return upper[k][1]
    (x1, c1), (x0, c0) = (upper[k][1], upper[k][6]), (upper[k + 1][1], upper[k + 1][6])
    f = c0 / (c0 - c1)
    return x0 + f * (x1 - x0)


def main():
    re_number, folder = sys.argv[1], sys.argv[2]
    files = glob.glob(os.path.join(folder, "bl_a*.txt"))
    alpha = lambda p: float(re.findall(r"bl_a(-?[\d.]+)\.txt$", p)[0])
    print("re,alpha,xsep_top")
    for path in sorted(files, key=alpha):
        rows = []
        for line in open(path):
            fields = line.split()
            if line.startswith("#") or len(fields) < 8:
                continue
            rows.append([float(v) for v in fields[:8]])
        print("%s,%g,%.4f" % (re_number, alpha(path), xsep_upper(rows)))


if __name__ == "__main__":
    main()
