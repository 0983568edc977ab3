#!/usr/bin/env bash
# Installs what is missing, builds, and runs every demo job in examples/.
set -euo pipefail
cd "$(dirname "$0")/.."
SWARF_NO_RS274=1 scripts/install-deps.sh
scripts/build.sh >/dev/null
out="${SWARF_DEMO_OUT:-out/demo}"
mkdir -p "$out"
for job in examples/*.json; do
  [[ "$job" == *tools*.json ]] && continue
  name=$(basename "$job" .json)
  echo "== $name"
  build/release/swarf run "$job" --output-dir "$out/$name"
done
echo "demo outputs are in $out/"
