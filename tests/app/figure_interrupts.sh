# Sourced by the tests that interrupt a command while it draws figures (reproduce_interrupt.sh,
# bench_interrupt.sh); needs fail() of scratch.sh.
set -m  # job control: a background job must not start with SIGINT ignored
command -v gnuplot >/dev/null || fail "no gnuplot on PATH"

# This suite's temporaries in folder $1, one name per line.
temporaries() { ls -A "$1" 2>/dev/null | grep 'molchaos-tmp'; }

# signal_at_first_temporary PID FOLDER SIGNAL: waits (up to 60 s) until FOLDER holds a temporary,
# then sends SIG<SIGNAL> to PID and waits for it; fails unless it ends by that signal (status 128 +
# its number). Sets `status`.
signal_at_first_temporary() {
  local pid=$1 folder=$2 signal=$3
  for _ in $(seq 6000); do
    [ -n "$(temporaries "$folder")" ] && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.01
  done
  kill -"$signal" "$pid" || fail "SIG$signal: the command ended before its figures"
  wait "$pid"
  status=$?
  local expected=$((128 + $(kill -l "$signal")))
  [ "$status" -eq "$expected" ] || fail "SIG$signal: exit status $status, expected $expected"
}

# no_leftovers FOLDER SIGNAL: a second after the command ended (an orphaned gnuplot would go on
# writing), FOLDER holds no temporary and no gnuplot writes into it.
no_leftovers() {
  local folder=$1 signal=$2
  sleep 1
  [ -z "$(temporaries "$folder")" ] ||
    fail "SIG$signal: temporaries left: $(temporaries "$folder" | tr '\n' ' ')"
  if pgrep -f -- "$folder/" >/dev/null; then
    pgrep -a -f -- "$folder/"
    fail "SIG$signal: gnuplot still runs after the command ended"
  fi
}
