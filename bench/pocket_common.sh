# Shared by the pocket benchmark scripts (sourced, with `build` set): the build's swarf and
# independent sweep, a temporary folder removed on exit, the FreeCAD check, the target
# engagement angle of a radial stepover and the summary of a batch's sweep lines.
swarf=$build/swarf
sweep=$build/bench/swarf_pocket_sweep
[ -x "$swarf" ] && [ -x "$sweep" ] || { echo "build first (scripts/build.sh)" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# FreeCAD's Adaptive2d (Debian freecad-python3) is a benchmark tool, not a Swarf dependency.
need_freecad() {
  python3 -c 'import sys; sys.path.append("/usr/lib/freecad-python3/lib"); import area' \
    2>/dev/null || { echo "needs FreeCAD: sudo apt-get install freecad-python3" >&2; exit 2; }
}
# target_deg DIAMETER STEPOVER: acos(1 - stepover / R) in degrees.
target_deg() {
  awk -v d="$1" -v s="$2" 'BEGIN { r = d / 2; printf "%.4f", atan2(sqrt(1 - (1 - s / r)^2), 1 - s / r) * 180 / 3.141592653589793 }'
}
# bench_shapes DIR: the two benchmark pockets made in code, DIR/star.json (R50 / R24, five
# points) and DIR/islands.json (80 x 60 with six round islands 1 mm of room from the walls,
# the case where Algorithm 4 used to slot), and `bench_pockets`, the five benchmark pockets
# as "name|file|tool diameter".
bench_shapes() {
  bench_pockets=("L 100x80 + 2 islands, D10|tests/data/pocket/l_pocket_islands.json|10"
                 "Kiri:Moto 40x40, D10|tests/data/pocket/kirimoto_pocket.json|10"
                 "star R50/24, D10|$1/star.json|10"
                 "PCB-vice bar slice, D6|tests/data/pocket/pcbvicebar_slice.json|6"
                 "80x60 + 6 islands 1 mm from walls, D10|$1/islands.json|10")
  python3 - "$1/star.json" <<'PY'
import json, math, sys
pts = [[(50 if k % 2 == 0 else 24) * math.cos(math.pi * k / 5 + math.pi / 2),
        (50 if k % 2 == 0 else 24) * math.sin(math.pi * k / 5 + math.pi / 2)] for k in range(10)]
json.dump({"outer": pts, "islands": []}, open(sys.argv[1], "w"))
PY
  python3 - "$1/islands.json" <<'PY'
import json, math, sys
isl = [[[15 + 25 * i + 4 * math.cos(math.pi * k / 16), 15 + 30 * j + 4 * math.sin(math.pi * k / 16)]
        for k in range(32)] for i in range(3) for j in range(2)]
json.dump({"outer": [[0, 0], [80, 0], [80, 60], [0, 60]], "islands": isl}, open(sys.argv[1], "w"))
PY
}
# sweep_summary FILE NOUN: one line over the sweep lines of FILE (one run each, or FAILED):
# how many, failures (and how many of them a tool too large for the pocket), residual,
# gouge and full slot in all, the share within +-20 %, climb and reversals on average.
sweep_summary() {
  awk -v noun="$2" '/FAILED/ { f++; if (/tool too large/) big++; next }
     /gouge/ { for (i = 1; i <= NF; i++) { if ($i == "gouge") g = ($(i+1) > g ? $(i+1) : g);
                                            if ($i == "residual") r += $(i+1);
                                            if ($i == "within20") { w += $(i+1); n++ }
                                            if ($i == "slot") sl += $(i+1);
                                            if ($i == "climb") c += $(i+1);
                                            if ($i == "reversals") rv += substr($(i+2), 2) } }
     END { printf "%s %d, failed %d (%d of them a tool too large for the pocket), residual %.2f mm2 in all, within +-20 %% %.1f %% on average, full slot %.1f mm in all, deepest gouge %.3f mm, climb %.1f %% and %.1f reversals per m on average\n", noun, n + f, f, big, r, (n ? w / n : 0), sl, g, (n ? c / n : 0), (n ? rv / n : 0) }' "$1"
}
