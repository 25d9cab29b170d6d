"""molchaos from Python: the kinetic theory and the event-driven simulation of granular gases
(compiled extension _molchaos), and readers for every file the suite writes (readers.py)."""

from ._molchaos import __version__, simulate, theory
from .readers import read_run_csv, read_snapshot_csv, read_table, read_trajectory

__all__ = [
    "__version__",
    "simulate",
    "theory",
    "read_run_csv",
    "read_snapshot_csv",
    "read_table",
    "read_trajectory",
]
