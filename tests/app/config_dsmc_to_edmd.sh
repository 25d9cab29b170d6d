#!/usr/bin/env bash
# Usage: config_dsmc_to_edmd.sh MOLCHAOS
# A DSMC result's header records relax 0, which DSMC forces: an EDMD run configured from it
# (--config dsmc.csv --method edmd) relaxes by EDMD's default, with a note, rather than starting
# unrelaxed without a word; --relax 0 given as a flag keeps none, without a note; the DSMC run
# repeated from its header is the same bytes, without a note; a sweep from it does the same.
set -u
bin=$(realpath "$1")
. "$(dirname "$0")/../scratch.sh"
enter_scratch_folder

"$bin" simulate --method dsmc --particles 200 --density 0.05 --restitution 0.9 --t-end 5 --quiet \
  --out dsmc.csv --write-config dsmc.toml 2>/dev/null || fail "DSMC run"
grep -qx '# relax_collisions_per_particle = 0' dsmc.csv || fail "the DSMC header does not record relax 0"
for file in dsmc.csv dsmc.toml; do
  "$bin" simulate --config "$file" --method edmd --quiet --out "edmd_$file.csv" 2>edmd.err ||
    fail "EDMD run from $file"
  ! grep -q '^# method = dsmc' "edmd_$file.csv" || fail "the run from $file is no EDMD run"  # EDMD files name no method
  grep -qx '# relax_collisions_per_particle = 20' "edmd_$file.csv" ||
    fail "the EDMD run from $file does not take EDMD's default relaxation: $(grep '^# relax' "edmd_$file.csv")"
  grep -qx "note: --config $file: relax_collisions_per_particle = 0 was DSMC's (it does not relax); this EDMD run relaxes 20 collisions per particle, the default (--relax 0 for none)" edmd.err ||
    fail "no note on the relaxation of the EDMD run from $file: $(cat edmd.err)"
done
echo "ok: an EDMD run from a DSMC file relaxes by EDMD's default, with a note"
"$bin" simulate --config dsmc.csv --method edmd --relax 0 --quiet --out none.csv 2>none.err ||
  fail "EDMD run from dsmc.csv with --relax 0"
grep -qx '# relax_collisions_per_particle = 0' none.csv || fail "--relax 0 as a flag not kept"
! grep -q "^note:" none.err || fail "a note with --relax 0 given as a flag: $(cat none.err)"
# An EDMD file's relax 0 was chosen: kept, without a note.
"$bin" simulate --config none.csv --quiet --out none_again.csv 2>none_again.err || fail "re-run of none.csv"
cmp -s <(grep -v '^# wall' none.csv) <(grep -v '^# wall' none_again.csv) || fail "the re-run of the unrelaxed EDMD run differs"
! grep -q "^note:" none_again.err || fail "a note on an EDMD file's relax 0: $(cat none_again.err)"
"$bin" simulate --config dsmc.csv --quiet --out again.csv 2>again.err || fail "re-run of dsmc.csv"
cmp -s <(grep -v '^# wall' dsmc.csv) <(grep -v '^# wall' again.csv) || fail "the DSMC re-run differs"
! grep -q "^note:" again.err || fail "a note on the DSMC re-run: $(cat again.err)"
echo "ok: --relax 0 as a flag and an EDMD file's 0 kept; the DSMC run repeats byte for byte"
# A sweep configured from the DSMC file takes the same rule (was: its EDMD runs unrelaxed, without
# a word); --relax 0 as a flag keeps none.
sweep=(sweep --config dsmc.csv --method edmd --seeds 1 --t-end-tau0 0.5 --cache '' --threads 1 --quiet)
"$bin" "${sweep[@]}" --out sweep.csv >/dev/null 2>sweep.err
[ -s sweep.csv ] || fail "no sweep summary: $(cat sweep.err)"
grep -qx '# relax_collisions_per_particle = 20' sweep.csv ||
  fail "the sweep from dsmc.csv does not take EDMD's default relaxation: $(grep '^# relax' sweep.csv)"
grep -qx "note: --config dsmc.csv: relax_collisions_per_particle = 0 was DSMC's (it does not relax); the EDMD runs of this sweep relax 20 collisions per particle, the default (--relax 0 for none)" sweep.err ||
  fail "no note on the relaxation of the sweep from dsmc.csv: $(cat sweep.err)"
"$bin" "${sweep[@]}" --relax 0 --out sweep_none.csv >/dev/null 2>sweep_none.err
grep -qx '# relax_collisions_per_particle = 0' sweep_none.csv || fail "--relax 0 as a flag not kept by the sweep"
! grep -q "relax_collisions_per_particle = 0 was" sweep_none.err || fail "a note with --relax 0: $(cat sweep_none.err)"
# The DSMC sweep it repeats records none, without a note.
"$bin" sweep --config dsmc.csv --seeds 1 --t-end-tau0 0.5 --cache '' --threads 1 --quiet \
  --out sweep_dsmc.csv >/dev/null 2>sweep_dsmc.err
grep -qx '# relax_collisions_per_particle = 0' sweep_dsmc.csv || fail "the DSMC sweep records a relaxation"
! grep -q "relax_collisions_per_particle = 0 was" sweep_dsmc.err || fail "a note on the DSMC sweep: $(cat sweep_dsmc.err)"
echo "ok: a sweep from a DSMC file relaxes its EDMD runs by the default, with a note"
