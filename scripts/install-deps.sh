#!/usr/bin/env bash
# Installs the Debian 12 packages Swarf needs to build, test and fuzz.
# Idempotent: quiet and quick when everything is already present.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  libpolyclipping-dev      # Clipper 6.4.2: polygon boolean operations and offsets
  nlohmann-json3-dev       # job files, tool libraries, pocket files
  libcli11-dev             # the swarf command line
  libpng-dev               # report pictures
  libgtest-dev libgmock-dev googletest
  libbenchmark-dev
  clang libclang-rt-14-dev # libFuzzer targets
)
# LinuxCNC's stand-alone RS-274 interpreter checks every dialect we write.
# Only the tests need it; SWARF_NO_RS274=1 skips it.
if [ "${SWARF_NO_RS274:-0}" != 1 ]; then packages+=(linuxcnc-uspace); fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
echo "install-deps: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
