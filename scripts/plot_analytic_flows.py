#!/usr/bin/env python3
"""Plot the LBM core's analytic validation flows beside their exact solutions.

usage: SHIP_LRM_VALIDATION_OUT=DIR test_lbm --gtest_filter='Validation.*'
       plot_analytic_flows.py DIR OUT.png

DIR holds the CSVs the tests write when SHIP_LRM_VALIDATION_OUT is set: poiseuille.csv (force-driven
channel between halfway bounce-back walls, exact parabola), couette.csv (a moving wall, exact linear
profile) and taylor_green.csv (the decaying Taylor-Green vortex at 32 and 64 cells per wavelength:
the velocity error's order and the viscosity measured from the decay).
"""
import csv
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    if not os.path.isfile(path):
        sys.exit(f"plot_analytic_flows.py: {path} not found (run the tests with SHIP_LRM_VALIDATION_OUT set)")
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"plot_analytic_flows.py: {path} has no data rows")
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    folder, out = sys.argv[1], sys.argv[2]
    p = read(os.path.join(folder, "poiseuille.csv"))
    c = read(os.path.join(folder, "couette.csv"))
    t = read(os.path.join(folder, "taylor_green.csv"))
    fig, axes = plt.subplots(1, 3, figsize=(14, 4.2))
    for ax, d, u, exact, title in ((axes[0], p, "u_over_peak", "exact_over_peak", "Poiseuille (force-driven)"),
                                   (axes[1], c, "u_over_U", "exact_over_U", "Couette (moving wall)")):
        err = max(abs(a - b) for a, b in zip(d[u], d[exact]))
        ax.plot(d[exact], d["y_from_wall"], "k-", label="exact")
        ax.plot(d[u], d["y_from_wall"], "o", ms=4, label=f"LBM (largest error {err:.1e})")
        ax.set_xlabel(u.replace("_over_", " / "))
        ax.set_ylabel("distance from the wall [cells]")
        ax.set_title(title)
        ax.legend(fontsize=8)
        ax.grid(True, alpha=0.3)
    n, e = t["cells_per_wavelength"], t["l2_error"]
    order = math.log2(e[0] / e[1])
    ax = axes[2]
    ax.loglog(n, e, "o-", label=f"LBM, observed order {order:.2f}")
    ax.loglog(n, [e[0] * (n[0] / x) ** 2 for x in n], "k--", label="second order")
    ax.set_xlabel("cells per wavelength")
    ax.set_ylabel("relative L2 velocity error")
    nu = t["nu_measured"][-1] / t["nu"][-1]
    ax.set_title(f"Taylor-Green vortex\nviscosity from the decay: {nu:.4f} of nu", fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    fig.suptitle("LBM core against analytic solutions (D3Q19, BGK, halfway bounce-back)")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
