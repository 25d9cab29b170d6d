#!/bin/bash
# Work per collision of the engine, counted by callgrind (instructions, mispredicted branches,
# data-cache misses of a simulated 48 KB L1 and 2 MB L2): the same for the same binary whatever
# the machine's load, so speed changes can be compared exactly.
# Usage: engine_counts.sh BUILD_DIR [CASE ...]   (cases: paper paper_series paper_contacts
# disks1e3 disks1e4 disks1e5 disks1e6 spheres10 spheres40; default paper spheres10 spheres40). About a minute and a half per case
# (valgrind emulates the setup too).
# The simulated caches stay fixed so that counts compare across machines and years; CACHES=local
# simulates this processor's own L1d and L2 instead (sizes and ways from getconf), to see which
# misses its L2 would serve.
set -euo pipefail
build=${1:?usage: engine_counts.sh BUILD_DIR [CASE ...]}
shift
cases=("$@")
[ ${#cases[@]} -gt 0 ] || cases=(paper spheres10 spheres40)
exe="$build/bench/engine_counts"
[ -x "$exe" ] || { echo "engine_counts.sh: $exe not built (cmake --build $build)" >&2; exit 1; }
command -v valgrind >/dev/null || { echo "engine_counts.sh: valgrind not installed (apt-get install valgrind)" >&2; exit 1; }
d1=49152,12,64 ll=2097152,16,64
if [ "${CACHES:-}" = local ]; then
  d1=$(getconf LEVEL1_DCACHE_SIZE),$(getconf LEVEL1_DCACHE_ASSOC),$(getconf LEVEL1_DCACHE_LINESIZE)
  ll=$(getconf LEVEL2_CACHE_SIZE),$(getconf LEVEL2_CACHE_ASSOC),$(getconf LEVEL2_CACHE_LINESIZE)
  for v in ${d1//,/ } ${ll//,/ }; do
    [[ $v =~ ^[1-9][0-9]*$ ]] ||
      { echo "engine_counts.sh: getconf does not know this processor's caches ($d1 / $ll)" >&2; exit 1; }
  done
  echo "simulated caches: L1d $d1, L2 $ll (size, ways, line; this processor's)"
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
printf '%-14s %12s %12s %14s %12s %12s\n' case events/coll instr/coll mispredict/coll L1miss/coll L2miss/coll
for c in "${cases[@]}"; do
  valgrind --tool=callgrind --collect-atstart=no --cache-sim=yes --branch-sim=yes \
    --D1=$d1 --LL=$ll --callgrind-out-file="$tmp/$c.out" "$exe" "$c" \
    >"$tmp/$c.txt" 2>"$tmp/$c.err" || { cat "$tmp/$c.err" >&2; exit 1; }
  read -r _ coll _ events <"$tmp/$c.txt"
  # events: Ir Dr Dw I1mr D1mr D1mw ILmr DLmr DLmw Bc Bcm Bi Bim
  grep '^summary:' "$tmp/$c.out" | awk -v c="$c" -v n="$coll" -v e="$events" \
    '{printf "%-14s %12.2f %12.0f %14.1f %12.1f %12.1f\n", c, e/n, $2/n, ($12+$14)/n, ($6+$7)/n, ($9+$10)/n}'
done
