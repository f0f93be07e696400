#!/usr/bin/env bash
# Installs the soft-sphere C ABI into PREFIX, as a C, C++ or Fortran engine links it:
#   PREFIX/lib/libsoft_sphere.so.*, libsoft_sphere.a      (cargo cinstall: versioned soname)
#   PREFIX/include/soft_sphere.h                          (the cbindgen header, with SS_VERSION_*)
#   PREFIX/lib/pkgconfig/soft-sphere.pc                   (cargo cinstall: Libs.private for -static)
#   PREFIX/lib/cmake/soft_sphere/soft_sphereConfig*.cmake (find_package(soft_sphere CONFIG))
#   PREFIX/include/soft_sphere.mod                        (gfortran's module, when gfortran is here)
#   PREFIX/share/soft-sphere/fortran/soft_sphere.f90      (the module's source, for other compilers)
#
# Usage: examples/c-abi/install.sh PREFIX
# Needs cargo-c (`cargo install --locked cargo-c`); docs/c-abi.md, "Installing".
set -euo pipefail
if [ $# -ne 1 ]; then
  echo "usage: $0 PREFIX" >&2
  exit 2
fi
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
mkdir -p "$1"
prefix="$(cd "$1" && pwd)"
libdir="$prefix/lib"
# cargo-c from PATH, or where CI keeps it (examples/c-abi/tests/installed.sh puts it there).
cache="${SOFT_SPHERE_CACHE:-$HOME/.cache/soft-sphere}"
if ! cargo cinstall --version >/dev/null 2>&1; then
  export PATH="$cache/cargo-c/bin:$PATH"
fi
if ! cargo cinstall --version >/dev/null 2>&1; then
  echo "cargo-c is missing: install it with 'cargo install --locked cargo-c'" >&2
  exit 1
fi

cd "$root"
cargo cinstall --release -p soft-sphere-ffi --prefix "$prefix" --libdir "$libdir"

# The CMake package: its paths relative to its own place, the static library's system
# libraries as cargo-c wrote them into the pkg-config file.
version="$(sed -n 's/^Version: //p' "$libdir/pkgconfig/soft-sphere.pc")"
IFS=. read -r major minor _ <<< "$version"
static_libs="$(sed -n 's/^Libs.private: //p' "$libdir/pkgconfig/soft-sphere.pc" \
  | tr ' ' '\n' | sed -n 's/^-l//p' | grep -vx 'c\|pthread' | paste -sd';' -)"
soname="$(objdump -p "$libdir/libsoft_sphere.so" | sed -n 's/^ *SONAME *//p')"
cmake_dir="$libdir/cmake/soft_sphere"
mkdir -p "$cmake_dir"
up="$(realpath -m --relative-to="$cmake_dir" "$prefix")"
relative_libdir="$(realpath -m --relative-to="$prefix" "$libdir")"
sed -e "s|@UP@|$up|" -e "s|@LIBDIR@|$relative_libdir|g" -e "s|@SONAME@|$soname|" \
  -e "s|@STATIC_LIBS@|$static_libs|" \
  "$here/cmake/soft_sphereConfig.cmake.in" > "$cmake_dir/soft_sphereConfig.cmake"
sed -e "s|@VERSION@|$version|" -e "s|@MAJOR@|$major|g" -e "s|@MINOR@|$minor|g" \
  "$here/cmake/soft_sphereConfigVersion.cmake.in" > "$cmake_dir/soft_sphereConfigVersion.cmake"

# The Fortran module: its source always, gfortran's compiled interface when gfortran is here.
mkdir -p "$prefix/share/soft-sphere/fortran"
cp "$here/fortran/soft_sphere.f90" "$prefix/share/soft-sphere/fortran/"
if command -v gfortran >/dev/null; then
  scratch="$(mktemp -d)"
  trap 'rm -rf "$scratch"' EXIT
  gfortran -c -J "$prefix/include" "$here/fortran/soft_sphere.f90" -o "$scratch/soft_sphere.o"
else
  echo "gfortran is missing: the Fortran module is installed as source only" >&2
fi
echo "installed soft-sphere $version into $prefix"
