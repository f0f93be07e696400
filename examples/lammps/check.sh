#!/usr/bin/env bash
# The soft-sphere LAMMPS plugin, checked inside LAMMPS (run by CI after build.sh):
#   1. Elghannay & Tafti's Kharaz impact and plate case with fix wall/soft/sphere aa against the
#      Rust validation run;
#   1b. Hertz-Mindlin (Chung & Ooi Test 5, two spheres) against LAMMPS's own pair granular;
#   2. the same physics as LAMMPS's own gran/hooke/history on a granular gas of equal spheres;
#   3. the reference scene on 1, 2 and 4 MPI ranks, and a stored spring carried between ranks;
#   4. speed inside the engine against the native style (printed, not asserted);
#   5. bad input stops LAMMPS with a clear ERROR.
# Ends with a line "N passed, M failed"; exits non-zero when a check failed.
set -uo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
work="$root/target/lammps-plugin"
mkdir -p "$work"
cd "$root"

built="$(bash "$here/build.sh")" || { echo "build.sh failed"; echo "0 passed, 1 failed"; exit 1; }
lmp="$(printf '%s\n' "$built" | sed -n 's/^lmp=//p')"
plugin="$(printf '%s\n' "$built" | sed -n 's/^plugin=//p')"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
passed=0
failed=0
result() { # name, 0|1, detail
  if [ "$2" -eq 0 ]; then passed=$((passed + 1)); echo "ok   $1: $3"; else failed=$((failed + 1)); echo "FAIL $1: $3"; fi
}
# `compare VALUE EXPECTED TOLERANCE`: relative difference within the tolerance.
compare() { python3 -c "import sys; a, b, t = map(float, sys.argv[1:]); sys.exit(0 if abs(a - b) <= t * abs(b) else 1)" "$@"; }
relative() { python3 -c "import sys; a, b = map(float, sys.argv[1:]); print(f'{abs(a - b) / abs(b):.2e}')" "$@"; }
run_lmp() { (cd "$work" && "$lmp" -log none -screen none -var plugin "$plugin" "$@" -echo none -nocite > /dev/null 2>&1) ; }

cargo build --release -q -p host-tests --bin lammps_cases --bin scene_bench

# 1. Kharaz and plate.
target/release/lammps_cases "$work/cases" "$plugin" 2>/dev/null
worst=0
kharaz_ok=0
for angle in $(seq 5 5 85); do
  line="$(cd "$work/cases" && "$lmp" -log none -in "kharaz_$angle.in" 2>&1 | grep '^RESULT')"
  u="$(echo "$line" | cut -d' ' -f2)"; w="$(echo "$line" | cut -d' ' -f3)"
  incoming="$(grep "^incoming_$angle," "$work/cases/expected.csv" | cut -d, -f2)"
  expected="$(grep "^kharaz_$angle," "$work/cases/expected.csv")"
  e_t="$(python3 -c "print($u / $incoming)")"; spin="$(python3 -c "print(abs($w))")"
  for pair in "$e_t $(echo "$expected" | cut -d, -f2)" "$spin $(echo "$expected" | cut -d, -f3)"; do
    # shellcheck disable=SC2086
    compare $pair 1e-6 || kharaz_ok=1
    # shellcheck disable=SC2086
    worst="$(python3 -c "print(max($worst, float('$(relative $pair)')))")"
  done
done
result "kharaz in LAMMPS (aa, 5-85 deg)" "$kharaz_ok" "e_t and spin equal the Rust validation run within $worst relative (bound 1e-6)"
line="$(cd "$work/cases" && "$lmp" -log none -in plate.in 2>&1 | grep '^RESULT')"
u="$(echo "$line" | cut -d' ' -f2)"; w="$(echo "$line" | cut -d' ' -f3)"
expected="$(grep '^plate,' "$work/cases/expected.csv")"
w_ratio="$(python3 -c "print($w * 5e-3 / 1.0)")"
plate_ok=0
compare "$u" "$(echo "$expected" | cut -d, -f2)" 1e-4 && compare "$w_ratio" "$(echo "$expected" | cut -d, -f3)" 1e-4 \
  && compare "$u" 0.714285714 5e-3 && compare "$w_ratio" 0.714285714 5e-3 || plate_ok=1
result "plate in LAMMPS (aa)" "$plate_ok" "u/u0 $u, w R/u0 $w_ratio (5/7 within 0.5 %, the Rust run within 1e-4)"

# The last thermo row of a log: "step ke rotational contacts".
last_row() { python3 - "$1" <<'PY'
import sys
lines = open(sys.argv[1]).read().splitlines()
row = None
for i, line in enumerate(lines):
    if line.split()[:1] == ["Step"]:
        j = i + 1
        while j < len(lines) and lines[j].split() and lines[j].split()[0].isdigit():
            row = lines[j].split()
            j += 1
print(" ".join(row))
PY
}

# 1b. Hertz-Mindlin beside LAMMPS's own pair granular (hertz/material, mindlin_rescale/force):
# Chung & Ooi's Test 5 as two identical steel spheres. LAMMPS's torque arm is R - delta/2, the
# kernel's R; the bound covers that.
hm_ok=0
hm_worst=0
for k in 0 1 2 3 4 5; do
  ours="$(grep "^chung_ooi_test5_$k," "$work/cases/expected.csv" | cut -d, -f3)"
  theirs="$(cd "$work/cases" && "$lmp" -log none -in "chung_ooi_test5_$k.in" 2>&1 | grep '^RESULT' | cut -d' ' -f2)"
  difference="$(python3 -c "print(abs(float('$ours') - float('${theirs:-nan}')))")"
  python3 -c "import sys; sys.exit(0 if float('$difference') <= 0.02 else 1)" || hm_ok=1
  hm_worst="$(python3 -c "print(max($hm_worst, float('$difference')))")"
done
result "hertz-mindlin vs pair granular (Chung & Ooi test 5, psi 0.1-10)" "$hm_ok" \
  "V_s'/(mu V_n') within $hm_worst of LAMMPS (bound 0.02)"

# 2. The same physics as the native style: a granular gas of 1,000 equal spheres, periodic, no
# walls (the native gamma_n is per unit mass, so it matches e only for equal masses).
mass_star="$(python3 -c "import math; print(2500 * math.pi / 6 * 1e-9 / 2)")"
gamma_n="$(python3 -c "
import math
l = math.log(0.9); zeta = -l / math.sqrt(math.pi ** 2 + l * l)
print(2 * zeta * math.sqrt(1000 / $mass_star))")"
gas() { # name, pair_style arguments
  cat > "$work/gas_$1.in" <<GAS
units si
atom_style sphere
atom_modify map array
boundary p p p
newton off
comm_modify vel yes
lattice sc 2.2e-3
region box block 0 10 0 10 0 10
create_box 1 box
create_atoms 1 box
set type 1 diameter 1e-3 density 2500
velocity all create 3e16 4928 loop geom mom yes
plugin load \${plugin}
pair_style $2
pair_coeff * *
neighbor 1e-4 bin
neigh_modify every 1 delay 0 check yes
fix integrate all nve/sphere
timestep 2e-6
compute rotational all erotate/sphere
compute contacts all contact/atom
compute total_contacts all reduce sum c_contacts
thermo_style custom step ke c_rotational c_total_contacts
thermo_modify format float %.16e
thermo 1000
run 3000
GAS
  run_lmp -in "gas_$1.in" -log "gas_$1.log"
  last_row "$work/gas_$1.log"
}
k_t="$(python3 -c "print(2 / 7 * 1000)")"
native_frictionless="$(gas native_frictionless "gran/hooke/history 1000 $k_t $gamma_n 0 0 1")"
ours_frictionless="$(gas frictionless "soft/sphere frictionless 1000 0.9 $k_t 0.5 0")"
native_friction="$(gas native_friction "gran/hooke/history 1000 $k_t $gamma_n $(python3 -c "print(0.5 * $gamma_n)") 0.5 1")"
ours_luding="$(gas luding "soft/sphere aa/luding 1000 0.9 $k_t 0.5 0.5")"
ours_aa="$(gas aa "soft/sphere aa 1000 0.9 $k_t 0.5 0.5")"
energy() { python3 -c "import sys; r = sys.argv[1].split(); print(float(r[1]) + float(r[2]))" "$1"; }
contacts() { echo "$1" | cut -d' ' -f4; }
ke_native="$(energy "$native_frictionless")"; ke_ours="$(energy "$ours_frictionless")"
compare "$ke_ours" "$ke_native" 1e-9; result "frictionless vs gran/hooke/history xmu 0 (gas)" $? \
  "final kinetic energy $ke_ours vs $ke_native J, $(relative "$ke_ours" "$ke_native") relative (bound 1e-9)"
ke_native="$(energy "$native_friction")"; ke_ours="$(energy "$ours_luding")"; ke_aa="$(energy "$ours_aa")"
c_native="$(contacts "$native_friction")"; c_ours="$(contacts "$ours_luding")"
# The native style differs from Luding's rule by design in two places: it only projects the stored
# spring into the tangent plane (the kernel turns it, keeping its length), and a contact that
# slides with a zero stored spring (the first step of an oblique touch) gets no tangential force
# there. The kinetic energies therefore agree to about 1e-5, not 1e-6; the contact count exactly.
luding_ok=1
compare "$ke_ours" "$ke_native" 1e-4 && [ "$c_ours" = "$c_native" ] && luding_ok=0
result "aa/luding vs gran/hooke/history (gas, 3000 steps)" "$luding_ok" \
  "final kinetic energy $(relative "$ke_ours" "$ke_native") relative (bound 1e-4; 1e-6 is not reached, see above), contacts $c_ours vs $c_native; the plain cap aa: $(relative "$ke_aa" "$ke_native")"

# 3. MPI: the reference scene (10,000 settled spheres on a floor) with aa, 2,000 steps, on 1, 2
# and 4 ranks.
target/release/scene_bench --steps 2000 --repeat 1 --lammps "$work/mpi" > /dev/null 2>&1
rows=()
for ranks in 1 2 4; do
  (cd "$work/mpi" && mpirun -np "$ranks" "$lmp" -in in.plugin -var plugin "$plugin" -log "log.$ranks" -screen none > /dev/null 2>&1)
  rows+=("$(last_row "$work/mpi/log.$ranks")")
done
mpi_ok=0
detail=""
for k in 1 2; do
  a="$(energy "${rows[0]}")"; b="$(energy "${rows[$k]}")"
  compare "$b" "$a" 1e-9 || mpi_ok=1
  compare "$(contacts "${rows[$k]}")" "$(contacts "${rows[0]}")" 1e-9 || mpi_ok=1
  detail="$detail $((k * 2)) ranks: energy $(relative "$b" "$a"), contacts $(contacts "${rows[$k]}") vs $(contacts "${rows[0]}");"
done
result "reference scene on 1, 2, 4 ranks (aa)" "$mpi_ok" "against 1 rank:$detail bound 1e-9"

# Stored springs carried between ranks: two spheres squeezed side by side in a box periodic in y
# (each touches the other and its image) slide and spin on the floor across the middle of a box
# split in x between two ranks: pair springs in fix neigh/history, floor springs in fix
# wall/soft/sphere. The two-rank run must give the one-rank result, and the springs must matter
# (the stateless law, which stores nothing, ends elsewhere).
cat > "$work/migrate.in" <<'MIG'
units si
atom_style sphere
atom_modify map array
boundary f p f
newton off
comm_modify vel yes
region box block -0.01 0.01 -0.99e-3 0.99e-3 0 0.01
create_box 1 box
create_atoms 1 single -1.5e-3 -0.495e-3 0.49999e-3
create_atoms 1 single -1.5e-3 0.495e-3 0.49999e-3
set type 1 diameter 1e-3 density 2500
velocity all set 0.6 0 0
group second id 2
set group all omega 0 1200 0
set group second omega 0 1205 0
plugin load ${plugin}
pair_style soft/sphere ${law} 1000 0.9 285.7142857142857 0.5 0.5
pair_coeff * *
neighbor 1e-4 bin
neigh_modify every 1 delay 0 check yes
fix integrate all nve/sphere
fix weight all gravity 9.81 vector 0 0 -1
fix floor all wall/soft/sphere ${law} 1000 0.9 285.7142857142857 0.5 0.5 zplane 0.0 NULL
timestep 2e-6
compute spin all property/atom omegay
variable u equal vx[2]
variable w equal c_spin[2]
variable u17 format u %.17g
variable w17 format w %.17g
thermo_style custom step v_u v_w
thermo 3000
run 3000
print "RESULT ${u17} ${w17} $(x[1]:%.6f)"
MIG
migrate() { # ranks, law
  (cd "$work" && mpirun -np "$1" "$lmp" -in migrate.in -var plugin "$plugin" -var law "$2" -log none 2>&1 | grep '^RESULT')
}
one="$(migrate 1 aa)"; two="$(migrate 2 aa)"; stateless="$(migrate 1 stateless)"
migrate_ok=1
if [ -n "$one" ] && [ -n "$two" ]; then
  x_end="$(echo "$one" | cut -d' ' -f4)"
  compare "$(echo "$two" | cut -d' ' -f2)" "$(echo "$one" | cut -d' ' -f2)" 1e-9 \
    && compare "$(echo "$two" | cut -d' ' -f3)" "$(echo "$one" | cut -d' ' -f3)" 1e-9 \
    && ! compare "$(echo "$stateless" | cut -d' ' -f3)" "$(echo "$one" | cut -d' ' -f3)" 1e-6 \
    && python3 -c "import sys; sys.exit(0 if $x_end > 0 else 1)" && migrate_ok=0
fi
result "a stored spring crosses ranks (aa, 2 ranks)" "$migrate_ok" \
  "1 rank: $one; 2 ranks: $two; stateless: $stateless"

# 4. Speed inside the engine: the reference scene, 10,000 steps, one rank, three runs each, and the
# two-rank speed-up. Printed, not asserted: this shared host drifts between hours.
target/release/scene_bench --steps 10000 --repeat 1 --lammps "$work/speed" > /dev/null 2>&1
timing() { # deck, ranks, log
  (cd "$work/speed" && mpirun -np "$2" "$lmp" -in "$1" -var plugin "$plugin" -log "$3" -screen none > /dev/null 2>&1)
  python3 - "$work/speed/$3" <<'PY'
import re, sys
text = open(sys.argv[1]).read()
loop = float(re.search(r"Loop time of ([\d.eE+-]+)", text).group(1))
pair = float(re.search(r"^Pair\s*\|\s*[\d.eE+-]+\s*\|\s*([\d.eE+-]+)", text, re.M).group(1))
print(f"{pair:.3f} {loop:.3f}")
PY
}
native=(); ours=()
for k in 1 2 3; do
  native+=("$(timing in.scene 1 log.native.$k)")
  ours+=("$(timing in.plugin 1 log.plugin.$k)")
done
two_ranks="$(timing in.plugin 2 log.plugin.2ranks)"
python3 - "${native[@]}" "${ours[@]}" "$two_ranks" <<'PY'
import statistics, sys
values = [tuple(map(float, v.split())) for v in sys.argv[1:]]
native, ours, two = values[:3], values[3:6], values[6]
def column(rows, k):
    return "/".join(f"{r[k]:.2f}" for r in rows)
median = lambda rows, k: statistics.median(r[k] for r in rows)
print("speed, reference scene (10,000 spheres, 10,000 steps, one rank; seconds, runs 1/2/3):")
print(f"  {'':28} {'Pair time':>20} {'loop time':>20}")
print(f"  {'gran/hooke/history (native)':28} {column(native, 0):>20} {column(native, 1):>20}")
print(f"  {'soft/sphere aa (plugin)':28} {column(ours, 0):>20} {column(ours, 1):>20}")
print(f"  ratio native/plugin, medians: Pair {median(native, 0) / median(ours, 0):.3f}, loop {median(native, 1) / median(ours, 1):.3f}")
print(f"  plugin on 2 ranks: loop {two[1]:.2f} s, speed-up {median(ours, 1) / two[1]:.2f}")
PY

# 5. Bad input: LAMMPS stops with a clear ERROR naming the parameter, before any atom moves.
bad() { # name, pair_style arguments or fix, expected words, timestep
  cat > "$work/bad.in" <<BAD
units si
atom_style sphere
comm_modify vel yes
region box block 0 0.01 0 0.01 0 0.01
create_box 1 box
create_atoms 1 single 0.005 0.005 0.005
set type 1 diameter 1e-3 density 2500
plugin load \${plugin}
pair_style $2
pair_coeff * *
fix integrate all nve/sphere
timestep $4
run 10
BAD
  output="$(cd "$work" && "$lmp" -in bad.in -var plugin "$plugin" -log none 2>&1)"
  status=$?
  message="$(printf '%s\n' "$output" | grep -m1 '^ERROR' || true)"
  ok=1
  if [ $status -ne 0 ] && printf '%s' "$message" | grep -q "$3" && ! printf '%s' "$output" | grep -qi nan; then ok=0; fi
  result "bad input: $1" "$ok" "${message:-no ERROR line (exit $status)}"
}
bad "negative stiffness" "soft/sphere aa -1000 0.9 285.7 0.5 0.5" "k_n (normal stiffness) must be positive" 1e-6
bad "restitution above 1" "soft/sphere aa 1000 1.5 285.7 0.5 0.5" "e (restitution) must lie in \[0, 1\]" 1e-6
bad "negative friction" "soft/sphere stateless 1000 0.9 285.7 0.5 -0.5" "mu (friction) must not be negative" 1e-6
bad "unknown law" "soft/sphere hertz 1000 0.9 285.7 0.5 0.5" "unknown law 'hertz'" 1e-6
bad "time step past the stability limit" "soft/sphere aa 1000 0.9 285.7 0.5 0.5" "stability limit" 1e-3

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
