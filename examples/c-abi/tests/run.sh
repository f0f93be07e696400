#!/usr/bin/env bash
# The C ABI from C and Fortran: builds the static and shared libraries, compiles the C Kharaz
# sweep against each and the Fortran single impact against the static one, and checks that every
# printed digit equals the Rust run's. Installs gcc/gfortran from the distribution when missing and
# says what it skipped if it cannot.
set -euo pipefail
cd "$(dirname "$0")/../../.."
out=target/ffi
mkdir -p "$out"

need() { # need COMMAND PACKAGE
  command -v "$1" >/dev/null && return 0
  echo "installing $2 for $1"
  (apt-get update -qq && apt-get install -y -qq "$2") >/dev/null 2>&1 || true
  command -v "$1" >/dev/null
}

cargo build --release -p soft-sphere-ffi
cargo run --release -q -p soft-sphere-ffi --example kharaz_reference > "$out/rust.txt"
lib=target/release

if need cc gcc; then
  cc -std=c99 -O2 -Wall -Wextra -Werror -Iexamples/c-abi/include examples/c-abi/c/kharaz.c \
    "$lib/libsoft_sphere_ffi.a" -lm -lpthread -ldl -o "$out/kharaz_static"
  "$out/kharaz_static" > "$out/c_static.txt"
  diff "$out/rust.txt" "$out/c_static.txt"
  cc -std=c99 -O2 -Iexamples/c-abi/include examples/c-abi/c/kharaz.c \
    -L"$lib" -lsoft_sphere_ffi -lm -o "$out/kharaz_shared"
  LD_LIBRARY_PATH="$lib" "$out/kharaz_shared" > "$out/c_shared.txt"
  diff "$out/rust.txt" "$out/c_shared.txt"
  echo "C (static and shared): 89 angles equal the Rust run to the last printed digit"
else
  echo "SKIPPED: no C compiler and gcc could not be installed"
fi

if need gfortran gfortran; then
  gfortran -O2 -J "$out" examples/c-abi/fortran/soft_sphere.f90 examples/c-abi/fortran/impact.f90 \
    "$lib/libsoft_sphere_ffi.a" \
    -lm -lpthread -ldl -o "$out/impact_fortran"
  "$out/impact_fortran" > "$out/fortran.txt"
  grep '^20 ' "$out/rust.txt" | diff - "$out/fortran.txt"
  echo "Fortran: the 20 degree impact equals the Rust run to the last printed digit"
else
  echo "SKIPPED: gfortran is missing and could not be installed"
fi
