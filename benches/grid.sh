#!/usr/bin/env bash
# Default rotor grid timing (the < 10 s target of the tables issue): the four shipped tables
# (NACA 8-H-12 and 23012, free and xtr 0.07; 3 904 points each), ROUNDS rounds, all cores.
# Prints wall and CPU time of every run, then the median, min and max per table, and checks
# that every run reproduces the shipped table byte for byte.
#
# The machine is shared and its speed drifts by up to 1.6x from hour to hour. With XFOIL
# installed (apt-get install -y xfoil gcc) each round also times XFOIL on the paper's free sweep
# (8-H-12, Re 1.9e6, M 0.41, alpha -4..12 step 0.5, through tools/xfoil_reference.py)
# as a yardstick of the machine's speed in that round; XFOIL=0 skips it.
set -euo pipefail
cd "$(dirname "$0")/.."
ROUNDS=${ROUNDS:-3}
XFREF=${XFREF:-tools/xfoil_reference.py}
cargo build --release --quiet --bin polargen
PG=${CARGO_TARGET_DIR:-target}/release/polargen
# The 1-minute load average (other jobs on the machine), printed with the results.
load_average() { cut -d' ' -f1 /proc/loadavg 2>/dev/null || echo unknown; }
load_start=$(load_average)
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
yardstick=0
if [ "${XFOIL:-1}" != 0 ] && command -v xfoil >/dev/null && [ -f "$XFREF" ]; then yardstick=1; fi

tables=(naca8h12_free naca8h12_xtr0.07 naca23012_free naca23012_xtr0.07)
for r in $(seq "$ROUNDS"); do
  if [ "$yardstick" = 1 ]; then
    t0=$(date +%s.%N)
    python3 "$XFREF" polar --airfoil geometry/naca8h12.dat --re 1.9e6 --mach 0.41 --xtr 1.0 \
      --alpha -4 12 0.5 --out "$tmp/xf.csv" >/dev/null
    t1=$(date +%s.%N)
    printf 'round %d  xfoil paper sweep  %.2f s\n' "$r" "$(awk "BEGIN{print $t1 - $t0}")"
  fi
  for t in "${tables[@]}"; do
    foil=${t%%_*}; setting=${t#*_}
    xtr=(); [ "$setting" = free ] || xtr=(--xtr "${setting#xtr}")
    /usr/bin/time -f '%e %U %S' -o "$tmp/time" \
      "$PG" --airfoil "$foil" "${xtr[@]}" --out "$tmp/$t.csv" 2>"$tmp/log"
    read -r wall user sys <"$tmp/time"
    conv=$(grep -o '[0-9]* of [0-9]* points converged' "$tmp/log")
    same=identical; cmp -s "$tmp/$t.csv" "polars/$t.csv" || same=DIFFERENT
    printf 'round %d  %-20s wall %6.2f s  cpu %6.2f s  %s  (%s to polars/)\n' \
      "$r" "$t" "$wall" "$(awk "BEGIN{print $user + $sys}")" "$conv" "$same"
    echo "$t $wall" >>"$tmp/walls"
  done
done
echo
for t in "${tables[@]}"; do
  grep "^$t " "$tmp/walls" | awk '{print $2}' | sort -n | awk -v t="$t" \
    '{v[NR]=$1} END {m = (NR % 2) ? v[(NR+1)/2] : (v[NR/2] + v[NR/2+1]) / 2;
      printf "%-20s median %6.2f s  min %6.2f s  max %6.2f s  (%d runs)\n", t, m, v[1], v[NR], NR}'
done
printf 'load average (1 min) at start %s, at end %s\n' "$load_start" "$(load_average)"
