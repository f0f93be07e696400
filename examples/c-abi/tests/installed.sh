#!/usr/bin/env bash
# The C ABI as an engine developer meets it: installed into a temporary prefix
# (examples/c-abi/install.sh), then three hosts copied outside the repository and built against
# the installed files only: C through pkg-config, C++ through find_package, Fortran through the
# installed module. Each runs the Kharaz impact and must print the Rust run's digits.
#
# cargo-c is built once (`cargo install --locked cargo-c`, a few CPU-minutes) into the cache
# outside the clone ($SOFT_SPHERE_CACHE, default ~/.cache/soft-sphere) and reused.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
root="$(cd "$here/../.." && pwd)"
cache="${SOFT_SPHERE_CACHE:-$HOME/.cache/soft-sphere}"
export PATH="$cache/cargo-c/bin:$PATH"
# The newest cargo-c that builds with the Rust this machine has (1.95); a newer Rust takes a
# newer one.
cargo_c="0.10.24"

missing=()
for package in cmake g++ gfortran pkg-config; do
  dpkg -s "$package" >/dev/null 2>&1 || missing+=("$package")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing ${missing[*]}"
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}" >/dev/null
fi
if ! cargo cinstall --version >/dev/null 2>&1; then
  echo "building cargo-c into $cache/cargo-c (once)"
  cargo install --locked -q cargo-c --version "$cargo_c" --root "$cache/cargo-c"
fi

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
[ "${KEEP:-0}" = 1 ] && trap 'echo "kept $work"' EXIT
prefix="$work/prefix"
bash "$here/install.sh" "$prefix"
(cd "$root" && cargo run --release -q -p soft-sphere-ffi --example kharaz_reference) > "$work/rust.txt"
grep '^20 ' "$work/rust.txt" > "$work/rust20.txt"

# The hosts' sources, copied away: nothing below names a path into the repository.
mkdir -p "$work/hosts"
cp "$here/c/kharaz.c" "$here/cpp/impact.cpp" "$here/cpp/CMakeLists.txt" "$here/fortran/impact.f90" \
  "$work/hosts/"
cd "$work/hosts"
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
libdir="$(pkg-config --variable=libdir soft-sphere)"

# C through pkg-config, shared (its soname found through the run path) and static.
# (-lm is the host's own: it calls sin and cos.)
cc -std=c99 -O2 -Wall -Wextra -Werror kharaz.c $(pkg-config --cflags --libs soft-sphere) -lm \
  -Wl,-rpath,"$libdir" -o kharaz_shared
./kharaz_shared | diff "$work/rust.txt" -
cc -std=c99 -O2 kharaz.c $(pkg-config --cflags soft-sphere) "$libdir/libsoft_sphere.a" \
  $(pkg-config --static --libs-only-l soft-sphere | sed 's/-lsoft_sphere//') -lm -o kharaz_static
./kharaz_static | diff "$work/rust.txt" -
echo "C through pkg-config (shared and static): 89 angles equal the Rust run's digits"

# C++ through find_package.
cmake -S . -B cpp-build -D CMAKE_PREFIX_PATH="$prefix" -D CMAKE_BUILD_TYPE=Release > /dev/null
cmake --build cpp-build > /dev/null
./cpp-build/impact | diff "$work/rust20.txt" -
echo "C++ through find_package(soft_sphere CONFIG): the 20 degree impact equals the Rust run's digits"

# Fortran through the installed module (found on the include path pkg-config gives).
gfortran -O2 $(pkg-config --cflags soft-sphere) impact.f90 $(pkg-config --libs soft-sphere) \
  -Wl,-rpath,"$libdir" -o impact_fortran
./impact_fortran | diff "$work/rust20.txt" -
echo "Fortran through the installed module: the 20 degree impact equals the Rust run's digits"

# A package asked for a version it does not have is not found.
sed -i 's/find_package(soft_sphere 0.1 CONFIG REQUIRED)/find_package(soft_sphere 9.0 CONFIG REQUIRED)/' CMakeLists.txt
if cmake -S . -B cpp-newer -D CMAKE_PREFIX_PATH="$prefix" > /dev/null 2>&1; then
  echo "find_package(soft_sphere 9.0) was met by $(pkg-config --modversion soft-sphere)" >&2
  exit 1
fi
echo "find_package refuses a version the install does not have"
