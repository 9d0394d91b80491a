#!/usr/bin/env bash
# The installed C interface as a user builds against it: `cmake --install` into a fresh prefix, the
# plain C caller compiled with nothing but `pkg-config --cflags --libs iwb_interface`, run from
# elsewhere, its last line the same as the build tree's caller.
# Usage: installed_caller.sh BUILD_DIR WORK_DIR
set -euo pipefail
build=$1 work=$2
src=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work" && mkdir -p "$work"
cmake --install "$build" --prefix "$work/prefix" > /dev/null
libdir=$(ls -d "$work"/prefix/lib*/pkgconfig | head -1)
export PKG_CONFIG_PATH=$libdir
cc -std=c99 -Wall -Wextra -Werror -o "$work/caller" "$src/c_caller.c" $(pkg-config --cflags --libs iwb_interface) \
   -Wl,-rpath,"$(pkg-config --variable=libdir iwb_interface)"
params=$(cd "$src/../../data/params" && pwd)/table_5_1_evaluation.toml
installed=$(cd / && "$work/caller" "$params" | tail -1)
built=$("$build/tests/c_caller" "$params" | tail -1)
echo "installed: $installed"
[ "$installed" = "$built" ]
