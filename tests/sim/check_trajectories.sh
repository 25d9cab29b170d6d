#!/bin/bash
# Byte-identity of trajectories between two molchaos binaries: runs the same simulate cases with
# REFERENCE and CANDIDATE and compares every CSV (time series and snapshots) with `cmp`, the
# version line (the git commit) filtered out. Refactorings of the engine must pass it.
# Usage: tests/sim/check_trajectories.sh REFERENCE_BINARY CANDIDATE_BINARY [WORK_DIR]
# The reference outputs are kept in WORK_DIR/reference and reused when present. About a minute.
set -euo pipefail
reference=${1:?usage: check_trajectories.sh REFERENCE_BINARY CANDIDATE_BINARY [WORK_DIR]}
candidate=${2:?usage: check_trajectories.sh REFERENCE_BINARY CANDIDATE_BINARY [WORK_DIR]}
work=${3:-$(mktemp -d)}
for exe in "$reference" "$candidate"; do
  [ -x "$exe" ] || { echo "check_trajectories.sh: '$exe' is not an executable" >&2; exit 2; }
done
mkdir -p "$work/reference" "$work/candidate"

. "$(dirname "$0")/trajectory_cases.sh"  # cases=(...) and run_case

# The column line of a result file (the first line that is not a comment).
columns() { grep -v -m1 '^#' "$1"; }
# True if OTHER's columns begin with FILE's and every line agrees in FILE's columns.
same_in_reference_columns() {
  local n
  n=$(columns "$1" | tr ',' '\n' | wc -l)
  case "$(columns "$2")," in "$(columns "$1"),"*) ;; *) return 1 ;; esac
  cmp -s <(grep -v '^# version' "$1" | cut -d, -f1-"$n") <(grep -v '^# version' "$2" | cut -d, -f1-"$n")
}
added_columns() { columns "$2" | cut -d, -f"$(( $(columns "$1" | tr ',' '\n' | wc -l) + 1 ))"-; }

failed=0
for entry in "${cases[@]}"; do
  name=${entry%%|*}
  read -r -a args <<<"${entry#*|}"
  [ -s "$work/reference/$name.csv" ] || run_case "$reference" "$work/reference" "$name" "${args[@]}"
  rm -f "$work/candidate/$name".*
  run_case "$candidate" "$work/candidate" "$name" "${args[@]}"
  for file in "$work/reference/$name"*.csv; do
    other="$work/candidate/$(basename "$file")"
    if [ -f "$other" ] && cmp -s <(grep -v '^# version' "$file") <(grep -v '^# version' "$other"); then
      echo "identical  $(basename "$file")  ($(grep -m1 '^# stop_reason' "$file" | cut -c3-60))"
    elif [ -f "$other" ] && same_in_reference_columns "$file" "$other"; then
      # A candidate that writes more columns (a newer file format): the reference's columns match.
      echo "identical  $(basename "$file")  in the reference's columns (the candidate adds $(added_columns "$file" "$other"))"
    else
      echo "DIFFERENT  $(basename "$file")"
      failed=1
    fi
  done
done
[ "$failed" = 0 ] && echo "all trajectories byte-identical" || { echo "trajectories differ" >&2; exit 1; }
