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

# name | arguments: 2D and 3D, each shuffle, cells and neighbour lists, a collapse, the TC model,
# contact statistics, snapshots, the collision and temperature stops.
cases=(
  "d2_paper_contacts|--dim 2 --particles 2000 --density 0.1 --restitution 0.8 --randomize paper --seed 3 --t-end 200 --contacts"
  "d2_none_snapshots|--dim 2 --particles 1000 --density 0.3 --restitution 0.9 --seed 5 --t-end 50 --snapshot-times 0 1 10"
  "d2_flux_tc|--dim 2 --particles 1000 --density 0.2 --restitution 0.5 --randomize flux --seed 7 --t-end 100 --tc 1e-4"
  "d2_collapse|--dim 2 --particles 1000 --density 0.5 --restitution 0.3 --seed 11 --t-end 1000"
  "d3_none_cells|--dim 3 --particles 2000 --density 0.1 --restitution 0.8 --seed 13 --t-end 100"
  "d3_paper_lists|--dim 3 --particles 2000 --density 0.6 --restitution 0.9 --randomize paper --seed 17 --t-end 20 --contacts"
  "d3_flux_min_temperature|--dim 3 --particles 1000 --density 0.2 --restitution 0.6 --randomize flux --seed 19 --t-end 1e4 --min-temperature 1e-3"
  "d2_max_collisions|--dim 2 --particles 500 --density 0.05 --restitution 0.98 --randomize paper --seed 23 --t-end 1e4 --max-collisions 50000"
)

run_case() {  # exe dir name args...
  local exe=$1 dir=$2 name=$3
  shift 3
  # A collapse ends with exit status 1 after writing its partial results: that is a case too.
  "$exe" simulate "$@" --quiet --out "$dir/$name.csv" >"$dir/$name.log" 2>&1 || true
  [ -s "$dir/$name.csv" ] || { echo "check_trajectories.sh: $exe wrote no $dir/$name.csv" >&2; cat "$dir/$name.log" >&2; exit 1; }
}

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
