#!/usr/bin/env bash
# Usage: bench_simulation_table.sh MOLCHAOS
# bench --simulation prints, for the same runs, the CPU seconds to 0.1 % on A in its table (the
# estimator A comes from, the integrated form) and once more in the line by estimator: both from
# the scatter relative to the measured A, so the two figures agree.
set -u
bin=$(realpath "$1")
. "$(dirname "$0")/../scratch.sh"
enter_scratch_folder

"$bin" bench --simulation --particles 100,200 --work 1000 --threads 1 --out b >out.txt 2>err.txt ||
  { cat err.txt; fail "bench --simulation"; }
for n in 100 200; do
  table=$(awk -v n="$n" '$1 == n && NF > 10 {print $(NF - 2)}' out.txt)
  line=$(grep "^  N = $n:" out.txt | sed -n 's/.*integrated \([0-9.]*\) s.*/\1/p')
  [ -n "$table" ] && [ -n "$line" ] || { cat out.txt; fail "N = $n: no table row or estimator line"; }
  [ "$table" = "$line" ] || { cat out.txt; fail "N = $n: 0.1 % costs $table s in the table, $line s by estimator"; }
  echo "N = $n: $table s both"
done
echo "ok: the table and the estimators' line give one cost"
