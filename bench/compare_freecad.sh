#!/usr/bin/env bash
# Swarf's adaptive pocket against FreeCAD's adaptive clearing (libarea Adaptive2d, the engine
# of FreeCAD's Path/CAM Adaptive operation, Debian package freecad-python3, not a Swarf
# dependency), on the benchmark pockets, both judged by the same independent sweep
# (bench/pocket_sweep.cpp = tests/pocket/sweep_checker.cpp at 0.05 mm, or a twentieth of the
# stepover where finer). Prints one table; times at the feeds and on a machine of 1000 mm/s^2
# and 0.01 mm junction deviation (the sweep's defaults: it takes --accel, --junction-deviation).
#   bench/compare_freecad.sh [build-dir] [stepover-fraction]
#     (defaults build/release and 0.1: the radial stepover as a fraction of the diameter)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
frac=${2:-0.1}
source bench/pocket_common.sh
need_freecad
bench_shapes "$tmp"
cpu() { /usr/bin/time -f "%U %S" -o "$tmp/t" "$@" >/dev/null 2>&1; awk '{printf "%.3f", $1 + $2}' "$tmp/t"; }
printf "| pocket | generator | CPU s | within +-20 %% (arc) | (removal) | (arc, any material) | max eng. deg | slot mm | machining s | on a machine s | residual mm^2 | gouge mm | climb | reversals per m |\n"
printf "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n"
row() {  # name generator cpu sweep-line
  echo "$4" | awk -v n="$1" -v g="$2" -v c="$3" '{
    gsub(/,/, ""); gsub(/\(/, ""); gsub(/\)/, "");
    for (i = 1; i <= NF; i++) { v[$i] = $(i + 1); if ($i == "reversals") rpm = $(i + 2) }
    printf "| %s | %s | %s | %s %% | %s %% | %s %% | %s | %s | %s | %s | %s | %s | %s %% | %s |\n", n, g, c,
           v["within20"], v["removal"], v["anymaterial"], v["engagement"], v["slot"],
           v["machining"], v["machine"], v["residual"], v["gouge"], v["climb"], rpm }'
}
for spec in "${bench_pockets[@]}"; do
  IFS="|" read -r name file d <<<"$spec"
  so=$(awk -v d="$d" -v f="$frac" 'BEGIN { print f * d }')
  target=$(target_deg "$d" "$so")
  t=$(cpu "$swarf" pocket "$file" --tool "flat:$d" --stepover "$so" --depth 6 -o "$tmp/s.nc")
  row "$name" "Swarf adaptive" "$t" "$("$sweep" "$file" "$d" "$target" "$tmp/s.nc")"
  for fp in on off; do
    flag=""; [ $fp = off ] && flag=--no-finishing-profile
    line=$(python3 bench/freecad_adaptive.py "$file" "$d" "$frac" "$tmp/f.nc" $flag)
    t=$(echo "$line" | sed -E 's/.*cpu ([0-9.]+) s.*/\1/')
    row "$name" "FreeCAD Adaptive2d, finishing profile $fp" "$t" "$("$sweep" "$file" "$d" "$target" "$tmp/f.nc")"
  done
done
