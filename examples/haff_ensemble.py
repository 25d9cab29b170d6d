"""A small ensemble of cooling runs from Python and Haff's law T(t) = 1/(1 + t/tau0)^2 fitted to
its mean temperature with scipy, beside the kinetic theory's tau0.

    python3 examples/haff_ensemble.py [runs]
"""

import sys

import numpy as np
from scipy.optimize import curve_fit

import molchaos


def haff(t, tau0):
    return 1.0 / (1.0 + t / tau0) ** 2


def main(runs=4, particles=400, restitution=0.9, density=0.05, t_end=40.0):
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
    theory = molchaos.theory(dim=2, restitution=restitution, density=density)["tau0"]
    fit = {"tau0": tau0, "tau0_error": tau0_error, "theory": theory["value"],
           "theory_error": theory["error"], "runs": runs}
    print(f"tau0 fitted {fit['tau0']:.3f} ± {fit['tau0_error']:.3f} ({runs} runs of N = "
          f"{particles}); kinetic theory {fit['theory']:.4f} ± {fit['theory_error']:.1e}")
    return fit


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 4)
