#!/usr/bin/env bash
# Usage: checkpoint_refused.sh MOLCHAOS EXPECT_USAGE_ERROR
# A checkpoint that does not fit the run is refused with exit status 2 and one line naming what
# differs: another format, version, dimension or parameter, a corrupt, truncated or extended file,
# a head edited to other parameters or to a value that is no number, a t_end before the
# checkpoint's time or its last snapshot time; a --checkpoint or snapshot name holding a file that
# the run would lose (one that is no checkpoint, or the checkpoint of a run it does not continue),
# any other output naming a checkpoint; and
# --checkpoint-interval without --checkpoint; a --restart path that is no file, or empty.
set -u
bin=$(realpath "$1")
expect=$(realpath "$2")
. "$(dirname "$0")/../scratch.sh"
enter_scratch_folder
base=(simulate --particles 400 --density 0.1 --contacts --quiet)
args=("${base[@]}" --restitution 0.9)
"$bin" "${args[@]}" --t-end 20 --out a.csv --checkpoint ck --checkpoint-interval 5 2>/dev/null ||
  fail "run with checkpoints"
failures=0
refused "--restart.*parameter restitution differs: checkpoint 0.9, this run 0.8.*only t_end" \
  "${base[@]}" --restitution 0.8 --out b.csv --restart ck --write-config b.toml
# A parameter no flag gives is the checkpoint's; one a flag gives must be the checkpoint's too.
refused "--restart.*parameter particles differs: checkpoint 400, this run 500" \
  simulate --particles 500 --out b.csv --restart ck
refused "--restart.*dimension differs: checkpoint 2, this run 3" \
  "${args[@]}" --dim 3 --out b.csv --restart ck
refused "--restart.*t_end = 1 lies before the checkpoint's time" \
  "${args[@]}" --t-end 1 --out b.csv --restart ck
# A restart keeps the run's snapshot times: a t_end before the last is named as such (was: a
# snapshot time out of range, "from --config").
"$bin" "${args[@]}" --t-end 20 --snapshot-times 4,15 --out s.csv --checkpoint s.ckpt \
  --checkpoint-interval 5 2>/dev/null || fail "run with snapshots and checkpoints"
refused "^molchaos: error: --t-end: value 12 lies before 15, the last snapshot time of the run in s.ckpt, which a restart keeps; allowed: t_end >= 15" \
  "${args[@]}" --t-end 12 --out b.csv --restart s.ckpt
# The format this build writes, from the file's second line "format = N".
current=$(sed -n 2p ck | sed 's/^format = //')
magic=20 format=$(sed -n 2p ck | wc -c)  # bytes of the lines "molchaos checkpoint", "format = N"
{ printf 'molchaos checkpoint\nformat = 999\n'; tail -c +$((magic + format + 1)) ck; } >other_format
refused "--restart.*format differs: checkpoint 999, this run $current" \
  "${args[@]}" --out b.csv --restart other_format
version=$(head -3 ck | tail -1 | wc -c)
{ printf 'molchaos checkpoint\nformat = %s\nversion = 0.0.1+other\n' "$current"
  tail -c +$((magic + format + version + 1)) ck; } >other_version
refused "--restart.*written by molchaos 0.0.1\+other, this is" \
  "${args[@]}" --out b.csv --restart other_version
size=$(wc -c <ck)
head -c $((size - 100)) ck >truncated
refused "--restart.*truncated payload" "${args[@]}" --out b.csv --restart truncated
cp ck extended
printf 'x' >>extended
refused "--restart.*bytes after the checksum" "${args[@]}" --out b.csv --restart extended
# The head is under the checksum too: a parameter edited there (and given to the run) is refused.
sed '0,/^restitution = 0.9$/s//restitution = 0.5/' ck >edited_head
cmp -s ck edited_head && fail "the head of ck has no line 'restitution = 0.9'"
refused "--restart.*checksum mismatch" "${base[@]}" --restitution 0.5 --out b.csv --restart edited_head
# ... and so is one edited to the same value written otherwise, given to no flag (was: "parameter
# restitution differs: checkpoint 0.900, this run 0.9").
sed '0,/^restitution = 0.9$/s//restitution = 0.900/' ck >same_value
cmp -s ck same_value && fail "the head of ck has no line 'restitution = 0.9'"
refused "--restart.*checksum mismatch" simulate --out b.csv --restart same_value
cp ck flipped
printf '\x5a' | dd of=flipped bs=1 seek=$((size - 20)) conv=notrunc 2>/dev/null
refused "--restart.*checksum mismatch" "${args[@]}" --out b.csv --restart flipped
refused "--restart.*not a molchaos checkpoint" "${args[@]}" --out b.csv --restart a.csv
refused "--restart.*no checkpoint file 'missing'" "${args[@]}" --out b.csv --restart missing
# A head that is no run's, read for the parameters of a restart given no others: named as the
# --restart file it came by (was: as a --config file, which the command line does not hold).
sed '0,/^density = 0.1$/s//density = abcd/' ck >unreadable_head
cmp -s ck unreadable_head && fail "the head of ck has no line 'density = 0.1'"
refused "^molchaos: error: --restart: unreadable_head: key 'density': .*'abcd' is not a number" \
  simulate --restart unreadable_head --t-end 30 --out b.csv
# A file that is no checkpoint at the --checkpoint name (a result table) would be lost at the
# first checkpoint (was: replaced without a word); so would a file of the user's own at a
# snapshot's derived name.
cp a.csv table.csv
refused "--checkpoint: table.csv holds a file that is no molchaos checkpoint" \
  "${args[@]}" --t-end 20 --out c.csv --checkpoint table.csv --checkpoint-interval 5
cmp a.csv table.csv || fail "the table named by --checkpoint was changed"
# Another run's checkpoint at the --checkpoint name, or the same command started afresh, would
# lose that run's progress (was: replaced without a word); the run restarted from it replaces it.
cp ck kept.ckpt
for restitution in 0.8 0.9; do
  refused "--checkpoint: kept.ckpt holds the checkpoint of a run that this run does not continue" \
    "${base[@]}" --restitution $restitution --t-end 20 --out c.csv --checkpoint kept.ckpt \
    --checkpoint-interval 5
done
cmp ck kept.ckpt || fail "another run's checkpoint was changed"
"$bin" "${args[@]}" --t-end 30 --out e.csv --restart kept.ckpt --checkpoint kept.ckpt \
  --checkpoint-interval 5 2>/dev/null || fail "a restart replacing its own checkpoint was refused"
cmp -s ck kept.ckpt && fail "the restarted run did not replace its checkpoint"
# Nor may any other output replace a checkpoint (was: --out, --write-config and a sweep's --out
# overwrote one without a word).
cp ck other.ckpt
refused "--out: other.ckpt holds the checkpoint of a run, which this output would replace" \
  "${args[@]}" --t-end 5 --out other.ckpt
refused "--write-config: other.ckpt holds the checkpoint of a run" \
  "${args[@]}" --t-end 5 --out c.csv --write-config other.ckpt
refused "--out: other.ckpt holds the checkpoint of a run" \
  sweep --particles 100 --seeds 1 --cache '' --out other.ckpt
cmp ck other.ckpt || fail "a checkpoint was replaced by another output"
printf 'x,y\n1,2\n' >mine.snapshot0.csv
refused "--out: mine.snapshot0.csv, the name of this run's snapshot 0, holds a file that is no result of molchaos" \
  "${args[@]}" --t-end 5 --snapshot-times 1 --out mine.csv
[ "$(cat mine.snapshot0.csv)" = "$(printf 'x,y\n1,2')" ] || fail "the user's file at a snapshot name was changed"
[ ! -e c.csv ] && [ ! -e mine.csv ] || fail "a refused run wrote its CSV"
# A path that holds no checkpoint is named as what it is (was: "no checkpoint file", as for a
# mistyped name).
refused "--restart: '/dev/null' is not a regular file" "${args[@]}" --out b.csv --restart /dev/null
: >empty.ckpt
refused "--restart: 'empty.ckpt' is empty" "${args[@]}" --out b.csv --restart empty.ckpt
refused "--restart: no checkpoint file 'missing.ckpt'" "${args[@]}" --out b.csv --restart missing.ckpt
refused "--checkpoint-interval: needs --checkpoint FILE" \
  "${args[@]}" --out b.csv --checkpoint-interval 5
[ ! -e b.csv ] && [ ! -e b.toml ] || fail "an output written by a refused restart: $(ls b.*)"
# --checkpoint alone writes only on a signal: a run that finishes says it left no file (was:
# nothing, and no file to go on from).
"$bin" "${args[@]}" --t-end 5 --out d.csv --checkpoint only_on_signal.ckpt 2>note.txt ||
  fail "run with --checkpoint alone"
[ ! -e only_on_signal.ckpt ] || fail "a checkpoint written without interval or signal"
grep -q "^note: no checkpoint written to only_on_signal.ckpt: without --checkpoint-interval or --checkpoint-wall one is written only on SIGINT or SIGTERM" note.txt ||
  fail "no note that no checkpoint was written: $(cat note.txt)"
[ "$failures" -eq 0 ] || fail "$failures refusals wrong"
echo "ok: every unfit checkpoint refused with a message naming what differs"
