"""Check a sweep's error bars by repetition: run the same `molchaos sweep` K times, each with its
own base seed, and compare at every state point the scatter of the K results with the standard
errors the sweep reported for them.

    PYTHONPATH=build/python /usr/bin/python3 examples/error_bar_audit.py --repeats 60 -- \\
        --particles 1000 --restitution 0.7,0.9 --randomize none,flux --seeds 6

Everything after `--` is passed to `molchaos sweep` (its own --base-seed, --cache and --out are
the audit's). With --reproduce TABLE it is passed to `molchaos reproduce` instead, and the audit
reads that table of each reproduction (e.g. fig4_fits.csv, the slopes of Fig. 4). For every
column X with an error column X_err (A, a2, mean_dyad, collision_ratio, breakdown_time of a
sweep), and for every further error of X (X_err_..., such as slope_err_over_seeds):

- R = (standard deviation of the K values of X) / (rms of their K reported errors). Honest error
  bars give R = 1; R > 1 means they are too small. The 95 % interval and the two-sided p value
  treat (K − 1) R² as χ² with K − 1 degrees of freedom (normal results, exact errors).
- With --reference-seeds M, one more sweep of the same points with M seeds and no --target-error
  gives each point's scatter per run, s; then Q = √(mean of s²/n) / (rms reported error), n the
  runs of each repetition, compares the errors with what they should be more precisely than R
  (Q's own relative error is about 1/√(2(M − 1)), R's 1/√(2(K − 1))). This is the check for
  staged sweeps (--target-error), whose number of runs depends on their scatter.
- kurtosis: the excess kurtosis κ of one run's value, where every repetition has the same runs n:
  from how the repetitions' scatter per run, s² = n·error², scatters (Var(s²)/σ⁴ = 2/(n − 1) +
  κ/n for any distribution). Q's error allows for it (a run with heavy tails makes the reference's
  s uncertain beyond the normal 1/√(2(M − 1))); R's interval needs no such allowance (measured by
  the tests: an outlier moves a repetition's mean and its error together).

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

# The columns that name a row (those a table has).
KEYS = ["dimension", "density", "restitution", "method", "randomize", "source"]
# The count behind a column's error: the runs of a point, or the runs that broke down.
RUNS_OF = {"breakdown_time": "breakdowns"}
# Options of `molchaos sweep` the audit sets itself, and those a reference sweep leaves out.
AUDIT_OWNS = ["--base-seed", "--cache", "--out", "--quiet"]
FLAGS = ["--quiet", "--no-figures"]  # options without a value
STAGING = ["--target-error", "--max-seeds", "--seeds"]


def without(args, options):
    """args with every option in `options` and its value removed (both `--x v` and `--x=v`)."""
    out, skip = [], False
    for a in args:
        if skip:
            skip = False
        elif a in options:
            skip = a not in FLAGS
        elif a.split("=", 1)[0] not in options:
            out.append(a)
    return out


def run_sweep(binary, args, base_seed, staged, reproduce_table=None):
    """One sweep's table, run with `base_seed`; a staged sweep in a temporary cache of its own.
    With reproduce_table: that table of a reproduction."""
    with tempfile.TemporaryDirectory(prefix="molchaos-audit-") as tmp:
        if reproduce_table:
            out = os.path.join(tmp, "out", reproduce_table)
            command = [binary, "reproduce", *args, "--base-seed", str(base_seed), "--out",
                       os.path.join(tmp, "out"), "--no-figures", "--quiet"]
        else:
            out = os.path.join(tmp, "sweep.csv")
            cache = os.path.join(tmp, "cache") if staged else ""
            command = [binary, "sweep", *args, "--base-seed", str(base_seed), "--cache", cache,
                       "--out", out, "--quiet"]
        done = subprocess.run(command, capture_output=True, text=True)
        # A sweep some of whose runs failed (a gas that clustered before its fit window) still
        # writes its table, whose points count the runs that succeeded, and exits with 1.
        if done.returncode not in (0, 1):
            raise RuntimeError(f"{' '.join(command)} failed (exit {done.returncode}):\n"
                               f"{done.stderr.strip()}")
        if not os.path.exists(out):
            written = sorted(f for f in os.listdir(os.path.dirname(out)) if f.endswith(".csv"))
            raise RuntimeError(f"{' '.join(command)} wrote no table {os.path.basename(out)}"
                               + (f"; its tables: {', '.join(written)}" if written else "")
                               + (f"\n{done.stderr.strip()}" if done.stderr.strip() else ""))
        table, _ = molchaos.read_table(out)
        return table


def point_key(row, keys):
    return tuple(row[c] for c in keys)


def audit(tables, reference=None):
    """The rows of the audit: one per state point and column with errors, from the K tables of
    the repetitions (and the reference table, if any). Each row: the point, the column and its
    error column, K, R with its 95 % interval and p, and Q with its error (nan without a
    reference)."""
    first = tables[0]
    keys = [c for c in KEYS if c in first.columns]
    # (X, its error column): X_err, and any further X_err_... (another estimate of X's error).
    pairs = [(c, e) for c in first.columns for e in first.columns
             if (e == c + "_err" or e.startswith(c + "_err_")) and c != "A_theory"]
    has_runs = "runs" in first.columns
    by_point = [{point_key(r, keys): r for _, r in t.iterrows()} for t in tables]
    ref = {point_key(r, keys): r for _, r in reference.iterrows()} if reference is not None else {}
    rows = []
    for key in by_point[0]:
        if any(key not in t for t in by_point):
            raise ValueError(f"point {key} is not in every repetition's table")
        for column, error_column in pairs:
            values = [t[key][column] for t in by_point]
            errors = [t[key][error_column] for t in by_point]
            runs = [t[key][RUNS_OF.get(column, "runs")] if has_runs else 1 for t in by_point]
            values, errors, runs = map(np.asarray, (values, errors, runs))
            usable = np.isfinite(values) & np.isfinite(errors) & (errors > 0)
            values, errors, runs = values[usable], errors[usable], runs[usable]
            k = len(values)
            if k < 3:
                continue
            r, low, high, p = r_statistics(values, errors)
            kurtosis = per_run_kurtosis(errors, runs) if has_runs else math.nan
            q = q_error = math.nan
            if key in ref and column not in RUNS_OF and error_column == column + "_err":
                rr = ref[key]
                m = rr["runs"]
                if m >= 2 and np.isfinite(rr[column + "_err"]):
                    q, q_error = q_statistics(rr[column + "_err"] * math.sqrt(m), m, errors, runs,
                                              kurtosis)
            rows.append(dict(zip(keys, key), column=column, error=error_column, K=k,
                             runs=float(np.mean(runs)) if has_runs else math.nan, R=r,
                             R_low=low, R_high=high, p=p, kurtosis=kurtosis, Q=q, Q_err=q_error))
    return rows


def r_statistics(values, errors):
    """R = (standard deviation of the K values) / (rms of their errors), its 95 % interval and the
    two-sided p of R = 1, from (K − 1) R² as χ² with K − 1 degrees of freedom."""
    dof = len(values) - 1
    r = np.std(values, ddof=1) / math.sqrt(np.mean(np.square(errors)))
    chi2 = dof * r * r
    p = 2.0 * min(stats.chi2.cdf(chi2, dof), stats.chi2.sf(chi2, dof))
    low = r * math.sqrt(dof / stats.chi2.ppf(0.975, dof))
    high = r * math.sqrt(dof / stats.chi2.ppf(0.025, dof))
    return r, low, high, p


def per_run_kurtosis(errors, runs):
    """The excess kurtosis of one run's value from the K repetitions' errors, each over the same
    n >= 2 runs: s² = n·error² has Var(s²)/σ⁴ = 2/(n − 1) + κ/n. nan where the repetitions have
    different runs (a staged sweep's runs depend on their scatter)."""
    runs = np.asarray(runs, dtype=float)
    if len(runs) < 3 or runs[0] < 2 or np.any(runs != runs[0]):
        return math.nan
    n = runs[0]
    s2 = n * np.square(errors)
    return n * (np.var(s2, ddof=1) / np.mean(s2) ** 2 - 2.0 / (n - 1.0))


def q_statistics(per_run, m, errors, runs, kurtosis):
    """Q = √(mean of per_run²/n) / (rms error), per_run the reference's scatter per run over m
    runs, and Q's error: the reference's s² varies by 2/(m − 1) + κ/m relative to σ⁴, the mean of
    the K squared errors by (2/(n − 1) + κ/n)/K (n the mean runs), κ the excess kurtosis of a run
    where known and positive, else 0 (normal runs)."""
    runs = np.asarray(runs, dtype=float)
    q = math.sqrt(np.mean(per_run**2 / runs)) / math.sqrt(np.mean(np.square(errors)))
    kappa = kurtosis if np.isfinite(kurtosis) and kurtosis > 0 else 0.0
    n = float(np.mean(runs))
    relative_variance = 2.0 / (m - 1) + kappa / m
    if n >= 2:
        relative_variance += (2.0 / (n - 1) + kappa / n) / len(errors)
    return q, q * 0.5 * math.sqrt(relative_variance)


def main(sweep_args, repeats=30, reference_seeds=0, first_base_seed=1000, binary=None,
         out=None, progress=False, reproduce_table=None):
    if isinstance(repeats, bool) or not isinstance(repeats, int) or repeats < 3:
        raise ValueError(f"repeats: must be a whole number >= 3, got {repeats!r}")
    if isinstance(reference_seeds, bool) or not isinstance(reference_seeds, int) or \
            reference_seeds == 1 or reference_seeds < 0:
        raise ValueError(f"reference_seeds: must be 0 (none) or a whole number >= 2, "
                         f"got {reference_seeds!r}")
    if reproduce_table and reference_seeds:
        raise ValueError("reference_seeds: a reference is a sweep's; give none with a "
                         "reproduction's table")
    # The last fallback is the build beside this script's repository, wherever it is run from.
    binary = binary or os.environ.get("MOLCHAOS_BIN") or shutil.which("molchaos") or \
        os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build", "molchaos")
    binary = shutil.which(binary) or binary  # a bare name given by --molchaos, from PATH
    if not (os.path.isfile(binary) and os.access(binary, os.X_OK)):
        raise ValueError(f"molchaos: no program at {binary}; give it with --molchaos PATH or "
                         f"MOLCHAOS_BIN")
    # The table a reproduction writes is known only after it ran: a misspelt name is found by
    # the first repetition (and named with the tables it did write), not after all of them.
    args = without(list(sweep_args), AUDIT_OWNS + (["--no-figures"] if reproduce_table else []))
    staged = any(a.split("=", 1)[0] == "--target-error" for a in args)
    tables = []
    for k in range(repeats):
        tables.append(run_sweep(binary, args, first_base_seed + k, staged, reproduce_table))
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
    if not rows:
        # One seed per point (or per stage) gives no error to test: say so, as a failure.
        raise RuntimeError("no column with errors to audit: the tables carry no error bars "
                           "(a sweep or reproduction of one seed per point has none; give "
                           "--seeds 2 or more) or no point has a value in every repetition")
    if out:
        import csv
        with open(out, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()) if rows else ["column"])
            writer.writeheader()
            writer.writerows(rows)
    return rows


def print_rows(rows):
    keys = [c for c in KEYS if c in rows[0]]
    print(" ".join(f"{c:>10}" for c in keys) + f" {'column':>16} {'error':>22} {'K':>4} "
          f"{'runs':>6} {'R':>6} {'95% interval':>14} {'p':>8} {'kurtosis':>8} {'Q':>12}")
    for r in rows:
        q = f"{r['Q']:.3f}±{r['Q_err']:.3f}" if np.isfinite(r["Q"]) else "-"
        kurtosis = f"{r['kurtosis']:.2f}" if np.isfinite(r["kurtosis"]) else "-"
        print(" ".join(f"{str(r[c]):>10}" for c in keys) + f" {r['column']:>16} "
              f"{r['error']:>22} {r['K']:>4} {r['runs']:>6.1f} {r['R']:>6.3f} "
              f"[{r['R_low']:.2f}, {r['R_high']:.2f}] {r['p']:>8.3g} {kurtosis:>8} {q:>12}")


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
    parser.add_argument("--reproduce", metavar="TABLE", default=None,
                        help="repeat `molchaos reproduce` instead and audit this table of it "
                             "(e.g. fig4_fits.csv)")
    parser.add_argument("--molchaos", default=None,
                        help="the molchaos program (default: $MOLCHAOS_BIN, then PATH, then "
                             "build/molchaos beside this script's folder)")
    parser.add_argument("--out", default=None, help="also write the table as CSV here")
    parser.add_argument("sweep_args", nargs=argparse.REMAINDER,
                        help="-- then the options of `molchaos sweep`")
    a = parser.parse_args()
    sweep_args = a.sweep_args[1:] if a.sweep_args[:1] == ["--"] else a.sweep_args
    try:
        result = main(sweep_args, a.repeats, a.reference_seeds, a.first_base_seed, a.molchaos,
                      a.out, progress=sys.stderr.isatty(), reproduce_table=a.reproduce)
    except (RuntimeError, ValueError) as e:
        print(f"error_bar_audit: {e}", file=sys.stderr)
        sys.exit(1)
    print_rows(result)
