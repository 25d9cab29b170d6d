#!/bin/bash
# Wall-clock comparison of this tree's engine with the engine of an earlier commit, on a machine
# whose speed drifts: builds bench_engine of REV in a temporary worktree, then alternates full
# runs of the two benches ROUNDS times and prints, per case, the median collisions per CPU second
# of each, their ranges, and the paired ratios now/REV. Usage:
#   bench/compare_engines.sh BUILD_DIR REV [ROUNDS=3] [FILTER=.]
# Takes ROUNDS x 2 bench runs (1-2 min each) plus the build of REV's bench (about 2 minutes);
# OLD_BENCH=PATH uses a bench_engine already built from REV instead of building it.
set -euo pipefail
. "$(dirname "$0")/rates_lib.sh"
build=${1:?usage: compare_engines.sh BUILD_DIR REV [ROUNDS] [FILTER]}
rev=${2:?usage: compare_engines.sh BUILD_DIR REV [ROUNDS] [FILTER]}
rounds=${3:-3}
filter=${4:-.}
case "$rounds" in ''|*[!0-9]*|0) echo "compare_engines.sh: ROUNDS must be a whole number >= 1, got '$rounds'" >&2; exit 2;; esac
build=$(cd "$build" 2>/dev/null && pwd) || { echo "compare_engines.sh: no build directory '$1'" >&2; exit 1; }
cd "$(dirname "$0")/.."  # the repository, whatever the caller's directory
now="$build/bench/bench_engine"
[ -x "$now" ] || { echo "compare_engines.sh: $now not built (cmake --build $build)" >&2; exit 1; }
git rev-parse --verify -q "$rev^{commit}" >/dev/null || { echo "compare_engines.sh: REV '$rev' is not a commit" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'git worktree remove --force "$tmp/tree" >/dev/null 2>&1 || true; rm -rf "$tmp"' EXIT
if [ -n "${OLD_BENCH:-}" ]; then
  [ -x "$OLD_BENCH" ] || { echo "compare_engines.sh: OLD_BENCH '$OLD_BENCH' is not an executable" >&2; exit 1; }
  old=$OLD_BENCH
else
  git worktree add -f --detach "$tmp/tree" "$rev" >/dev/null 2>&1
  echo "building bench_engine of $rev ..." >&2
  cmake -S "$tmp/tree" -B "$tmp/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$tmp/build" -j "$(nproc)" --target bench_engine >/dev/null
  old="$tmp/build/bench/bench_engine"
fi
for r in $(seq "$rounds"); do
  for side in old now; do
    exe=$old; [ "$side" = now ] && exe=$now
    echo "round $r/$rounds: $side" >&2
    "$exe" --benchmark_filter="$filter" 2>/dev/null |
      awk -v s="$side" -v r="$r" "$rates_awk"'/collisions_per_cpu_s=/ {
        name = $1; sub("/iterations:1/manual_time", "", name)
        for (i = 1; i <= NF; ++i) if ($i ~ /^collisions_per_cpu_s=/)
          printf "%s %s %s %.6f\n", name, s, r, millions(substr($i, 22))
      }' >>"$tmp/rates"
  done
done
echo "collisions per CPU second (millions): median [min-max] over $rounds rounds; now = this tree, old = $rev"
sort -k1,1 -k3,3n -k2,2 "$tmp/rates" | awk "$rates_awk"'
  function flush(   k, ro, rn, line) {
    if (name == "") return
    line = ""
    for (k = 1; k <= n; ++k) { ro[k] = o[k]; rn[k] = w[k]; line = line sprintf(" %.2f", w[k] / o[k]) }
    sort(ro, n); sort(rn, n)
    printf "%-45s now %.3f [%.3f-%.3f]  old %.3f [%.3f-%.3f]  ratios%s\n", name, med(rn, n), rn[1], rn[n], med(ro, n), ro[1], ro[n], line
  }
  { if ($1 != name) { flush(); name = $1; n = 0; delete o; delete w }
    if ($2 == "old") { n = $3; o[n] = $4 } else { w[$3] = $4 } }
  END { flush() }'
