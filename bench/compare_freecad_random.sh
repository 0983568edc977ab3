#!/usr/bin/env bash
# Swarf's adaptive pocket against FreeCAD's adaptive clearing (libarea Adaptive2d, with its
# finishing profile on, FreeCAD's default, and off) on the random pockets of
# bench/random_pocket.py, all three judged by the same independent sweep
# (swarf_pocket_sweep). Prints one line per pocket and a summary. Needs FreeCAD
# (sudo apt-get install freecad-python3; a benchmark tool, not a Swarf dependency).
#   bench/compare_freecad_random.sh [first-seed] [last-seed] [build-dir] [swarf pocket flags...]
set -euo pipefail
cd "$(dirname "$0")/.."
first=${1:-12}
last=${2:-60}
build=${3:-build/release}
extra=("${@:4}")
source bench/pocket_common.sh
need_freecad
# field NAME LINE: the number after NAME in a sweep line
field() { echo "$2" | sed -E "s/.*$1 ([0-9.]+).*/\1/"; }
# reversals per metre of floor path in a sweep line
per_m() { echo "$1" | sed -E "s/.*reversals [0-9]+ \(([0-9.]+) per m\).*/\1/"; }
for s in $(seq "$first" "$last"); do
  read -r D so kind ni < <(python3 bench/random_pocket.py "$s" "$tmp/p.json")
  frac=$(awk -v d="$D" -v s="$so" 'BEGIN { printf "%.4f", s / d }')
  target=$(target_deg "$D" "$so")
  /usr/bin/time -f "%U %S" -o "$tmp/t" "$swarf" pocket "$tmp/p.json" --tool "flat:$D" \
    --stepover "$so" --depth 6 "${extra[@]}" -o "$tmp/s.nc" >/dev/null 2>&1
  line="$s D$D so=$so $kind isl=$ni"
  add() {  # generator cpu sweep-line
    line="$line | $1 ${2}s w20 $(field within20 "$3") res $(field residual "$3") gouge $(field gouge "$3") slot $(field slot "$3") time $(field machining "$3") machine $(field machine "$3") lifts $(field lifts "$3") rev $(per_m "$3")"
  }
  add swarf "$(awk '{printf "%.3f", $1 + $2}' "$tmp/t")" "$("$sweep" "$tmp/p.json" "$D" "$target" "$tmp/s.nc")"
  for fp in on off; do
    flag=""
    [ $fp = off ] && flag=--no-finishing-profile
    out=$(python3 bench/freecad_adaptive.py "$tmp/p.json" "$D" "$frac" "$tmp/f.nc" $flag | tail -1)
    add "FC-$fp" "$(echo "$out" | sed -E 's/.*cpu ([0-9.]+) s.*/\1/')" \
      "$("$sweep" "$tmp/p.json" "$D" "$target" "$tmp/f.nc")"
  done
  echo "$line"
done | tee "$tmp/out"
python3 - "$tmp/out" <<'PY'
import re, statistics, sys
rows = []
for l in open(sys.argv[1]):
    parts = l.split(" | ")
    gens = {}
    for p in parts[1:]:
        m = re.match(r"(\S+) (\S+)s w20 (\S+) res (\S+) gouge (\S+) slot (\S+) time (\S+) machine (\S+) "
                     r"lifts (\S+) rev (\S+)", p)
        gens[m[1]] = [float(x) for x in m.groups()[1:]]
    rows.append(gens)
print("%d pockets: generator, CPU s in all, within +-20 %% mean / median, residual mm2 in all "
      "(pockets over 1 mm2), pockets with a gouge over 5 um, full slot mm in all, machining "
      "time s in all (at the feeds / on a machine of 1000 mm/s^2), lifts in all, reversals "
      "per m mean" % len(rows))
for g in ("swarf", "FC-on", "FC-off"):
    v = [r[g] for r in rows]
    print("  %-6s %6.1f  %5.1f / %5.1f %%  %8.0f (%d)  %d  %6.1f  %7.0f / %7.0f  %4d  %5.1f" % (
        g, sum(x[0] for x in v), statistics.mean(x[1] for x in v),
        statistics.median(x[1] for x in v), sum(x[2] for x in v), sum(x[2] > 1 for x in v),
        sum(x[3] > 0.005 for x in v), sum(x[4] for x in v), sum(x[5] for x in v),
        sum(x[6] for x in v), sum(x[7] for x in v), statistics.mean(x[8] for x in v)))
for g in ("FC-on", "FC-off"):
    for k, what in ((5, "machining time"), (6, "machine time")):
        ratios = [r[g][k] / r["swarf"][k] for r in rows if r["swarf"][k] > 0]
        print("  %s of %s over Swarf's, median per pocket: %.2f (Swarf faster on %d of %d)"
              % (what, g, statistics.median(ratios), sum(x > 1 for x in ratios), len(ratios)))
PY
