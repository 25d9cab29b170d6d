"""molchaos from Python: the kinetic theory and the event-driven simulation of granular gases
(compiled extension _molchaos), and readers for every file the suite writes (readers.py)."""

try:  # simulate() returns numpy arrays, the readers pandas tables
    import numpy as _numpy  # noqa: F401
    import pandas as _pandas  # noqa: F401
except ImportError as missing:
    raise ImportError(f"molchaos needs numpy and pandas ({missing}); on Debian: apt-get install "
                      "python3-numpy python3-pandas") from missing

from ._molchaos import __version__, clear_relaxed_states, simulate
from ._molchaos import _theory, _theory_keywords
from .readers import read_run_csv, read_snapshot_csv, read_table, read_trajectory


def theory(*args, **kwargs):
    # `dimension` names `dim`, as in simulate().
    if "dimension" in kwargs:
        if "dim" in kwargs:
            raise TypeError("theory() got 'dimension' and 'dim' for the same parameter; give one")
        kwargs["dim"] = kwargs.pop("dimension")
    # An unknown keyword named, as simulate() names it (pybind11's message lists the signature).
    for key in kwargs:
        if key not in _theory_keywords:
            raise TypeError(f"theory() got an unexpected keyword argument '{key}'; allowed: "
                            f"{', '.join(_theory_keywords)} (dimension for dim)")
    return _theory(*args, **kwargs)


theory.__doc__ = _theory.__doc__

__all__ = [
    "__version__",
    "simulate",
    "clear_relaxed_states",
    "theory",
    "read_run_csv",
    "read_snapshot_csv",
    "read_table",
    "read_trajectory",
]
