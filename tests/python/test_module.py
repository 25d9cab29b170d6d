"""The Python module against the CLI: the same functions, so the same numbers bit for bit."""

import json
import math
import os
import re
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import molchaos


def theory_cli(molchaos_bin, *flags):
    """`molchaos theory --json` with these flags, as a dict."""
    out = subprocess.run([molchaos_bin, "theory", *flags, "--json"], check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out)


@pytest.mark.parametrize("kwargs, flags", [
    ({}, []),
    (dict(dim=3, restitution=0.5, density=0.3, b=0.1),
     ["--dim", "3", "--restitution", "0.5", "--density", "0.3", "--b", "0.1"]),
    (dict(dimension=2, restitution=1, b=-1.5, particles=100000, growth=1e6),
     ["--restitution", "1", "--b", "-1.5", "--particles", "100000", "--growth", "1e6"]),
    (dict(restitution=0.2, quadrature="adaptive", tolerance=1e-6),
     ["--restitution", "0.2", "--quadrature", "adaptive", "--tolerance", "1e-6"]),
])
def test_theory_is_the_cli_json_document(molchaos_bin, kwargs, flags):
    # One computation and one document on both sides: every key, every double, bit for bit (the
    # Sonine levels, the contact response, the hydrodynamics included), but the run time.
    cli = theory_cli(molchaos_bin, *flags)
    py = molchaos.theory(**kwargs)
    assert isinstance(py.pop("seconds"), float)
    cli.pop("seconds")
    assert py == cli


def test_theory_A_is_tau0_times_one_minus_eps_squared():
    py = molchaos.theory(dim=2, restitution=0.9, density=0.05)
    # A = tau0 (1 - eps^2) (paper, Sec. 2), within the propagated quadrature error.
    assert abs(py["A"] - py["tau0"] * (1 - 0.9**2)) <= \
        py["A_error"] + py["tau0_error"] * (1 - 0.9**2) + 1e-15 * py["A"]


@pytest.mark.parametrize("dim, density, beyond", [(2, 0.05, False), (2, 1.15, True),
                                                  (3, 0.9, False), (3, 0.95, True)])
def test_theory_says_where_g2_extrapolates_as_the_cli_does(molchaos_bin, dim, density, beyond):
    # Beyond the equilibrium fluid (packing 0.700 for disks, 0.494 for spheres; n = 0.9 and 0.95
    # lie either side of it in d = 3) g2 extrapolates the fluid's equation of state.
    out = subprocess.run(
        [molchaos_bin, "theory", "--dim", str(dim), "--restitution", "0.9", "--density",
         str(density), "--json"], check=True, capture_output=True, text=True).stdout
    assert json.loads(out)["g2_extrapolated"] is beyond
    assert molchaos.theory(dim=dim, restitution=0.9, density=density)["g2_extrapolated"] is beyond


def test_theory_rejects_bad_density():
    with pytest.raises(ValueError, match="density"):
        molchaos.theory(dim=2, restitution=0.9, density=2.0)


@pytest.mark.parametrize("restitution", [0.9, 1.0])
def test_theory_refuses_the_density_the_cli_refuses(molchaos_bin, restitution):
    # At n = 1e-320 A and tau0 ~ 1/n overflow a double: the module and the CLI both refuse it,
    # with the same smallest density, and never return A = inf.
    cli = subprocess.run(
        [molchaos_bin, "theory", "--restitution", str(restitution), "--density", "1e-320"],
        capture_output=True, text=True)
    assert cli.returncode == 2
    smallest = re.search(r"allowed range \(([0-9.e+-]+), 1\.1547005383792517\)", cli.stderr).group(1)
    with pytest.raises(ValueError, match=rf"density: .*allowed range \({smallest}, 1\.1547005383792517\)"):
        molchaos.theory(restitution=restitution, density=1e-320)
    # Just above the smallest density, the prediction is finite.
    A = molchaos.theory(restitution=restitution, density=2 * float(smallest))["A"]
    assert math.isfinite(A)


@pytest.mark.parametrize("b", [-1.5, 0.6])
def test_theory_takes_the_b_the_cli_takes(molchaos_bin, b):
    # The allowed b depends on d and eps ([-2, 0.671215957784484) here); the module and the CLI share it.
    out = subprocess.run(
        [molchaos_bin, "theory", "--restitution", "0.9", "--density", "0.05", "--b", str(b),
         "--json"], check=True, capture_output=True, text=True).stdout
    assert molchaos.theory(restitution=0.9, density=0.05, b=b)["A"] == json.loads(out)["A"]


def test_theory_refuses_b_where_mu2_vanishes():
    with pytest.raises(ValueError, match=r"0\.9 is outside the allowed range \[-2, 0\.67121595[0-9]*\)"):
        molchaos.theory(restitution=0.9, density=0.05, b=0.9)


SMALL = dict(dim=2, particles=200, density=0.05, restitution=0.9, seed=3, t_end=20.0,
             relax_collisions_per_particle=5.0, samples_per_decade=5)
# The same run by the CLI (the relaxation flag left to the caller: DSMC takes none).
SMALL_FLAGS = ["--dim", "2", "--particles", "200", "--density", "0.05", "--restitution", "0.9",
               "--seed", "3", "--t-end", "20", "--samples-per-decade", "5", "--quiet"]


def simulate_cli(molchaos_bin, out, *flags):
    """`molchaos simulate` of SMALL with extra flags, written to out."""
    subprocess.run([molchaos_bin, "simulate", *SMALL_FLAGS, *flags, "--out", str(out)],
                   check=True, capture_output=True)


def test_simulate_equals_cli_run(molchaos_bin, tmp_path):
    run = molchaos.simulate(**SMALL)
    for key in ("t", "T", "a2", "collisions"):
        assert isinstance(run[key], np.ndarray)
        assert len(run[key]) == len(run["t"])
    assert run["stop_reason"] == "t_end"
    assert run["parameters"]["particles"] == 200
    out = tmp_path / "run.csv"
    simulate_cli(molchaos_bin, out, "--relax", "5")
    frame, meta = molchaos.read_run_csv(out)
    # Same seed, same engine: the same trajectory, so the same doubles.
    np.testing.assert_array_equal(frame["t"].to_numpy(), run["t"])
    np.testing.assert_array_equal(frame["T"].to_numpy(), run["T"])
    np.testing.assert_array_equal(frame["a2"].to_numpy(), run["a2"])
    np.testing.assert_array_equal(frame["collisions"].to_numpy(), run["collisions"])
    assert meta["seed"] == 3 and meta["restitution"] == 0.9 and meta["dimension"] == 2
    assert meta["stop_reason"] == run["stop_reason"]
    assert meta["collisions"] == run["total_collisions"]


def test_run_csv_header_gives_the_parameters_as_simulate_does(molchaos_bin, tmp_path):
    # Was: a real parameter written whole ("t_end = 20", "restitution = 1") read back as int,
    # where simulate() and read_trajectory() give a float.
    run = molchaos.simulate(**dict(SMALL, restitution=1))
    out = tmp_path / "run.csv"
    flags = [("1" if previous == "--restitution" else word)
             for previous, word in zip([""] + SMALL_FLAGS, SMALL_FLAGS)]
    subprocess.run([molchaos_bin, "simulate", *flags, "--relax", "5", "--out", str(out)],
                   check=True, capture_output=True)
    _, meta = molchaos.read_run_csv(out)
    for key, value in run["parameters"].items():
        if key in meta:
            assert meta[key] == value and type(meta[key]) is type(value), key
    assert type(meta["t_end"]) is float and type(meta["restitution"]) is float


def test_simulate_is_reproducible_and_cools():
    a = molchaos.simulate(**SMALL)
    b = molchaos.simulate(**SMALL)
    np.testing.assert_array_equal(a["T"], b["T"])
    assert a["T"][0] == pytest.approx(1.0, rel=1e-12)  # T0 = 1 by construction
    assert np.all(np.diff(a["T"]) <= 0)  # inelastic: energy never grows between samples
    # And it cools like Haff's law: with tau0 from the theory, T(20) = 1/(1 + 20/tau0)^2. One run of
    # N = 200 disks fluctuates by about sqrt(2/(d N)) = 7 % in T; 5 such deviations bound it.
    tau0 = molchaos.theory(dim=2, restitution=0.9, density=0.05)["tau0"]
    haff = 1.0 / (1.0 + a["t"][-1] / tau0) ** 2
    assert abs(a["T"][-1] - haff) < 5 * np.sqrt(2 / (2 * 200)) * haff
    assert np.all(np.diff(a["collisions"].astype(np.int64)) >= 0)


@pytest.mark.parametrize("name,value", [("restitution", 1.5), ("density", 5.0),
                                        ("particles", 1), ("t_end", -1.0),
                                        ("relax_collisions_per_particle", 1e30),
                                        ("snapshot_times", [3.0, 1.0])])
def test_simulate_bad_parameter_names_it(name, value):
    kwargs = dict(SMALL)
    kwargs[name] = value
    with pytest.raises(ValueError, match=name):
        molchaos.simulate(**kwargs)


DSMC_SMALL = {k: v for k, v in SMALL.items() if k != "relax_collisions_per_particle"}


def test_simulate_dsmc_equals_cli_run(molchaos_bin, tmp_path):
    run = molchaos.simulate(**DSMC_SMALL, method="dsmc")
    assert run["parameters"]["method"] == "dsmc"
    assert run["parameters"]["relax_collisions_per_particle"] == 0  # DSMC does no relaxation
    out = tmp_path / "dsmc.csv"
    simulate_cli(molchaos_bin, out, "--method", "dsmc")
    frame, _ = molchaos.read_run_csv(out)
    np.testing.assert_array_equal(frame["T"].to_numpy(), run["T"])
    assert molchaos.simulate(**SMALL)["parameters"]["method"] == "edmd"


def test_simulate_method_refuses_unknown_and_shuffles():
    with pytest.raises(ValueError, match="method"):
        molchaos.simulate(**SMALL, method="md")
    with pytest.raises(ValueError, match="randomize"):
        molchaos.simulate(**SMALL, method="dsmc", randomize="flux")
    with pytest.raises(ValueError, match="relax_collisions_per_particle.*method = edmd only"):
        molchaos.simulate(**SMALL, method="dsmc")


@pytest.mark.parametrize("name,value,expected", [
    ("restitution", True, "a real number"),     # Python's True is the integer 1: not eps = 1
    ("density", "0.05", "a real number"),
    ("particles", 2.5, "an integer"),
    ("particles", False, "an integer"),
    ("seed", 3.0, "an integer"),
    ("contact_statistics", 1, "True or False"),
    ("snapshot_times", "5", "a list of real numbers"),
    ("snapshot_times", [5.0, True], "a real number"),
    ("randomize", 1, "a string"),
    ("checkpoint", 3, r"a file name \(str or os\.PathLike\)"),
])
def test_simulate_wrong_type_names_the_parameter_and_its_type(name, value, expected):
    with pytest.raises(TypeError, match=rf"{name}: expected {expected}, got "):
        molchaos.simulate(**dict(SMALL, **{name: value}))


@pytest.mark.parametrize("name,value,expected", [
    ("restitution", True, "a real number"), ("density", None, "a real number"),
    ("dim", 2.0, "an integer"), ("tolerance", "1e-8", "a real number"),
    ("particles", 5000.0, "an integer"), ("growth", "10", "a real number")])
def test_theory_wrong_type_names_the_parameter_and_its_type(name, value, expected):
    with pytest.raises(TypeError, match=rf"{name}: expected {expected}, got "):
        molchaos.theory(**{name: value})


def test_numbers_of_other_python_types_are_taken():
    # An int where a real is expected, numpy scalars, a tuple or an array for a list of times,
    # a pathlib.Path for a file: the same run as with the plain types.
    plain = molchaos.simulate(**SMALL, snapshot_times=[5.0])
    other = molchaos.simulate(**dict(SMALL, particles=np.int64(200), density=np.float64(0.05),
                                     t_end=20, snapshot_times=np.array([5.0])))
    np.testing.assert_array_equal(plain["T"], other["T"])
    assert molchaos.theory(restitution=1)["A"] == molchaos.theory(restitution=1.0)["A"]
    eps = np.float32(0.9)
    assert molchaos.theory(restitution=eps)["inputs"]["restitution"] == float(eps)
    # An integer beyond the parameter's C++ type is a value out of range, not a wrong type; the
    # message names the allowed range (was: "does not fit the parameter's type").
    with pytest.raises(ValueError, match=rf"seed: value -1 is outside the allowed range "
                                         rf"\[0, {2**64 - 1}\]"):
        molchaos.simulate(**dict(SMALL, seed=-1))
    with pytest.raises(ValueError, match=rf"max_collisions: value {2**64} is outside the "
                                         rf"allowed range \[0, {2**64 - 1}\]"):
        molchaos.simulate(**dict(SMALL, max_collisions=2**64))
    with pytest.raises(ValueError, match=rf"particles: value {2**70} is outside the allowed "
                                         r"range \[2, 100000000\]"):
        molchaos.simulate(**dict(SMALL, particles=2**70))
    with pytest.raises(ValueError, match=rf"dim: value {2**70} is outside the allowed range "
                                         r"\{2, 3\}"):
        molchaos.theory(dim=2**70)
    with pytest.raises(ValueError, match=r"dim: value 4 is outside the allowed range \{2, 3\}"):
        molchaos.theory(dim=4)
    with pytest.raises(ValueError, match=r"particles: value 1 is outside the allowed range "
                                         r"\[2, 100000000\]"):
        molchaos.theory(particles=1)
    with pytest.raises(ValueError, match=r"growth: value 1 is outside the allowed range \(1, "):
        molchaos.theory(growth=1)
    with pytest.raises(TypeError, match="'dimension' and 'dim' for the same parameter"):
        molchaos.theory(dim=2, dimension=3)


@pytest.mark.parametrize("b,shown", [(float("nan"), "nan"), (5.0, "5")])
def test_theory_b_out_of_range_is_named_by_its_keyword(b, shown):
    # Was: named correlation_b, a name theory() does not take.
    with pytest.raises(ValueError, match=rf"^b: value {shown} is outside the allowed range \[-2, "):
        molchaos.theory(b=b)


def test_checkpoint_refuses_a_file_that_is_no_checkpoint(tmp_path):
    # Was: the first checkpoint replaced a result table given that name, without a word.
    table = tmp_path / "table.csv"
    table.write_text("x,y\n1,2\n")
    with pytest.raises(ValueError, match="checkpoint: .*table.csv holds a file that is no "
                                         "molchaos checkpoint"):
        molchaos.simulate(**SMALL, checkpoint=table, checkpoint_interval=1.0)
    assert table.read_text() == "x,y\n1,2\n"


def test_checkpoint_refuses_the_checkpoint_of_a_run_it_does_not_continue(tmp_path):
    # Was: a new run (or the same call again) replaced another run's checkpoint without a word.
    ckpt = tmp_path / "run.ckpt"
    molchaos.simulate(**dict(SMALL, t_end=5.0), checkpoint=ckpt, checkpoint_interval=1.0)
    saved = ckpt.read_bytes()
    for restitution in (0.8, SMALL["restitution"]):
        with pytest.raises(ValueError, match="checkpoint: .*run.ckpt holds the checkpoint of a "
                                             "run that this run does not continue"):
            molchaos.simulate(**dict(SMALL, t_end=5.0, restitution=restitution),
                              checkpoint=ckpt, checkpoint_interval=1.0)
    assert ckpt.read_bytes() == saved
    molchaos.simulate(t_end=8.0, restart=ckpt, checkpoint=ckpt, checkpoint_interval=1.0)
    assert ckpt.read_bytes() != saved


def test_checkpoint_takes_a_path_object(tmp_path):
    path = tmp_path / "run.ckpt"
    molchaos.simulate(**dict(SMALL, t_end=5.0), checkpoint=path, checkpoint_interval=1.0)
    assert path.is_file()
    assert molchaos.simulate(**SMALL, restart=path)["stop_reason"] == "t_end"


def test_simulate_unknown_keyword():
    with pytest.raises(TypeError, match="restitutoin"):
        molchaos.simulate(restitutoin=0.9)


def test_a_checkpoint_without_an_interval_notes_that_none_was_written(tmp_path):
    # Was: silence, where the CLI notes it; the caller finds no file to go on from.
    path = tmp_path / "run.ckpt"
    with pytest.warns(UserWarning, match=f"no checkpoint written to {re.escape(str(path))}: without "
                                         "checkpoint_interval or checkpoint_wall"):
        molchaos.simulate(**SMALL, checkpoint=path)
    assert not path.exists()


def test_simulate_refuses_an_unwritable_checkpoint_before_the_run():
    # Refused before the run, as by the CLI, not at the first checkpoint after part of the work.
    with pytest.raises(ValueError, match="checkpoint: cannot create a file next to /proc/run.ckpt"):
        molchaos.simulate(**SMALL, checkpoint="/proc/run.ckpt", checkpoint_interval=1.0)
    with pytest.raises(ValueError, match=r"checkpoint_interval: value inf is outside .*\[0, inf\)"):
        molchaos.simulate(**SMALL, checkpoint="run.ckpt", checkpoint_interval=float("inf"))


@pytest.mark.parametrize("kind", ["directory", "fifo", "symlink"])
def test_simulate_refuses_a_checkpoint_path_that_is_no_regular_file(tmp_path, kind):
    # Was: a directory passed the up-front check and failed after the run ("rename failed (Is a
    # directory)"); a FIFO or a symlink was replaced by the checkpoint. The CLI refuses each.
    path = tmp_path / "run.ckpt"
    if kind == "directory":
        path.mkdir()
        reason = "is a directory"
    elif kind == "fifo":
        os.mkfifo(path)
        reason = "exists and is not a regular file"
    else:
        (tmp_path / "target.ckpt").write_bytes(b"")
        path.symlink_to(tmp_path / "target.ckpt")
        reason = "exists and is not a regular file"
    before = os.lstat(path)
    with pytest.raises(ValueError, match=rf"^checkpoint: '{re.escape(str(path))}' {reason}"):
        molchaos.simulate(**SMALL, checkpoint=path, checkpoint_interval=1.0)
    after = os.lstat(path)  # left as it was
    assert (after.st_ino, after.st_mode) == (before.st_ino, before.st_mode)


def test_simulate_names_restart_for_a_checkpoint_it_cannot_read(tmp_path):
    # Was: "checkpoint ...: not a file", which reads as if the checkpoint keyword were meant.
    path = tmp_path / "run.ckpt"
    path.mkdir()
    with pytest.raises(ValueError, match=rf"^restart: checkpoint {re.escape(str(path))}: "
                                         r"not a file"):
        molchaos.simulate(**SMALL, restart=path)


def test_simulate_restart_of_a_missing_file_is_file_not_found(tmp_path):
    # Was: ValueError, where Python's own open() raises FileNotFoundError.
    path = tmp_path / "missing.ckpt"
    with pytest.raises(FileNotFoundError) as raised:
        molchaos.simulate(**SMALL, restart=path)
    assert raised.value.filename == str(path) and "restart" in str(raised.value)
    # A bad parameter beside it is named first, as the command line names the flag.
    with pytest.raises(ValueError, match="^particles: "):
        molchaos.simulate(**dict(SMALL, particles=-5), restart=path)


def test_simulate_takes_the_wall_clock_checkpoint_interval(tmp_path):
    # Was: TypeError (an unknown keyword), though the CLI has --checkpoint-wall.
    ckpt = tmp_path / "run.ckpt"
    run = molchaos.simulate(**SMALL, checkpoint=ckpt, checkpoint_wall=0.0)
    assert run["stop_reason"] == "t_end"
    with pytest.raises(ValueError, match="checkpoint_wall: needs checkpoint=FILE"):
        molchaos.simulate(**SMALL, checkpoint_wall=1.0)
    with pytest.raises(ValueError, match=r"checkpoint_wall: value -1.0 is outside .*\[0, inf\)"):
        molchaos.simulate(**SMALL, checkpoint=ckpt, checkpoint_wall=-1.0)


def test_simulate_names_dim_or_dimension_as_given():
    # Was: "dimension: ..." for dim=1, a name the caller did not use.
    with pytest.raises(ValueError, match=r"^dim: value 1 is outside the allowed range \[2, 3\]"):
        molchaos.simulate(**dict(SMALL, dim=1))
    small = {k: v for k, v in SMALL.items() if k != "dim"}
    with pytest.raises(ValueError, match=r"^dimension: value 4 is outside the allowed range"):
        molchaos.simulate(**small, dimension=4)


def test_simulate_refuses_dim_and_dimension_together():
    with pytest.raises(TypeError, match="'dimension' and 'dim' for the same parameter"):
        molchaos.simulate(**SMALL, dimension=3)  # SMALL has dim=2


def test_simulate_snapshots_match_snapshot_csv(molchaos_bin, tmp_path):
    run = molchaos.simulate(**SMALL, snapshot_times=[5.0])
    simulate_cli(molchaos_bin, tmp_path / "run.csv", "--relax", "5", "--snapshot-times", "5")
    frame, meta = molchaos.read_snapshot_csv(tmp_path / "run.snapshot0.csv")
    snap = run["snapshots"][0]
    assert meta["t"] == snap["t"] and meta["box"] == snap["box"]
    assert 0 < snap["collisions"] < run["total_collisions"]  # collisions before t = 5
    np.testing.assert_array_equal(frame[["x", "y"]].to_numpy(), snap["positions"])
    np.testing.assert_array_equal(frame[["vx", "vy"]].to_numpy(), snap["velocities"])


def test_simulate_contact_statistics_equal_the_cli_columns(molchaos_bin, tmp_path):
    """contact_statistics = True gives the contact columns of the CLI's CSV (they were dropped)."""
    run = molchaos.simulate(**SMALL, contact_statistics=True)
    out = tmp_path / "run.csv"
    simulate_cli(molchaos_bin, out, "--relax", "5", "--contacts")
    frame, _ = molchaos.read_run_csv(out)
    for key in ("contacts", "sum_c1e_c2e", "sum_c1_dot_c2", "sum_gn2", "sum_abs_gn", "sum_g2"):
        np.testing.assert_array_equal(frame[key].to_numpy(), run[key], err_msg=key)
    impact = frame[[f"impact_{b}" for b in range(10)]].to_numpy()
    np.testing.assert_array_equal(impact, run["impact"])
    assert run["impact"].sum() == run["contacts"].sum() > 0
    assert "contacts" not in molchaos.simulate(**SMALL)


def test_simulate_restart_continues_exactly(tmp_path):
    """A run to t = 5 with checkpoints, continued from its last one to t_end: the uninterrupted
    run's numbers, bit for bit (paper shuffle: the random generator is part of the state)."""
    kwargs = dict(SMALL, randomize="paper", contact_statistics=True)
    whole = molchaos.simulate(**kwargs)
    ckpt = str(tmp_path / "run.ckpt")
    short = molchaos.simulate(**dict(kwargs, t_end=5.0), checkpoint=ckpt, checkpoint_interval=1.0)
    assert short["t"][-1] == 5.0
    continued = molchaos.simulate(**kwargs, restart=ckpt)
    for key in ("t", "T", "a2", "collisions", "events", "velocity_mode", "density_mode"):
        assert np.array_equal(whole[key], continued[key]), key
    assert whole["total_collisions"] == continued["total_collisions"]
    assert continued["parameters"]["randomize"] == "paper"
    with pytest.raises(ValueError, match="restitution differs"):
        molchaos.simulate(**dict(kwargs, restitution=0.8), restart=ckpt)
    with pytest.raises(ValueError, match="checkpoint .*: not a file"):
        molchaos.simulate(**kwargs, restart=str(tmp_path))  # a folder: named, not a stream error


def test_gil_released_during_run():
    """A Python thread keeps counting while the engine runs: simulate() releases the GIL."""
    ticks = []
    done = threading.Event()

    def count():
        while not done.is_set():
            ticks.append(1)
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    # Runs until half a second has passed, however fast the machine (one run may take a tenth).
    start = time.monotonic()
    runs = 0
    while time.monotonic() - start < 0.5:
        molchaos.simulate(dim=2, particles=4000, density=0.3, restitution=1.0, t_end=100)
        runs += 1
    elapsed = time.monotonic() - start
    done.set()
    counter.join()
    # Held, the GIL would let the counter tick only between runs, a few times each; released, it
    # ticks about once per millisecond (asserted: a tenth of that, for a loaded machine).
    assert len(ticks) > max(0.1 * elapsed / 0.001, 10 * runs)


def test_readers_refuse_truncated_files(molchaos_bin, tmp_path):
    # A file cut short is refused, never read as fewer rows or as a row of NaN.
    out = tmp_path / "run.csv"
    simulate_cli(molchaos_bin, out, "--relax", "5", "--snapshot-times", "5")
    frame, _ = molchaos.read_run_csv(out)  # whole: read
    text = out.read_bytes()
    cut = tmp_path / "cut.csv"
    cut.write_bytes(text[: text.rindex(b",")])  # inside the last row
    with pytest.raises(ValueError, match="ends in the middle of a line"):
        molchaos.read_run_csv(cut)
    cut.write_bytes(text[: text.rindex(b"\n", 0, len(text) - 1) + 1])  # the last row left out
    with pytest.raises(ValueError, match=rf"header says {len(frame)} rows, file has {len(frame) - 1}"):
        molchaos.read_run_csv(cut)
    snapshot = (tmp_path / "run.snapshot0.csv").read_bytes()
    cut.write_bytes(snapshot[:-5])
    with pytest.raises(ValueError, match="ends in the middle of a line"):
        molchaos.read_snapshot_csv(cut)


def run_with_address_space(limit, call, error):
    # `call` in a fresh interpreter whose address space is cut to `limit` (a Python expression of
    # `held`, the bytes it holds after the imports); prints the message of `error` it raises.
    code = f"""
import resource, molchaos
held = next(int(line.split()[1]) * 1024 for line in open("/proc/self/status")
            if line.startswith("VmSize:"))
resource.setrlimit(resource.RLIMIT_AS, ({limit}, {limit}))
try:
    {call}
except {error} as e:
    print(e)
"""
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    return out.stdout


def test_a_run_beyond_the_memory_raises_memory_error_with_the_clis_words():
    # Was: MemoryError("std::bad_alloc"). 0.5 GB above what the interpreter holds: 3e6 disks pass
    # the check before the run (at least 150 bytes each) but need about 210.
    said = run_with_address_space("held + 500_000_000",
                                  "molchaos.simulate(particles=3_000_000, t_end=1.0)", "MemoryError")
    assert said.startswith("out of memory") and "fewer particles" in said


def test_a_run_whose_parameters_exceed_the_memory_is_refused_before_it_starts():
    # 1e8 disks hold at least 15 GB, more than 2 GB.
    said = run_with_address_space("2_000_000_000",
                                  "molchaos.simulate(particles=100_000_000, t_end=1.0)", "ValueError")
    assert said.startswith("particles: a run of 100000000 disks holds at least 15 GB")
    assert "allowed: at most" in said


def test_theory_names_an_unknown_keyword():
    # Was pybind11's "incompatible function arguments" with the whole signature.
    with pytest.raises(TypeError, match=r"theory\(\) got an unexpected keyword argument "
                                        r"'restiution'; allowed: dim, restitution, density"):
        molchaos.theory(restiution=0.9)
    assert molchaos.theory(restitution=0.8)["inputs"]["restitution"] == 0.8


def test_simulate_names_an_unknown_keyword_and_what_a_flag_is_called_here():
    with pytest.raises(TypeError, match=r"simulate\(\) got an unexpected keyword argument 'relax'; "
                                        r"the CLI's --relax is 'relax_collisions_per_particle' "
                                        r"here; allowed: dim, dimension, particles"):
        molchaos.simulate(relax=0)
    with pytest.raises(TypeError, match=r"argument 'tend'; allowed: dim, .*, restart$"):
        molchaos.simulate(tend=1)


def test_clear_relaxed_states_frees_the_kept_states_and_the_runs_after_it_give_the_same_bits():
    first = molchaos.simulate(particles=300, t_end=1, seed=21)
    molchaos.clear_relaxed_states()
    again = molchaos.simulate(particles=300, t_end=1, seed=21)  # relaxes itself again
    assert np.array_equal(first["T"], again["T"]) and first["total_events"] == again["total_events"]
    assert "clear_relaxed_states()" in molchaos.simulate.__doc__
