"""Rotate a contour file (Selig: a name line, or plain "x y" lines) nose-up by DEG degrees about
the origin and write it with a name line: python3 rotate.py IN DEG OUT"""
import math
import os
import sys

src, deg, out = sys.argv[1], float(sys.argv[2]), sys.argv[3]
lines = [l for l in open(src).read().splitlines() if l.strip()]


def point(line):
    try:
        x, y = (float(v) for v in line.split())
        return x, y
    except ValueError:
        return None


name = os.path.splitext(os.path.basename(src))[0] if point(lines[0]) else lines[0].strip()
c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
rows = []
for line in lines:
    p = point(line)
    if p:
        x, y = p
        rows.append("%.8f %.8f" % (c * x + s * y, -s * x + c * y))
open(out, "w").write("%s rotated %g deg nose-up\n" % (name, deg) + "\n".join(rows) + "\n")
