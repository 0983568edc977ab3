#!/usr/bin/env bash
# End-to-end benchmark: runs the swarf CLI on the sample parts and prints one table
# (operation, input, size, wall time, quality figures from each run's summary.json).
# Needs a release build (scripts/build.sh) and python3 for the table. Record its output in
# bench/RESULTS.md when something that matters changes.
set -euo pipefail
cd "$(dirname "$0")/.."
swarf=build/release/swarf
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
threads="${SWARF_BENCH_THREADS:-1}"

row=0
run() {  # name input size-description -- swarf args...
  local name=$1 input=$2 size=$3
  shift 4
  local start end dir
  row=$((row + 1))
  dir="$out/$row-$name"
  start=$(date +%s%N)
  "$swarf" --quiet --threads "$threads" "$@" --report "$dir" >/dev/null
  end=$(date +%s%N)
  printf '%s\t%s\t%s\t%s\t%s\n' "$name" "$input" "$size" "$(((end - start) / 1000000))" "$dir/summary.json"
}

pocket=examples/l-pocket-islands.json
torus=examples/parts/filleted-torus-part.stl
kiri=examples/parts/kirimoto_pocket-test.stl
{
  run pocket "L-pocket + 2 islands" "100x80 mm, D10, 10% stepover, 1 layer" -- \
    pocket "$pocket" --tool flat:10 --stepover 1 --depth 3 --stepdown 3 -o "$out/p.nc"
  run contour "L-pocket + 2 islands" "100x80 mm, D10, 10% stepover, 1 layer" -- \
    contour "$pocket" --tool flat:10 --stepover 1 --depth 3 --stepdown 3 -o "$out/c.nc"
  run surface "torus part" "scan x, D8 ball, stepover 0.5, sampling 0.1, pitch 0.05" -- \
    surface "$torus" --tool ball:8 --stepover 0.5 --sampling 0.1 --pitch 0.05 -o "$out/s.nc"
  run dropcut "torus part" "exact drop-cutter, same grid" -- \
    dropcut "$torus" --tool ball:8 --stepover 0.5 --sampling 0.1 --csv "$out/d.csv"
  run dropcut "torus part" "exact drop-cutter, bull-nose D8 r2, same grid" -- \
    dropcut "$torus" --tool bull:8:2 --stepover 0.5 --sampling 0.1 --csv "$out/b.csv"
  run rest "torus part" "D8 ball, pitch 0.5" -- rest "$torus" --tool ball:8 --pitch 0.5
  run rest "torus part" "D8 ball, pitch 0.1 (the issue's example)" -- \
    rest "$torus" --tool ball:8 --pitch 0.1
  run waterline "torus part" "contour, D8 ball, stepdown 1, pitch 0.05" -- \
    surface "$torus" --tool ball:8 --pattern contour --stepdown 1 --pitch 0.05 -o "$out/w.nc"
  run rough "Kiri:Moto pocket test" "D10, 4/2/0.5 mm, GA" -- \
    rough "$kiri" --tool flat:10 --stepover 4 --stepdown 2 --stock-to-leave 0.5 --margin 10 -o "$out/r.nc"
  run simulate "seed 001 validation cut" "D8 ball, 3600 rpm, pitch 0.1" -- \
    simulate examples/sim/validation_cut.nc --tool ball:8 --stock box:0,0,0,50,30,20 --rpm 3600 --csv "$out/f.csv"
} >"$out/rows.tsv"

python3 - "$out/rows.tsv" <<'PY'
import json, sys
keys = {
  "pocket": ["machining_time_s", "machine_time_s", "cutting_length_mm", "air_length_mm", "engagement_within_20pct", "engagement_p5_deg", "engagement_p95_deg", "material_left_mm2"],
  "contour": ["machining_time_s", "machine_time_s", "cutting_length_mm", "air_length_mm", "lift_offs"],
  "surface": ["cl_points", "model_s", "finishing_s", "machining_time_s", "machine_time_s"],
  "dropcut": ["cl_points", "max_z_mm"],
  "rest": ["residue_area_mm2", "max_thickness_mm"],
  "waterline": ["model_s", "contour_s", "machining_time_s", "machine_time_s"],
  "rough": ["machining_time_s", "machine_time_s", "lift_offs", "air_length_mm", "total_length_mm", "regions"],
  "simulate": ["machining_time_s", "peak_force_n", "mean_force_n", "collisions"],
}
print("| operation | input | size | wall time (s) | quality figures |")
print("|---|---|---|---|---|")
for line in open(sys.argv[1]):
    name, inp, size, t, summary = line.rstrip("\n").split("\t")
    s = json.load(open(summary))
    figs = []
    for k in keys.get(name, []):
        if k in s:
            v = s[k]
            figs.append(f"{k}={v:.4g}" if isinstance(v, float) else f"{k}={v}")
    print(f"| {name} | {inp} | {size} | {int(t) / 1000:.3f} | {', '.join(figs)} |")
PY
