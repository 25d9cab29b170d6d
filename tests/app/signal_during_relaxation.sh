#!/usr/bin/env bash
# Usage: signal_during_relaxation.sh MOLCHAOS
# SIGINT or SIGTERM during the relaxation of a run that writes checkpoints (the relaxation has
# none, and no pause to write one) ends the process at once, killed by that signal as without a
# handler: no output and no checkpoint. A relaxation of 1e8 collisions would take a minute or more.
set -u
set -m  # job control: a background job must not start with SIGINT ignored
bin=$(realpath "$1")
. "$(dirname "$0")/../scratch.sh"
enter_scratch_folder
for signal in INT TERM; do
  "$bin" simulate --particles 2000 --relax 100000 --t-end 10 --checkpoint run.ckpt \
    --out run.csv --quiet 2>err.txt &
  pid=$!
  sleep 0.5
  kill "-$signal" "$pid" || fail "the run ended before SIG$signal"
  for _ in $(seq 50); do  # up to 5 s
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
  done
  if kill -0 "$pid" 2>/dev/null; then
    kill -KILL "$pid"
    wait "$pid"
    fail "SIG$signal during the relaxation: still running 5 s later"
  fi
  wait "$pid"
  status=$?
  expected=$((128 + $(kill -l "$signal")))
  [ "$status" -eq "$expected" ] || fail "SIG$signal: status $status, expected $expected"
  [ ! -e run.csv ] && [ ! -e run.ckpt ] || fail "SIG$signal: a file written: $(ls)"
  echo "ok: SIG$signal during the relaxation ends the run at once"
done
