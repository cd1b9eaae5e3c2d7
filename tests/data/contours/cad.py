"""A NACA 0012 as a CAD export: N points spaced evenly in x (the open-trailing-edge thickness
formula of NACA Report 460), upper trailing edge to lower trailing edge, every coordinate printed
with DECIMALS decimals. Usage: python3 cad.py N DECIMALS OUT"""
import math
import sys

n, decimals, out = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
m = (n - 1) // 2
half = []
for i in range(m + 1):
    x = i / m
    t = 0.6 * (0.2969 * math.sqrt(x) - 0.1260 * x - 0.3516 * x**2 + 0.2843 * x**3 - 0.1015 * x**4)
    half.append((x, t))
points = [(x, y) for x, y in reversed(half)] + [(x, -y) for x, y in half[1:]]
rows = ["%.*f %.*f" % (decimals, x, decimals, y) for x, y in points]
open(out, "w").write("NACA 0012 %d points %d decimals\n" % (n, decimals) + "\n".join(rows) + "\n")
