"""Arguments of theory() and simulate() of kinds a physicist's script produces: numpy scalars and
arrays of every dtype and shape, complex and boolean numbers, bytes. Each is taken as the number or
list it stands for, or refused with a TypeError naming the parameter; never silently read as
something else, and never a crash."""

import json
import subprocess
import sys

import numpy as np
import pytest

import molchaos

SMALL = dict(dim=2, particles=200, density=0.05, restitution=0.9, seed=3, t_end=20.0,
             relax_collisions_per_particle=5.0, samples_per_decade=5)


def test_numpy_arrays_of_snapshot_times_are_read_element_by_element():
    # numpy hands out each element as a new object: the list is read from owned references.
    plain = molchaos.simulate(**SMALL, snapshot_times=[5.0, 10.0])
    for times in (np.array([5.0, 10.0], dtype=np.float32), np.array([5, 10]),
                  np.arange(5.0, 15.0, 5.0), (5.0, 10.0)):
        run = molchaos.simulate(**SMALL, snapshot_times=times)
        assert run["parameters"]["snapshot_times"] == [5.0, 10.0]
        for a, b in zip(plain["snapshots"], run["snapshots"]):
            np.testing.assert_array_equal(a["positions"], b["positions"])


def test_a_two_dimensional_array_of_times_is_refused_without_a_crash():
    # Once a use-after-free: the rows of the array were read through dangling handles.
    code = ("import numpy as np, molchaos\n"
            "try:\n"
            "    molchaos.simulate(particles=200, t_end=20.0, snapshot_times=np.array([[5., 6.]]))\n"
            "except TypeError as e:\n"
            "    print(e)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert out.returncode == 0, out.stderr
    assert out.stdout.startswith("snapshot_times: expected a list of real numbers, got array(")


@pytest.mark.parametrize("value", [np.array(5.0), np.array([[5.0]]), b"\x05", bytearray(b"\x05")],
                         ids=["0-d array", "2-d array", "bytes", "bytearray"])
def test_snapshot_times_that_are_no_list_of_numbers_are_refused(value):
    with pytest.raises(TypeError, match="snapshot_times: expected a list of real numbers, got "):
        molchaos.simulate(**SMALL, snapshot_times=value)


@pytest.mark.parametrize("value,shown", [
    (np.True_, r"True \(bool_\)"),                       # would run as eps = 1
    (np.complex128(0.9 + 1j), r"\(0\.9\+1j\) \(complex128\)"),  # would drop the imaginary part
    (np.array([0.9]), r"array\(\[0\.9\]\) \(ndarray\)"),  # one number is not a list of one
    (np.array([0.9, 0.8]), r"array\(\[0\.9, 0\.8\]\) \(ndarray\)"),
])
def test_numpy_values_that_are_no_real_number_are_refused(value, shown):
    with pytest.raises(TypeError, match=rf"restitution: expected a real number, got {shown}"):
        molchaos.theory(restitution=value)
    with pytest.raises(TypeError, match=rf"restitution: expected a real number, got {shown}"):
        molchaos.simulate(**dict(SMALL, restitution=value))
    with pytest.raises(TypeError, match=r"snapshot_times: expected a real number, got "):
        molchaos.simulate(**SMALL, snapshot_times=[value])


def test_numpy_numbers_of_the_right_kind_are_taken():
    assert molchaos.theory(restitution=np.array(0.9))["A"] == molchaos.theory(restitution=0.9)["A"]
    assert molchaos.theory(dim=np.uint8(3))["inputs"]["dim"] == 3
    with pytest.raises(TypeError, match=r"particles: expected an integer, got True \(bool_\)"):
        molchaos.simulate(**dict(SMALL, particles=np.True_))
    with pytest.raises(TypeError, match=r"particles: expected an integer, got 200\.0 \(float64\)"):
        molchaos.simulate(**dict(SMALL, particles=np.float64(200)))
    # numpy's bool (what a comparison of numpy numbers gives) is a bool.
    run = molchaos.simulate(**SMALL, contact_statistics=np.float64(1.0) > 0)
    assert run["parameters"]["contact_statistics"] is True


@pytest.mark.parametrize("name", ["checkpoint", "restart"])
def test_an_empty_checkpoint_name_is_refused(name):
    # Was: read as no file at all, so restart="" ran a new run from t = 0 without a word.
    with pytest.raises(ValueError, match=f"{name}: the file name is empty"):
        molchaos.simulate(**SMALL, **{name: ""})


def test_theory_quadrature_and_its_tolerance(molchaos_bin):
    # Was: tolerance was taken and changed nothing (the Gauss rules take none), and the adaptive
    # quadrature of the CLI could not be chosen.
    out = subprocess.run([molchaos_bin, "theory", "--quadrature", "adaptive", "--tolerance", "1e-4",
                          "--json"], check=True, capture_output=True, text=True).stdout
    adaptive = molchaos.theory(quadrature="adaptive", tolerance=1e-4)
    assert adaptive["mu2"] == json.loads(out)["mu2"]
    assert adaptive["mu2_error"] == json.loads(out)["mu2_error"]
    gauss = molchaos.theory()
    assert gauss["inputs"]["quadrature"] == "gauss"
    assert adaptive["inputs"]["quadrature"] == "adaptive"
    # Different routes, each within its own error estimate of the other.
    assert adaptive["mu2"] != gauss["mu2"]
    assert abs(adaptive["mu2"] - gauss["mu2"]) <= adaptive["mu2_error"] + gauss["mu2_error"]
    with pytest.raises(ValueError, match=r"tolerance: applies to quadrature='adaptive' only"):
        molchaos.theory(tolerance=1e-4)
    with pytest.raises(ValueError, match=r"quadrature: must be one of \{gauss, adaptive\}"):
        molchaos.theory(quadrature="qagiu")


def test_help_names_every_parameter_and_the_result_types():
    doc = molchaos.simulate.__doc__
    run = molchaos.simulate(**dict(SMALL, dim=3), snapshot_times=[5.0])
    for name in run["parameters"]:
        assert f"\n  {name}" in doc, name
    assert "collisions, events: uint64 arrays" in doc
    for key in ("collisions", "events"):
        assert run[key].dtype == np.uint64 and run[key].shape == run["t"].shape
    for key in ("t", "T", "a2", "velocity_mode", "density_mode"):
        assert run[key].dtype == np.float64 and run[key].shape == run["t"].shape
    snap = run["snapshots"][0]
    assert snap["positions"].shape == snap["velocities"].shape == (200, 3)
    assert snap["positions"].dtype == np.float64
    assert isinstance(run["total_collisions"], int) and isinstance(run["wall_seconds"], float)
    assert "quadrature" in molchaos.theory.__doc__
