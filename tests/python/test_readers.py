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


def rewrite_rows(source, target, change):
    """A copy of source with change(k, row) for each data row k (from 0) and the line number of
    its column names; change returns the row's new text."""
    lines = source.read_bytes().split(b"\n")
    column_line = next(i for i, line in enumerate(lines) if not line.startswith(b"#"))
    rows = range(column_line + 1, len(lines) - 1)  # the last is the empty one after the newline
    for k, i in enumerate(rows):
        lines[i] = change(k, lines[i])
    target.write_bytes(b"\n".join(lines))
    return column_line + 1


@pytest.mark.parametrize("reader,name", [(molchaos.read_run_csv, "run.csv"),
                                         (molchaos.read_snapshot_csv, "run.snapshot0.csv"),
                                         (molchaos.read_table, "run.csv")])
def test_a_comma_at_the_end_of_every_row_is_refused(files, reader, name, tmp_path):
    # Was: read with the first column as the index, every name over its neighbour's values ('t'
    # holding T), the '# rows' count still right.
    edited = tmp_path / "edited.csv"
    column_line = rewrite_rows(files / name, edited, lambda k, row: row + b",")
    fields = (files / name).read_text().split("\n")[column_line - 1].count(",") + 1
    with pytest.raises(ValueError, match=rf"edited\.csv: line {column_line + 1} has {fields + 1} "
                                         rf"fields, where the column names on line "
                                         rf"{column_line} are {fields} "):
        reader(edited)


@pytest.mark.parametrize("reader,name", [(molchaos.read_run_csv, "run.csv"),
                                         (molchaos.read_snapshot_csv, "run.snapshot0.csv"),
                                         (molchaos.read_table, "run.csv")])
def test_a_row_cut_short_or_too_long_in_the_middle_is_refused(files, reader, name, tmp_path):
    # Was: the short row's missing columns filled with NaN without a word.
    short, long = tmp_path / "short.csv", tmp_path / "long.csv"
    column_line = rewrite_rows(files / name, short,
                               lambda k, row: row.rsplit(b",", 2)[0] if k == 20 else row)
    rewrite_rows(files / name, long, lambda k, row: row + b",1" if k == 20 else row)
    with pytest.raises(ValueError, match=rf"short\.csv: line {column_line + 21} has "):
        reader(short)
    with pytest.raises(ValueError, match=rf"long\.csv: line {column_line + 21} has "):
        reader(long)


def test_quoted_commas_and_comment_lines_after_the_rows_are_no_fields(tmp_path):
    # As `molchaos reproduce` and `molchaos bench` write their tables: quoted text with commas,
    # empty fields, '#' lines after the rows.
    table = tmp_path / "table.csv"
    table.write_text('# a table\nd,quantity,measured,note\n'
                     '2,"S_perp(k, tau)",,"a note, ""quoted"" # not a comment"\n'
                     '3,plain,1.5,\n# target 1 %: cheapest N = 3, with 4 seeds\n')
    frame, meta = molchaos.read_table(table)
    assert frame["quantity"].tolist() == ["S_perp(k, tau)", "plain"]
    assert frame["note"][0] == 'a note, "quoted" # not a comment'
    assert frame["measured"][1] == 1.5 and meta == {"description": "a table"}


@pytest.mark.parametrize("reader,name", [(molchaos.read_run_csv, "run.csv"),
                                         (molchaos.read_snapshot_csv, "run.snapshot0.csv"),
                                         (molchaos.read_table, "run.csv")])
def test_a_byte_order_mark_is_no_part_of_the_header(files, reader, name, tmp_path):
    # Was: the first line read as "\ufeff# molchaos ...", no header at all: metadata {}.
    marked = tmp_path / name
    marked.write_bytes(b"\xef\xbb\xbf" + (files / name).read_bytes())
    frame, meta = reader(marked)
    plain_frame, plain_meta = reader(files / name)
    assert meta == plain_meta and meta["particles"] == 150
    assert frame.equals(plain_frame)


@pytest.mark.parametrize("text", ['a,b,c\n1, "x,y",2\n', 'a,b,c\n1,p"q,r"s,2\n'])
def test_a_quote_inside_a_field_is_no_quoted_field(tmp_path, text):
    # pandas takes such a quote literally and splits the row into more fields than the names,
    # keeping the first ones with only a warning.
    table = tmp_path / "quote.csv"
    table.write_text(text)
    with pytest.raises(ValueError, match=r"quote\.csv: a row with more fields than the column"):
        molchaos.read_table(table)


def test_an_extended_xyz_file_is_no_table(files):
    # Was: read as a table of one column named by the particle count.
    with pytest.raises(ValueError, match=r"run\.xyz: an extended XYZ file, not a CSV table"):
        molchaos.read_table(files / "run.xyz")


@pytest.mark.parametrize("reader", [molchaos.read_run_csv, molchaos.read_snapshot_csv,
                                    molchaos.read_table])
def test_a_parameter_file_is_no_table(molchaos_bin, tmp_path, reader):
    # Was: read_table gave a table of one column named by the file's first key = value line, the
    # other readers a row "cut short" where an array holds a comma.
    subprocess.run(
        [molchaos_bin, "simulate", "--particles", "50", "--t-end", "1", "--relax", "0", "--quiet",
         "--snapshot-times", "0.5", "--out", str(tmp_path / "run.csv"),
         "--write-config", str(tmp_path / "run.toml")],
        check=True, capture_output=True)
    with pytest.raises(ValueError, match=r"run\.toml: a TOML file of key = value lines"):
        reader(tmp_path / "run.toml")


def test_a_carriage_return_alone_is_refused(tmp_path):
    # pandas ends a line there, so the short second row would be filled with NaN.
    table = tmp_path / "cr.csv"
    table.write_bytes(b"a,b,c\r1,2,3\r4,5\r\n")
    with pytest.raises(ValueError, match=r"cr\.csv: a carriage return alone ends a line"):
        molchaos.read_table(table)


def test_text_keys_stay_text(tmp_path):
    # A cache key of hexadecimal digits with an 'e' read as a float: 916905785310e500 was inf; one
    # of decimal digits would lose its leading zeros as an int.
    run = tmp_path / "key.csv"
    run.write_text("# molchaos simulate: a header\n# cache_key = 916905785310e500\n"
                   "# checksum = 0012\n# version = 1\n# particles = 150\nt,T\n0,1\n")
    _, meta = molchaos.read_table(run)
    assert meta["cache_key"] == "916905785310e500" and meta["checksum"] == "0012"
    assert meta["version"] == "1" and meta["particles"] == 150


def test_a_sweep_summary_lists_its_points_as_lists(molchaos_bin, tmp_path):
    # One density and one mode were a float and a string, two densities a list: a script looping
    # over the header's points broke on the single ones.
    out = tmp_path / "sweep.csv"
    subprocess.run([molchaos_bin, "sweep", "--particles", "100", "--restitution", "0.9,0.8",
                    "--seeds", "2", "--t-end-tau0", "0.5", "--cache", "", "--quiet", "--threads",
                    "1", "--out", str(out)], check=True, capture_output=True)
    frame, meta = molchaos.read_table(out)
    assert meta["density"] == [0.05] and meta["restitution"] == [0.9, 0.8]
    assert meta["randomize"] == ["none"] and meta["method"] == ["edmd"] and len(frame) == 2
