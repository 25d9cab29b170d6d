#!/usr/bin/env bash
# Usage: snapshot_times_cleared.sh MOLCHAOS EXPECT_USAGE_ERROR
# --snapshot-times "" is the empty list: it clears the snapshot times of a --config file (a run
# repeated without its snapshots); an empty value among others is refused.
set -u
bin=$(realpath "$1")
expect=$(realpath "$2")
. "$(dirname "$0")/../scratch.sh"
enter_scratch_folder

"$bin" simulate --particles 200 --density 0.05 --restitution 0.9 --t-end 5 --snapshot-times 1 2 \
  --quiet --out run.csv 2>/dev/null || fail "first run"
[ -f run.snapshot1.csv ] || fail "no snapshot written"
"$bin" simulate --config run.csv --snapshot-times "" --quiet --out none.csv 2>none.err ||
  fail "run with --snapshot-times \"\": $(cat none.err)"
grep -Eq '^# snapshot_times =\s*$' none.csv || fail "snapshot times not cleared: $(grep '^# snapshot_times' none.csv)"
[ ! -e none.snapshot0.csv ] || fail "a snapshot written with --snapshot-times \"\""
cmp -s <(grep -v '^# wall\|^# snapshot_times' run.csv) <(grep -v '^# wall\|^# snapshot_times' none.csv) ||
  fail "the run without snapshots differs"
"$bin" simulate --help | grep -q -- '"" for none' || fail "the help does not name --snapshot-times \"\""
echo "ok: --snapshot-times \"\" clears a --config file's snapshot times"
failures=0
refused '^molchaos: error: --snapshot-times: an empty value, which gives no values, among others' \
  simulate --config run.csv --snapshot-times "" 1 --out mixed.csv
refused '^molchaos: error: --snapshot-times: .*empty item 2 of 2' simulate --snapshot-times 1, --out comma.csv
[ "$failures" -eq 0 ] || fail "$failures refusal(s) not as expected"
echo "ok: an empty value among others refused"
