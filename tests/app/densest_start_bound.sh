#!/usr/bin/env bash
# Usage: densest_start_bound.sh MOLCHAOS
# Above the densest initial state for its N a density is refused with the range that the check
# applies: the bound printed is refused, the double just below it runs (a bound computed apart from
# the check was 1.1111100000011112 where 1.11111 ran, 0.999999 for spheres where 0.9999999 ran).
set -u
bin=$(realpath "$1")
. "$(dirname "$0")/../scratch.sh"
enter_scratch_folder
for args in "--particles 1000 --density 1.12" "--dim 3 --particles 1000 --density 1.05"; do
  # shellcheck disable=SC2086 # the words of $args are separate flags
  bound=$("$bin" simulate $args --out x.csv 2>&1 | grep -o 'allowed range (0, [0-9.e+-]*)' |
    sed 's/.*(0, //; s/)//')
  [ -n "$bound" ] || fail "no bound in the refusal of $args"
  below=$(/usr/bin/python3 -c "import math; print(repr(math.nextafter($bound, 0)))")
  # shellcheck disable=SC2086
  set -- $args
  "$bin" simulate "${@:1:$#-2}" --density "$bound" --relax 0 --t-end 1e-9 --quiet --out at.csv \
    >/dev/null 2>&1 && fail "$args: the printed bound $bound runs"
  "$bin" simulate "${@:1:$#-2}" --density "$below" --relax 0 --t-end 1e-9 --quiet --out below.csv \
    >/dev/null 2>&1 || fail "$args: $below, just below the printed bound $bound, is refused"
done
echo "ok: the densest-start bound printed is the check's own"
