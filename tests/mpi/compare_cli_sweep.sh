#!/usr/bin/env bash
# Usage: compare_cli_sweep.sh MPIEXEC NP WORK_DIR MOLCHAOS [MPIEXEC_FLAGS...]
# Runs one small `molchaos sweep` on the local thread pool and once under `MPIEXEC -np NP`, each
# into a fresh cache folder and summary CSV, and passes when
#  - the summary CSVs, the printed tables and every cache file are byte-identical,
#  - rank 0 reports that every rank computed runs (the sweep really was distributed),
#  - no rank other than 0 wrote anything (OpenMPI --tag-output marks each line with its rank),
#  - a second MPI pass resumes all runs from the cache and leaves the cache files unchanged.
set -u
mpiexec=$1 np=$2 work=$3 molchaos=$4
shift 4
mpi_flags=("$@")
sweep=(sweep --particles 500 --density 0.05 --restitution 0.85,0.95 --randomize none,flux
       --seeds 3)
fail() { echo "FAIL: $*"; exit 1; }

rm -rf "$work" && mkdir -p "$work/local" "$work/mpi" || fail "cannot create $work"
"$molchaos" "${sweep[@]}" --threads 2 --cache "$work/local/cache" --out "$work/local/summary.csv" \
  >"$work/local/stdout" 2>"$work/local/stderr" || { cat "$work/local/stderr"; fail "local sweep"; }

run_mpi() {  # $1: output prefix
  "$mpiexec" -np "$np" "${mpi_flags[@]}" --tag-output "$molchaos" "${sweep[@]}" \
    --cache "$work/mpi/cache" --out "$work/mpi/summary.csv" >"$1.stdout" 2>"$1.stderr"
}
run_mpi "$work/mpi/first" || { cat "$work/mpi/first.stderr"; fail "mpi sweep exit status $?"; }
cat "$work/mpi/first.stderr"

cmp "$work/local/summary.csv" "$work/mpi/summary.csv" || fail "summary CSVs differ"
diff -r "$work/local/cache" "$work/mpi/cache" || fail "cache folders differ"
# The table on stdout, with the rank tags taken off.
sed -E 's/^\[[0-9]+,0\]<stdout>://' "$work/mpi/first.stdout" | cmp - "$work/local/stdout" ||
  fail "printed tables differ"
if grep -Eq '^\[[0-9]+,[1-9][0-9]*\]' "$work/mpi/first.stdout" "$work/mpi/first.stderr"; then
  fail "a non-root rank printed something"
fi
counts=$(sed -nE 's/.*runs computed per rank:(( [0-9]+)+)$/\1/p' "$work/mpi/first.stderr")
[ -n "$counts" ] || fail "rank 0 did not distribute the sweep (no 'runs computed per rank' line)"
set -- $counts
[ $# -eq "$np" ] || fail "expected $np per-rank counts, got '$counts'"
for c in "$@"; do [ "$c" -gt 0 ] || fail "a rank computed no run: '$counts'"; done

cp -r "$work/mpi/cache" "$work/mpi/cache.first"
run_mpi "$work/mpi/second" || { cat "$work/mpi/second.stderr"; fail "resumed mpi sweep"; }
grep -q '12/12 runs done (12 from cache)' "$work/mpi/second.stderr" ||
  { cat "$work/mpi/second.stderr"; fail "second pass did not resume from the cache"; }
diff -r "$work/mpi/cache.first" "$work/mpi/cache" || fail "resume changed the cache"
cmp "$work/local/summary.csv" "$work/mpi/summary.csv" || fail "resumed summary differs"
echo "ok: local and $np-rank sweeps byte-identical"
