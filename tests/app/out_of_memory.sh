#!/usr/bin/env bash
# Usage: out_of_memory.sh MOLCHAOS
# A run whose parameters alone say it cannot fit in the memory this process may use is refused
# before it starts (exit 2, naming the parameter and how far it may go); a run that passes that
# check and still runs out of memory stops with one line saying so (not "std::bad_alloc") and
# exit status 1. Neither leaves an output behind; in a sweep, the failed runs are noted.
set -u
bin=$(realpath "$1")
. "$(dirname "$0")/../scratch.sh"
enter_scratch_folder
no_files() { [ -z "$(ls -A | grep -v '^err.txt$')" ] || fail "$1: files left behind: $(ls -A)"; }
# refused_at_once LABEL PATTERN ARGS...: simulate ARGS, its address space limited to 2 GB, exits 2
# at once with a message matching PATTERN and leaves no file.
refused_at_once() {
  local label=$1 pattern=$2
  shift 2
  (ulimit -v 2000000; "$bin" simulate "$@" --out run.csv 2>err.txt)
  local status=$?
  [ "$status" -eq 2 ] || fail "simulate, $label: exit status $status, expected 2"
  grep -q -- "$pattern" err.txt || fail "simulate, $label, said: $(cat err.txt)"
  no_files "$label"
  echo "ok: refused at once: $(cat err.txt)"
}
# 1e8 disks hold at least 15 GB.
refused_at_once "1e8 disks" \
  "--particles: a run of 100000000 disks holds at least 15 GB.*allowed: at most [0-9]* particles" \
  --particles 100000000 --t-end 1
# 3000 snapshots of 1e5 disks take 9.6 GB.
refused_at_once "3000 snapshots" \
  "--snapshot-times: 3000 snapshots of 100000 disks take at least 9.6 GB.*allowed: at most [0-9]* snapshot times" \
  --particles 100000 --relax 0 --t-end 3000 --snapshot-times $(seq -s ' ' 1 3000)
# 3e6 disks pass the check under 0.5 GB (at least 150 bytes each) but need more.
(ulimit -v 500000; "$bin" simulate --particles 3000000 --t-end 1 --out run.csv 2>err.txt)
status=$?
[ "$status" -eq 1 ] || fail "simulate, 3e6 disks: exit status $status, expected 1"
grep -q "out of memory.*fewer particles" err.txt || fail "simulate, 3e6 disks, said: $(cat err.txt)"
no_files "3e6 disks"
echo "ok: simulate: $(cat err.txt)"
(ulimit -v 500000; "$bin" sweep --particles 3000000 --restitution 0.9 --seeds 1 --threads 1 \
  --t-end-tau0 0.1 --cache '' --out summary.csv >out.txt 2>err.txt)
grep -q "out of memory" err.txt out.txt summary.csv 2>/dev/null ||
  fail "sweep did not say out of memory: $(cat err.txt out.txt)"
echo "ok: sweep notes the run as out of memory"
