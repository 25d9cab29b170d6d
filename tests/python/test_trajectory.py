"""H5MD and extended XYZ files of `molchaos simulate`, read by h5py and ASE (readers written
elsewhere), against the snapshot CSVs of the same run: the same doubles come back."""

import os
import subprocess
import time

import ase.io
import h5py
import numpy as np
import pytest

import molchaos

TIMES = [2.0, 6.0]  # the last at t_end, where the run CSV's last row counts the collisions


@pytest.fixture(scope="module", params=[2, 3])
def run(request, molchaos_bin, tmp_path_factory):
    dim = request.param
    d = tmp_path_factory.mktemp(f"traj{dim}")
    subprocess.run(
        [molchaos_bin, "simulate", "--dim", str(dim), "--particles", "150", "--density", "0.05",
         "--restitution", "0.9", "--seed", "7", "--t-end", "6", "--relax", "5", "--quiet",
         "--snapshot-times", *map(str, TIMES), "--out", str(d / "run.csv"),
         "--trajectory", str(d / "run.h5"), "--xyz", str(d / "run.xyz")],
        check=True, capture_output=True)
    snaps = [molchaos.read_snapshot_csv(d / f"run.snapshot{k}.csv") for k in range(len(TIMES))]
    return dim, d, snaps


def collisions_at_snapshots(d):
    """The collisions since t = 0 at each snapshot time, from the run CSV's samples (a frame's
    step in H5MD, its Collisions in extended XYZ): the sample at the last snapshot, t_end, and a
    count strictly between 0 and it for the one before."""
    table, _ = molchaos.read_run_csv(d / "run.csv")
    with h5py.File(d / "run.h5", "r") as f:
        step = f["particles/all/position/step"][()]
    assert table["t"].iloc[-1] == TIMES[-1]
    assert step[-1] == table["collisions"].iloc[-1]
    assert 0 < step[0] < step[-1]
    return step


def test_h5md_layout_and_values(run):
    dim, d, snaps = run
    with h5py.File(d / "run.h5", "r") as f:
        assert list(f["h5md"].attrs["version"]) == [1, 1]
        assert "name" in f["h5md/author"].attrs
        assert f["h5md/creator"].attrs["name"] == b"molchaos" or \
            f["h5md/creator"].attrs["name"] == "molchaos"
        box = f["particles/all/box"]
        assert box.attrs["dimension"] == dim
        assert [b.decode() if isinstance(b, bytes) else b for b in box.attrs["boundary"]] == \
            ["periodic"] * dim
        for name, cols in (("position", ["x", "y", "z"][:dim]),
                           ("velocity", ["vx", "vy", "vz"][:dim])):
            el = f[f"particles/all/{name}"]
            value = el["value"][()]
            assert value.dtype == np.float64 and value.shape == (len(TIMES), 150, dim)
            np.testing.assert_array_equal(el["time"][()], [m["t"] for _, m in snaps])
            np.testing.assert_array_equal(el["step"][()], collisions_at_snapshots(d))
            for series in ("value", "time", "step"):  # H5MD's [variable] time dimension
                assert el[series].maxshape[0] is None, series
                assert el[series].maxshape[1:] == el[series].shape[1:], series
            for k, (frame, _) in enumerate(snaps):
                np.testing.assert_array_equal(value[k], frame[cols].to_numpy())
        np.testing.assert_array_equal(box["edges"][()], [snaps[0][1]["box"]] * dim)
        params = f["parameters"].attrs
        assert params["dimension"] == dim and params["seed"] == 7
        assert params["restitution"] == 0.9
        np.testing.assert_array_equal(params["snapshot_times"], TIMES)
    traj = molchaos.read_trajectory(d / "run.h5")
    assert traj["position"].shape == (len(TIMES), 150, dim)


def test_extended_xyz_read_by_ase(run):
    dim, d, snaps = run
    frames = ase.io.read(d / "run.xyz", index=":", format="extxyz")
    assert len(frames) == len(TIMES)
    for atoms, (frame, meta) in zip(frames, snaps):
        assert len(atoms) == 150
        cols = ["x", "y", "z"][:dim]
        np.testing.assert_array_equal(atoms.get_positions()[:, :dim], frame[cols].to_numpy())
        vel = atoms.arrays["vel"]
        np.testing.assert_array_equal(vel[:, :dim], frame[["vx", "vy", "vz"][:dim]].to_numpy())
        # ASE's own velocities (from the momenta column, m = 1): not zero (was: no momenta).
        np.testing.assert_array_equal(atoms.get_velocities()[:, :dim],
                                      frame[["vx", "vy", "vz"][:dim]].to_numpy())
        if dim == 2:
            assert np.all(atoms.get_positions()[:, 2] == 0.0)
        assert atoms.cell[0, 0] == meta["box"] and atoms.cell[1, 1] == meta["box"]
        assert list(atoms.pbc) == [True, True, dim == 3]
        assert atoms.info["Time"] == meta["t"]
        # The run's flags are logicals (T, F), which ASE reads as bools: "false" was a string,
        # which Python takes for true.
        assert atoms.info["contact_statistics"] is False
        assert not any(v in ("true", "false") for v in atoms.info.values() if isinstance(v, str))
    assert [atoms.info["Collisions"] for atoms in frames] == list(collisions_at_snapshots(d))


def test_same_seed_same_h5md_bytes(molchaos_bin, tmp_path):
    """HDF5 object timestamps are off: the same run gives the same file, byte for byte, even when
    written a second later."""
    files = []
    for name in ("a", "b"):
        (tmp_path / name).mkdir()
        subprocess.run(
            [molchaos_bin, "simulate", "--particles", "150", "--density", "0.05", "--seed", "7",
             "--t-end", "6", "--relax", "5", "--quiet", "--snapshot-times", "2", "5",
             "--out", str(tmp_path / name / "run.csv"),
             "--trajectory", str(tmp_path / name / "run.h5")],
            check=True, capture_output=True)
        files.append((tmp_path / name / "run.h5").read_bytes())
        time.sleep(1.1)  # timestamps have a resolution of one second
    assert files[0] == files[1]


@pytest.mark.parametrize("author", [None, "", "Ada Lovelace", "Jürgen Höfling"])
def test_h5md_author_is_the_person_not_the_program(molchaos_bin, tmp_path, author):
    """H5MD's /h5md/author names who ran the simulation (the program is /h5md/creator): the name
    in MOLCHAOS_AUTHOR, "unknown" where it is unset or empty (was: "molchaos" always)."""
    env = {k: v for k, v in os.environ.items() if k != "MOLCHAOS_AUTHOR"}
    if author is not None:
        env["MOLCHAOS_AUTHOR"] = author
    subprocess.run(
        [molchaos_bin, "simulate", "--particles", "50", "--density", "0.05", "--t-end", "1",
         "--relax", "1", "--quiet", "--snapshot-times", "1", "--out", str(tmp_path / "run.csv"),
         "--trajectory", str(tmp_path / "run.h5")],
        check=True, capture_output=True, env=env)
    with h5py.File(tmp_path / "run.h5", "r") as f:
        name = f["h5md/author"].attrs["name"]
        # A name beyond ASCII is marked UTF-8, as HDF5 readers decode it.
        cset = f["h5md/author"].attrs.get_id("name").get_type().get_cset()
    assert (name.decode() if isinstance(name, bytes) else name) == (author or "unknown")
    assert cset == h5py.h5t.CSET_UTF8


def test_h5md_parameters_are_the_table(run):
    """The parameters group holds every parameter of the run CSV's header, equal to it."""
    dim, d, _ = run
    header = {}
    for line in open(d / "run.csv"):
        if not line.startswith("# ") or " = " not in line:
            continue
        key, value = line[2:].rstrip("\n").split(" = ", 1)
        header[key] = value
    with h5py.File(d / "run.h5", "r") as f:
        attrs = f["parameters"].attrs
        for key in ("dimension", "particles", "density", "restitution", "seed", "t_end",
                    "relax_collisions_per_particle", "tc", "samples_per_decade",
                    "t_first_sample", "max_collisions", "min_temperature"):
            assert float(attrs[key]) == float(header[key]), key
        randomize = attrs["randomize"]
        randomize = randomize.decode() if isinstance(randomize, bytes) else str(randomize)
        assert randomize == header["randomize"]
        assert int(attrs["contact_statistics"]) == (header["contact_statistics"] == "true")
        assert list(attrs["snapshot_times"]) == [float(x) for x in header["snapshot_times"].split()]


@pytest.mark.parametrize("contacts", [False, True])
def test_read_trajectory_gives_the_parameters_simulate_gives(molchaos_bin, tmp_path, contacts):
    """Every parameter of read_trajectory equals simulate()'s for the same run, in value and in
    Python type: a flag such as contact_statistics, stored as the integer 0 or 1, reads as False or
    True (was: 0 or 1), as simulate() and read_run_csv give it."""
    subprocess.run(
        [molchaos_bin, "simulate", "--particles", "150", "--density", "0.05", "--seed", "7",
         "--t-end", "6", "--relax", "5", "--quiet", "--snapshot-times", "2", "6",
         *(["--contacts"] if contacts else []), "--out", str(tmp_path / "run.csv"),
         "--trajectory", str(tmp_path / "run.h5")],
        check=True, capture_output=True)
    run = molchaos.simulate(particles=150, density=0.05, seed=7, t_end=6.0,
                            relax_collisions_per_particle=5.0, snapshot_times=[2.0, 6.0],
                            contact_statistics=contacts)
    read = molchaos.read_trajectory(tmp_path / "run.h5")["parameters"]
    assert read["contact_statistics"] is contacts
    assert {k: (type(read[k]), read[k]) for k in run["parameters"]} == \
        {k: (type(v), v) for k, v in run["parameters"].items()}
    _, header = molchaos.read_run_csv(tmp_path / "run.csv")
    assert header["contact_statistics"] is contacts


def test_read_trajectory_refuses_a_flag_that_is_not_0_or_1(run, tmp_path):
    _, d, _ = run
    path = tmp_path / "edited.h5"
    path.write_bytes((d / "run.h5").read_bytes())
    with h5py.File(path, "r+") as f:
        f["parameters"].attrs.modify("contact_statistics", np.int64(2))
    with pytest.raises(ValueError, match=r"edited\.h5: attribute /parameters/contact_statistics "
                                         r"is not a flag, 0 or 1: 2"):
        molchaos.read_trajectory(path)


def test_config_refuses_a_negative_unsigned_parameter(run, molchaos_bin, tmp_path):
    """h5py stores a Python int as int64; HDF5's conversion to the seed's uint64 would clip -1 to
    0 and run another seed without a word."""
    _, d, _ = run
    path = tmp_path / "negative.h5"
    path.write_bytes((d / "run.h5").read_bytes())
    with h5py.File(path, "r+") as f:
        f["parameters"].attrs["seed"] = np.int64(-1)
    out = tmp_path / "again.csv"
    r = subprocess.run([molchaos_bin, "simulate", "--config", str(path), "--out", str(out),
                        "--quiet"], capture_output=True, text=True)
    assert r.returncode == 2
    assert ("negative.h5: attribute /parameters/seed is -1, outside the allowed range "
            "[0, 18446744073709551615]") in r.stderr
    assert not out.exists()


def test_config_refuses_an_attribute_that_names_no_parameter(run, molchaos_bin, tmp_path):
    """A CSV header's unknown key is refused; so is an H5MD attribute the writer does not write
    (here a misspelt parameter added by hand), whose value would otherwise be dropped."""
    _, d, _ = run
    path = tmp_path / "extra.h5"
    path.write_bytes((d / "run.h5").read_bytes())
    with h5py.File(path, "r+") as f:
        f["parameters"].attrs["restitutoin"] = 0.5
    out = tmp_path / "again.csv"
    r = subprocess.run([molchaos_bin, "simulate", "--config", str(path), "--out", str(out),
                        "--quiet"], capture_output=True, text=True)
    assert r.returncode == 2
    assert "extra.h5: attribute /parameters/restitutoin names no parameter of this version" \
        in r.stderr
    assert not out.exists()


def test_config_refuses_a_dataset_under_parameters(run, molchaos_bin, tmp_path):
    """A parameter stored as a dataset in place of its attribute was passed over (and reported as
    missing); any group or dataset under /parameters is refused, named."""
    _, d, _ = run
    path = tmp_path / "dataset.h5"
    path.write_bytes((d / "run.h5").read_bytes())
    with h5py.File(path, "r+") as f:
        f["parameters"].create_dataset("restitution_ds", data=0.5)
    r = subprocess.run([molchaos_bin, "simulate", "--config", str(path), "--out",
                        str(tmp_path / "again.csv"), "--quiet"], capture_output=True, text=True)
    assert r.returncode == 2
    assert ("dataset.h5: /parameters holds 1 group(s) or dataset(s), such as 'restitution_ds'"
            in r.stderr)
