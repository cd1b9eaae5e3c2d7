#!/usr/bin/env python3
"""Make polargen's XFOIL reference files: drive XFOIL 6.99 with a fixed keystroke stream.

Every file in tests/data/xfoil/ was made by one command of this script; that folder's
README.md lists them. Needs `xfoil` (Debian/Ubuntu package `xfoil`, version 6.99) and `gcc`.

Kinds of file
  polar     viscous polar as CSV: alpha,cl,cd,cdp,cm,xtr_top,xtr_bot (points XFOIL did not
            converge are absent, as in XFOIL's own polar file)
  inviscid  inviscid polar, the same columns (XFOIL leaves cd, xtr_top, xtr_bot at 0)
  paneled   XFOIL's paneled nodes (PANE, then PSAV: plain "x y" lines)
  buffer    XFOIL's NACA buffer airfoil before paneling (PCOP, then PSAV)
Both polar kinds also write, at any α of their path, XFOIL's boundary-layer dump (DUMP, with
--bl-dump ALPHA FILE) and pressure distribution (CPWR, with --cp-dump ALPHA FILE).

The α path of a polar is XFOIL's usual sweep: the α ≥ 0 of the list in ascending order with
warm starts, then (viscous) INIT, which discards the boundary layer, and the α < 0 in
descending order, again with warm starts.

--dry-run prints the keystrokes without running XFOIL; --keys FILE keeps them.

The Debian build of XFOIL traps floating-point exceptions and stops with SIGFPE at the first
operating point; the script compiles a one-line preload library that replaces gfortran's
trap setting with a no-op, so XFOIL runs as the upstream build does.
"""

import argparse
import os
import shutil
import subprocess
import sys
import tempfile

# Replaces libgfortran's _gfortran_set_fpe, which the Debian build calls to enable the traps.
NO_TRAP_SOURCE = "void _gfortran_set_fpe(int flags) { (void)flags; }\n"

POLAR_HEADER = "alpha,cl,cd,cdp,cm,xtr_top,xtr_bot"


def alpha_list(start, stop, step):
    """start, start + step, ... up to stop (inclusive), rounded to 6 decimals."""
    if step <= 0 or stop < start:
        raise SystemExit("--alpha A0 A1 DA needs A0 <= A1 and DA > 0")
    count = int(round((stop - start) / step))
    return [round(start + k * step, 6) for k in range(count + 1)]


def number(value):
    """A number as XFOIL reads it (shortest form, no trailing zeros)."""
    return "%g" % value


def naca_digits(airfoil):
    """The digits of "NACA dddd[d]", or None for a coordinate file."""
    words = airfoil.split()
    if len(words) == 2 and words[0].upper() == "NACA" and words[1].isdigit():
        return words[1]
    return None


def is_plain(path):
    """Whether a coordinate file has no name line (its first line holds two numbers)."""
    with open(path) as f:
        first = f.readline().replace(",", " ").split()
    if len(first) < 2:
        return False
    try:
        float(first[0]), float(first[1])
    except ValueError:
        return False
    return True


def geometry_keys(airfoil):
    """Keystrokes that put `airfoil` into XFOIL's buffer: a NACA designation or a file
    (copied into the work folder as foil.dat; LOAD asks for a name when the file has none).
    Graphics off first (PLOP, G F)."""
    keys = ["PLOP", "G F", ""]
    digits = naca_digits(airfoil)
    if digits is not None:
        return keys + ["NACA " + digits]
    keys.append("LOAD foil.dat")
    if is_plain(airfoil):
        keys.append(os.path.splitext(os.path.basename(airfoil))[0])
    return keys


def paneling_keys(panels):
    """PPAR with the node count, then PANE."""
    return ["PPAR", "N %d" % panels, "", "", "PANE"]


def sweep_keys(alphas, viscous, bl_dumps, cp_dumps):
    """ALFA commands of the α path, with DUMP / CPWR after the requested α."""
    up = sorted(a for a in alphas if a >= 0.0)
    down = sorted((a for a in alphas if a < 0.0), reverse=True)
    keys = []

    def visit(a):
        keys.append("ALFA " + number(a))
        for at, name in bl_dumps:
            if abs(at - a) < 1e-9:
                keys.append("DUMP " + name)
        for at, name in cp_dumps:
            if abs(at - a) < 1e-9:
                keys.append("CPWR " + name)

    for a in up:
        visit(a)
    if down and up and viscous:
        keys.append("INIT")
    for a in down:
        visit(a)
    return keys


def polar_keys(args, viscous):
    """The whole session of a polar (viscous or inviscid)."""
    keys = geometry_keys(args.airfoil) + paneling_keys(args.panels) + ["OPER"]
    if viscous:
        keys += ["VISC " + number(args.re), "MACH " + number(args.mach), "ITER %d" % args.iter]
        keys.append("VPAR")
        if args.ncrit_top is None and args.ncrit_bot is None:
            keys.append("N " + number(args.ncrit))
        else:
            top = args.ncrit if args.ncrit_top is None else args.ncrit_top
            bot = args.ncrit if args.ncrit_bot is None else args.ncrit_bot
            keys += ["NT " + number(top), "NB " + number(bot)]
        xtr_bot = args.xtr if args.xtr_bot is None else args.xtr_bot
        keys += ["XTR %s %s" % (number(args.xtr), number(xtr_bot)), ""]
    else:
        keys.append("MACH " + number(args.mach))
    # Polar accumulation on, into polar.txt, no dump file.
    keys += ["PACC", "polar.txt", ""]
    alphas = alpha_list(*args.alpha)
    for at, _ in args.bl_dump + args.cp_dump:
        if not any(abs(at - a) < 1e-9 for a in alphas):
            raise SystemExit("dump α %g is not on the α path" % at)
    keys += sweep_keys(alphas, viscous, args.bl_dump, args.cp_dump)
    keys += ["PACC", "", "QUIT", ""]
    return keys


def nodes_keys(args, buffer):
    """The session writing XFOIL's paneled nodes, or its buffer airfoil (PCOP copies the
    buffer points to the current airfoil unchanged)."""
    keys = geometry_keys(args.airfoil)
    keys += ["PCOP"] if buffer else paneling_keys(args.panels)
    return keys + ["PSAV nodes.dat", "QUIT", ""]


def polar_csv(polar_file):
    """XFOIL's polar file as CSV text (first seven columns, in XFOIL's row order of α)."""
    rows = {}
    with open(polar_file) as f:
        for line in f:
            fields = line.split()
            if len(fields) < 7:
                continue
            try:
                values = [float(t) for t in fields[:7]]
            except ValueError:
                continue  # header lines
            rows[round(values[0], 4)] = values
    lines = [POLAR_HEADER]
    for alpha in sorted(rows):
        lines.append(",".join("%.6g" % v for v in rows[alpha]))
    return "\n".join(lines) + "\n", len(rows)


def no_trap_library():
    """The FPE-trap shim, compiled once per user into the temporary directory (kept, so that
    timing runs do not pay for the compiler); its path."""
    library = os.path.join(tempfile.gettempdir(), "polargen-xfoil-no-fpe-trap-%d.so" % os.getuid())
    if os.path.exists(library):
        return library
    build = tempfile.mkdtemp(prefix="xfoil-no-fpe-trap-")
    try:
        source = os.path.join(build, "no_fpe_trap.c")
        with open(source, "w") as f:
            f.write(NO_TRAP_SOURCE)
        made = os.path.join(build, "no_fpe_trap.so")
        subprocess.run(["gcc", "-shared", "-fPIC", "-o", made, source], check=True)
        os.replace(made, library)
    finally:
        shutil.rmtree(build, ignore_errors=True)
    return library


def run_xfoil(keys, work, xfoil, log):
    """Feed `keys` to XFOIL in folder `work`."""
    env = dict(os.environ, LD_PRELOAD=no_trap_library())
    done = subprocess.run([xfoil], input="\n".join(keys), text=True, cwd=work, env=env,
                          stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=3600)
    if log:
        with open(log, "w") as f:
            f.write(done.stdout)
    return done


def parse_args():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("kind", choices=["polar", "inviscid", "paneled", "buffer"])
    p.add_argument("--airfoil", required=True,
                   help='"NACA dddd" / "NACA ddddd" (XFOIL\'s generator) or a coordinate file')
    p.add_argument("--out", help="the polar CSV or the node file (a polar may have dumps only)")
    p.add_argument("--re", type=float, help="Reynolds number (polar)")
    p.add_argument("--mach", type=float, default=0.0)
    p.add_argument("--ncrit", type=float, default=9.0, help="VPAR N, both surfaces")
    p.add_argument("--ncrit-top", type=float, help="VPAR NT (upper surface), else --ncrit")
    p.add_argument("--ncrit-bot", type=float, help="VPAR NB (lower surface), else --ncrit")
    p.add_argument("--xtr", type=float, default=1.0, help="forced transition x/c (1 = free)")
    p.add_argument("--xtr-bot", type=float, help="lower-surface x/c, else --xtr")
    p.add_argument("--alpha", type=float, nargs=3, metavar=("A0", "A1", "DA"),
                   help="α from A0 to A1 in steps of DA [deg]")
    p.add_argument("--panels", type=int, default=160, help="PPAR N (default 160)")
    p.add_argument("--iter", type=int, default=200, help="ITER, Newton iterations (default 200)")
    p.add_argument("--bl-dump", nargs=2, action="append", default=[], metavar=("ALPHA", "FILE"),
                   help="write XFOIL's DUMP at ALPHA to FILE")
    p.add_argument("--cp-dump", nargs=2, action="append", default=[], metavar=("ALPHA", "FILE"),
                   help="write XFOIL's CPWR at ALPHA to FILE")
    p.add_argument("--keys", help="also write the keystrokes sent to XFOIL to this file")
    p.add_argument("--log", help="write XFOIL's terminal output to this file")
    p.add_argument("--dry-run", action="store_true", help="print the keystrokes, run nothing")
    p.add_argument("--xfoil", default="xfoil", help="the XFOIL program (default: xfoil)")
    args = p.parse_args()
    args.bl_dump = [(float(a), f) for a, f in args.bl_dump]
    args.cp_dump = [(float(a), f) for a, f in args.cp_dump]
    polar = args.kind in ("polar", "inviscid")
    if polar and args.alpha is None:
        p.error("a polar needs --alpha A0 A1 DA")
    if args.kind == "polar" and (args.re is None or args.re <= 0):
        p.error("a viscous polar needs --re > 0")
    if not polar and (args.out is None or args.bl_dump or args.cp_dump):
        p.error("node files need --out and take no dumps")
    if polar and args.out is None and not (args.bl_dump or args.cp_dump):
        p.error("nothing to write: give --out, --bl-dump or --cp-dump")
    return args


def main():
    args = parse_args()
    polar = args.kind in ("polar", "inviscid")
    # Dumps are written inside the work folder under plain names, then copied out.
    outputs = []
    for kind, dumps in (("bl", args.bl_dump), ("cp", args.cp_dump)):
        for k, (alpha, target) in enumerate(dumps):
            inner = "%s_%d.txt" % (kind, k)
            outputs.append((inner, target))
            dumps[k] = (alpha, inner)
    if polar:
        keys = polar_keys(args, viscous=args.kind == "polar")
    else:
        keys = nodes_keys(args, buffer=args.kind == "buffer")
    if args.dry_run:
        print("\n".join(keys))
        return
    if args.keys:
        with open(args.keys, "w") as f:
            f.write("\n".join(keys) + "\n")
    xfoil = shutil.which(args.xfoil)
    if xfoil is None:
        sys.exit("%s not found (Debian/Ubuntu: apt-get install xfoil gcc)" % args.xfoil)
    work = tempfile.mkdtemp(prefix="xfoil-reference-")
    try:
        if naca_digits(args.airfoil) is None:
            shutil.copyfile(args.airfoil, os.path.join(work, "foil.dat"))
        run_xfoil(keys, work, xfoil, args.log)
        if polar:
            if args.out:
                text, count = polar_csv(os.path.join(work, "polar.txt"))
                with open(args.out, "w") as f:
                    f.write(text)
                print("%s: %d of %d points converged" %
                      (args.out, count, len(alpha_list(*args.alpha))))
        else:
            outputs.append(("nodes.dat", args.out))
        for inner, target in outputs:
            made = os.path.join(work, inner)
            if not os.path.exists(made):
                sys.exit("XFOIL wrote no %s for %s (see --log)" % (inner, target))
            shutil.copyfile(made, target)
            print(target)
    finally:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
