#!/bin/bash
# The README's list of Debian packages is the Makefile's (PACKAGES, printed by `make packages`):
# an administrator who installs the README's list can build and run every target.
# Usage: readme_packages.sh SOURCE_DIR
set -euo pipefail
src=${1:?usage: readme_packages.sh SOURCE_DIR}
fail() { echo "FAIL: $*"; exit 1; }
make_list=$(make -s -C "$src" --no-print-directory packages | tr ' ' '\n' | sed '/^$/d' | sort)
# The README's list: the code block after the line that names PACKAGES.
readme_list=$(awk '/`PACKAGES`/ {armed = 1} armed && /^```/ {if (inside) exit; inside = 1; next}
                   inside {print}' "$src/README.md" | tr ' ' '\n' | sed '/^$/d' | sort)
[ -n "$readme_list" ] || fail "README.md: no package list after the line naming PACKAGES"
if [ "$make_list" != "$readme_list" ]; then
  echo "only in the Makefile: $(comm -23 <(echo "$make_list") <(echo "$readme_list") | tr '\n' ' ')"
  echo "only in README.md:    $(comm -13 <(echo "$make_list") <(echo "$readme_list") | tr '\n' ' ')"
  fail "README.md's package list differs from the Makefile's PACKAGES"
fi
echo "README.md lists the Makefile's $(echo "$make_list" | wc -l) packages"
