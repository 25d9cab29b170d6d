"""The readers against files of the wrong kind, empty, cut short or not text, and against a title
line with equals signs in its prose: each refused naming the file, or read as what it is."""

import os
import subprocess

import h5py
import pytest

import molchaos


@pytest.fixture(scope="module")
def files(molchaos_bin, tmp_path_factory):
    d = tmp_path_factory.mktemp("files")
    subprocess.run(
        [molchaos_bin, "simulate", "--particles", "150", "--density", "0.05", "--seed", "7",
         "--t-end", "6", "--relax", "5", "--quiet", "--snapshot-times", "2",
         "--out", str(d / "run.csv"), "--trajectory", str(d / "run.h5"),
         "--xyz", str(d / "run.xyz")],
        check=True, capture_output=True)
    return d


def test_title_lines_are_no_keys(files):
    # "# molchaos simulate: ... (sigma = m = 1, T0 = 1)" once read as a key
    # "molchaos simulate: ... (sigma" with the value "m = 1, T0 = 1)".
    _, meta = molchaos.read_run_csv(files / "run.csv")
    assert all(key.isidentifier() for key in meta), list(meta)
    assert meta["description"].startswith("molchaos simulate: ")
    assert meta["version"].startswith("0.") and meta["particles"] == 150


@pytest.mark.parametrize("reader,name,kind", [
    (molchaos.read_run_csv, "run.snapshot0.csv", "run CSV"),
    (molchaos.read_run_csv, "run.xyz", "run CSV"),
    (molchaos.read_snapshot_csv, "run.csv", "snapshot CSV"),
])
def test_a_file_of_another_kind_is_refused(files, reader, name, kind):
    # Was: read without a word, as a frame of the other file's columns.
    with pytest.raises(ValueError, match=rf"{name}: not a {kind}: its columns are "):
        reader(files / name)


@pytest.mark.parametrize("reader", [molchaos.read_run_csv, molchaos.read_snapshot_csv,
                                    molchaos.read_table])
def test_empty_and_binary_files_are_refused_naming_them(files, reader, tmp_path):
    empty = tmp_path / "empty.csv"
    empty.write_bytes(b"")
    with pytest.raises(ValueError, match=r"empty\.csv: no column names and no rows"):
        reader(empty)
    with pytest.raises(ValueError, match=r"run\.h5: not a text file"):
        reader(files / "run.h5")


def test_a_file_descriptor_is_no_file_name(files):
    # open(3) would read, and then close, the process's file descriptor 3.
    fd = os.open(files / "run.csv", os.O_RDONLY)
    try:
        with pytest.raises(TypeError, match=rf"path: expected a file name .*got {fd} \(int\)"):
            molchaos.read_run_csv(fd)
        os.fstat(fd)  # still open
    finally:
        os.close(fd)


def test_read_trajectory_refuses_other_files_naming_them(files, tmp_path):
    other = tmp_path / "other.h5"
    with h5py.File(other, "w") as f:
        f["x"] = 1
    with pytest.raises(ValueError, match=r"other\.h5: not an H5MD trajectory of molchaos"):
        molchaos.read_trajectory(other)
    with pytest.raises(OSError, match=r"run\.csv: cannot be read as HDF5"):
        molchaos.read_trajectory(files / "run.csv")
    cut = tmp_path / "cut.h5"
    cut.write_bytes((files / "run.h5").read_bytes()[:3000])
    with pytest.raises(OSError, match=r"cut\.h5: cannot be read as HDF5 \(.*truncated"):
        molchaos.read_trajectory(cut)
    with pytest.raises(FileNotFoundError):
        molchaos.read_trajectory(tmp_path / "missing.h5")
