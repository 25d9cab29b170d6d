#!/usr/bin/env bash
# Usage: reproduce_interrupt.sh MOLCHAOS
# SIGTERM and SIGINT while `reproduce` renders its figures: the gnuplot under way is ended, no
# temporary file is left beside the figures, the exit status is 128 + signal with one line on
# stderr naming what stopped, and the same command then writes every figure and the report from
# the cache, byte for byte those of an uninterrupted run into another folder.
set -u
set -m  # job control: a background job must not start with SIGINT ignored
bin=$(realpath "$1")
. "$(dirname "$0")/../scratch.sh"
enter_scratch_folder
command -v gnuplot >/dev/null || fail "no gnuplot on PATH"

args=(reproduce --quick --threads 1 --quiet --cache "$PWD/cache")
"$bin" "${args[@]}" --out "$PWD/whole" >/dev/null 2>whole.err || { cat whole.err; fail "reference run"; }

temporaries() { ls -A "$1" 2>/dev/null | grep 'molchaos-tmp'; }
for signal in TERM INT; do
  out=$PWD/stopped_$signal
  # An earlier run's report in the folder: removed when the figures start to be replaced, so that
  # it does not describe an interrupted run's new figures.
  mkdir -p "$out" && cp whole/REPORT.md "$out/"
  "$bin" "${args[@]}" --out "$out" >/dev/null 2>"$signal.err" &
  pid=$!
  for _ in $(seq 1200); do  # up to 60 s for the first figure's temporaries
    [ -n "$(temporaries "$out")" ] && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.05
  done
  kill -"$signal" "$pid" || fail "SIG$signal: reproduce ended before its figures"
  wait "$pid"
  status=$?
  expected=$((128 + $(kill -l "$signal")))
  [ "$status" -eq "$expected" ] || fail "SIG$signal: exit status $status, expected $expected"
  [ "$(wc -l <"$signal.err")" -eq 1 ] || { cat "$signal.err"; fail "SIG$signal: not one line on stderr"; }
  grep -Eq "^molchaos: reproduce stopped by SIG$signal .*; the cache $PWD/cache keeps every finished run" \
    "$signal.err" || fail "SIG$signal: stderr says $(cat "$signal.err")"
  echo "SIG$signal: status $status; $(cat "$signal.err")"
  sleep 1  # an orphaned gnuplot would go on writing its temporaries
  [ -z "$(temporaries "$out")" ] || fail "SIG$signal: temporaries left: $(temporaries "$out" | tr '\n' ' ')"
  if pgrep -f -- "$out/" >/dev/null; then
    pgrep -a -f -- "$out/"
    fail "SIG$signal: gnuplot still runs after reproduce ended"
  fi
  [ ! -e "$out/REPORT.md" ] || fail "SIG$signal: a report was written, or the earlier one kept"

  "$bin" "${args[@]}" --out "$out" >/dev/null 2>"$signal.again.err" ||
    { cat "$signal.again.err"; fail "SIG$signal: the run after the interrupt failed"; }
  [ -z "$(temporaries "$out")" ] || fail "SIG$signal: temporaries after the second run"
  for f in "$PWD"/whole/*.png "$PWD"/whole/REPORT.md; do
    cmp -s "$f" "$out/$(basename "$f")" || fail "SIG$signal: $(basename "$f") differs from the uninterrupted run's"
  done
done
echo "ok: an interrupted reproduce leaves no temporary and no gnuplot; the next run completes it"
