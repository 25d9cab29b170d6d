#!/usr/bin/env bash
# Usage: out_of_memory.sh MOLCHAOS
# A run that does not fit in memory stops with one line saying so (not "std::bad_alloc") and exit
# status 1, and leaves no output behind; in a sweep, the failed runs are noted as out of memory.
set -u
bin=$(realpath "$1")
. "$(dirname "$0")/../scratch.sh"
enter_scratch_folder
# 1e8 disks need about 20 GB; the address space is limited to 2 GB.
(ulimit -v 2000000; "$bin" simulate --particles 100000000 --t-end 1 --out run.csv 2>err.txt)
status=$?
[ "$status" -eq 1 ] || fail "simulate: exit status $status, expected 1"
grep -q "out of memory.*fewer particles" err.txt || fail "simulate said: $(cat err.txt)"
[ -z "$(ls -A | grep -v '^err.txt$')" ] || fail "files left behind: $(ls -A)"
echo "ok: simulate: $(cat err.txt)"
(ulimit -v 2000000; "$bin" sweep --particles 100000000 --restitution 0.9 --seeds 1 --threads 1 \
  --t-end-tau0 0.1 --cache '' --out summary.csv >out.txt 2>err.txt)
grep -q "out of memory" err.txt out.txt summary.csv 2>/dev/null ||
  fail "sweep did not say out of memory: $(cat err.txt out.txt)"
echo "ok: sweep notes the run as out of memory"
