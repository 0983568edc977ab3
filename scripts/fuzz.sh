#!/usr/bin/env bash
# Builds the libFuzzer targets with clang and runs each one for a few seconds, seeded from
# its kept corpus in fuzz/corpus/<parser>/. New inputs go to a scratch folder (copy the
# interesting ones into the corpus by hand); a crashing input is kept in build/fuzz/crashes/.
set -euo pipefail
shopt -s nullglob
cd "$(dirname "$0")/.."
seconds="${1:-10}"
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$(nproc)" >/dev/null
mkdir -p build/fuzz/crashes
status=0
for bin in build/fuzz/fuzz/*_fuzz; do
  name=$(basename "$bin" _fuzz)
  scratch=$(mktemp -d)
  log="build/fuzz/$name.log"
  if "$bin" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=0 \
      -artifact_prefix="build/fuzz/crashes/$name-" "$scratch" "fuzz/corpus/$name" >"$log" 2>&1; then
    echo "fuzz $name: $(grep -Eo 'Done [0-9]+ runs' "$log" | tail -n 1) in ${seconds}s, no crash"
  else
    echo "fuzz $name: FAILED, input kept in build/fuzz/crashes/" >&2
    tail -n 40 "$log" >&2
    status=1
  fi
  rm -rf "$scratch"
done
exit $status
