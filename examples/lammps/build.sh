#!/usr/bin/env bash
# Builds LAMMPS from the distribution's own source package (MPI, GRANULAR, PLUGIN, shared
# libraries) into a cache outside the clone, reused when present, then the soft-sphere plugin
# against it and the Rust C ABI, in the clone's target directory. Prints, as its last three
# lines, lammps_source=PATH (the LAMMPS source tree), lmp=PATH and plugin=PATH.
#
# Usage: examples/lammps/build.sh [v3]   (cache: $SOFT_SPHERE_CACHE, default ~/.cache/soft-sphere)
# With v3, the kernel is compiled for x86-64-v3 (AVX2, FMA) into its own target directory and
# plugin build, beside the portable one.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
cache="${SOFT_SPHERE_CACHE:-$HOME/.cache/soft-sphere}"
mkdir -p "$cache"
say() { printf '%s\n' "$*" >&2; }

# 1. Build tools from the distribution.
missing=()
for package in cmake g++ dpkg-dev openmpi-bin libopenmpi-dev; do
  dpkg -s "$package" >/dev/null 2>&1 || missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  say "installing ${missing[*]}"
  apt-get update -qq >&2
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}" >&2
fi

# 2. The LAMMPS source of the distribution's own lammps package.
lammps_build="$cache/lammps-build"
lmp="$lammps_build/lmp"
if [ ! -x "$lmp" ]; then
  src="$(find "$cache" -maxdepth 3 -name CMakeLists.txt -path '*/cmake/*' -print -quit 2>/dev/null)"
  if [ -z "$src" ]; then
    if ! grep -rqs '^Types: deb-src' /etc/apt/sources.list.d/; then
      # A deb-src entry made by copying the machine's own apt source entry.
      entry="$(grep -lrs '^Types: deb$' /etc/apt/sources.list.d/*.sources | head -n 1 || true)"
      [ -n "$entry" ] || { say "no apt source entry to copy for deb-src"; exit 1; }
      sed 's/^Types: deb$/Types: deb-src/' "$entry" > /etc/apt/sources.list.d/soft-sphere-deb-src.sources
      apt-get update -qq >&2
    fi
    say "fetching the lammps source package into $cache"
    (cd "$cache" && apt-get source -qq lammps >&2)
    src="$(find "$cache" -maxdepth 3 -name CMakeLists.txt -path '*/cmake/*' -print -quit)"
  fi
  say "building LAMMPS (MPI, GRANULAR, PLUGIN, shared) in $lammps_build: a few CPU-minutes once"
  rm -rf "$lammps_build"
  cmake -S "$(dirname "$src")" -B "$lammps_build" -D CMAKE_BUILD_TYPE=Release \
    -D BUILD_MPI=on -D BUILD_OMP=off -D BUILD_SHARED_LIBS=on -D PKG_GRANULAR=on -D PKG_PLUGIN=on \
    -D CMAKE_CXX_FLAGS=-O2 >&2
  cmake --build "$lammps_build" -j "$(nproc)" >&2
fi

# 3. The Rust static library (the C ABI) and 4. the plugin against both.
variant="${1:-portable}"
case "$variant" in
  portable) target_dir="$root/target"; suffix="" ;;
  v3) target_dir="$root/target/v3"; suffix="-v3" ;;
  *) say "unknown build '$variant' (portable or v3)"; exit 1 ;;
esac
# The C ABI as an engine finds it: installed (examples/c-abi/install.sh, cargo-c) into a prefix
# under target/, found by the plugin's find_package. SOFT_SPHERE_BUILD_TREE=1 links the build
# tree's static library instead, for a machine without cargo-c.
flags=""
[ "$variant" = v3 ] && flags="-C target-cpu=x86-64-v3"
prefix="$target_dir/soft-sphere-prefix"
if [ "${SOFT_SPHERE_BUILD_TREE:-0}" = 1 ]; then
  (cd "$root" && RUSTFLAGS="$flags" CARGO_TARGET_DIR="$target_dir" \
    cargo build --release -q -p soft-sphere-ffi) >&2
  link=(-D SOFT_SPHERE_BUILD_TREE=ON -D SOFT_SPHERE_LIB="$target_dir/release/libsoft_sphere_ffi.a"
    -D SOFT_SPHERE_INCLUDE="$root/examples/c-abi/include")
else
  RUSTFLAGS="$flags" CARGO_TARGET_DIR="$target_dir" bash "$root/examples/c-abi/install.sh" "$prefix" >&2
  link=(-D SOFT_SPHERE_BUILD_TREE=OFF -D CMAKE_PREFIX_PATH="$prefix")
fi
plugin_build="$root/target/lammps-plugin-build$suffix"
# The source tree LAMMPS was built from (its headers, and its examples for check.sh).
lammps_source="$(realpath "$(grep -m1 '^lammps_SOURCE_DIR' "$lammps_build/CMakeCache.txt" | cut -d= -f2)/..")"
cmake -S "$here" -B "$plugin_build" -D CMAKE_BUILD_TYPE=Release \
  -D LAMMPS_SOURCE_DIR="$lammps_source/src" \
  -D LAMMPS_BINARY_DIR="$lammps_build" "${link[@]}" >&2
cmake --build "$plugin_build" -j "$(nproc)" >&2

echo "lammps_source=$lammps_source"
echo "lmp=$lmp"
echo "plugin=$plugin_build/softsphereplugin.so"
