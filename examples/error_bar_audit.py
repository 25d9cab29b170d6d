"""Check a sweep's error bars by repetition: run the same `molchaos sweep` K times, each with its
own base seed, and compare at every state point the scatter of the K results with the standard
errors the sweep reported for them.

    PYTHONPATH=build/python /usr/bin/python3 examples/error_bar_audit.py --repeats 60 -- \\
        --particles 1000 --restitution 0.7,0.9 --randomize none,flux --seeds 6

Everything after `--` is passed to `molchaos sweep` (its own --base-seed, --cache and --out are
the audit's). For every column X with an error column X_err (A, a2, mean_dyad, collision_ratio,
breakdown_time):

- R = (standard deviation of the K values of X) / (rms of their K reported errors). Honest error
  bars give R = 1; R > 1 means they are too small. The 95 % interval and the two-sided p value
  treat (K − 1) R² as χ² with K − 1 degrees of freedom (normal results, exact errors).
- With --reference-seeds M, one more sweep of the same points with M seeds and no --target-error
  gives each point's scatter per run, s; then Q = √(mean of s²/n) / (rms reported error), n the
  runs of each repetition, compares the errors with what they should be far more precisely than R
  (Q's own relative error is about 1/√(2(M − 1))). This is the check for staged sweeps
  (--target-error), whose number of runs depends on their scatter.

Each repetition's base seed is --first-base-seed + k (k = 0 … K − 1); a staged sweep gets a
temporary cache of its own. The table is printed, and written as CSV with --out.
"""

import argparse
import math
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np
from scipy import stats

import molchaos

POINT = ["density", "restitution", "method", "randomize"]
# The count behind a column's error: the runs of a point, or the runs that broke down.
RUNS_OF = {"breakdown_time": "breakdowns"}
# Options of `molchaos sweep` the audit sets itself, and those a reference sweep leaves out.
AUDIT_OWNS = ["--base-seed", "--cache", "--out", "--quiet"]
STAGING = ["--target-error", "--max-seeds", "--seeds"]


def without(args, options):
    """args with every option in `options` and its value removed (both `--x v` and `--x=v`)."""
    out, skip = [], False
    for a in args:
        if skip:
            skip = False
        elif a in options:
            skip = a != "--quiet"
        elif a.split("=", 1)[0] not in options:
            out.append(a)
    return out


def run_sweep(binary, args, base_seed, staged):
    """One sweep's table, run with `base_seed`; a staged sweep in a temporary cache of its own."""
    with tempfile.TemporaryDirectory(prefix="molchaos-audit-") as tmp:
        out = os.path.join(tmp, "sweep.csv")
        cache = os.path.join(tmp, "cache") if staged else ""
        command = [binary, "sweep", *args, "--base-seed", str(base_seed), "--cache", cache,
                   "--out", out, "--quiet"]
        done = subprocess.run(command, capture_output=True, text=True)
        # A sweep some of whose runs failed (a gas that clustered before its fit window) still
        # writes its table, whose points count the runs that succeeded, and exits with 1.
        if done.returncode not in (0, 1) or not os.path.exists(out):
            raise RuntimeError(f"{' '.join(command)} failed (exit {done.returncode}):\n"
                               f"{done.stderr.strip()}")
        table, _ = molchaos.read_table(out)
        return table


def point_key(row):
    return tuple(row[c] for c in POINT)


def audit(tables, reference=None):
    """The rows of the audit: one per state point and column with errors, from the K tables of
    the repetitions (and the reference table, if any). Each row: the point, the column, K, R with
    its 95 % interval and p, and Q with its relative error (nan without a reference)."""
    first = tables[0]
    columns = [c for c in first.columns if c + "_err" in first.columns and c != "A_theory"]
    by_point = [{point_key(r): r for _, r in t.iterrows()} for t in tables]
    ref = {point_key(r): r for _, r in reference.iterrows()} if reference is not None else {}
    rows = []
    for key in by_point[0]:
        if any(key not in t for t in by_point):
            raise ValueError(f"point {key} is not in every repetition's table")
        for column in columns:
            values = [t[key][column] for t in by_point]
            errors = [t[key][column + "_err"] for t in by_point]
            runs = [t[key][RUNS_OF.get(column, "runs")] for t in by_point]
            values, errors, runs = map(np.asarray, (values, errors, runs))
            usable = np.isfinite(values) & np.isfinite(errors) & (errors > 0)
            values, errors, runs = values[usable], errors[usable], runs[usable]
            k = len(values)
            if k < 3:
                continue
            rms_error = math.sqrt(np.mean(errors**2))
            r = np.std(values, ddof=1) / rms_error
            dof = k - 1
            chi2 = dof * r * r
            p = 2.0 * min(stats.chi2.cdf(chi2, dof), stats.chi2.sf(chi2, dof))
            low = r * math.sqrt(dof / stats.chi2.ppf(0.975, dof))
            high = r * math.sqrt(dof / stats.chi2.ppf(0.025, dof))
            q = q_error = math.nan
            if key in ref and column not in RUNS_OF:
                rr = ref[key]
                m = rr[RUNS_OF.get(column, "runs")]
                if m >= 2 and np.isfinite(rr[column + "_err"]):
                    per_run = rr[column + "_err"] * math.sqrt(m)
                    q = math.sqrt(np.mean(per_run**2 / runs)) / rms_error
                    q_error = q / math.sqrt(2.0 * (m - 1))
            rows.append(dict(zip(POINT, key), column=column, K=k, runs=float(np.mean(runs)), R=r,
                             R_low=low, R_high=high, p=p, Q=q, Q_err=q_error))
    return rows


def main(sweep_args, repeats=30, reference_seeds=0, first_base_seed=1000, binary=None,
         out=None, progress=False):
    if isinstance(repeats, bool) or not isinstance(repeats, int) or repeats < 3:
        raise ValueError(f"repeats: must be a whole number >= 3, got {repeats!r}")
    if isinstance(reference_seeds, bool) or not isinstance(reference_seeds, int) or \
            reference_seeds == 1 or reference_seeds < 0:
        raise ValueError(f"reference_seeds: must be 0 (none) or a whole number >= 2, "
                         f"got {reference_seeds!r}")
    binary = binary or os.environ.get("MOLCHAOS_BIN") or shutil.which("molchaos") or \
        "build/molchaos"
    args = without(list(sweep_args), AUDIT_OWNS)
    staged = any(a.split("=", 1)[0] == "--target-error" for a in args)
    tables = []
    for k in range(repeats):
        tables.append(run_sweep(binary, args, first_base_seed + k, staged))
        if progress:
            print(f"\rrepetition {k + 1}/{repeats}", end="", file=sys.stderr, flush=True)
    if progress:
        print(file=sys.stderr)
    reference = None
    if reference_seeds:
        # Its base seed lies beyond every repetition's, so that its runs are none of theirs.
        reference = run_sweep(binary, without(args, STAGING) + ["--seeds", str(reference_seeds)],
                              first_base_seed + repeats, staged=False)
    rows = audit(tables, reference)
    if out:
        import csv
        with open(out, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()) if rows else POINT)
            writer.writeheader()
            writer.writerows(rows)
    return rows


def print_rows(rows):
    print(f"{'density':>8} {'eps':>6} {'method':>6} {'mode':>6} {'column':>16} {'K':>4} "
          f"{'runs':>6} {'R':>6} {'95% interval':>14} {'p':>7} {'Q':>12}")
    for r in rows:
        q = f"{r['Q']:.3f}±{r['Q_err']:.3f}" if np.isfinite(r["Q"]) else "-"
        print(f"{r['density']:>8} {r['restitution']:>6} {r['method']:>6} {r['randomize']:>6} "
              f"{r['column']:>16} {r['K']:>4} {r['runs']:>6.1f} {r['R']:>6.3f} "
              f"[{r['R_low']:.2f}, {r['R_high']:.2f}] {r['p']:>7.3g} {q:>12}")


def whole_number(minimum):
    def parse(text):
        try:
            value = int(text)
        except ValueError:
            value = None
        if value is None or value < minimum:
            raise argparse.ArgumentTypeError(f"must be a whole number >= {minimum}, got {text!r}")
        return value
    return parse


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--repeats", type=whole_number(3), default=30,
                        help="independent repetitions K of the sweep (>= 3; default 30)")
    parser.add_argument("--reference-seeds", type=whole_number(2), default=0,
                        help="seeds M of a reference sweep for Q (>= 2; default: none)")
    parser.add_argument("--first-base-seed", type=whole_number(0), default=1000,
                        help="base seed of the first repetition (default 1000)")
    parser.add_argument("--molchaos", default=None,
                        help="the molchaos program (default: $MOLCHAOS_BIN, then PATH, then "
                             "build/molchaos)")
    parser.add_argument("--out", default=None, help="also write the table as CSV here")
    parser.add_argument("sweep_args", nargs=argparse.REMAINDER,
                        help="-- then the options of `molchaos sweep`")
    a = parser.parse_args()
    sweep_args = a.sweep_args[1:] if a.sweep_args[:1] == ["--"] else a.sweep_args
    try:
        result = main(sweep_args, a.repeats, a.reference_seeds, a.first_base_seed, a.molchaos,
                      a.out, progress=sys.stderr.isatty())
    except (RuntimeError, ValueError) as e:
        print(f"error_bar_audit: {e}", file=sys.stderr)
        sys.exit(1)
    print_rows(result)
