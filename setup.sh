#!/usr/bin/env bash
# Installs what iwb needs to build and test (Debian bookworm packages only) and builds into build/.
# Non-interactive and idempotent: packages already installed are not touched, the build is
# incremental. Usage: ./setup.sh
set -euo pipefail
cd "$(dirname "$0")"

PACKAGES=(
  cmake ninja-build g++ pkg-config
  libeigen3-dev catch2 libcli11-dev libtomlplusplus-dev nlohmann-json3-dev libfmt-dev libssl-dev
  liggghts libliggghts-dev yade gnuplot-nox libnlopt-cxx-dev
  chromium  # the report test opens the HTML in headless Chromium
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  echo "setup: installing ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
echo "setup: done; the workbench is build/iwb"
