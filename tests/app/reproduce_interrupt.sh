#!/usr/bin/env bash
# Usage: reproduce_interrupt.sh MOLCHAOS
# SIGTERM and SIGINT while `reproduce` renders its figures: the gnuplot under way is ended, no
# temporary file is left beside the figures, the exit status is 128 + signal with one line on
# stderr naming what stopped, and the same command then writes every figure and the report from
# the cache, byte for byte those of an uninterrupted run into another folder.
set -u
bin=$(realpath "$1")
. "$(dirname "$0")/../scratch.sh"
. "$(dirname "$0")/figure_interrupts.sh"
enter_scratch_folder

args=(reproduce --quick --threads 1 --quiet --cache "$PWD/cache")
"$bin" "${args[@]}" --out "$PWD/whole" >/dev/null 2>whole.err || { cat whole.err; fail "reference run"; }

for signal in TERM INT; do
  out=$PWD/stopped_$signal
  # An earlier run's report in the folder: removed when the figures start to be replaced, so that
  # it does not describe an interrupted run's new figures.
  mkdir -p "$out" && cp whole/REPORT.md "$out/"
  "$bin" "${args[@]}" --out "$out" >/dev/null 2>"$signal.err" &
  signal_at_first_temporary $! "$out" "$signal"
  [ "$(wc -l <"$signal.err")" -eq 1 ] || { cat "$signal.err"; fail "SIG$signal: not one line on stderr"; }
  grep -Eq "^molchaos: reproduce stopped by SIG$signal .*; the cache $PWD/cache keeps every finished run" \
    "$signal.err" || fail "SIG$signal: stderr says $(cat "$signal.err")"
  echo "SIG$signal: status $status; $(cat "$signal.err")"
  no_leftovers "$out" "$signal"
  [ ! -e "$out/REPORT.md" ] || fail "SIG$signal: a report was written, or the earlier one kept"

  "$bin" "${args[@]}" --out "$out" >/dev/null 2>"$signal.again.err" ||
    { cat "$signal.again.err"; fail "SIG$signal: the run after the interrupt failed"; }
  [ -z "$(temporaries "$out")" ] || fail "SIG$signal: temporaries after the second run"
  for f in "$PWD"/whole/*.png "$PWD"/whole/REPORT.md; do
    cmp -s "$f" "$out/$(basename "$f")" || fail "SIG$signal: $(basename "$f") differs from the uninterrupted run's"
  done
done
echo "ok: an interrupted reproduce leaves no temporary and no gnuplot; the next run completes it"
