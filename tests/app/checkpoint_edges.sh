#!/usr/bin/env bash
# Usage: checkpoint_edges.sh MOLCHAOS EXPECT_USAGE_ERROR CASE
# Checkpoints and restarts at the edges of a run, one CASE each:
#   t_end_at_checkpoint  a restart whose t_end equals the checkpoint's time is refused, saying it
#                        leaves nothing to run (was: "lies before" the checkpoint's time);
#   interval_not_reached a --checkpoint-interval longer than the run notes that no checkpoint was
#                        written and the intervals that give one (was: nothing);
#   write_failure        a periodic checkpoint that cannot be written warns and the run goes on to
#                        its result, with no temporary left behind (was: the run ended, status 1);
#   config_t_end_only    --restart with a --config file that gives only t_end takes the other
#                        parameters from the checkpoint (was: the defaults, refused as differing).
set -u
bin=$(realpath "$1")
expect=$(realpath "$2")
case=$3
. "$(dirname "$0")/../scratch.sh"
enter_scratch_folder
args=(simulate --particles 400 --density 0.1 --restitution 0.9 --contacts --quiet)
failures=0
case $case in
  t_end_at_checkpoint)
    "$bin" "${args[@]}" --t-end 20 --out a.csv --checkpoint ck --checkpoint-interval 5 \
      2>/dev/null || fail "run with checkpoints"
    # The checkpoint's time, as a refusal of an earlier t_end gives it (round-trip digits).
    "$bin" "${args[@]}" --t-end 1 --out b.csv --restart ck 2>err.txt
    time=$(sed -n "s/.*lies before the checkpoint's time \([0-9.e+-]*\).*/\1/p" err.txt)
    [ -n "$time" ] || fail "no checkpoint time in: $(cat err.txt)"
    refused "^molchaos: error: --restart: checkpoint ck: t_end = $time equals the checkpoint's time $time, which leaves nothing to run; allowed: t_end in \($time, inf\), or the checkpoint's own 20" \
      "${args[@]}" --t-end "$time" --out b.csv --restart ck
    refused "^molchaos: error: --restart: checkpoint ck: t_end = 1 lies before the checkpoint's time $time; allowed: t_end in \($time, inf\)" \
      "${args[@]}" --t-end 1 --out b.csv --restart ck
    [ ! -e b.csv ] || fail "a refused restart wrote its CSV"
    ;;
  interval_not_reached)
    "$bin" "${args[@]}" --t-end 5 --out a.csv --checkpoint ck --checkpoint-interval 100 \
      2>note.txt || fail "run with an interval longer than the run: $(cat note.txt)"
    [ ! -e ck ] || fail "a checkpoint written, the interval never reached"
    grep -q "^note: no checkpoint written to ck: --checkpoint-interval 100 is longer than the run (t = 0 to 5), so no periodic checkpoint was due; one is taken with --checkpoint-interval in (0, [0-9.e+-]*\]$" note.txt ||
      fail "no note that the interval was not reached: $(cat note.txt)"
    # The longest interval it names gives a checkpoint; one reached says nothing.
    longest=$(sed -n 's/.*--checkpoint-interval in (0, \([0-9.e+-]*\)\]$/\1/p' note.txt)
    "$bin" "${args[@]}" --t-end 5 --out a.csv --checkpoint ck --checkpoint-interval "$longest" \
      2>note.txt || fail "run with interval $longest: $(cat note.txt)"
    [ -e ck ] || fail "no checkpoint at the longest interval named, $longest"
    grep -q "^note" note.txt && fail "a note for an interval reached: $(cat note.txt)"
    ;;
  write_failure)
    # The file-size limit (ulimit -f, in 512-byte blocks) makes every checkpoint write fail as on
    # a full disk, while the run's CSV fits below it.
    "$bin" "${args[@]}" --t-end 20 --out whole.csv 2>/dev/null || fail "run without checkpoints"
    [ "$(wc -c <whole.csv)" -lt 30000 ] || fail "the CSV does not fit below the limit"
    (ulimit -f 60 && exec "$bin" "${args[@]}" --t-end 20 --out a.csv --checkpoint ck \
      --checkpoint-interval 5) 2>err.txt
    status=$?
    [ "$status" -eq 0 ] || fail "a failed periodic checkpoint ended the run, status $status: $(cat err.txt)"
    cmp -s whole.csv a.csv || fail "the result differs from the run without checkpoints"
    grep -q "^warning: --checkpoint: the checkpoint at t = [0-9.e+-]* could not be written (cannot write ck: .*File too large.*); the run goes on, and ck keeps the last checkpoint written, if any" err.txt ||
      fail "no warning of the failed checkpoint: $(cat err.txt)"
    [ ! -e ck ] || fail "a checkpoint file left by failed writes"
    [ -z "$(ls -A | grep molchaos-tmp || true)" ] || fail "temporaries left behind: $(ls -A)"
    ;;
  config_t_end_only)
    "$bin" "${args[@]}" --t-end 20 --out whole.csv 2>/dev/null || fail "uninterrupted run"
    "$bin" "${args[@]}" --t-end 10 --out a.csv --checkpoint ck --checkpoint-interval 5 \
      2>/dev/null || fail "run with checkpoints"
    printf 't_end = 20\n' >longer.toml
    "$bin" simulate --restart ck --config longer.toml --out b.csv --quiet 2>err.txt ||
      fail "restart with a --config file of t_end only: $(cat err.txt)"
    grep -q '^# t_end = 20$' b.csv && grep -q '^# particles = 400$' b.csv &&
      grep -q '^# restitution = 0.9$' b.csv ||
      fail "the restart did not take the checkpoint's parameters: $(grep '^# ' b.csv | head -20)"
    # A flag still wins over both files, and is checked against the checkpoint.
    refused "--restart.*parameter particles differs: checkpoint 400, this run 500" \
      simulate --restart ck --config longer.toml --particles 500 --out c.csv
    ;;
  *) fail "unknown case $case" ;;
esac
[ "$failures" -eq 0 ] || fail "$failures refusals wrong"
echo "ok: $case"
