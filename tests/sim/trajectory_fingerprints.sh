#!/bin/bash
# The same seed gives the same bytes on every build of this tree, whatever its compiler flags
# (-march=native included: contraction is off): runs the cases of trajectory_cases.sh with
# MOLCHAOS and compares the SHA-256 of every CSV it writes (the version line left out) with
# trajectory_fingerprints.txt, recorded with the baseline x86-64 build on Debian 12 (GCC 12,
# glibc 2.36: the initial velocities go through libm's log, sin and cos, which another C library
# may round differently). An engine change that should keep trajectories fails here when it does
# not.
# Usage: tests/sim/trajectory_fingerprints.sh MOLCHAOS [--record]
# --record rewrites the fingerprints: only for an engine change that alters event order on
# purpose, or a new header of a result file whose rows stay the same, said in its commit
# (check_trajectories.sh shows which cases change). A few seconds.
set -euo pipefail
exe=${1:?usage: trajectory_fingerprints.sh MOLCHAOS [--record]}
mode=${2:-check}
[ -x "$exe" ] || { echo "trajectory_fingerprints.sh: '$exe' is not an executable" >&2; exit 2; }
case "$mode" in check|--record) ;; *) echo "trajectory_fingerprints.sh: unknown option '$mode'" >&2; exit 2;; esac
here=$(cd "$(dirname "$0")" && pwd)
recorded="$here/trajectory_fingerprints.txt"
. "$here/trajectory_cases.sh"  # cases=(...) and run_case
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

for entry in "${cases[@]}"; do
  name=${entry%%|*}
  read -r -a args <<<"${entry#*|}"
  run_case "$exe" "$work" "$name" "${args[@]}"
done
(cd "$work" && for f in *.csv; do
  printf '%s  %s\n' "$(grep -v '^# version' "$f" | sha256sum | cut -d' ' -f1)" "$f"
done) >"$work/fingerprints"

if [ "$mode" = --record ]; then
  cp "$work/fingerprints" "$recorded"
  echo "recorded $(wc -l <"$recorded") fingerprints in $recorded"
  exit 0
fi
[ -f "$recorded" ] || { echo "trajectory_fingerprints.sh: no $recorded (run with --record)" >&2; exit 2; }
if diff <(cut -d' ' -f3 "$recorded") <(cut -d' ' -f3 "$work/fingerprints") >/dev/null; then :; else
  echo "trajectory_fingerprints.sh: the cases wrote other files than recorded:" >&2
  diff <(cut -d' ' -f3 "$recorded") <(cut -d' ' -f3 "$work/fingerprints") >&2 || true
  exit 1
fi
failed=0
while read -r sum file; do
  if grep -qx "$sum  $file" "$recorded"; then
    echo "same bytes  $file"
  else
    echo "DIFFERENT   $file"
    failed=1
  fi
done <"$work/fingerprints"
[ "$failed" = 0 ] && echo "all $(wc -l <"$recorded") result files byte-identical to the recorded ones" ||
  { echo "trajectories differ from the recorded ones" >&2; exit 1; }
