#!/usr/bin/env python3
"""Reference data for polargen's geometry operations from XFOIL 6.99 (Debian package `xfoil`).

For every case of CASES below, XFOIL loads the input section, applies one geometry operation
(GDES TSET, TGAP or FLAP, or the top-level INTX blend), makes the result the current airfoil
(eXec / PCOP), saves its ordinates (SAVE, 7 significant digits), repanels it (PANE, 160
nodes) and computes the inviscid CL and CM at alpha 0, 4 and 8 degrees (OPER, PACC).

    python3 tools/xfoil_geometry_ops.py --out tests/data/geometry_ops

writes, per case, <case>.dat (XFOIL's ordinates) and <case>_inviscid.csv (alpha,cl,cm), plus
the inputs (naca0012.dat, naca2412.dat, naca4412.dat, clarky.dat) and cases.csv (case, input,
operation as given to XFOIL). Needs `xfoil` and `gcc` on PATH; XFOIL runs through
tools/xfoil_reference.py's runner (its floating-point-trap shim included).
"""
import argparse
import os
import shutil
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import xfoil_reference  # noqa: E402  (the repository's XFOIL runner, beside this script)

# Inputs: name in the output folder -> (XFOIL name line, source).
#   "naca DDDD" sources are XFOIL's own NACA buffer airfoil (NACA DDDD, PCOP, SAVE);
#   file sources are copied.
INPUTS = {
    "naca0012": ("NACA 0012", "naca 0012"),
    "naca2412": ("NACA 2412", "naca 2412"),
    "naca4412": ("NACA 4412", "naca 4412"),
    "clarky": ("Clark Y", os.path.join(ROOT, "geometry", "clarky.dat")),
}

# (case, input, operation): "tset T C" (C may be "-": thickness only), "tgap GAP BLEND",
# "flap X Y DEG", "intx OTHER FRACTION" (OTHER one of INPUTS).
CASES = [
    ("naca2412_tset_0.15_0.03", "naca2412", "tset 0.15 0.03"),
    ("naca2412_tset_0.09", "naca2412", "tset 0.09 -"),
    ("clarky_tset_0.24", "clarky", "tset 0.24 -"),
    ("clarky_tset_0.44", "clarky", "tset 0.44 -"),
    ("naca2412_tgap_0.01_0.5", "naca2412", "tgap 0.01 0.5"),
    ("naca2412_tgap_0_0.2", "naca2412", "tgap 0 0.2"),
    ("clarky_tgap_0.005_1", "clarky", "tgap 0.005 1"),
    ("naca2412_flap_0.75_0_10", "naca2412", "flap 0.75 0 10"),
    ("naca2412_flap_0.75_0_-10", "naca2412", "flap 0.75 0 -10"),
    ("naca0012_flap_0.8_0_1", "naca0012", "flap 0.8 0 1"),
    ("naca2412_flap_0.7_-0.05_20", "naca2412", "flap 0.7 -0.05 20"),
    ("naca4412_flap_0.7_0.1_15", "naca4412", "flap 0.7 0.1 15"),
    ("clarky_flap_0.75_0.02_-15", "clarky", "flap 0.75 0.02 -15"),
    ("naca0012_intx_naca2412_0.5", "naca0012", "intx naca2412 0.5"),
    ("clarky_intx_naca4412_0.3", "clarky", "intx naca4412 0.3"),
]

ALPHAS = [0.0, 4.0, 8.0]


def xfoil(commands, work):
    """Run XFOIL in `work` on `commands`; its console output."""
    return xfoil_reference.run_xfoil(commands + [""], work, "xfoil", None).stdout


def make_input(name, out):
    """Write input `name` as a Selig file (name line, then x y) into `out`."""
    label, source = INPUTS[name]
    target = os.path.join(out, name + ".dat")
    if source.startswith("naca "):
        work = tempfile.mkdtemp(prefix="xfgeo-")
        xfoil(["PLOP", "G F", "", "NACA " + source.split()[1], "PCOP", "SAVE foil.dat", "QUIT"],
              work)
        lines = open(os.path.join(work, "foil.dat")).read().splitlines()[1:]
        shutil.rmtree(work, ignore_errors=True)
    else:
        lines = open(source).read().splitlines()[1:]
    with open(target, "w") as f:
        f.write(label + "\n" + "\n".join(l for l in lines if l.strip()) + "\n")


def run_case(case, source, operation, out):
    """Apply `operation` to input `source` in XFOIL; write <case>.dat and <case>_inviscid.csv."""
    work = tempfile.mkdtemp(prefix="xfgeo-")
    shutil.copy(os.path.join(out, source + ".dat"), os.path.join(work, "in.dat"))
    words = operation.split()
    commands = ["PLOP", "G F", "", "LOAD in.dat"]
    if words[0] == "intx":
        shutil.copy(os.path.join(out, words[1] + ".dat"), os.path.join(work, "other.dat"))
        commands += ["INTX", "F", "in.dat", "F", "other.dat", words[2], "blend", "PCOP"]
    else:
        commands.append("GDES")
        if words[0] == "tset":
            if words[2] == "-":
                # Thickness only: <return> at the camber prompt keeps the camber.
                commands += ["TSET " + words[1], ""]
            else:
                commands.append("TSET %s %s" % (words[1], words[2]))
        elif words[0] == "tgap":
            commands.append("TGAP %s %s" % (words[1], words[2]))
        elif words[0] == "flap":
            commands.append("FLAP %s %s %s" % (words[1], words[2], words[3]))
        else:
            sys.exit("unknown operation " + operation)
        commands += ["X", ""]
    commands += ["SAVE result.dat", "PPAR", "N 160", "", "", "PANE", "OPER", "PACC",
                 "polar.txt", ""]
    commands += ["ALFA %g" % a for a in ALPHAS]
    commands += ["PACC", "", "QUIT"]
    log = xfoil(commands, work)
    result = os.path.join(work, "result.dat")
    if not os.path.exists(result):
        sys.exit("%s: XFOIL wrote no airfoil\n%s" % (case, log[-3000:]))
    shutil.copy(result, os.path.join(out, case + ".dat"))
    rows = []
    for line in open(os.path.join(work, "polar.txt")):
        fields = line.split()
        try:
            values = [float(v) for v in fields[:5]]
        except ValueError:
            continue
        if len(values) == 5:
            rows.append("%g,%s,%s" % (values[0], fields[1], fields[4]))
    if len(rows) != len(ALPHAS):
        sys.exit("%s: %d of %d inviscid points\n%s" % (case, len(rows), len(ALPHAS), log[-3000:]))
    with open(os.path.join(out, case + "_inviscid.csv"), "w") as f:
        f.write("alpha,cl,cm\n" + "\n".join(rows) + "\n")
    shutil.rmtree(work, ignore_errors=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", required=True, help="output folder")
    args = parser.parse_args()
    if not shutil.which("xfoil"):
        sys.exit("xfoil not found (Debian: apt-get install xfoil)")
    os.makedirs(args.out, exist_ok=True)
    for name in INPUTS:
        make_input(name, args.out)
    with open(os.path.join(args.out, "cases.csv"), "w") as f:
        f.write("case,input,operation\n")
        for case, source, operation in CASES:
            f.write("%s,%s,%s\n" % (case, source, operation))
    for case, source, operation in CASES:
        run_case(case, source, operation, args.out)
        print(case)


if __name__ == "__main__":
    main()
