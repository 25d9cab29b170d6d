#!/usr/bin/env bash
# Usage: reproduce_interrupt.sh MOLCHAOS
# SIGTERM and SIGINT while `reproduce` renders its figures: the gnuplot under way is ended, no
# temporary file is left, the folder's earlier outputs (report, tables, figures) stay as they
# were, the exit status is 128 + signal with one line on stderr naming what stopped, and the same
# command then writes every figure and the report from the cache, byte for byte those of an
# uninterrupted run into another folder.
set -u
bin=$(realpath "$1")
. "$(dirname "$0")/../scratch.sh"
. "$(dirname "$0")/figure_interrupts.sh"
enter_scratch_folder

base=(reproduce --quick --threads 1 --quiet)
args=("${base[@]}" --cache "$PWD/cache")
"$bin" "${args[@]}" --out "$PWD/whole" >/dev/null 2>whole.err || { cat whole.err; fail "reference run"; }

for signal in TERM INT; do
  out=$PWD/stopped_$signal
  # An earlier reproduction in the folder (here one of 2 seeds): it stays whole, no new figure
  # beside its report (was: its report removed, new figures beside its tables).
  "$bin" "${base[@]}" --seeds 2 --cache "$PWD/cache2" --out "$out" >/dev/null 2>&1 ||
    fail "SIG$signal: the earlier reproduction"
  before=$(cd "$out" && md5sum * 2>/dev/null)
  "$bin" "${args[@]}" --out "$out" >/dev/null 2>"$signal.err" &
  signal_at_first_temporary $! "$out" "$signal"
  [ "$(wc -l <"$signal.err")" -eq 1 ] || { cat "$signal.err"; fail "SIG$signal: not one line on stderr"; }
  grep -Eq "^molchaos: reproduce stopped by SIG$signal .*; the output folder is as it was, the cache $PWD/cache keeps every finished run" \
    "$signal.err" || fail "SIG$signal: stderr says $(cat "$signal.err")"
  echo "SIG$signal: status $status; $(cat "$signal.err")"
  no_leftovers "$out" "$signal"
  [ "$(cd "$out" && md5sum * 2>/dev/null)" = "$before" ] ||
    fail "SIG$signal: the earlier reproduction's files changed"

  "$bin" "${args[@]}" --out "$out" >/dev/null 2>"$signal.again.err" ||
    { cat "$signal.again.err"; fail "SIG$signal: the run after the interrupt failed"; }
  [ -z "$(temporaries "$out")" ] || fail "SIG$signal: temporaries after the second run"
  for f in "$PWD"/whole/*.png "$PWD"/whole/REPORT.md; do
    cmp -s "$f" "$out/$(basename "$f")" || fail "SIG$signal: $(basename "$f") differs from the uninterrupted run's"
  done
done
echo "ok: an interrupted reproduce leaves no temporary and no gnuplot; the next run completes it"

# A reproduction without figures into that folder names the figures its report does not describe.
"$bin" "${args[@]}" --no-figures --out "$out" >/dev/null 2>nofig.err || fail "--no-figures run"
grep -q "^note: $out holds [0-9]* figure(s) and 0 table(s) of an earlier reproduction, which the new report does not describe: fig3_temperature.png, " \
  nofig.err || fail "no note of the earlier figures: $(cat nofig.err)"
# So are tables of an earlier reproduction that this one did not write (a quick look into the
# folder of a paper-scale one, whose break-down tables it has not); a CSV of the user's own is not.
sed 's/^# quick = true$/# quick = false/' "$out/fig4_A_of_eps.csv" >"$out/breakdown_gases.csv"
printf 'x,y\n1,2\n' >"$out/mine.csv"
"$bin" "${args[@]}" --no-figures --out "$out" >/dev/null 2>nofig.err || fail "--no-figures run"
grep -q "^note: $out holds [0-9]* figure(s) and 1 table(s) of an earlier reproduction, which the new report does not describe: breakdown_gases.csv, fig3_temperature.png, " \
  nofig.err || fail "no note of the earlier table: $(cat nofig.err)"
! grep -q "mine.csv" nofig.err || fail "a CSV of the user's own named as a reproduction's"
echo "ok: figures and tables of an earlier reproduction named"
