#!/usr/bin/env bash
# The adaptive pocket on a stress set of pockets the tests do not use (rounded rectangle,
# circle, hexagon with two islands, random blob, U, T, six islands 1 mm of room from the
# walls, slot 15 mm wide, triangle, comb), each judged by the independent sweep
# (swarf_pocket_sweep). Looks for gouges, residual material, full slots and failures on
# shapes nobody tuned for. Prints one line per pocket.
#   bench/pocket_stress.sh [build-dir] [tool-diameter] [stepover-fraction]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
d=${2:-10}
f=${3:-0.1}
swarf=$build/swarf
sweep=$build/bench/swarf_pocket_sweep
[ -x "$swarf" ] && [ -x "$sweep" ] || { echo "build first (scripts/build.sh)" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
python3 - "$tmp" <<'PY'
import json, math, random, sys
random.seed(7)
def circ(cx, cy, r, n=64):
    return [[cx + r * math.cos(2 * math.pi * k / n), cy + r * math.sin(2 * math.pi * k / n)] for k in range(n)]
def rrect(x0, y0, x1, y1, r, n=8):
    pts = []
    for cx, cy, a0 in ((x1 - r, y0 + r, -90), (x1 - r, y1 - r, 0), (x0 + r, y1 - r, 90), (x0 + r, y0 + r, 180)):
        for k in range(n + 1):
            a = math.radians(a0 + 90 * k / n)
            pts.append([cx + r * math.cos(a), cy + r * math.sin(a)])
    return pts
blob = []
for k in range(14):
    a, r = 2 * math.pi * k / 14, random.uniform(22, 40)
    blob.append([r * math.cos(a), r * math.sin(a)])
P = {
    "rrect": {"outer": rrect(0, 0, 60, 40, 3), "islands": []},
    "circle": {"outer": circ(0, 0, 30, 128), "islands": []},
    "hex2": {"outer": [[40 * math.cos(math.pi * k / 3), 40 * math.sin(math.pi * k / 3)] for k in range(6)],
             "islands": [circ(-12, 0, 6), [[8, -5], [20, -5], [20, 8], [8, 8]]]},
    "blob": {"outer": blob, "islands": []},
    "U": {"outer": [[0, 0], [70, 0], [70, 50], [50, 50], [50, 16], [20, 16], [20, 50], [0, 50]], "islands": []},
    "T": {"outer": [[30, 0], [50, 0], [50, 40], [80, 40], [80, 60], [0, 60], [0, 40], [30, 40]], "islands": []},
    "islands6": {"outer": [[0, 0], [80, 0], [80, 60], [0, 60]],
                 "islands": [circ(15 + 25 * i, 15 + 30 * j, 4, 32) for i in range(3) for j in range(2)]},
    "slot": {"outer": [[0, 0], [80, 0], [80, 15], [0, 15]], "islands": []},
    "triangle": {"outer": [[0, 0], [70, 0], [10, 50]], "islands": []},
    "comb": {"outer": [[0, 0], [90, 0], [90, 60], [75, 60], [75, 20], [60, 20], [60, 60], [45, 60], [45, 20],
                       [30, 20], [30, 60], [15, 60], [15, 20], [0, 20]], "islands": []},
}
for k, v in P.items():
    json.dump(v, open(f"{sys.argv[1]}/{k}.json", "w"))
PY
so=$(awk -v d="$d" -v f="$f" 'BEGIN { print d * f }')
target=$(awk -v d="$d" -v s="$so" 'BEGIN { r = d / 2; printf "%.4f", atan2(sqrt(1 - (1 - s / r)^2), 1 - s / r) * 180 / 3.141592653589793 }')
echo "flat end mill D$d, stepover $so mm (target $target deg)"
for n in rrect circle hex2 blob U T islands6 slot triangle comb; do
  if ! "$swarf" pocket "$tmp/$n.json" --tool "flat:$d" --stepover "$so" --depth 6 -o "$tmp/$n.nc" >"$tmp/log" 2>&1; then
    printf "%-9s FAILED: %s\n" "$n" "$(head -1 "$tmp/log")"
    continue
  fi
  printf "%-9s %s\n" "$n" "$("$sweep" "$tmp/$n.json" "$d" "$target" "$tmp/$n.nc")"
done
