"""Readers for the files molchaos writes: run CSVs and snapshot CSVs with their `# key = value`
header, the summary tables of `molchaos reproduce`, and H5MD trajectories. Each returns a pandas
DataFrame (or numpy arrays) together with the metadata dict."""

import pandas as pd


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


def _read_header(path):
    """The `# key = value` lines at the top of a file, and how many comment lines there are."""
    metadata = {}
    comment_lines = 0
    with open(path, encoding="utf-8") as f:
        for line in f:
            if not line.startswith("#"):
                break
            comment_lines += 1
            body = line[1:].strip()
            if " = " in body:
                key, value = body.split(" = ", 1)
                metadata[key.strip()] = _header_value(value.strip())
            elif "=" in body and body.endswith("="):
                metadata[body[:-1].strip()] = ""
            elif body:
                metadata.setdefault("description", body)
    if "snapshot_times" in metadata and not isinstance(metadata["snapshot_times"], list):
        value = metadata["snapshot_times"]
        metadata["snapshot_times"] = [] if value == "" else [float(value)]
    return metadata, comment_lines


def _read_rows(path):
    """The data rows of a suite's CSV file. Every file the suite writes ends with a newline, so
    one that does not was cut short (a copy or download broken off): refused, where pandas would
    fill the cut row's missing columns with NaN without a word."""
    with open(path, "rb") as f:
        f.seek(0, 2)
        if f.tell() > 0:
            f.seek(-1, 2)
            if f.read(1) != b"\n":
                raise ValueError(f"{path}: ends in the middle of a line (a truncated file?)")
    return pd.read_csv(path, comment="#", float_precision="round_trip")


def read_run_csv(path):
    """A `molchaos simulate --out` file: (DataFrame with columns t, T, a2, collisions, ...,
    metadata dict with the run's parameters, version, stop_reason)."""
    metadata, _ = _read_header(path)
    frame = _read_rows(path)
    if "rows" in metadata and metadata["rows"] != len(frame):
        raise ValueError(f"{path}: header says {metadata['rows']} rows, file has {len(frame)}")
    return frame, metadata


def read_snapshot_csv(path):
    """A snapshot file written next to a run CSV (`--snapshot-times`): (DataFrame, metadata)."""
    metadata, _ = _read_header(path)
    return _read_rows(path), metadata


def read_table(path):
    """A summary table of `molchaos reproduce` (e.g. fig4_A_of_eps.csv): (DataFrame, metadata
    from its `#` lines, possibly empty)."""
    metadata, _ = _read_header(path)
    return _read_rows(path), metadata


def read_trajectory(path):
    """An H5MD file written by `molchaos simulate --trajectory`: dict with numpy arrays time (F),
    step (F), position and velocity (F x N x d), edges (d), and the run's parameters."""
    import h5py

    with h5py.File(path, "r") as f:
        particles = f["particles/all"]
        out = {
            "time": particles["position/time"][()],
            "step": particles["position/step"][()],
            "position": particles["position/value"][()],
            "velocity": particles["velocity/value"][()],
            "edges": particles["box/edges"][()],
            "parameters": {k: _attribute(v) for k, v in f["parameters"].attrs.items()},
        }
    return out


def _attribute(value):
    if isinstance(value, bytes):
        return value.decode()
    if hasattr(value, "tolist"):
        return value.tolist()
    return value
