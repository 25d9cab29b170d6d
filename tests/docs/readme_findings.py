#!/usr/bin/env python3
"""Checks that every "value ± error" quoted in README.md's findings is in a reproduction report.

Usage: readme_findings.py README.md results/REPORT.md

A quote matches a pair of the report that rounds to it (the README rounds to fewer digits), signs
and minus signs (− or -) alike. Prints the quotes not found and exits 1 if there are any, so that
a `make reproduce` whose numbers moved says which sentences of the README to update.
"""
import re
import sys

PAIR = re.compile(r"([+\-−]?\d+(?:\.\d+)?)\s*±\s*(\d+(?:\.\d+)?(?:e-?\d+)?)")


def decimals(text):
    return len(text.split(".")[1]) if "." in text else 0


def rounds_to(quoted, exact):
    """True when the number `exact` (from the report) rounds to `quoted` at quoted's decimals."""
    q = float(quoted.replace("−", "-"))
    return abs(float(exact) - q) <= 0.5 * 10 ** -decimals(quoted) * (1 + 1e-9)


def findings_section(readme):
    match = re.search(r"^## What it finds\n(.*?)(?=^## )", readme, re.S | re.M)
    if not match:
        sys.exit("readme_findings.py: README.md has no '## What it finds' section")
    return match.group(1)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__.strip().splitlines()[2])
    with open(sys.argv[1], encoding="utf-8") as f:
        quotes = PAIR.findall(findings_section(f.read()))
    with open(sys.argv[2], encoding="utf-8") as f:
        pairs = PAIR.findall(f.read().replace("−", "-"))
    missing = [f"{v} ± {e}" for v, e in quotes
               if not any(rounds_to(v, pv) and rounds_to(e, pe) for pv, pe in pairs)]
    for quote in missing:
        print(f"README.md quotes {quote}, which {sys.argv[2]} does not show")
    print(f"README.md's findings quote {len(quotes)} values with errors; "
          f"{len(quotes) - len(missing)} of them are in {sys.argv[2]}")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
