#!/usr/bin/env bash
# The reference scene in LAMMPS and in soft-sphere, on the same settled packing, one thread each:
# prints both loop times (min/median/max over repeats), the speed ratio, and checks that the
# physics agrees (kinetic energy and contacts per particle at the end).
#
# Usage: [RUSTFLAGS="-C target-cpu=x86-64-v3"] host-tests/lammps/compare.sh [SPHERES=10000|50000]
#        [REPEATS=3]
# The caller's RUSTFLAGS reach the build of scene_bench (each set of flags builds into its own
# target directory), and the report says which build it timed.
# Installs LAMMPS from the distribution's package (binary lmp) if it is missing.
set -euo pipefail
spheres="${1:-10000}"
repeats="${2:-3}"
root="$(cd "$(dirname "$0")/../.." && pwd)"
work="$root/target/lammps/$spheres"
mkdir -p "$work"
cd "$root"

if ! command -v lmp >/dev/null; then
  echo "LAMMPS (lmp) is missing: installing the distribution's lammps package"
  apt-get update -qq && apt-get install -y -qq lammps >/dev/null
fi

flags="${RUSTFLAGS:-}"
target="target/compare-$(printf '%s' "${flags:-portable}" | tr -c 'A-Za-z0-9' '_')"
echo "build: RUSTFLAGS='$flags' (target directory $target)"
RUSTFLAGS="$flags" CARGO_TARGET_DIR="$target" cargo build --release -q -p host-tests --bin scene_bench
bench="$target/release/scene_bench"

# Settle (cached), write the packing and the deck, and time our run.
"$bench" --spheres "$spheres" --repeat "$repeats" --lammps "$work" | tee "$work/ours.txt"

# LAMMPS, same packing, one thread, $repeats times.
times=()
for _ in $(seq "$repeats"); do
  (cd "$work" && OMP_NUM_THREADS=1 lmp -in in.scene -log log.lammps -screen none)
  times+=("$(sed -n 's/^Loop time of \([0-9.eE+-]*\) on 1 procs.*/\1/p' "$work/log.lammps")")
done
python3 - "$work" "$spheres" "${times[@]}" <<'PY'
import re, statistics, sys
work, n, times = sys.argv[1], int(sys.argv[2]), sorted(map(float, sys.argv[3:]))
ours = open(f"{work}/ours.txt").read()
o_min, o_med, o_max = map(float, re.search(r"min ([\d.]+) s median ([\d.]+) s max ([\d.]+) s", ours).groups())
o_ke, o_contacts = map(float, re.search(r"kinetic energy ([\d.e+-]+) J, contacts per particle ([\d.]+)", ours).groups())
log = open(f"{work}/log.lammps").read().splitlines()
row = None
for i, line in enumerate(log):
    if line.split()[:1] == ["Step"]:
        row = log[i + 2].split()  # the thermo line at the last step
ke_t, ke_r, contacts = float(row[1]), float(row[2]), float(row[3])
l_ke, l_contacts = ke_t + ke_r, contacts / n
l_med = statistics.median(times)
print(f"LAMMPS gran/hooke/history: loop time min {times[0]:.3f} s median {l_med:.3f} s max {times[-1]:.3f} s")
print(f"soft-sphere:               loop time min {o_min:.3f} s median {o_med:.3f} s max {o_max:.3f} s")
print(f"speed ratio (LAMMPS time / ours, median): {l_med / o_med:.3f}  (min/min {times[0] / o_min:.3f}, max/max {times[-1] / o_max:.3f})")
print(f"kinetic energy at the end: LAMMPS {l_ke:.4e} J, ours {o_ke:.4e} J ({100 * (o_ke / l_ke - 1):+.1f} %)")
print(f"contacts per particle:     LAMMPS {l_contacts:.4f}, ours {o_contacts:.4f} ({100 * (o_contacts / l_contacts - 1):+.2f} %)")
ok = abs(o_contacts / l_contacts - 1) < 0.02 and abs(o_ke / l_ke - 1) < 0.10
print("physics agrees (contacts within 2 %, kinetic energy within 10 %)" if ok else "PHYSICS DIFFERS")
sys.exit(0 if ok else 1)
PY
