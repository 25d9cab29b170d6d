#!/usr/bin/env bash
# Usage: checkpoint_restart.sh MOLCHAOS DIM RANDOMIZE PARTICLES T_END DENSITY
# A run interrupted and continued with --restart writes the same bytes as the uninterrupted run:
# stopped by a checkpoint interval (a shorter run continued to a later t_end, once or twice, and
# the last interval checkpoint of a whole run), by SIGTERM and SIGINT (a checkpoint, exit status
# 3), and killed by SIGKILL between wall-clock checkpoints (continued from the last one). Contact
# statistics and a snapshot are on (and a dense case uses neighbour lists), so the observers'
# accumulators and pending outputs are part of the state. A restart takes the run's parameters
# from the checkpoint when no flag gives them.
set -u
set -m  # job control: a background job must not start with SIGINT ignored
bin=$(realpath "$1") dim=$2 mode=$3 particles=$4 t_end=$5 density=$6
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir" || exit 1
frac() { awk -v t="$t_end" -v k="$1" 'BEGIN { printf "%.17g", t / k }'; }  # t_end / k
args=(simulate --dim "$dim" --particles "$particles" --density "$density" --restitution 0.9
      --randomize "$mode" --contacts --seed 7 --snapshot-times "$(frac 8)" --quiet)
fail() { echo "FAIL: $*"; exit 1; }
same() {  # same <name>: name.csv and its snapshot equal the reference's, byte for byte
  cmp ref.csv "$1.csv" || fail "$1.csv differs from the uninterrupted run's"
  cmp ref.snapshot0.csv "$1.snapshot0.csv" || fail "$1's snapshot differs"
  echo "ok: $1 identical to the uninterrupted run"
}
"$bin" "${args[@]}" --t-end "$t_end" --out ref.csv 2>/dev/null || fail "reference run"

# A checkpoint interval: a run to t_end / 4 leaves its last checkpoint before that time; continued
# to the full t_end.
"$bin" "${args[@]}" --t-end "$(frac 4)" --out short.csv --checkpoint short.ckpt \
  --checkpoint-interval "$(frac 40)" 2>/dev/null || fail "short run"
"$bin" "${args[@]}" --t-end "$t_end" --out interval.csv --restart short.ckpt 2>/dev/null ||
  fail "restart to a later t_end"
same interval
# Continued twice: from short.ckpt to t_end / 2 (checkpointing on), then from its last checkpoint
# to the full t_end.
"$bin" "${args[@]}" --t-end "$(frac 2)" --out half.csv --restart short.ckpt --checkpoint half.ckpt \
  --checkpoint-interval "$(frac 40)" 2>/dev/null || fail "first restart, to t_end / 2"
"$bin" "${args[@]}" --t-end "$t_end" --out twice.csv --restart half.ckpt 2>/dev/null ||
  fail "second restart, to t_end"
same twice
# The last interval checkpoint of a whole run, continued (and checkpointing on) to the end.
"$bin" "${args[@]}" --t-end "$t_end" --out whole.csv --checkpoint whole.ckpt \
  --checkpoint-interval "$(frac 3)" 2>/dev/null || fail "run with checkpoints"
same whole
"$bin" "${args[@]}" --t-end "$t_end" --out last.csv --checkpoint whole.ckpt --restart whole.ckpt \
  2>/dev/null || fail "restart from the last interval checkpoint"
same last

# Signals: the run is stopped once its first wall-clock checkpoint exists (it is under way). It is
# frozen (SIGSTOP) as soon as the file appears, signalled, then let go (SIGCONT): the signal is
# handled at the run's next pause, so however fast the machine, the run cannot end between the
# check and the signal (a fixed sleep there let the whole run finish first on a faster machine).
wait_for() {  # wait_for FILE PID: until FILE exists (up to 60 s) while PID runs
  for _ in $(seq 6000); do
    [ -e "$1" ] && return 0
    kill -0 "$2" 2>/dev/null || return 1
    sleep 0.01
  done
  return 1
}
stopped=$((128 + $(kill -l STOP)))
for signal in TERM INT KILL; do
  rm -f sig.ckpt
  "$bin" "${args[@]}" --t-end "$t_end" --out "sig$signal.csv" --checkpoint sig.ckpt \
    --checkpoint-wall 0.01 2>"sig$signal.err" &
  pid=$!
  wait_for sig.ckpt "$pid" || fail "no checkpoint before the end of the run (SIG$signal)"
  kill -STOP "$pid" 2>/dev/null || fail "the run ended before it could be frozen for SIG$signal"
  kill "-$signal" "$pid"
  kill -CONT "$pid" 2>/dev/null
  # With job control, wait also returns when the job stops (status 128 + SIGSTOP), possibly after
  # the process has already ended: waiting again then gives the exit status that bash kept.
  while wait "$pid"; status=$?; [ "$status" -eq "$stopped" ]; do :; done
  case $signal in
    KILL) [ "$status" -eq 137 ] || fail "SIGKILL: status $status" ;;
    *) [ "$status" -eq 3 ] || fail "SIG$signal: status $status, expected 3 (checkpoint written)"
       grep -q "checkpoint written to sig.ckpt" "sig$signal.err" || fail "SIG$signal: no message"
       [ ! -e "sig$signal.csv" ] || fail "SIG$signal: an output written by an interrupted run" ;;
  esac
  # After SIGTERM the parameters are left to the checkpoint's head (a run stopped by a signal
  # wrote no CSV to take them from).
  again=("${args[@]}")
  [ "$signal" = TERM ] && again=(simulate --quiet)
  "$bin" "${again[@]}" --t-end "$t_end" --out "sig$signal.csv" --checkpoint sig.ckpt \
    --restart sig.ckpt 2>/dev/null || fail "restart after SIG$signal"
  same "sig$signal"
done
leftover=$(ls -A | grep -c 'molchaos-tmp' || true)
echo "temporary files left by SIGKILL: $leftover (the checkpoint itself is always whole)"
echo "ok: every interrupted run continued to the uninterrupted run's bytes (d = $dim, $mode)"
