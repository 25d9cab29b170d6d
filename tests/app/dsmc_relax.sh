#!/usr/bin/env bash
# Usage: dsmc_relax.sh MOLCHAOS
# DSMC does no relaxation: its result's header records relax 0, and the file re-runs from its own
# header to the same bytes; a sweep over both methods relaxes its EDMD runs only.
set -u
bin=$(realpath "$1")
. "$(dirname "$0")/../scratch.sh"
enter_scratch_folder

args=(--particles 200 --density 0.05 --restitution 0.9 --t-end 5 --quiet)
"$bin" simulate --method dsmc "${args[@]}" --out dsmc.csv 2> /dev/null || fail "DSMC run"
grep -qx '# relax_collisions_per_particle = 0' dsmc.csv || fail "the DSMC header does not record relax 0"
"$bin" simulate --config dsmc.csv --quiet --out again.csv 2> /dev/null || fail "re-run from the header"
cmp -s <(grep -v '^# wall' dsmc.csv) <(grep -v '^# wall' again.csv) || fail "the re-run differs"
"$bin" simulate "${args[@]}" --out edmd.csv 2> /dev/null || fail "EDMD run"
grep -qx '# relax_collisions_per_particle = 20' edmd.csv || fail "the EDMD default relaxation is not 20"
"$bin" sweep --particles 200 --density 0.05 --restitution 0.9 --seeds 1 --t-end-tau0 1 --quiet \
  --threads 2 --cache cache --method edmd,dsmc --relax 7 > /dev/null 2>&1 || fail "sweep over both methods"
[ "$(grep -lx '# method = dsmc' cache/*.csv | xargs grep -lx '# relax_collisions_per_particle = 0' | wc -l)" -eq 1 ] ||
  fail "the DSMC run of the sweep does not record relax 0"
[ "$(grep -lx '# relax_collisions_per_particle = 7' cache/*.csv | wc -l)" -eq 1 ] ||
  fail "the EDMD run of the sweep does not record relax 7"
echo "ok: DSMC records no relaxation and re-runs from its header; --relax applies to EDMD runs"
