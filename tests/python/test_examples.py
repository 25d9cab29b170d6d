"""The example scripts run on small inputs and give what they claim."""

import importlib.util
import os
import subprocess
import sys

import numpy as np
import pytest

EXAMPLES = os.environ.get("MOLCHAOS_EXAMPLES", "examples")


def load(name):
    spec = importlib.util.spec_from_file_location(name, os.path.join(EXAMPLES, name + ".py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_haff_ensemble_fit_agrees_with_theory():
    fit = load("haff_ensemble").main(runs=4, particles=400, t_end=40.0)
    assert np.isfinite(fit["tau0"]) and fit["tau0_error"] > 0
    # Independent runs: their tau0 spread is the standard error. 5 of them bound the difference
    # (t distribution with 3 degrees of freedom: two-sided p = 0.015); the theory's quadrature
    # error is negligible beside it.
    assert abs(fit["tau0"] - fit["theory"]) < 5 * fit["tau0_error"] + fit["theory_error"]


@pytest.mark.parametrize("runs", ["1", "0", "-3", "2.5", "four"])
def test_haff_ensemble_refuses_fewer_than_two_runs_naming_the_argument(runs):
    # Was: one run printed "± nan" (the standard error of a single value); a word, a traceback.
    out = subprocess.run([sys.executable, os.path.join(EXAMPLES, "haff_ensemble.py"), "--", runs],
                         capture_output=True, text=True, timeout=60)
    assert out.returncode == 2 and out.stdout == ""
    assert "argument runs: must be a whole number >= 2" in out.stderr
    assert repr(runs) in out.stderr and "Traceback" not in out.stderr


@pytest.mark.parametrize("runs", [1, 0, 2.0, True])
def test_haff_ensemble_main_refuses_fewer_than_two_runs(runs):
    with pytest.raises(ValueError, match=r"runs: must be a whole number >= 2 .*got " + repr(runs)):
        load("haff_ensemble").main(runs=runs)


def test_fig4_from_reproduce_quick(molchaos_bin, tmp_path):
    subprocess.run([molchaos_bin, "reproduce", "--quick", "--seeds", "1", "--no-figures",
                    "--threads", "2", "--out", str(tmp_path)], check=True, capture_output=True)
    png = tmp_path / "fig4.png"
    table = load("fig4_from_csv").main(tmp_path / "fig4_A_of_eps.csv", png)
    assert len(table) > 0 and {"A", "A_err", "A_theory"} <= set(table.columns)
    assert png.stat().st_size > 10000
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_haff_ensemble_help_states_its_whole_purpose():
    # Was: the description stopped mid-sentence ("... fitted to"), the docstring's first line.
    out = subprocess.run([sys.executable, os.path.join(EXAMPLES, "haff_ensemble.py"), "--help"],
                         capture_output=True, text=True, timeout=60)
    assert out.returncode == 0
    assert "the runs' mean tau0 beside the kinetic theory's." in " ".join(out.stdout.split())


@pytest.mark.parametrize("arguments,message", [
    ([], "the following arguments are required: table"),
    (["a2_of_eps.csv"], "a2_of_eps.csv: not a Fig. 4 table (fig4_A_of_eps.csv): no column A, "),
    (["missing.csv"], "No such file or directory: 'missing.csv'"),
])
def test_fig4_from_csv_names_a_missing_or_wrong_table(tmp_path, arguments, message):
    # Was: a traceback (IndexError without arguments, KeyError 'randomize' for another table).
    (tmp_path / "a2_of_eps.csv").write_text(
        "# molchaos reproduce\ndimension,density,restitution,source,a2,a2_err\n"
        "2,0.05,0.9,none,-0.02,0.001\n")
    out = subprocess.run([sys.executable, os.path.join(EXAMPLES, "fig4_from_csv.py"), *arguments],
                         capture_output=True, text=True, timeout=60, cwd=tmp_path)
    assert out.returncode == 2 and "Traceback" not in out.stderr
    assert message in out.stderr


def synthetic_sweeps(repeats, rng):
    """Tables as `molchaos sweep` writes them, of two points whose A scatters by 0.1 over 4 runs
    (0.2 per run): the first reports that error, the second half of it."""
    import pandas as pd
    tables = []
    for _ in range(repeats):
        tables.append(pd.DataFrame({
            "density": [0.05, 0.05], "restitution": [0.8, 0.9], "method": ["edmd", "edmd"],
            "randomize": ["none", "none"], "A": 20.0 + 0.1 * rng.standard_normal(2),
            "A_err": [0.1, 0.05], "runs": [4, 4], "A_theory": [20.0, 20.0],
            "A_theory_err": [1e-12, 1e-12]}))
    return tables


def test_error_bar_audit_finds_honest_bars_and_flags_halved_ones():
    audit = load("error_bar_audit").audit
    rng = np.random.default_rng(5)
    reference = synthetic_sweeps(1, rng)[0].assign(runs=[400, 400], A_err=[0.01, 0.01])
    rows = audit(synthetic_sweeps(200, rng), reference)
    assert [(r["restitution"], r["column"]) for r in rows] == [(0.8, "A"), (0.9, "A")]
    honest, halved = rows
    # R's interval covers 1 for the honest bars (this seed; 95 % of seeds) and excludes it far
    # for the halved ones; Q is exact here: the reference's 0.01 · √400 = 0.2 per run over the
    # repetitions' 4 runs is 0.1.
    assert honest["R_low"] < 1.0 < honest["R_high"] and honest["p"] > 0.05
    assert halved["R_low"] > 1.7 and halved["p"] < 1e-10
    assert honest["Q"] == pytest.approx(1.0, rel=1e-12)
    assert halved["Q"] == pytest.approx(2.0, rel=1e-12)
    # Q's error: the reference's s over 400 runs and the mean of the 200 repetitions' squared
    # errors over 4 runs each (these errors do not scatter: no kurtosis is estimated above 0).
    assert honest["Q_err"] == pytest.approx(0.5 * np.sqrt(2 / 399 + (2 / 3) / 200), rel=1e-12)


def heavy_tailed(rng, shape):
    """Runs whose value is normal with standard deviation 4 in one of 20 cases, else 1: excess
    kurtosis 3·(0.95 + 0.05·4⁴)/(0.95 + 0.05·4²)² − 3 = 10.47."""
    z = rng.standard_normal(shape)
    return np.where(rng.random(shape) < 0.05, 4.0 * z, z)


def test_error_bar_audit_allows_for_runs_with_heavy_tails():
    # 1000 audits of honest errors, K = 180 repetitions of 13 runs, reference of 400 runs.
    a = load("error_bar_audit")
    rng = np.random.default_rng(7)
    covered, kurtosis, q, q_err, q_err_normal = 0, [], [], [], []
    for _ in range(1000):
        runs = heavy_tailed(rng, (180, 13))
        values, errors = runs.mean(axis=1), runs.std(axis=1, ddof=1) / np.sqrt(13)
        _, low, high, _ = a.r_statistics(values, errors)
        covered += low < 1.0 < high
        kurtosis.append(a.per_run_kurtosis(errors, np.full(180, 13)))
        reference = heavy_tailed(rng, 400).std(ddof=1)
        q_k, q_err_k = a.q_statistics(reference, 400, errors, np.full(180, 13), kurtosis[-1])
        q.append(q_k)
        q_err.append(q_err_k)
        q_err_normal.append(a.q_statistics(reference, 400, errors, np.full(180, 13), np.nan)[1])
    # R's interval keeps about its 95 % (an outlier moves a repetition's mean and its error
    # together), measured 0.939.
    assert covered / 1000 > 0.92
    # The kurtosis is found (10.09 ± 0.09 over the audits) ...
    assert abs(np.mean(kurtosis) - 10.47) < 1.0
    # ... and Q's error with it matches Q's scatter (0.97 measured), where the normal one is
    # 2.4 times too small.
    rms = np.sqrt(np.mean(np.square(q_err)))
    assert 0.9 < np.std(q) / rms < 1.1
    assert np.std(q) / np.sqrt(np.mean(np.square(q_err_normal))) > 2.0


def test_error_bar_audit_runs_staged_sweeps_against_a_reference(molchaos_bin, tmp_path):
    out = tmp_path / "audit.csv"
    rows = load("error_bar_audit").main(
        ["--particles", "100", "--restitution", "0.8", "--seeds", "2", "--target-error", "0.2",
         "--threads", "2", "--out", str(tmp_path / "ignored.csv")],
        repeats=3, reference_seeds=4, binary=molchaos_bin, out=str(out))
    assert {r["column"] for r in rows} == {"A", "a2", "mean_dyad"}
    assert all(r["K"] == 3 and np.isfinite(r["R"]) and np.isfinite(r["Q"]) for r in rows)
    assert not (tmp_path / "ignored.csv").exists()
    assert out.read_text().startswith("density,restitution,method,randomize,column,error,K,")


def test_error_bar_audit_reads_the_fits_of_repeated_reproductions(molchaos_bin):
    rows = load("error_bar_audit").main(["--quick", "--seeds", "2", "--threads", "2"], repeats=3,
                                        binary=molchaos_bin, reproduce_table="fig4_fits.csv")
    # Every gas of both densities: intercept and slope with the fit's errors, and the slope with
    # the jackknife's over seeds.
    assert len(rows) == 2 * 4 * 3
    assert {(r["column"], r["error"]) for r in rows} == {
        ("intercept", "intercept_err"), ("slope", "slope_err"),
        ("slope", "slope_err_over_seeds")}
    assert all(r["K"] == 3 and np.isfinite(r["R"]) for r in rows)


@pytest.mark.parametrize("args, message", [
    (["--repeats", "2"], "argument --repeats: must be a whole number >= 3, got '2'"),
    (["--reference-seeds", "1"], "argument --reference-seeds: must be a whole number >= 2"),
])
def test_error_bar_audit_refuses_bad_arguments_naming_them(args, message):
    out = subprocess.run([sys.executable, os.path.join(EXAMPLES, "error_bar_audit.py"), *args],
                         capture_output=True, text=True, timeout=60)
    assert out.returncode == 2 and message in out.stderr and "Traceback" not in out.stderr


def test_error_bar_audit_passes_on_the_sweeps_own_error(molchaos_bin):
    env = dict(os.environ, MOLCHAOS_BIN=molchaos_bin)
    out = subprocess.run([sys.executable, os.path.join(EXAMPLES, "error_bar_audit.py"),
                          "--repeats", "3", "--", "--restitution", "2"],
                         capture_output=True, text=True, timeout=60, env=env)
    assert out.returncode == 1 and "Traceback" not in out.stderr
    assert out.stderr.startswith("error_bar_audit: ") and "restitution" in out.stderr


def test_error_bar_audit_takes_the_table_of_a_sweep_whose_runs_failed(molchaos_bin):
    # Such a sweep exits with 1 but writes its table (its points count the runs that succeeded):
    # the audit took the exit status for a failure of the whole sweep. Here every run ends before
    # its transient, so no column has values to audit, which is an error (it was an empty
    # audit and exit status 0).
    with pytest.raises(RuntimeError, match="no column with errors to audit"):
        load("error_bar_audit").main(
            ["--particles", "100", "--restitution", "0.8", "--seeds", "2", "--t-end-tau0",
             "0.01"], repeats=3, binary=molchaos_bin)


def test_error_bar_audit_names_why_it_cannot_audit(molchaos_bin, tmp_path):
    audit = os.path.join(EXAMPLES, "error_bar_audit.py")
    env = dict(os.environ, MOLCHAOS_BIN=molchaos_bin)
    # One seed per point: no error bars (was "too few repetitions" and exit status 0).
    out = subprocess.run([sys.executable, audit, "--repeats", "3", "--", "--particles", "100",
                          "--seeds", "1", "--cache", ""], capture_output=True, text=True,
                         timeout=120, env=env)
    assert out.returncode == 1 and "--seeds 2 or more" in out.stderr, out.stderr
    # A table the reproduction does not write: named after the first repetition, with the
    # tables it wrote (was "failed (exit 0)" after all repetitions).
    out = subprocess.run([sys.executable, audit, "--repeats", "3", "--reproduce", "nonexist.csv",
                          "--", "--quick", "--threads", "2"], capture_output=True, text=True,
                         timeout=120, env=env)
    assert out.returncode == 1 and "wrote no table nonexist.csv; its tables: " in out.stderr
    assert "fig4_fits.csv" in out.stderr and "Traceback" not in out.stderr
    # Run from another folder without MOLCHAOS_BIN or molchaos on PATH: the build beside the
    # script, or a message naming where it looked (was a FileNotFoundError traceback).
    bare = {k: v for k, v in os.environ.items() if k != "MOLCHAOS_BIN"}
    bare["PATH"] = "/usr/bin:/bin"
    out = subprocess.run([sys.executable, audit, "--repeats", "3", "--", "--restitution", "2"],
                         capture_output=True, text=True, timeout=60, env=bare, cwd=tmp_path)
    assert out.returncode == 1 and "Traceback" not in out.stderr, out.stderr
