#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite:
# unit and integration tests (ctest), then a short seeded run of every fuzz target.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
ctest --preset release -j "$(nproc)"
scripts/fuzz.sh "${SWARF_FUZZ_SECONDS:-10}"
