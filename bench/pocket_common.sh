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
