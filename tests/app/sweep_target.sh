#!/usr/bin/env bash
# Usage: sweep_target.sh MOLCHAOS
# `sweep --target-error R` adds seeds in stages until SE(A)/A ≤ R at every point: the points end
# below the target with more runs than the first stage, every seed is run once (the stages read
# the runs before them back from the cache), the header records the target, and `--config` of the
# summary repeats the sweep row for row. Without a cache it is refused.
set -u
bin=$(realpath "$1")
. "$(dirname "$0")/../scratch.sh"
enter_scratch_folder

target=0.004
args=(sweep --particles 300 --density 0.05 --restitution 0.8,0.9,0.95 --seeds 3 --t-end-tau0 2
      --quiet --threads 2 --cache cache)
"$bin" "${args[@]}" --target-error "$target" --out staged.csv > staged.txt || fail "staged sweep"
rows() { grep -v '^#' "$1" | tail -n +2; }
[ "$(rows staged.csv | wc -l)" -eq 3 ] || fail "$(rows staged.csv | wc -l) rows, 3 expected"
# Columns: density,restitution,method,randomize,A,A_err,runs,failed
rows staged.csv | awk -F, -v t="$target" '$6 > t * $5 { bad = 1 } END { exit bad }' ||
  fail "a point ends with SE(A)/A above $target: $(rows staged.csv | cut -d, -f2,5-7)"
rows staged.csv | awk -F, '$7 > 3 { more = 1 } END { exit !more }' ||
  fail "no point got seeds beyond the first stage's 3"
runs=$(rows staged.csv | awk -F, '{ n += $7 + $8 } END { print n }')
[ "$(ls cache/*.csv | wc -l)" -eq "$runs" ] ||
  fail "$(ls cache/*.csv | wc -l) cache entries for $runs runs: a stage ran a seed twice or lost one"
grep -qx "# target_error = $target" staged.csv || fail "the header does not record the target"
grep -qx '# max_seeds = 1000' staged.csv || fail "the header does not record --max-seeds"
"$bin" sweep --config staged.csv --cache cache --quiet --out again.csv > /dev/null ||
  fail "sweep --config of the summary"
diff <(rows staged.csv) <(rows again.csv) > /dev/null || fail "--config of the summary gives other rows"
# A bound below what the target needs: the sweep stops there and says so.
"$bin" "${args[@]}" --target-error 0.0005 --max-seeds 6 --out bounded.csv > /dev/null 2> bounded.err ||
  fail "bounded sweep"
rows bounded.csv | awk -F, '$7 + $8 > 6 { bad = 1 } END { exit bad }' || fail "more than --max-seeds 6 runs"
grep -q 'SE(A)/A is above --target-error 0.0005 at 3 point(s): --max-seeds 6' bounded.err ||
  fail "no note on the points left above the target: $(cat bounded.err)"
# Without a cache the stages would run every earlier seed again: refused (an empty --cache cannot
# be passed from a CTest command line, hence here).
"$bin" sweep --target-error 0.01 --cache '' > /dev/null 2> nocache.err
[ $? -eq 2 ] || fail "--target-error without a cache: exit status other than 2"
grep -q -- '--target-error: needs a cache' nocache.err || fail "no reason given: $(cat nocache.err)"
echo "ok: --target-error $target reached at every point in $runs runs, each seed run once"
