#!/usr/bin/env bash
# Builds the firmware for thumbv7em-none-eabihf, runs it under QEMU (mps2-an386, Cortex-M4 with
# FPU, semihosting), checks that its scene ends bit for bit where the host's does, and reports
# code size (.text of each law's contact routine and of the whole image) and stack use.
# Installs qemu-system-arm from the distribution when missing; says so if it cannot.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$here/../.."
out="$root/target/firmware"
mkdir -p "$out"

rustup target add thumbv7em-none-eabihf >/dev/null 2>&1 || true
(cd "$here" && cargo build --release)
elf="$here/target/thumbv7em-none-eabihf/release/firmware"

if ! command -v qemu-system-arm >/dev/null; then
  echo "installing qemu-system-arm"
  (apt-get update -qq && apt-get install -y -qq qemu-system-arm) >/dev/null 2>&1 || true
fi
if ! command -v qemu-system-arm >/dev/null; then
  echo "SKIPPED: qemu-system-arm is missing and could not be installed (firmware built only)"
  exit 0
fi

timeout 300 qemu-system-arm -cpu cortex-m4 -machine mps2-an386 -nographic \
  -semihosting-config enable=on,target=native -kernel "$elf" > "$out/qemu.txt"
cat "$out/qemu.txt"
steps=$(sed -n 's/^scene steps \([0-9]*\) .*/\1/p' "$out/qemu.txt")
(cd "$root" && cargo run --release -q -p host-tests --bin firmware_reference -- "$steps") > "$out/host.txt"
grep '^scene ' "$out/qemu.txt" | diff "$out/host.txt" -
echo "Cortex-M4F (QEMU) and host: the scene after $steps steps is bit for bit the same"

# Code size, from the symbol table (llvm-tools from rustup, else binutils' nm/size if present).
tools="$(rustc --print sysroot)/lib/rustlib/$(rustc -vV | sed -n 's/^host: //p')/bin"
rustup component add llvm-tools >/dev/null 2>&1 || true
nm="$tools/llvm-nm"; size="$tools/llvm-size"
if [ -x "$nm" ] && [ -x "$size" ]; then
  echo "code size (thumbv7em-none-eabihf, opt-level s, LTO):"
  "$nm" --print-size --size-sort --radix=d "$elf" | awk '/ss_contact_/ {printf "  %-24s %6d bytes of .text\n", $4, $2}'
  "$size" -A "$elf" | awk '$1 == ".text" {printf "  %-24s %6d bytes\n", "whole image .text", $2}'
else
  echo "SKIPPED: code size (llvm-tools not available)"
fi
