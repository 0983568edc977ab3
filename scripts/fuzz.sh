#!/usr/bin/env bash
# Builds the libFuzzer targets with clang and runs each one for a few seconds,
# seeded from its kept corpus in fuzz/corpus/<parser>/. New inputs found go to a
# scratch folder; copy interesting ones into the corpus by hand.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-10}"
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$(nproc)"
for bin in build/fuzz/fuzz/*_fuzz; do
  name=$(basename "$bin" _fuzz)
  scratch=$(mktemp -d)
  echo "fuzz: $name for ${seconds}s"
  "$bin" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=0 \
    -artifact_prefix="$scratch/" "$scratch" "fuzz/corpus/$name" 2>&1 | tail -n 2
  rm -rf "$scratch"
done
