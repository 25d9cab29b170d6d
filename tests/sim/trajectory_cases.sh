# The simulate cases whose trajectories the engine must keep byte for byte, and how one is run;
# sourced by check_trajectories.sh (two binaries against each other) and trajectory_fingerprints.sh
# (one binary against the recorded fingerprints).

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
  [ -s "$dir/$name.csv" ] || { echo "$(basename "$0"): $exe wrote no $dir/$name.csv" >&2; cat "$dir/$name.log" >&2; exit 1; }
}
