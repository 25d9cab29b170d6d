"""A small ensemble of cooling runs from Python, Haff's law T(t) = 1/(1 + t/tau0)^2 fitted to each
run's temperature with scipy, and the runs' mean tau0 beside the kinetic theory's.

    PYTHONPATH=build/python /usr/bin/python3 examples/haff_ensemble.py [runs]

runs: a whole number >= 2 (default 4): the error bar of tau0 is the spread between runs.
"""

import argparse

import numpy as np
from scipy.optimize import curve_fit

import molchaos


def haff(t, tau0):
    return 1.0 / (1.0 + t / tau0) ** 2


# The standard error of the mean tau0 comes from the spread of the runs' fits: one run has none.
RUNS_RULE = "a whole number >= 2 (the error bar of tau0 is the spread between runs)"


def main(runs=4, particles=400, restitution=0.9, density=0.05, t_end=40.0):
    if isinstance(runs, bool) or not isinstance(runs, int) or runs < 2:
        raise ValueError(f"runs: must be {RUNS_RULE}, got {runs!r}")
    series = [molchaos.simulate(dim=2, particles=particles, density=density,
                                restitution=restitution, seed=seed, t_end=t_end,
                                relax_collisions_per_particle=5.0)
              for seed in range(1, runs + 1)]
    # One Haff fit per run (from t = 1 on, after about one collision per particle); the runs are
    # independent, so the spread of their tau0 gives an honest standard error, which the
    # time-correlated points of a single run would not.
    fits = []
    for run in series:
        late = run["t"] >= 1.0
        (tau0_run,), _ = curve_fit(haff, run["t"][late], run["T"][late], p0=[t_end])
        fits.append(tau0_run)
    tau0 = float(np.mean(fits))
    tau0_error = float(np.std(fits, ddof=1) / np.sqrt(runs))
    theory = molchaos.theory(dim=2, restitution=restitution, density=density)
    fit = {"tau0": tau0, "tau0_error": tau0_error, "theory": theory["tau0"],
           "theory_error": theory["tau0_error"], "runs": runs}
    print(f"tau0 fitted {fit['tau0']:.3f} ± {fit['tau0_error']:.3f} ({runs} runs of N = "
          f"{particles}); kinetic theory {fit['theory']:.4f} ± {fit['theory_error']:.1e}")
    return fit


def runs_argument(text):
    """The command line's runs, checked before any run starts."""
    try:
        runs = int(text)
    except ValueError:
        runs = None
    if runs is None or runs < 2:
        raise argparse.ArgumentTypeError(f"must be {RUNS_RULE}, got {text!r}")
    return runs


if __name__ == "__main__":
    # The docstring's first paragraph (its opening sentence spans two lines).
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("runs", nargs="?", type=runs_argument, default=4,
                        help=f"independent runs, {RUNS_RULE}; default 4")
    main(parser.parse_args().runs)
