#!/usr/bin/env bash
# XFOIL 6.99 against polargen on nodes of the default rotor grid, node by node: NACA 8-H-12,
# free transition, alpha -10..20 step 0.5 marched from 0 both ways (both tools), one polar
# per run, polargen with --threads 1. Alternates the two tools node by node, ROUNDS times,
# and prints the CPU time (user + system, XFOIL's Python driver included) per converged
# point of each tool and their ratio, pooled over the nodes and rounds, with the converged
# counts. NODES lists Re:M pairs of the default grid (default: four spread over it); ITER
# is XFOIL's Newton cap (default 200, the reference script's; XFOIL's own is 20).
# PG=path times that polargen binary instead of building this tree's.
#
# Needs XFOIL: apt-get install -y xfoil gcc   (driven by tools/xfoil_reference.py)
set -euo pipefail
cd "$(dirname "$0")/.."
ROUNDS=${ROUNDS:-1}
ITER=${ITER:-200}
NODES=${NODES:-"1e5:0 4e5:0.2 1e6:0.4 2e6:0.3"}
XFREF=${XFREF:-tools/xfoil_reference.py}
command -v xfoil >/dev/null || { echo "xfoil not found: apt-get install -y xfoil gcc" >&2; exit 1; }
if [ -z "${PG:-}" ]; then
  cargo build --release --quiet --bin polargen
  PG=${CARGO_TARGET_DIR:-target}/release/polargen
fi
# The 1-minute load average (other jobs on the machine), printed with the results.
load_average() { cut -d' ' -f1 /proc/loadavg 2>/dev/null || echo unknown; }
load_start=$(load_average)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
cpu() { local out=$1; shift; /usr/bin/time -f '%U %S' -a -o "$out" "$@"; }
n_xf=0; n_pg=0
for r in $(seq "$ROUNDS"); do
  for node in $NODES; do
    re=${node%%:*}; mach=${node#*:}
    cpu "$tmp/cpu_xf" python3 "$XFREF" polar --airfoil geometry/naca8h12.dat --re "$re" --mach "$mach" \
      --xtr 1.0 --alpha -10 20 0.5 --iter "$ITER" --out "$tmp/xf.csv" >/dev/null
    cpu "$tmp/cpu_pg" "$PG" --airfoil naca8h12 --re "$re" --mach "$mach" --alpha=-10:20:0.5 \
      --threads 1 --out "$tmp/pg.csv" 2>/dev/null
    k_xf=$(grep -vc alpha "$tmp/xf.csv" || true); k_pg=$(awk -F, 'NR == 1 {for (i = 1; i <= NF; i++) if ($i == "converged") c = i; next}
      $c == "true" {n++} END {print n + 0}' "$tmp/pg.csv")
    printf 'round %d  Re %-5s M %-4s  converged: xfoil %2d, polargen %2d of 61\n' "$r" "$re" "$mach" "$k_xf" "$k_pg"
    n_xf=$((n_xf + k_xf)); n_pg=$((n_pg + k_pg))
  done
done
c_xf=$(awk '{s += $1 + $2} END {print s}' "$tmp/cpu_xf")
c_pg=$(awk '{s += $1 + $2} END {print s}' "$tmp/cpu_pg")
printf 'XFOIL cap %d iterations; CPU per converged point: xfoil %.1f ms, polargen %.1f ms\n' \
  "$ITER" "$(awk "BEGIN{print 1000 * $c_xf / $n_xf}")" "$(awk "BEGIN{print 1000 * $c_pg / $n_pg}")"
printf 'CPU-time ratio per converged point: %.3f\n' "$(awk "BEGIN{print ($c_pg / $n_pg) / ($c_xf / $n_xf)}")"
printf 'load average (1 min) at start %s, at end %s\n' "$load_start" "$(load_average)"
