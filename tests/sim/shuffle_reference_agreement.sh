#!/usr/bin/env bash
# The engine's collision frequency under the paper's shuffle against the brute-force reference
# (reference_shuffle_frequency.cpp, every pair time recomputed after every collision) under the
# same rule, the pairwise exchange of the donors. N = 32, n = 0.05, ε = 1, collisions counted over
# t ∈ (300, 3000], SEEDS independent runs of each code; the two means of ω/ω_E must agree within
# 3 combined standard errors. With 1000 seeds that error is about 6e-4, so the other reading of
# the rule (donors in the order drawn, 0.29 % more collisions: doc/validation.md) fails the test
# with a probability of about 0.97.
# Usage: tests/sim/shuffle_reference_agreement.sh MOLCHAOS REFERENCE [SEEDS]
set -euo pipefail
molchaos=${1:?molchaos binary}; reference=${2:?reference_shuffle_frequency binary}
seeds=${3:-1000}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
n=32 density=0.05 t_skip=300 t_end=3000

# Both codes on the two cores; each run leaves one file, the log holds what they said.
if ! { seq 1 "$seeds" | xargs -P 2 -I{} sh -c \
         "'$reference' $n $density 1 {} 20 $t_skip $t_end > '$work/reference_{}'" &&
       seq 1 "$seeds" | xargs -P 2 -I{} "$molchaos" simulate --quiet --particles $n \
         --density $density --restitution 1 --randomize paper --seed {} --t-end $t_end \
         --samples-per-decade 1 --t-first-sample $t_skip --out "$work/engine_{}.csv"; } \
     2> "$work/log"; then
  echo "a run failed; what the runs said:" >&2
  cat "$work/log" >&2
  exit 1
fi

# Enskog's frequency at T = 1 as the suite computes it (Henderson's g2, as the reference uses).
omega_enskog=$("$molchaos" theory --density $density --restitution 1 --json |
  python3 -c "import json, sys; print(repr(json.load(sys.stdin)['enskog_collision_frequency']))")

python3 - "$work" "$seeds" $n $t_skip $t_end "$omega_enskog" <<'EOF'
import math, sys
work, seeds, n, t_skip, t_end, omega_enskog = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), \
    float(sys.argv[4]), float(sys.argv[5]), float(sys.argv[6])

def engine_ratio(path):
    rows = {float(r[0]): int(r[3]) for r in
            (line.split(',') for line in open(path) if line[0].isdigit())}
    return 2 * (rows[t_end] - rows[t_skip]) / (n * (t_end - t_skip)) / omega_enskog

def mean_se(x):
    m = sum(x) / len(x)
    return m, math.sqrt(sum((v - m) ** 2 for v in x) / (len(x) - 1) / len(x))

engine = mean_se([engine_ratio(f"{work}/engine_{s}.csv") for s in range(1, seeds + 1)])
reference = mean_se([float(open(f"{work}/reference_{s}").read().split()[0]) for s in range(1, seeds + 1)])
z = (engine[0] - reference[0]) / math.hypot(engine[1], reference[1])
print(f"omega/omega_E, paper's shuffle, {seeds} seeds each: engine {engine[0]:.5f} ± {engine[1]:.5f},"
      f" reference {reference[0]:.5f} ± {reference[1]:.5f}, difference {z:+.2f} SE")
sys.exit(0 if abs(z) < 3 else 1)
EOF
