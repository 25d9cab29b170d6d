#!/usr/bin/env bash
# Usage: cache_write_failure.sh MPIEXEC NP WORK_DIR MOLCHAOS [MPIEXEC_FLAGS...]
# A cache that cannot take a run's result is the sweep's failure, not the run's, under mpirun as
# on the local thread pool: exit 1 with rank 0's one line naming the cache folder and the OS
# error, no run counted as failed, no summary written, no temporary left, the workers released.
#  1. Every entry's name taken by a directory (the rename into place fails): needs no privileges.
#  2. A full cache disk (a tmpfs of 8 kB), where mounting is allowed, for `sweep` and `reproduce`.
set -u
mpiexec=$1 np=$2 work=$3 molchaos=$4
shift 4
mpi_flags=("$@")
sweep=(sweep --particles 200 --density 0.05 --restitution 0.9 --seeds 4 --quiet)
. "$(dirname "$0")/../scratch.sh"
enter_scratch_folder "$work"

# expect_cache_failure NAME PATTERN ARGS...: runs ARGS under mpirun and checks the outcome.
expect_cache_failure() {
  local name=$1 pattern=$2
  shift 2
  "$mpiexec" -np "$np" "${mpi_flags[@]}" --tag-output "$molchaos" "$@" >"$name.out" 2>"$name.err"
  local status=$?
  cat "$name.err"
  [ "$status" -eq 1 ] || fail "$name: exit status $status, expected 1"
  grep -Eq "^\[[0-9]+,0\]<stderr>:molchaos: failed: $pattern" "$name.err" ||
    fail "$name: no 'molchaos: failed: $pattern' line from rank 0"
  if grep -Eq 'run\(s\) failed|\) failed: ' "$name.err"; then
    fail "$name: a cache write failure was counted as a failed run"
  fi
  if grep -Eq '^\[[0-9]+,[1-9][0-9]*\]' "$name.out" "$name.err"; then
    fail "$name: a non-root rank printed something"
  fi
}

# 1. The entries' names are taken by directories.
"$molchaos" "${sweep[@]}" --threads 1 --cache names >/dev/null 2>&1 || fail "local sweep"
mkdir blocked
for entry in names/*.csv; do mkdir "blocked/$(basename "$entry")"; done
expect_cache_failure blocked \
  "cannot store a run in the cache blocked: cannot write blocked/[0-9a-f]{16}\.csv: rename failed \(Is a directory\)$" \
  "${sweep[@]}" --cache blocked --out blocked.csv
[ ! -e blocked.csv ] || fail "a summary was written although the cache failed"
[ -z "$(find blocked -type f)" ] || fail "files left in the blocked cache: $(find blocked -type f)"
echo "ok: entries that cannot be renamed into place stop the sweep"

# 2. A full cache disk.
if mount_small_tmpfs small 8k; then
  expect_cache_failure full_sweep \
    "cannot store a run in the cache small: .*No space left on device" \
    "${sweep[@]}" --cache small --out full.csv
  [ ! -e full.csv ] || fail "a summary was written although the cache was full"
  [ -z "$(ls -A small | grep -v '\.csv$' || true)" ] || fail "temporaries left: $(ls -A small)"
  rm -f small/*
  # reproduce once stopped here with "Fig3Data.curves[0].t is empty".
  expect_cache_failure full_reproduce \
    "cannot store a run in the cache small: .*No space left on device" \
    reproduce --quick --seeds 1 --no-figures --cache small --out rep
  [ ! -e rep/REPORT.md ] || fail "a report was written although the cache was full"
  echo "ok: a full cache disk stops the sweep and the reproduction"
else
  echo "note: cannot mount a tmpfs here; full-disk case not run"
fi
echo "ok: cache write failures under $np MPI ranks"
