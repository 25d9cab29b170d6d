#!/usr/bin/env bash
# Usage: simulate_pair_correlations.sh MOLCHAOS
# `simulate --pair-correlations FILE` writes g(r), G_par(r), G_perp(r) at each snapshot time, all,
# approaching and receding pairs apart, under a header that repeats the run (same bytes again);
# in a gas of uncorrelated positions g ≈ 1 away from contact.
set -u
bin=$(realpath "$1")
. "$(dirname "$0")/../scratch.sh"
enter_scratch_folder

args=(simulate --particles 1000 --density 0.05 --restitution 0.9 --t-end 20 --quiet)
"$bin" "${args[@]}" --snapshot-times 5 20 --pair-correlations pc.csv > /dev/null 2>&1 ||
  fail "simulate --pair-correlations"
grep -q '^t,tau,side,r_lo,r_hi,g,g_err,G_par,G_par_err,G_perp,G_perp_err,pairs$' pc.csv ||
  fail "no column line"
rows() { grep -v '^#' "$1" | tail -n +2; }
bins=$(rows pc.csv | awk -F, '$1 == 5 && $3 == "all"' | wc -l)
[ "$bins" -ge 10 ] || fail "$bins bins at t = 5"
for t in 5 20; do
  for side in all approaching receding; do
    [ "$(rows pc.csv | awk -F, -v t=$t -v s=$side '$1 == t && $3 == s' | wc -l)" -eq "$bins" ] ||
      fail "not $bins bins for t = $t, $side"
  done
done
# Pairs split into approaching and receding: their counts add up to all's in every bin.
rows pc.csv | awk -F, '{ n[$1 "," $4 "," $3] = $12 }
  END { for (k in n) { split(k, a, ","); if (a[3] == "all" &&
          n[a[1] "," a[2] ",approaching"] + n[a[1] "," a[2] ",receding"] != n[k]) exit 1 } }' ||
  fail "approaching + receding pairs differ from all pairs"
# g of the outer half of the bins (r well beyond contact) is 1 within 5 of its errors, as a whole.
rows pc.csv | awk -F, '$3 == "all" && $4 > 3 { z = ($6 - 1) / $7; c += z * z; k++ }
  END { if (k < 5 || c / k > 5) { print "chi2/dof = " c / k " over " k; exit 1 } }' ||
  fail "g(r) far from contact is not 1"
"$bin" simulate --config pc.csv --quiet --out again.csv --pair-correlations again_pc.csv > /dev/null 2>&1 ||
  fail "the header does not repeat the run"
diff <(grep -v '^# version' pc.csv) <(grep -v '^# version' again_pc.csv) > /dev/null ||
  fail "the repeated run's table differs"
# The times and bin edges in full: a snapshot time 3.3333333333333335 printed as 3.333333333 matched
# no snapshot's "# t = ", and edges cut to 6 digits gave other pair counts.
"$bin" "${args[@]}" --snapshot-times 3.3333333333333335 --pair-correlations third.csv \
  --out third.csv.run > /dev/null 2>&1 || fail "run with a snapshot at 10/3"
[ "$(rows third.csv | cut -d, -f1 | sort -u)" = 3.3333333333333335 ] ||
  fail "the time column is not the snapshot's time: $(rows third.csv | cut -d, -f1 | sort -u)"
rows third.csv | awk -F, '{ if (split($4, a, ".") == 2 && length(a[2]) > 6) long++ }
  END { exit long > 0 ? 0 : 1 }' || fail "the bin edges are cut to 6 digits"
"$bin" "${args[@]}" --pair-correlations x.csv > err.txt 2>&1 && fail "accepted without --snapshot-times"
grep -q -- '--pair-correlations.*--snapshot-times' err.txt || fail "error does not name the flags"
[ -e x.csv ] && fail "a table was written after the error"
echo "pair-correlation table: $bins bins per side and time"
