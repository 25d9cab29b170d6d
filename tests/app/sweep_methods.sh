#!/usr/bin/env bash
# Usage: sweep_methods.sh MOLCHAOS
# `sweep --method edmd,dsmc --randomize none,flux` runs every (method, mode) pair a method can run:
# both MD gases and DSMC once per state point (DSMC has no shuffles). Its EDMD runs are the cache
# entries of an EDMD-only sweep (the method stays out of an EDMD run's key), its rows those of the
# one-method sweeps with the method in a column; the header names the methods.
set -u
bin=$(realpath "$1")
. "$(dirname "$0")/../scratch.sh"
enter_scratch_folder

args=(sweep --particles 200 --density 0.05 --restitution 0.8,0.9 --seeds 2 --t-end-tau0 2
      --quiet --threads 2 --cache cache)
"$bin" "${args[@]}" --randomize none,flux --out edmd.csv > /dev/null || fail "EDMD sweep"
[ "$(ls cache/*.csv | wc -l)" -eq 8 ] || fail "$(ls cache | wc -l) entries after the EDMD sweep, 8 expected"
"$bin" "${args[@]}" --method edmd,dsmc --randomize none,flux --out both.csv > both.txt ||
  fail "sweep over both methods"
# 2 restitutions x 2 seeds of DSMC added; the 8 EDMD entries reused.
[ "$(ls cache/*.csv | wc -l)" -eq 12 ] || fail "$(ls cache | wc -l) entries after both methods, 12 expected"
"$bin" "${args[@]}" --method dsmc --out dsmc.csv > /dev/null || fail "DSMC sweep"
[ "$(ls cache/*.csv | wc -l)" -eq 12 ] || fail "the DSMC-only sweep did not reuse the DSMC entries"

rows() { grep -v '^#' "$1" | tail -n +2; }
grep -q '^density,restitution,method,randomize,A,' both.csv || fail "no method column"
grep -qx '# method = edmd dsmc' both.csv || fail "the header does not name both methods"
grep -q '^# method' edmd.csv && fail "an EDMD-only summary names its method in the header"
[ "$(rows both.csv | wc -l)" -eq 6 ] || fail "$(rows both.csv | wc -l) rows, 6 expected (3 per state point)"
[ "$(rows both.csv | grep -c ',dsmc,none,')" -eq 2 ] || fail "not one DSMC row per state point"
[ "$(rows both.csv | grep -c ',dsmc,flux,')" -eq 0 ] || fail "a shuffled DSMC row"
diff <(rows both.csv | grep ',edmd,') <(rows edmd.csv) > /dev/null ||
  fail "the EDMD rows differ from the EDMD-only sweep's"
diff <(rows both.csv | grep ',dsmc,') <(rows dsmc.csv) > /dev/null ||
  fail "the DSMC rows differ from the DSMC-only sweep's"
grep -Eq '^ +0.05 +0.8 +dsmc +none ' both.txt || fail "the printed table has no DSMC row"
echo "ok: --method edmd,dsmc --randomize none,flux: 3 gases per state point, EDMD cache entries reused"
