#!/bin/bash
# Work per collision of the engine, counted by callgrind (instructions, mispredicted branches,
# data-cache misses of a simulated 48 KB L1 and 2 MB L2): the same for the same binary whatever
# the machine's load, so speed changes can be compared exactly.
# Usage: engine_counts.sh BUILD_DIR [CASE ...]   (cases: paper paper_series paper_contacts
# disks1e5 disks1e6 spheres10 spheres40; default paper spheres10 spheres40). About a minute and a half per case
# (valgrind emulates the setup too).
set -euo pipefail
build=${1:?usage: engine_counts.sh BUILD_DIR [CASE ...]}
shift
cases=("$@")
[ ${#cases[@]} -gt 0 ] || cases=(paper spheres10 spheres40)
exe="$build/bench/engine_counts"
[ -x "$exe" ] || { echo "engine_counts.sh: $exe not built (cmake --build $build)" >&2; exit 1; }
command -v valgrind >/dev/null || { echo "engine_counts.sh: valgrind not installed (apt-get install valgrind)" >&2; exit 1; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
printf '%-14s %12s %12s %14s %12s %12s\n' case events/coll instr/coll mispredict/coll L1miss/coll L2miss/coll
for c in "${cases[@]}"; do
  valgrind --tool=callgrind --collect-atstart=no --cache-sim=yes --branch-sim=yes \
    --D1=49152,12,64 --LL=2097152,16,64 --callgrind-out-file="$tmp/$c.out" "$exe" "$c" \
    >"$tmp/$c.txt" 2>"$tmp/$c.err" || { cat "$tmp/$c.err" >&2; exit 1; }
  read -r _ coll _ events <"$tmp/$c.txt"
  # events: Ir Dr Dw I1mr D1mr D1mw ILmr DLmr DLmw Bc Bcm Bi Bim
  grep '^summary:' "$tmp/$c.out" | awk -v c="$c" -v n="$coll" -v e="$events" \
    '{printf "%-14s %12.2f %12.0f %14.1f %12.1f %12.1f\n", c, e/n, $2/n, ($12+$14)/n, ($6+$7)/n, ($9+$10)/n}'
done
