"""Ctrl-C and other signals during simulate(), and runs from several Python threads. Each signal
case runs in its own interpreter under a time limit, so that a run that does not stop fails the
test instead of holding it for hours."""

import subprocess
import sys
import threading

import numpy as np
import pytest

import molchaos

# A run of hours uninterrupted (elastic, dense, t_end = 1e6), relaxed in well under a second.
LONG = "dict(particles=4000, density=0.3, restitution=1.0, t_end=1e6)"
# DSMC: no relaxation; progress about every 2^20 collisions.
LONG_DSMC = "dict(method='dsmc', particles=100000, density=0.05, restitution=1.0, t_end=1e6)"
# DSMC whose first sample time lies hours away (was: no stop before it, the progress came only
# at sample times).
FAR_SAMPLE_DSMC = ("dict(method='dsmc', particles=50000, restitution=1.0, t_end=1e5, "
                   "samples_per_decade=1, t_first_sample=9e4)")


def run_script(body, timeout=120):
    """Runs body after `import molchaos, os, signal, threading, time`; returns its stdout."""
    code = "import molchaos, os, signal, threading, time\n" + body
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=timeout)
    assert out.returncode == 0, out.stderr
    return out.stdout


INTERRUPT = """
threading.Timer({delay}, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
start = time.monotonic()
try:
    molchaos.simulate(**{kwargs})
    print("finished")
except KeyboardInterrupt:
    print("interrupted", time.monotonic() - start)
"""


@pytest.mark.parametrize("kwargs", [LONG, LONG_DSMC, FAR_SAMPLE_DSMC],
                         ids=["edmd", "dsmc", "dsmc_far_sample"])
def test_ctrl_c_stops_a_long_run_promptly(kwargs):
    # Was: the KeyboardInterrupt came only after the whole run.
    words = run_script(INTERRUPT.format(delay=0.5, kwargs=kwargs)).split()
    assert words[0] == "interrupted"
    assert float(words[1]) < 30  # the first pause after the signal, on a loaded machine


def test_ctrl_c_leaves_a_checkpoint_that_continues_the_run_exactly(tmp_path):
    ckpt = tmp_path / "run.ckpt"
    # About 3 s uninterrupted (elastic and dense: it does not slow down by cooling).
    kwargs = ("dict(particles=4000, density=0.3, restitution=1.0, randomize='paper', seed=5, "
              f"t_end=1500.0, checkpoint={str(ckpt)!r})")
    assert run_script(INTERRUPT.format(delay=0.3, kwargs=kwargs)).startswith("interrupted")
    assert ckpt.is_file()
    params = dict(particles=4000, density=0.3, restitution=1.0, randomize="paper", seed=5,
                  t_end=1500.0)
    continued = molchaos.simulate(**params, restart=ckpt)
    # The parameters left to the checkpoint's head: the same run.
    bare = molchaos.simulate(restart=ckpt)
    whole = molchaos.simulate(**params)
    for key in ("t", "T", "a2", "collisions", "events"):
        np.testing.assert_array_equal(continued[key], whole[key])
        np.testing.assert_array_equal(bare[key], whole[key])


def test_a_signal_handler_that_raises_stops_the_run():
    body = f"""
def on_alarm(signum, frame):
    raise TimeoutError("time is up")
signal.signal(signal.SIGALRM, on_alarm)
signal.alarm(1)
start = time.monotonic()
try:
    molchaos.simulate(**{LONG})
except TimeoutError as e:
    print(e, "|", time.monotonic() - start)
"""
    said, elapsed = run_script(body).split("|")
    assert said.strip() == "time is up" and float(elapsed) < 30


def test_a_sigterm_handler_that_raises_stops_a_cooling_run_with_its_checkpoint(tmp_path):
    # A cooling run's sample intervals all fall short of a progress pause (2^20 events). Was: the
    # handler ran only after the whole run, and its KeyboardInterrupt was dropped.
    ckpt = tmp_path / "run.ckpt"
    body = f"""
def on_term(signum, frame):
    raise KeyboardInterrupt
signal.signal(signal.SIGTERM, on_term)
threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGTERM)).start()
start = time.monotonic()
try:
    molchaos.simulate(particles=20000, restitution=0.9, t_end=1e6,
                      relax_collisions_per_particle=0, checkpoint={str(ckpt)!r})
    print("finished")
except KeyboardInterrupt:
    print("interrupted", time.monotonic() - start)
"""
    words = run_script(body).split()
    assert words[0] == "interrupted" and float(words[1]) < 30
    assert ckpt.is_file()


def test_a_sigint_handler_of_the_callers_is_run_and_left_in_place():
    body = """
seen = []
handler = lambda signum, frame: seen.append(signum)
signal.signal(signal.SIGINT, handler)
molchaos.simulate(particles=200, t_end=20.0, relax_collisions_per_particle=5.0)
os.kill(os.getpid(), signal.SIGINT)
time.sleep(0.1)
print(signal.getsignal(signal.SIGINT) is handler, seen == [signal.SIGINT])
"""
    assert run_script(body).split() == ["True", "True"]


def test_runs_in_several_threads_give_the_single_threaded_arrays():
    kinds = [dict(particles=300, density=0.1, restitution=0.8, seed=s, t_end=30.0,
                  randomize=r) for s in (1, 2) for r in ("none", "flux")]
    alone = [molchaos.simulate(**k) for k in kinds]
    results = [None] * len(kinds)

    def work(i):
        results[i] = (molchaos.simulate(**kinds[i]), molchaos.theory(restitution=0.8))

    threads = [threading.Thread(target=work, args=(i,)) for i in range(len(kinds))]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for a, (b, theory) in zip(alone, results):
        for key in ("t", "T", "a2", "collisions", "events"):
            np.testing.assert_array_equal(a[key], b[key])
        assert theory["A"] == molchaos.theory(restitution=0.8)["A"]


# A relaxation of several seconds (elastic collisions before t = 0), then a short run.
LONG_RELAXATION = ("dict(particles=4000, density=0.3, restitution=1.0, "
                   "relax_collisions_per_particle=5000.0, t_end=1.0)")


def test_ctrl_c_during_the_relaxation_stops_the_run_promptly():
    # Was: Ctrl-C was obeyed only once the whole relaxation was done.
    words = run_script(INTERRUPT.format(delay=0.5, kwargs=LONG_RELAXATION)).split()
    assert words[0] == "interrupted"
    assert float(words[1]) < 5  # the first relaxation pause after the signal (2^20 events)


# Two million disks: seconds to build (random positions, the sort by cell, the first predictions).
LARGE_START = "dict(particles=2000000, density=0.05, relax_collisions_per_particle=0.0, t_end=1e-6)"


def test_ctrl_c_while_a_large_initial_state_is_built_stops_it_promptly():
    # Was: Ctrl-C was obeyed only once the whole initial state was built. The build's own time,
    # measured in the same interpreter, is the yardstick (the machine's speed drifts).
    words = run_script(f"""
start = time.monotonic()
molchaos.simulate(**{LARGE_START})
built = time.monotonic() - start
""" + INTERRUPT.format(delay=0.2, kwargs=LARGE_START) + """
print(built)
""").split()
    assert words[0] == "interrupted"
    interrupted, built = float(words[1]), float(words[2])
    assert interrupted < 0.5 * built, (interrupted, built)
