#!/usr/bin/env bash
# Usage: expect_clean_usage_error.sh MPIEXEC NP MOLCHAOS [MPIEXEC_FLAGS...] -- ARGS...
# Bad input under mpirun: the job ends (CTest's timeout catches a hang), with exit status 2 and
# rank 0's one-line "molchaos: error: ..." message; the workers were released and said nothing.
set -u
mpiexec=$1 np=$2 molchaos=$3
shift 3
mpi_flags=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do mpi_flags+=("$1"); shift; done
shift
out=$(mktemp) err=$(mktemp)
"$mpiexec" -np "$np" "${mpi_flags[@]}" --tag-output "$molchaos" "$@" >"$out" 2>"$err"
status=$?
cat "$err"
errors=$(grep -c '^\[[0-9]*,0\]<stderr>:molchaos: error: ' "$err")
others=$(grep -Ec '^\[[0-9]+,[1-9][0-9]*\]' "$out" "$err" | awk -F: '{s += $NF} END {print s}')
rm -f "$out" "$err"
[ "$status" -eq 2 ] || { echo "FAIL: exit status $status, expected 2"; exit 1; }
[ "$errors" -eq 1 ] || { echo "FAIL: expected one 'molchaos: error:' line from rank 0"; exit 1; }
[ "$others" -eq 0 ] || { echo "FAIL: non-root ranks printed $others line(s)"; exit 1; }
echo "ok"
