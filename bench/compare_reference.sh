#!/bin/bash
# Same-run comparison of this engine with another hard-sphere EDMD program on the 3D bench work
# (elastic spheres, N ~ 1e5, packing fractions 0.1 and 0.4). The machine's speed drifts by tens of
# per cent within minutes, so the two are alternated: each round runs this tree's bm_spheres
# (both packings) and then every reference command once; the script prints, per reference, the
# median collisions per CPU second of each side, the ranges, and the paired ratios ours/theirs.
#
#   bench/compare_reference.sh BUILD_DIR ROUNDS 'LABEL:PACKING_PERCENT:COMMAND' ...
#
# COMMAND is run through bash and must print `collisions_per_cpu_s=<number>` somewhere in its
# output (the rate of its timed phase, per CPU second). PACKING_PERCENT (10 or 40) names the
# bm_spheres case it is compared with. Nothing is built here: the reference programs are built
# by whoever runs the comparison, outside this repository.
set -euo pipefail
. "$(dirname "$0")/rates_lib.sh"
usage="usage: compare_reference.sh BUILD_DIR ROUNDS 'LABEL:PACKING_PERCENT:COMMAND' ..."
build=${1:?$usage}
rounds=${2:?$usage}
shift 2
[ $# -ge 1 ] || { echo "$usage" >&2; exit 2; }
case "$rounds" in ''|*[!0-9]*|0) echo "compare_reference.sh: ROUNDS must be a whole number >= 1, got '$rounds'" >&2; exit 2;; esac
ours="$build/bench/bench_engine"
[ -x "$ours" ] || { echo "compare_reference.sh: $ours not built (cmake --build $build --target bench_engine)" >&2; exit 1; }
for ref in "$@"; do
  IFS=: read -r label packing command <<<"$ref"
  case "$packing" in 10|40) ;; *) echo "compare_reference.sh: PACKING_PERCENT must be 10 or 40 in '$ref'" >&2; exit 2;; esac
  [ -n "$label" ] && [ -n "$command" ] || { echo "compare_reference.sh: '$ref' is not LABEL:PACKING_PERCENT:COMMAND" >&2; exit 2; }
done
rates=$(mktemp)
trap 'rm -f "$rates"' EXIT
for r in $(seq "$rounds"); do
  echo "round $r/$rounds: this engine" >&2
  "$ours" --benchmark_filter=bm_spheres 2>/dev/null |
    awk -v r="$r" "$rates_awk"'/^bm_spheres/ { split($1, a, "[:/]"); p = a[3]
      for (i = 1; i <= NF; ++i) if ($i ~ /^collisions_per_cpu_s=/) printf "ours%s %s %.6f\n", p, r, millions(substr($i, 22)) }' >>"$rates"
  [ "$(grep -c "^ours[14]0 $r " "$rates")" = 2 ] ||
    { echo "compare_reference.sh: $ours printed no bm_spheres rates in round $r" >&2; exit 1; }
  for ref in "$@"; do
    IFS=: read -r label packing command <<<"$ref"
    echo "round $r/$rounds: $label" >&2
    value=$({ bash -c "$command" 2>/dev/null || true; } | { grep -o 'collisions_per_cpu_s=[0-9.eE+]*' || true; } |
            head -1 | cut -d= -f2)
    [ -n "$value" ] || { echo "compare_reference.sh: '$label' printed no collisions_per_cpu_s=" >&2; exit 1; }
    awk -v label="$label" -v r="$r" -v v="$value" -v p="$packing" "$rates_awk"'BEGIN { printf "%s %s %.6f %s\n", label, r, millions(v), p }' >>"$rates"
  done
done
echo "collisions per CPU second (millions), median [min-max] over $rounds alternating rounds"
for ref in "$@"; do
  IFS=: read -r label packing command <<<"$ref"
  awk -v label="$label" -v ours="ours$packing" "$rates_awk"'
    $1 == ours  { o[$2] = $3 }
    $1 == label { t[$2] = $3; n = $2 > n ? $2 : n }
    END {
      line = ""; for (k = 1; k <= n; ++k) { line = line sprintf(" %.2f", o[k] / t[k]); so[k] = o[k]; st[k] = t[k] }
      sort(so, n); sort(st, n)
      printf "%-28s ours %.3f [%.3f-%.3f]  reference %.3f [%.3f-%.3f]  ratios ours/reference%s\n",
             label, med(so, n), so[1], so[n], med(st, n), st[1], st[n], line }' "$rates"
done
