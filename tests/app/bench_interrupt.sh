#!/usr/bin/env bash
# Usage: bench_interrupt.sh MOLCHAOS
# SIGTERM and SIGINT while `bench` draws its figures: the gnuplot under way is ended, no temporary
# is left beside the figures, the table is in place and no figure of an earlier run beside it,
# and the exit status is 128 + signal with one line on stderr naming what stopped. The next run
# into the same folder writes every file.
set -u
bin=$(realpath "$1")
. "$(dirname "$0")/../scratch.sh"
. "$(dirname "$0")/figure_interrupts.sh"
enter_scratch_folder

args=(bench --simulation --particles 100 --work 1000 --threads 1)
for signal in TERM INT; do
  out=$PWD/stopped_$signal
  # An earlier run of other measurements in the folder: its figures must not stay beside the new
  # table.
  "$bin" bench --simulation --particles 200 --work 1000 --threads 1 --out "$out" >/dev/null 2>&1 ||
    fail "SIG$signal: the earlier run"
  earlier=$(cd "$out" && md5sum work_precision_simulation.png work_precision_simulation.pdf \
    work_precision_simulation.gp | cut -d' ' -f1)
  "$bin" "${args[@]}" --out "$out" >/dev/null 2>"$signal.err" &
  signal_at_first_temporary $! "$out" "$signal"
  grep -Eq "^molchaos: bench stopped by SIG$signal (while rendering|after writing) .*work_precision_simulation\.csv" \
    "$signal.err" || fail "SIG$signal: stderr says $(cat "$signal.err")"
  echo "SIG$signal: status $status; $(tail -n 1 "$signal.err")"
  no_leftovers "$out" "$signal"
  [ -s "$out/work_precision_simulation.csv" ] || fail "SIG$signal: the table is not in place"
  for f in png pdf gp; do
    [ -e "$out/work_precision_simulation.$f" ] || continue
    ! grep -qx "$(md5sum <"$out/work_precision_simulation.$f" | cut -d' ' -f1)" <<<"$earlier" ||
      fail "SIG$signal: the earlier run's .$f stayed beside the new table"
  done

  "$bin" "${args[@]}" --out "$out" >/dev/null 2>"$signal.again.err" ||
    { cat "$signal.again.err"; fail "SIG$signal: the run after the interrupt failed"; }
  [ -z "$(temporaries "$out")" ] || fail "SIG$signal: temporaries after the second run"
  for f in csv png pdf gp; do
    [ -s "$out/work_precision_simulation.$f" ] || fail "SIG$signal: no .$f after the second run"
  done
done
echo "ok: an interrupted bench leaves no temporary and no gnuplot, and its table in place"

# A signal during the measurements (which write nothing until they are done) ends bench at once;
# the folders it created for the table go with it, a folder that existed before stays.
mkdir kept
"$bin" bench --simulation --particles 20000 --work 2000000 --threads 1 --out kept/new/deeper \
  >/dev/null 2>early.err &
pid=$!
for _ in $(seq 100); do [ -d kept/new/deeper ] && break; sleep 0.05; done
[ -d kept/new/deeper ] || fail "bench did not create its --out folder"
sleep 0.5
kill -TERM $pid
wait $pid
status=$?
[ $status -eq 143 ] || fail "a signal during the measurements: status $status, stderr $(cat early.err)"
[ -d kept ] && [ ! -e kept/new ] || fail "the folders created for the table stayed: $(find kept)"
# And says so in one line (was: nothing after the last progress line).
grep -qx "molchaos: bench interrupted during its measurements; nothing written .*" early.err ||
  fail "a signal during the measurements said: $(cat early.err)"
! grep -q "from cache" early.err || fail "bench, which has no cache, counted runs from one"
echo "ok: a signal during the measurements removes the empty folders bench created, and says so"
