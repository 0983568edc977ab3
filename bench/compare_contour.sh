#!/usr/bin/env bash
# Adaptive pocketing against the contour-parallel baseline on speed, at the depths where the
# two are used. Contour-parallel rings start with a full slot (and slot again in concave
# corners), so a machinist limits their depth of cut to what the tool may slot, here half
# the diameter; the adaptive path never slots outside its entry and takes the whole depth in
# one layer. Both at the same feeds (1000 mm/min, rapids 5000), ø10 at 10 % stepover (the
# PCB-vice bar ø6), times on a machine of 1000 mm/s^2 and 0.01 mm junction deviation from
# each program's summary (`machine_time_s`); the contour's largest engagement and full-slot
# length from the independent sweep of its one-layer program.
#   bench/compare_contour.sh [build-dir]     (default build/release)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
source bench/pocket_common.sh
bench_shapes "$tmp"
machine_s() { "$@" 2>&1 | sed -nE 's/.*machine_time_s=([0-9.]+).*/\1/p'; }
printf "| pocket | depth mm | adaptive, 1 layer s | contour, 1 layer s | its largest engagement deg / slot mm | contour, stepdown D/2 s | adaptive faster than contour 1 layer / D/2 |\n"
printf "|---|---|---|---|---|---|---|\n"
for spec in "${bench_pockets[@]}"; do
  IFS="|" read -r name file d <<<"$spec"
  so=$(awk -v d="$d" 'BEGIN { print 0.1 * d }')
  half=$(awk -v d="$d" 'BEGIN { print 0.5 * d }')
  target=$(target_deg "$d" "$so")
  for depth in 6 20; do
    common=("$file" --tool "flat:$d" --stepover "$so" --depth "$depth")
    a=$(machine_s "$swarf" pocket "${common[@]}" -o "$tmp/a.nc")
    c1=$(machine_s "$swarf" contour "${common[@]}" --stepdown "$depth" -o "$tmp/c.nc")
    eng=$("$sweep" "$file" "$d" "$target" "$tmp/c.nc" |
      sed -nE 's/.*max engagement ([0-9.]+) deg, slot ([0-9.]+) mm.*/\1 \/ \2/p')
    c2=$(machine_s "$swarf" contour "${common[@]}" --stepdown "$half" -o "$tmp/c.nc")
    awk -v n="$name" -v z="$depth" -v a="$a" -v c1="$c1" -v e="$eng" -v c2="$c2" 'BEGIN {
      printf "| %s | %s | %.0f | %.0f | %s | %.0f | %.2fx / %.2fx |\n", n, z, a, c1, e, c2, c1 / a, c2 / a }'
  done
done
