# Shared by the pocket benchmark scripts (sourced, with `build` set): the build's swarf and
# independent sweep, a temporary folder removed on exit, the FreeCAD check and the target
# engagement angle of a radial stepover.
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
