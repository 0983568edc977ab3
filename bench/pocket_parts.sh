#!/usr/bin/env bash
# The adaptive pocket on outlines of real and machinist-drawn parts no test tuned for:
# slices of opencamlib's mould cavity (ktoolcav.stl, inches, at five heights; made by
# bench/slice_pocket.py from ../shared/data/real or tests/data) and, where openscad is
# installed, a 24-tooth gear with a keyed bore, a bracket (hull of three bosses with two
# holes and a slot) and a flower of eight lobes round a disc with four holes. Each at five
# tool / stepover pairs (ø3 at 10 %, ø6 at 20 %, ø10 at 10 % and 35 %, ø16 at 25 %), judged
# by the independent sweep (swarf_pocket_sweep). Prints one line per run and a summary.
#   bench/pocket_parts.sh [build-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
source bench/pocket_common.sh
stl=../shared/data/real/opencamlib_ktoolcav.stl
[ -f "$stl" ] || { echo "needs $stl (the shared sample parts)" >&2; exit 2; }
pockets=()
for z in -1.2 -0.5 0 1.0 1.5; do
  python3 bench/slice_pocket.py "$stl" "$z" 25.4 "$tmp/ktoolcav_z$z.json" >/dev/null
  pockets+=("$tmp/ktoolcav_z$z.json")
done
if command -v openscad >/dev/null; then
  cat >"$tmp/gear.scad" <<'SCAD'
$fn=96;
difference(){
  union(){ circle(r=34); for(i=[0:23]) rotate(i*15) polygon([[33,-3.2],[41,-1.6],[41,1.6],[33,3.2]]); }
  difference(){ circle(r=9); translate([7,-2]) square([4,4]); }
}
SCAD
  cat >"$tmp/bracket.scad" <<'SCAD'
$fn=64;
difference(){
  hull(){ circle(r=20); translate([70,10]) circle(r=12); translate([30,45]) circle(r=8); }
  circle(r=6); translate([70,10]) circle(r=4);
  hull(){ translate([28,10]) circle(r=3); translate([45,20]) circle(r=3); }
}
SCAD
  cat >"$tmp/flower.scad" <<'SCAD'
$fn=80;
difference(){
  union(){ circle(r=25); for(i=[0:7]) rotate(i*45) translate([28,0]) circle(r=10); }
  for(i=[0:3]) rotate(i*90+22.5) translate([14,0]) circle(r=3.5);
}
SCAD
  for n in gear bracket flower; do
    openscad -q -o "$tmp/$n.dxf" "$tmp/$n.scad"
    pockets+=("$tmp/$n.dxf")
  done
else
  echo "(openscad not installed: the gear, bracket and flower are left out)"
fi
printf "%-16s %-4s %-5s %s\n" pocket tool stepov "sweep of the G-code"
for f in "${pockets[@]}"; do
  for pair in "3 0.3" "6 1.2" "10 1.0" "10 3.5" "16 4.0"; do
    read -r d so <<<"$pair"
    name=$(basename "$f")
    if ! "$swarf" pocket "$f" --tool "flat:$d" --stepover "$so" --depth 6 -o "$tmp/p.nc" >"$tmp/log" 2>&1; then
      printf "%-16s D%-3s %-5s FAILED: %s\n" "${name%.*}" "$d" "$so" "$(tail -1 "$tmp/log")"
      continue
    fi
    printf "%-16s D%-3s %-5s %s\n" "${name%.*}" "$d" "$so" \
      "$("$sweep" "$f" "$d" "$(target_deg "$d" "$so")" "$tmp/p.nc")"
  done
done | tee "$tmp/out"
sweep_summary "$tmp/out" runs
