"""Readers for the files molchaos writes: run CSVs and snapshot CSVs with their `# key = value`
header, the summary tables of `molchaos reproduce`, and H5MD trajectories. Each returns a pandas
DataFrame (or numpy arrays) together with the metadata dict."""

import io
import os
import re
import warnings

import numpy as np
import pandas as pd

# A `# key = value` header line: the key is one word (a parameter's name); a title or a note with
# an equals sign in its prose ("(sigma = m = 1, T0 = 1)") is text, not a key.
_KEY_LINE = re.compile(r"([A-Za-z_][A-Za-z0-9_]*)\s*=(?:\s(.*))?$")

# Keys whose value is text whatever it looks like: a cache key of hexadecimal digits such as
# 916905785310e500 reads as a float (inf), one of decimal digits as an int without its leading
# zeros.
_TEXT_KEYS = {"cache_key", "checksum", "version", "stop_reason"}

# The options of `molchaos sweep` that list values: lists in its summary's header even when they
# hold one value, as numbers (density, restitution) or names (randomize, method).
_SWEEP_LISTS = {"density": float, "restitution": float, "randomize": str, "method": str}


def _header_value(text):
    """A header value as int, float, bool, list of floats or str, whichever reads back exactly."""
    for convert in (int, float):
        try:
            return convert(text)
        except ValueError:
            pass
    if text in ("true", "false"):
        return text == "true"
    words = text.split()
    if len(words) > 1:
        try:
            return [float(w) for w in words]
        except ValueError:
            pass
    return text


def _file_name(path):
    """A file name given as str or os.PathLike; anything else (an int would be taken by open() as
    a file descriptor of the process, and closed) is refused."""
    if not isinstance(path, (str, os.PathLike)):
        raise TypeError(f"path: expected a file name (str or os.PathLike), got {path!r} "
                        f"({type(path).__name__})")
    return os.fspath(path)


def _read_header(path):
    """The `# key = value` lines at the top of a file, and how many comment lines there are. Lines
    of text without a key (the title, notes) are joined into metadata["description"]."""
    metadata = {}
    raw = {}
    text = []
    comment_lines = 0
    try:
        # utf-8-sig: a byte order mark (as some Windows editors save) is no part of the first line.
        with open(path, encoding="utf-8-sig") as f:
            for line in f:
                if not line.startswith("#"):
                    break
                comment_lines += 1
                body = line[1:].strip()
                match = _KEY_LINE.match(body)
                if match:
                    key, value = match.group(1), (match.group(2) or "").strip()
                    metadata[key] = value if key in _TEXT_KEYS else _header_value(value)
                    raw[key] = value
                elif body:
                    text.append(body)
    except UnicodeDecodeError:
        raise ValueError(f"{path}: not a text file (molchaos writes its CSV files as UTF-8 text)") \
            from None
    if text:
        metadata["description"] = "\n".join(text)
    # A real parameter whose value is whole ("t_end = 5") is a float, as simulate() and
    # read_trajectory() give it.
    from ._molchaos import _real_parameters
    for key in _real_parameters:
        if type(metadata.get(key)) is int:
            metadata[key] = float(metadata[key])
    if "snapshot_times" in metadata and not isinstance(metadata["snapshot_times"], list):
        value = metadata["snapshot_times"]
        metadata["snapshot_times"] = [] if value == "" else [float(value)]
    if text and text[0].startswith("molchaos sweep summary"):
        # A sweep of event-driven MD alone leaves its method out of the header (as a run's CSV
        # leaves out a parameter at its default).
        raw.setdefault("method", "edmd")
        for key, convert in _SWEEP_LISTS.items():
            if key in raw:
                metadata[key] = [convert(w) for w in raw[key].split()]
    return metadata, comment_lines


def _read_rows(path):
    """The data rows of a suite's CSV file. Every file the suite writes ends with a newline, so
    one that does not was cut short (a copy or download broken off): refused, where pandas would
    fill the cut row's missing columns with NaN without a word. So is a row of another number of
    fields than the column names (_check_field_counts)."""
    with open(path, "rb") as f:
        data = f.read().removeprefix(b"\xef\xbb\xbf")
    if data and not data.endswith(b"\n"):
        raise ValueError(f"{path}: ends in the middle of a line (a truncated file?)")
    if re.search(rb"\r(?!\n)", data):  # pandas would end lines there, the count below would not
        raise ValueError(f"{path}: a carriage return alone ends a line (old Mac line ends); "
                         "the suite's files end their lines with LF or CR LF")
    # A parameter file of `simulate --write-config` (TOML, key = value lines after its title)
    # would read as a table of one column named by its first line.
    first = next((line for line in data.splitlines() if line.strip()
                  and not line.startswith(b"#")), b"")
    if re.match(rb"\s*[A-Za-z_\"][A-Za-z0-9_\"-]*\s*=", first):
        raise ValueError(f"{path}: a TOML file of key = value lines (`simulate --write-config`"
                         "), not a CSV table (`molchaos simulate --config` reads it)")
    _check_field_counts(path, data)
    try:
        # index_col=False: a field more in every row is not an index column (checked above).
        # pandas only warns where it splits a row into more fields than the column names (a
        # quote inside a field, which the count above takes for an opening one) and drops the
        # extra ones: an error here.
        with warnings.catch_warnings():
            warnings.simplefilter("error", pd.errors.ParserWarning)
            return pd.read_csv(io.BytesIO(data), comment="#", index_col=False,
                               float_precision="round_trip")
    except pd.errors.ParserWarning as warning:
        raise ValueError(f"{path}: a row with more fields than the column names ({warning})") \
            from None
    except pd.errors.EmptyDataError:
        raise ValueError(f"{path}: no column names and no rows (an empty or truncated file?)") \
            from None


def _check_field_counts(path, data):
    """Refuses a row whose number of fields differs from the column names', naming its line:
    pandas takes one field more in every row (a comma at the end of each) as an index column,
    every name then standing over its neighbour's values, and fills a row cut short with NaN.
    Fields are split as pandas splits them: at commas outside double quotes, up to a '#' outside
    quotes (the comment rule; a line starting with one is no row), blank lines skipped; a row
    ends at its line's end (the suite writes no line break inside quotes). Counted with numpy
    over the whole file: a snapshot file has a row per particle."""
    chars = np.frombuffer(data, dtype=np.uint8)
    ends = np.flatnonzero(chars == ord("\n"))  # the file ends with one, checked before
    starts = np.concatenate(([0], ends + 1))[:-1]
    quotes = np.flatnonzero(chars == ord('"'))

    def outside_quotes(positions):
        """The positions with an even number of quotes before them on their line."""
        if quotes.size == 0:
            return positions
        before = np.searchsorted(quotes, positions) - \
            np.searchsorted(quotes, starts[np.searchsorted(ends, positions)])
        return positions[before % 2 == 0]

    content_ends = ends.copy()
    hashes = outside_quotes(np.flatnonzero(chars == ord("#")))
    hash_lines, first_hash = np.unique(np.searchsorted(ends, hashes), return_index=True)
    content_ends[hash_lines] = hashes[first_hash]
    commas = outside_quotes(np.flatnonzero(chars == ord(",")))
    fields = np.searchsorted(commas, content_ends) - np.searchsorted(commas, starts) + 1

    def blank(line):
        return not data[starts[line]:content_ends[line]].strip()

    lines = np.flatnonzero(content_ends > starts)  # the column line and the rows
    column_line = next((k for k in lines if not blank(k)), None)
    if column_line is None:
        return
    for k in lines[fields[lines] != fields[column_line]]:
        if not blank(k):
            raise ValueError(f"{path}: line {k + 1} has {fields[k]} fields, where the column "
                             f"names on line {column_line + 1} are {fields[column_line]} (a row "
                             f"cut short, or a comma too many?)")


def _require_columns(path, frame, expected, kind):
    if list(frame.columns[: len(expected)]) != expected:
        raise ValueError(f"{path}: not a {kind}: its columns are {', '.join(map(str, frame.columns))}"
                         f", where a {kind} starts with {', '.join(expected)}")


RUN_COLUMNS = ["t", "T", "a2", "collisions", "events", "velocity_mode", "density_mode"]


def read_run_csv(path):
    """A `molchaos simulate --out` file: (DataFrame with columns t, T, a2, collisions, events,
    velocity_mode, density_mode[, contact columns], metadata dict with the run's parameters,
    version, stop_reason). Another kind of file (a snapshot, a summary table) is refused."""
    path = _file_name(path)
    metadata, _ = _read_header(path)
    frame = _read_rows(path)
    _require_columns(path, frame, RUN_COLUMNS, "run CSV")
    if "rows" in metadata and metadata["rows"] != len(frame):
        raise ValueError(f"{path}: header says {metadata['rows']} rows, file has {len(frame)}")
    return frame, metadata


def read_snapshot_csv(path):
    """A snapshot file written next to a run CSV (`--snapshot-times`): (DataFrame with columns x,
    y[, z], vx, vy[, vz], one row per particle; metadata with the time t, the box side, the
    collisions since t = 0 and the run's version and parameters)."""
    path = _file_name(path)
    metadata, _ = _read_header(path)
    frame = _read_rows(path)
    dim = 3 if "z" in frame.columns else 2
    axes = ["x", "y", "z"][:dim]
    _require_columns(path, frame, axes + ["v" + a for a in axes], "snapshot CSV")
    for key in ("t", "box"):
        if key not in metadata:
            raise ValueError(f"{path}: not a snapshot CSV: no '# {key} = ...' line in its header")
    return frame, metadata


def read_table(path):
    """A summary table of `molchaos reproduce` (e.g. fig4_A_of_eps.csv): (DataFrame, metadata
    from its `#` lines, possibly empty)."""
    path = _file_name(path)
    # An extended XYZ file (a particle count, then a comment line of key=value pairs) would read
    # as a table of one column named by the count (the run and snapshot readers refuse it by
    # its columns).
    with open(path, "rb") as f:
        head = f.read(1 << 16).split(b"\n", 2)
    if len(head) > 1 and head[0].strip().isdigit() and b"Properties=" in head[1]:
        raise ValueError(f"{path}: an extended XYZ file, not a CSV table (ase.io.read reads it)")
    metadata, _ = _read_header(path)
    return _read_rows(path), metadata


def read_trajectory(path):
    """An H5MD file written by `molchaos simulate --trajectory`: dict with numpy arrays time (F),
    step (F, the collisions since t = 0), position and velocity (F x N x d), edges (d), and
    parameters: the run's parameters as simulate() returns them (numbers as int or float, lists
    as lists of floats, choices as their names, flags such as contact_statistics as True or
    False, stored in the file as 1 or 0), with its stop_reason and version."""
    import h5py

    path = _file_name(path)
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        if type(e) is not OSError:  # FileNotFoundError, IsADirectoryError, ...: they name it
            raise
        # Not HDF5, or cut short: h5py's message does not name the file.
        raise OSError(f"{path}: cannot be read as HDF5 ({e})") from None
    with f:
        for group in ("particles/all/position", "particles/all/velocity", "particles/all/box",
                      "parameters"):
            if group not in f:
                raise ValueError(f"{path}: not an H5MD trajectory of molchaos (no group {group})")
        particles = f["particles/all"]
        out = {
            "time": particles["position/time"][()],
            "step": particles["position/step"][()],
            "position": particles["position/value"][()],
            "velocity": particles["velocity/value"][()],
            "edges": particles["box/edges"][()],
            "parameters": _parameters(path, f["parameters"].attrs),
        }
    return out


def _parameters(path, attributes):
    """The /parameters attributes, each flag (stored as the integer 1 or 0) as True or False."""
    from ._molchaos import _flag_parameters

    parameters = {k: _attribute(v) for k, v in attributes.items()}
    for name in _flag_parameters:
        if name in parameters:
            if parameters[name] not in (0, 1) or isinstance(parameters[name], float):
                raise ValueError(f"{path}: attribute /parameters/{name} is not a flag, 0 or 1: "
                                 f"{parameters[name]!r}")
            parameters[name] = parameters[name] == 1
    return parameters


def _attribute(value):
    if isinstance(value, bytes):
        return value.decode()
    if hasattr(value, "tolist"):
        return value.tolist()
    return value
