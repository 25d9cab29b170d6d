#!/usr/bin/env python3
"""Checks that every "value ± error", χ² and p quoted in README.md's findings is in a report.

Usage: readme_findings.py README.md results/REPORT.md

A "value ± error" quote matches a pair of the report that rounds to it (the README rounds to
fewer digits), signs and minus signs (− or -) alike; a quoted χ² (or chi2) matches a χ² of the
report, a quoted p a p of the report, in the same way (3e-10 matches 2.7e-10). Prints the quotes
not found and exits 1 if there are any, so that a `make reproduce` whose numbers moved says which
sentences of the README to update.
"""
import re
import sys

PAIR = re.compile(r"([+\-−]?\d+(?:\.\d+)?)\s*±\s*(\d+(?:\.\d+)?(?:e-?\d+)?)")
# "χ² = 5.5" and "χ² of A = A_theory = 14.9" (the report names what the χ² tests)
CHI2 = re.compile(r"(?:χ²|chi2)(?:\s+of\s[^=]+=[^=]+)?\s*=\s*(\d+(?:\.\d+)?)")
P_VALUE = re.compile(r"\bp\s*=\s*(\d+(?:\.\d+)?(?:e-?\d+)?)")


def decimals(text):
    return len(text.split(".")[1]) if "." in text else 0


def rounds_to(quoted, exact):
    """True when the number `exact` (from the report) rounds to `quoted` at quoted's last digit
    (of its mantissa times its power of ten, for a quote such as 3e-10)."""
    mantissa, _, exponent = quoted.replace("−", "-").partition("e")
    unit = 10.0 ** (int(exponent) if exponent else 0)
    return abs(float(exact) - float(mantissa) * unit) <= 0.5 * 10 ** -decimals(mantissa) * unit * (
        1 + 1e-9)


def findings_section(readme):
    match = re.search(r"^## What it finds\n(.*?)(?=^## )", readme, re.S | re.M)
    if not match:
        sys.exit("readme_findings.py: README.md has no '## What it finds' section")
    return match.group(1)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__.strip().splitlines()[2])
    with open(sys.argv[1], encoding="utf-8") as f:
        findings = findings_section(f.read())
    with open(sys.argv[2], encoding="utf-8") as f:
        report = f.read().replace("−", "-")
    quotes = PAIR.findall(findings)
    pairs = PAIR.findall(report)
    missing = [f"{v} ± {e}" for v, e in quotes
               if not any(rounds_to(v, pv) and rounds_to(e, pe) for pv, pe in pairs)]
    tests = 0
    for name, pattern in (("χ²", CHI2), ("p", P_VALUE)):
        quoted = pattern.findall(findings)
        tests += len(quoted)
        shown = pattern.findall(report)
        missing += [f"{name} = {q}" for q in quoted if not any(rounds_to(q, s) for s in shown)]
    for quote in missing:
        print(f"README.md quotes {quote}, which {sys.argv[2]} does not show")
    print(f"README.md's findings quote {len(quotes)} values with errors and {tests} χ² and p; "
          f"{len(quotes) + tests - len(missing)} of them are in {sys.argv[2]}")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
