#!/usr/bin/env bash
# Elastic-limit check of every randomization mode: at restitution 1 the gas is in
# equilibrium, so its collision frequency per particle, omega = 2 C / (N t), must equal Enskog's,
# 2 n g2 sqrt(pi T) (d = 2, Henderson g2) or 4 n g2 sqrt(pi T) (d = 3, Carnahan-Starling g2), T = 1.
# Runs `molchaos simulate` for independent seeds and prints omega/omega_E with its standard error.
# Collisions are counted over the second half of each run, as the reproduction counts them: a
# shuffle builds its pair correlations over the first few tens of time units after the elastic
# relaxation, and a count from t = 0 would take in that transient.
# Usage: tests/sim/measure_elastic_limit.sh BUILD_DIR OUT_DIR [SEEDS] [COLLISIONS_COUNTED] [N]
set -euo pipefail
build=${1:?build dir}; out=${2:?output dir}; seeds=${3:-10}; collisions=${4:-500000}; n=${5:-5000}
mkdir -p "$out"
printf "%-3s %-6s %-6s %6s %12s %10s %10s %8s\n" d n mode seeds coll/run ratio stderr dev/se
for d in 2 3; do
  for density in 0.05 0.1; do
    # Enskog's frequency at T = 1 as the suite computes it, and a run twice as long as the
    # counted collisions need.
    omega_enskog=$("$build/molchaos" theory --dim "$d" --density "$density" --restitution 1 --json |
      python3 -c "import json, sys; print(repr(json.load(sys.stdin)['enskog_collision_frequency']))")
    t_end=$(python3 -c "print(4*$collisions/($n*$omega_enskog))")
    t_half=$(python3 -c "print($t_end/2)")
    for mode in none paper flux; do
      ratios=()
      for seed in $(seq 1 "$seeds"); do
        f="$out/d${d}_n${density}_${mode}_s${seed}.csv"
        "$build/molchaos" simulate --quiet --dim "$d" --particles "$n" --density "$density" \
          --restitution 1 --randomize "$mode" --seed "$seed" --t-end "$t_end" \
          --samples-per-decade 1 --t-first-sample "$t_half" --out "$f" 2>/dev/null
        ratios+=("$(python3 -c "
rows=[l.split(',') for l in open('$f') if l[0].isdigit()]
(t0,c0),(t1,c1)=[(float(r[0]),int(r[3])) for r in rows[-2:]]  # t_end/2 and t_end
print(2*(c1-c0)/($n*(t1-t0))/$omega_enskog, c1-c0)")")
      done
      printf "%s\n" "${ratios[@]}" | python3 -c "
import sys,math
rows=[l.split() for l in sys.stdin if l.strip()]
x=[float(r[0]) for r in rows]; c=sum(int(r[1]) for r in rows)//len(rows)
m=sum(x)/len(x); se=math.sqrt(sum((v-m)**2 for v in x)/(len(x)-1)/len(x))
print('%-3s %-6s %-6s %6d %12d %10.5f %10.5f %8.1f' % ('$d','$density','$mode',len(x),c,m,se,(m-1)/se))"
    done
  done
done
