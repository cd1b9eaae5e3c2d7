#!/usr/bin/env bash
# Side-by-side timing of polargen and XFOIL 6.99 on the same two sweeps:
# NACA 8-H-12, Re 1.9e6, M 0.41, alpha -4..12 step 0.5, free transition and xtr 0.07.
# Runs each tool ROUNDS times, alternating, and prints the ratio of the total times.
# ITER sets XFOIL's Newton iteration cap (default 200, the reference script's; XFOIL's own
# default is 20). The wall-time ratio is the issue's measure; on a loaded, shared machine the
# CPU-time ratio (user + system, XFOIL's Python driver included) is the steadier one.
# PG=path times that polargen binary instead of building this tree's.
#
# Needs XFOIL: apt-get install -y xfoil gcc   (driven by tools/xfoil_reference.py)
set -euo pipefail
cd "$(dirname "$0")/.."
ROUNDS=${ROUNDS:-5}
XFREF=${XFREF:-tools/xfoil_reference.py}
command -v xfoil >/dev/null || { echo "xfoil not found: apt-get install -y xfoil gcc" >&2; exit 1; }
[ -f "$XFREF" ] || { echo "missing $XFREF" >&2; exit 1; }
ITER=${ITER:-200}
if [ -z "${PG:-}" ]; then
  cargo build --release --quiet --bin polargen
  PG=${CARGO_TARGET_DIR:-target}/release/polargen
fi
# The 1-minute load average (other jobs on the machine), printed with the results.
load_average() { cut -d' ' -f1 /proc/loadavg 2>/dev/null || echo unknown; }
load_start=$(load_average)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT

now() { date +%s.%N; }
# CPU seconds (user + system, children included) of a command, appended to file $1.
cpu() { local out=$1; shift; /usr/bin/time -f '%U %S' -a -o "$out" "$@"; }
t_xf=0; t_pg=0
for r in $(seq "$ROUNDS"); do
  for xtr in 1.0 0.07; do
    t0=$(now)
    cpu "$tmp/cpu_xf" python3 "$XFREF" polar --airfoil geometry/naca8h12.dat --re 1.9e6 --mach 0.41 --xtr $xtr \
      --alpha -4 12 0.5 --iter "$ITER" --out "$tmp/xf_$xtr.csv" >/dev/null
    t1=$(now)
    cpu "$tmp/cpu_pg" "$PG" --airfoil naca8h12 --re 1.9e6 --mach 0.41 --xtr $xtr --alpha -4:12:0.5 \
      --threads 1 --out "$tmp/pg_$xtr.csv" 2>/dev/null
    t2=$(now)
    t_xf=$(awk "BEGIN{print $t_xf + $t1 - $t0}"); t_pg=$(awk "BEGIN{print $t_pg + $t2 - $t1}")
  done
done
n_xf=$(( $(cat "$tmp"/xf_*.csv | grep -vc alpha) ))
n_pg=$(( $(cat "$tmp"/pg_*.csv | grep -c ',true') ))
printf 'rounds: %d (2 sweeps of 33 points each per round), XFOIL cap %d iterations\n' "$ROUNDS" "$ITER"
printf 'converged points per round: xfoil %d, polargen %d\n' "$n_xf" "$n_pg"
printf 'per converged point: xfoil %.2f ms, polargen %.2f ms\n' \
  "$(awk "BEGIN{print 1000 * $t_xf / ($ROUNDS * $n_xf)}")" "$(awk "BEGIN{print 1000 * $t_pg / ($ROUNDS * $n_pg)}")"
printf 'time ratio polargen/xfoil: %.3f\n' "$(awk "BEGIN{print $t_pg / $t_xf}")"
printf 'ratio per converged point: %.3f\n' "$(awk "BEGIN{print ($t_pg / $n_pg) / ($t_xf / $n_xf)}")"
c_xf=$(awk '{s += $1 + $2} END {print s}' "$tmp/cpu_xf")
c_pg=$(awk '{s += $1 + $2} END {print s}' "$tmp/cpu_pg")
printf 'CPU-time ratio per converged point (robust to load): %.3f\n' \
  "$(awk "BEGIN{print ($c_pg / $n_pg) / ($c_xf / $n_xf)}")"
printf 'load average (1 min) at start %s, at end %s\n' "$load_start" "$(load_average)"
