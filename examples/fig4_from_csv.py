"""Fig. 4 of the paper from the table `molchaos reproduce` writes: the cooling amplitude A(eps)
measured (with its standard error) beside the kinetic theory, one curve per randomization mode.

    PYTHONPATH=build/python /usr/bin/python3 examples/fig4_from_csv.py results/fig4_A_of_eps.csv \
        fig4.png
"""

import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import molchaos  # noqa: E402


# The columns of `molchaos reproduce`'s fig4_A_of_eps.csv that the figure draws.
FIG4_COLUMNS = {"density", "restitution", "randomize", "A", "A_err", "A_theory"}


def main(table_path, png_path):
    table, meta = molchaos.read_table(table_path)
    missing = FIG4_COLUMNS - set(table.columns)
    if missing:
        raise ValueError(f"{table_path}: not a Fig. 4 table (fig4_A_of_eps.csv): no column "
                         f"{', '.join(sorted(missing))}")
    # One panel per density on a linear axis, as the paper's Fig. 4: the gases differ by a few
    # per cent, which a shared or logarithmic axis would flatten.
    densities = sorted(table["density"].unique())
    fig, axes = plt.subplots(1, len(densities), figsize=(4.5 * len(densities), 4), squeeze=False)
    labels = {"none": "original gas", "paper": "paper's shuffle", "flux": "flux-weighted shuffle",
              "dsmc": "DSMC"}
    for ax, density in zip(axes[0], densities):
        panel = table[table["density"] == density]
        for mode, rows in panel.groupby("randomize"):
            rows = rows.sort_values("restitution")
            # A_err is nan for a point of one run (no standard error): no bar there.
            error = rows["A_err"] if rows["A_err"].notna().any() else None
            ax.errorbar(rows["restitution"], rows["A"], yerr=error, fmt="o", capsize=2,
                        label=labels.get(mode, mode))
        theory = panel.drop_duplicates("restitution").sort_values("restitution")
        ax.plot(theory["restitution"], theory["A_theory"], "k--", label="kinetic theory (b = 0)")
        ax.set_xlabel(r"restitution $\varepsilon$")
        ax.set_ylabel(r"$A = \tau_0 (1-\varepsilon^2)$")
        ax.set_title(f"d = {meta.get('dimension', '?')}, n = {density}, "
                     f"N = {meta.get('particles', '?')}")
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(png_path, dpi=120)
    return table


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("table", help="fig4_A_of_eps.csv of `molchaos reproduce`")
    parser.add_argument("png", nargs="?", default="fig4.png", help="the figure (default fig4.png)")
    arguments = parser.parse_args()
    try:
        main(arguments.table, arguments.png)
    except (OSError, ValueError) as error:
        parser.error(str(error))
