#!/usr/bin/env bash
# Usage: reproduce_one_seed.sh MOLCHAOS
# One seed per point gives values without standard errors: the report and every figure are still
# written (b at contact, which needs the error of the mean dyad, is left out of its figure), where
# the reproduction failed with "BData.panels[0].series[2].restitution is empty".
set -u
bin=$(realpath "$1")
. "$(dirname "$0")/../scratch.sh"
enter_scratch_folder

"$bin" reproduce --quick --seeds 1 --threads 2 --out one --cache one/cache >log.txt 2>&1 ||
  { cat log.txt; echo "FAIL: reproduce --quick --seeds 1 failed"; exit 1; }
for f in REPORT.md fig4_A_of_eps.png fig_b_of_eps.png; do
  [ -s "one/$f" ] || { echo "FAIL: no one/$f"; exit 1; }
done
echo "ok: reproduce --quick --seeds 1 writes its report and figures"
