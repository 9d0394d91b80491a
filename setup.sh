#!/usr/bin/env bash
# Installs what iwb needs to build and test (Debian bookworm packages only) and builds into build/.
# Non-interactive and idempotent: packages already installed are not touched, the build is
# incremental. Usage: ./setup.sh
set -euo pipefail
cd "$(dirname "$0")"
# Each phase is timed into build/budgets/setup.json for tools/budgets/budgets.py (issue 60).
t_start=$SECONDS
fresh_build=false
[ -f build/build.ninja ] || fresh_build=true

PACKAGES=(
  cmake ninja-build g++ clang pkg-config  # clang compiles iwb (build time, see below); g++ for libstdc++
  liblapack3  # the column's band solver (src/column), loaded when a column first solves
  libeigen3-dev catch2 libcli11-dev libtomlplusplus-dev nlohmann-json3-dev libfmt-dev libssl-dev
  liggghts libliggghts-dev yade gnuplot-nox libnlopt-cxx-dev
  mpi-default-dev  # mpi.h for liggghts_tri, LIGGGHTS with the triclinic fix (the periodic soil cell)
  libboost-dev  # Boost.Math's quantile functions (Latin hypercube samples, src/assessment)
  libtbb-dev    # the assessment's thousands of model runs on every core (src/assessment/evaluate.*)
  chromium  # the report test opens the HTML in headless Chromium
  libvtk9-dev  # VTK's legacy readers and XML writers (issue 21); beside YADE's python3-vtk9
  paraview     # the tests open the .pvd outputs in ParaView itself (pvpython, below)
  gfortran pybind11-dev python3-dev python3-numpy  # the C interface's Fortran and Python callers (src/c_api)
  clang-format  # the format check (tests/format/check.sh; Debian bookworm: version 14)
  slurmctld slurmd slurm-client munge  # a one-node Slurm for the tests of `iwb sweep --executor slurm` (issue 35)
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
t_packages=$SECONDS

# ParaView's Python (pvpython) is Debian's python3-paraview, which declares a conflict with
# python3-vtk9 (both ship a `vtkmodules` package) and so cannot be installed beside YADE. Its files
# work from a private prefix: the package is unpacked there, not installed (tools/paraview/pvpython).
PARAVIEW_PREFIX=/opt/iwb-paraview
if [ ! -x "$PARAVIEW_PREFIX/usr/bin/pvpython3.11" ]; then
  echo "setup: unpacking python3-paraview into $PARAVIEW_PREFIX"
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  download=$(mktemp -d)
  chmod 777 "$download"
  (cd "$download" && apt-get download -qq python3-paraview)
  $sudo dpkg -x "$download"/python3-paraview_*.deb "$PARAVIEW_PREFIX"
  rm -rf "$download"
fi

# Debian's Python (numpy, and the module the C interface's Python caller builds) is /usr/bin/python3
t_paraview=$SECONDS
# The compiler is clang (Debian's clang 14): on the 2 cores it builds iwb in 460 s of compiler time
# where GCC 12 takes 820 s (issue 60; CMakeLists.txt, IWB_ORCHESTRATION_OPT). A build directory
# configured with another compiler is configured afresh (CMake cannot switch one in place).
if [ -f build/CMakeCache.txt ] && ! grep -q '^CMAKE_CXX_COMPILER:[A-Z]*=.*clang++' build/CMakeCache.txt; then
  echo "setup: build/ was configured with another compiler; configuring it afresh with clang"
  rm -rf build/CMakeCache.txt build/CMakeFiles
  fresh_build=true
fi
CC=clang CXX=clang++ cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DPython3_EXECUTABLE=/usr/bin/python3
t_configure=$SECONDS
cmake --build build -j"$(nproc)"
t_build=$SECONDS
mkdir -p build/budgets
cat > build/budgets/setup.json <<JSON
{"when": "$(date -u +%Y-%m-%dT%H:%M:%SZ)", "cores": $(nproc), "packages_installed": $([ ${#missing[@]} -gt 0 ] && echo true || echo false),
 "fresh_build": $fresh_build, "packages_s": $((t_packages - t_start)), "paraview_s": $((t_paraview - t_packages)),
 "configure_s": $((t_configure - t_paraview)), "build_s": $((t_build - t_configure)), "total_s": $((t_build - t_start))}
JSON
echo "setup: done; the workbench is build/iwb"
