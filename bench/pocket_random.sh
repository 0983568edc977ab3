#!/usr/bin/env bash
# The adaptive pocket on random pockets nobody tuned for: star, polygon, rectangle, circle
# and L outlines up to 120 mm with 0-4 round or square islands (some nearer each other or
# a wall than the tool), flat end mills of 3-20 mm, stepovers of 5-40 % of the diameter.
# Each pocket is generated from its seed (the same seed gives the same pocket), run through
# `swarf pocket` and judged by the independent sweep (swarf_pocket_sweep). Prints one line
# per pocket and a summary: total residual, mean share within +-20 %, total full-slot
# length, deepest gouge, failures.
#   bench/pocket_random.sh [first-seed] [last-seed] [build-dir] [swarf pocket flags...]
# Flags after the build folder go to every `swarf pocket` (e.g. --conventional --stepdown 2
# --wall-stock 0.3); with --wall-stock the sweep judges the pocket shrunk by that stock.
set -euo pipefail
cd "$(dirname "$0")/.."
first=${1:-12}
last=${2:-60}
build=${3:-build/release}
extra=("${@:4}")
sweep_flags=()
for ((k = 0; k < ${#extra[@]}; ++k)); do
  [ "${extra[k]}" = --wall-stock ] && sweep_flags=(--wall-stock "${extra[k + 1]}")
done
source bench/pocket_common.sh
printf "%-5s %-4s %-6s %-6s %-3s %s\n" seed tool stepov shape isl "sweep of the G-code"
for s in $(seq "$first" "$last"); do
  read -r D so kind ni < <(python3 bench/random_pocket.py "$s" "$tmp/p.json")
  target=$(target_deg "$D" "$so")
  if ! "$swarf" pocket "$tmp/p.json" --tool "flat:$D" --stepover "$so" --depth 6 "${extra[@]}" -o "$tmp/p.nc" >"$tmp/log" 2>&1; then
    printf "%-5s D%-3s %-6s %-6s %-3s FAILED: %s\n" "$s" "$D" "$so" "$kind" "$ni" "$(tail -1 "$tmp/log")"
    continue
  fi
  printf "%-5s D%-3s %-6s %-6s %-3s %s\n" "$s" "$D" "$so" "$kind" "$ni" "$("$sweep" "${sweep_flags[@]}" "$tmp/p.json" "$D" "$target" "$tmp/p.nc")"
done | tee "$tmp/out"
sweep_summary "$tmp/out" pockets
