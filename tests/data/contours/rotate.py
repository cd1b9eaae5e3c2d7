"""Rotate a Selig-format contour nose-up by DEG degrees about the origin: python3 rotate.py IN DEG OUT"""
import math, sys
src, deg, out = sys.argv[1], float(sys.argv[2]), sys.argv[3]
lines = open(src).read().splitlines()
c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
rows = []
for line in lines[1:]:
    f = line.split()
    if len(f) == 2:
        x, y = float(f[0]), float(f[1])
        rows.append("%.8f %.8f" % (c * x + s * y, -s * x + c * y))
open(out, "w").write("%s rotated %g deg nose-up\n" % (lines[0].strip(), deg) + "\n".join(rows) + "\n")
