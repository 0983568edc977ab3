#!/usr/bin/env bash
# Installs what is missing, builds, and runs every demo job in examples/ (files named
# *job*.json), each into its own folder under out/demo/.
set -euo pipefail
cd "$(dirname "$0")/.."
SWARF_NO_RS274=1 scripts/install-deps.sh
scripts/build.sh >/dev/null
out="${SWARF_DEMO_OUT:-out/demo}"
mkdir -p "$out"
while IFS= read -r job; do
  name=$(basename "$job" .json)
  echo "== $job"
  build/release/swarf run "$job" --output-dir "$out/$name"
done < <(find examples -name '*job*.json' | sort)
echo
echo "demo outputs are in $out/:"
find "$out" -type f | sort | sed 's/^/  /'
