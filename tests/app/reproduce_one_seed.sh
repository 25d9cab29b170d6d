#!/usr/bin/env bash
# Usage: reproduce_one_seed.sh MOLCHAOS
# One seed per point gives values without standard errors: the report and every figure are still
# written (b at contact, which needs the error of the mean dyad, is left out of its figure), where
# the reproduction failed with "BData.panels[0].series[2].restitution is empty". A verdict that
# needs a standard error says it is not decided (it said "not reproduced" on a χ² of 0 points).
set -u
bin=$(realpath "$1")
. "$(dirname "$0")/../scratch.sh"
enter_scratch_folder

"$bin" reproduce --quick --seeds 1 --threads 2 --out one --cache one/cache >log.txt 2>&1 ||
  { cat log.txt; fail "reproduce --quick --seeds 1 failed"; }
for f in REPORT.md fig4_A_of_eps.png fig_b_of_eps.png; do
  [ -s "one/$f" ] || fail "no one/$f"
done
# No verdict rests on a standard error that one seed cannot give: the claims that compare
# simulated values say they are not decided; those on theory alone keep their verdicts.
report=one/REPORT.md
for zero in '± 0.0000' 'for 0 points' '(differs)' 'equal within errors'; do
  # The estimator rows are information, their degrees of freedom beside each shift (0 with one
  # seed; the least-squares fit's shift from itself is 0 ± 0).
  ! grep -v 'relative sd of A per run' $report | grep -qF "$zero" ||
    fail "the report rests a verdict on a zero error: $(grep -v 'relative sd of A per run' $report | grep -F "$zero" | head -2)"
done
! grep -Eq '[0-9]{6,}(\.[0-9]+)? SE' $report || fail "a difference of millions of standard errors: $(grep -Eo '[0-9]{6,}(\.[0-9]+)? SE' $report | head -1)"
grep -Eq '^\| paper 5 \| .* \| \*\*not decided\*\* \| one seed per point gives no standard errors' $report ||
  fail "the Haff claim of the randomized gas is not 'not decided': $(grep '^| paper 5 ' $report)"
grep -Eq '^\| suite 12 \| .* \| \*\*not decided\*\* \|' $report || fail "the elastic limit is decided on one run"
# The Fig. 4 slopes: with one seed their error is the scatter of three points about a line (one
# degree of freedom), not a standard error of A.
for claim in 'paper 6' 'paper 7'; do
  grep -Eq "^\| $claim \| .* \| \*\*not decided\*\* \|" $report ||
    fail "a Fig. 4 slope claim is decided on one seed: $(grep "^| $claim " $report | cut -c1-200)"
done
# What one seed cannot measure is said to be not measured, not printed as 0.
for zero in 'cost ×0.00' 'r = +0.000 ± 0.000'; do
  ! grep -qF "$zero" $report || fail "the report prints an unmeasured value as 0: $zero"
done
grep -q '^none,integrated,nan,0,nan,nan,nan,true$' one/haff_estimators.csv ||
  fail "the estimator table holds numbers without a second run: $(grep '^none,integrated' one/haff_estimators.csv)"
grep -Eq '^\| paper 1 \| .* \| \*\*reproduced\*\* \|' $report || fail "the theory claim lost its verdict"
grep -q '| not decided |' $report || fail "no comparison row says 'not decided'"
! grep -q 'jackknife over seeds 0\.0000' $report || fail "a jackknife over one seed is reported as 0"
echo "ok: reproduce --quick --seeds 1 writes its report and figures, its verdicts only where errors decide"

# Every table re-runs the reproduction from its own header (reproduce --config TABLE: the quick
# and seeds lines), here from the run cache: the same tables, byte for byte.
for table in one/*.csv; do
  grep -q '^# quick = true$' "$table" && grep -q '^# seeds = 1$' "$table" ||
    fail "$table does not name the options that re-run it"
done
"$bin" reproduce --config one/pair_correlations.csv --threads 2 --out again --cache one/cache \
  --no-figures --quiet >log.txt 2>&1 || { cat log.txt; fail "reproduce --config of a table failed"; }
for table in one/*.csv; do
  cmp "$table" "again/${table#one/}" || fail "$table differs when re-run from its own header"
done
"$bin" simulate --particles 50 --t-end 1 --out run.csv --quiet 2>/dev/null || fail "a plain run"
"$bin" reproduce --config run.csv --out never >out.txt 2>&1 && fail "reproduce ran from a run's CSV"
grep -q 'names no quick (not a table of molchaos reproduce' out.txt ||
  fail "reproduce --config of a run's CSV: $(cat out.txt)"
[ ! -e never ] || fail "the refused reproduction left its folder behind"
grep -v '^# quick = ' one/fig4_A_of_eps.csv >no_quick.csv  # seeds alone: no scale to run at
"$bin" reproduce --config no_quick.csv --out never >out.txt 2>&1 && fail "reproduce ran without quick"
grep -q 'no_quick.csv: names no quick' out.txt || fail "a table without quick: $(cat out.txt)"
echo "ok: a table of the reproduction re-runs it from its header; a run's CSV is refused"
