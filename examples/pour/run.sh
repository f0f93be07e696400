#!/usr/bin/env bash
# The pour as a user runs it, read back with VTK's own reader (examples/pour/check.py).
# Installs the distribution's VTK Python bindings and NumPy (which check.py reads the arrays
# with) when missing.
#
# Usage: examples/pour/run.sh [SPHERES [SECONDS]]   (CI: 200 spheres, 0.4 s of pour)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
cd "$root"
spheres="${1:-200}"
seconds="${2:-0.4}"
# The distribution's Python, which sees the distribution's VTK.
python=/usr/bin/python3
if ! "$python" -c "import vtkmodules.vtkIOXML, numpy" 2>/dev/null; then
  echo "VTK's Python bindings or NumPy are missing: installing the distribution's packages"
  apt-get update -qq \
    && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq python3-vtk9 python3-numpy >/dev/null
fi
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
cargo run --release -q -p pour -- --out "$out" --spheres "$spheres" --time "$seconds"
"$python" examples/pour/check.py "$out/pour.pvd" "$spheres"
