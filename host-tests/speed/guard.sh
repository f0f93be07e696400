#!/usr/bin/env bash
# The speed guard: instructions executed (valgrind's callgrind), which a noisy shared machine
# cannot blur, of one contact and of the reference scene, against the budgets committed in
# host-tests/speed/budgets.txt. Fails when a figure exceeds its budget by more than 3 %.
#
# Counted: the instructions of our own code (the measured binary), not the C library's: its
# memset and memcpy pick a variant by CPU (AVX2, AVX-512, ERMS), so their counts differ between
# machines; they are printed beside, for reading.
#
# Usage: host-tests/speed/guard.sh [--write]   (--write records the figures as the new budgets)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
cd "$root"
budgets="host-tests/speed/budgets.txt"
work="target/speed-guard"
mkdir -p "$work"

if ! command -v valgrind >/dev/null; then
  echo "valgrind is missing: installing the distribution's package"
  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq valgrind >/dev/null
fi

# A portable build whatever the caller's flags: the budgets are for it.
RUSTFLAGS="" cargo build --release -q -p host-tests --bin contact_count --bin scene_bench
bin="target/release"
# The settled packing is made (and cached in target/scene) by a plain run, not under callgrind.
"$bin/scene_bench" --steps 1 --repeat 1 > /dev/null 2>&1

# count NAME UNITS_PATTERN TOGGLE COMMAND...: runs COMMAND under callgrind, counting inside the
# functions matching TOGGLE; prints "NAME own libc units". Each TOGGLE ends with the function's
# own name: a closure inside it (`...::evaluate_with::{{closure}}`) would also match a pattern
# ending in `*`, and entering it would toggle the count off for whatever it calls.
count() {
  local name="$1" units="$2" toggle="$3"
  shift 3
  valgrind --tool=callgrind --toggle-collect="$toggle" \
    --callgrind-out-file="$work/$name.out" "$@" > "$work/$name.txt" 2> "$work/$name.log"
  python3 - "$work/$name.out" "$work/$name.txt" "$units" "$name" <<'PY'
import re, sys
out, text, units, name = sys.argv[1:]
objects, current, own, other, skip = {}, None, 0, 0, False
binary = None
for line in open(out):
    if line.startswith("cmd:"):
        binary = line.split()[1]
    m = re.match(r"ob=\((\d+)\)(?: (.*))?", line)
    if m:
        if m.group(2):
            objects[m.group(1)] = m.group(2).strip()
        current = objects[m.group(1)]
        continue
    m = re.match(r"c?ob=\((\d+)\) (.*)", line)
    if m:
        objects[m.group(1)] = m.group(2).strip()
        continue
    if line.startswith("calls="):
        skip = True
        continue
    if line[:1].isdigit() or line[:1] in "+-*":
        if skip:
            skip = False
            continue
        cost = int(line.split()[-1])
        if current is not None and current.endswith(binary.split("/")[-1]):
            own += cost
        else:
            other += cost
n = int(re.search(units, open(text).read()).group(1))
print(name, own, other, n)
PY
}

results="$work/results.txt"
{
  count contact_linear_aa 'contacts evaluated: (\d+)' '*contact_count::measured' \
    "$bin/contact_count" linear-aa 20
  count contact_hertz_aa 'contacts evaluated: (\d+)' '*contact_count::measured' \
    "$bin/contact_count" hertz-aa 20
  count scene_pair_phase 'of (\d+) pair contact-steps' '*MaterialTable*>::evaluate_with' \
    "$bin/scene_bench" --steps 100 --repeat 1
  count scene_step 'of (\d+) pair contact-steps' '*Scene*>::step_on' \
    "$bin/scene_bench" --steps 100 --repeat 1
} > "$results"

python3 - "$results" "$budgets" "${1:-}" <<'PY'
import sys
results, budgets, write = sys.argv[1], sys.argv[2], sys.argv[3] == "--write"
what = {
    "contact_linear_aa": "one contact, linear Model AA, f64 (per contact)",
    "contact_hertz_aa": "one contact, Hertz-Mindlin AA, f64 (per contact)",
    "scene_pair_phase": "reference scene, pair phase (per touching pair contact)",
    "scene_step": "reference scene, whole step (per touching pair contact)",
}
figures = {}
for line in open(results):
    name, own, other, units = line.split()
    figures[name] = (int(own) / int(units), int(other) / int(units))
if write:
    with open(budgets, "w") as f:
        f.write("# Instructions per unit of our own code (callgrind), portable release build.\n")
        f.write("# Written by host-tests/speed/guard.sh --write; the guard fails 3 % above.\n")
        for name, (own, _) in figures.items():
            f.write(f"{name} {own:.1f}\n")
    print(f"budgets written to {budgets}")
budget = {}
for line in open(budgets):
    if line.strip() and not line.startswith("#"):
        name, value = line.split()
        budget[name] = float(value)
failed = 0
for name, (own, other) in figures.items():
    limit = budget.get(name)
    if own == 0:
        verdict, failed = "NOTHING COUNTED (is the measured function renamed?)", failed + 1
    elif limit is None:
        verdict, failed = "NO BUDGET", failed + 1
    elif own > 1.03 * limit:
        verdict, failed = f"OVER BUDGET ({100 * (own / limit - 1):+.1f} %)", failed + 1
    elif own < 0.97 * limit:
        verdict = f"below budget ({100 * (own / limit - 1):+.1f} %): lower it (--write)"
    else:
        verdict = f"ok ({100 * (own / limit - 1):+.1f} %)"
    print(f"{what[name]}: {own:.1f} instructions (budget {limit}), C library {other:.1f}: {verdict}")
print(f"speed guard: {len(figures) - failed} passed, {failed} failed")
sys.exit(1 if failed else 0)
PY
