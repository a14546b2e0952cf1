#!/usr/bin/env python3
"""Centre-plane plots of a ship-wake precompute (thesis figs. 7.2, 7.3, 7.6) and the comparison of two
runs (two resolutions, or a moving ship against the static one).

  plot_wake.py plane  CSV PNG              mean |u| / U and TKE / U^2 (and phase differences if any)
  plot_wake.py compare COARSE.csv FINE.csv PNG [--summary OUT.csv]
                                           both on the centre plane and their difference; prints the
                                           RMS and largest difference of mean u / U and TKE / U^2 over
                                           the fluid points of the fine grid above the waterline
  plot_wake.py phases MOVING.csv STATIC.csv PNG
                                           phase-averaged mean u minus the static mean (fig. 7.6)

CSV: written by `ship_lrm wake` (x_m, z_m, solid, mean_u, mean_v, mean_w, tke, [phaseK_u, phaseK_w,
phaseK_tke], wind). Coordinates: ship frame, x forward, z down, origin at the hangar-door base.
"""
import argparse
import sys

import numpy as np


def load(path):
    data = np.genfromtxt(path, delimiter=",", names=True)
    if data.size == 0:
        sys.exit(f"plot_wake.py: {path} has no rows")
    xs, zs = np.unique(data["x_m"]), np.unique(data["z_m"])
    nx, nz = len(xs), len(zs)
    if nx * nz != data.size:
        sys.exit(f"plot_wake.py: {path} is not a full plane")
    grid = {name: data[name].reshape(nz, nx) for name in data.dtype.names}
    grid["xs"], grid["zs"] = xs, zs
    grid["U"] = float(data["wind"][0])
    return grid


def imshow(ax, g, field, title, cmap, vmin=None, vmax=None):
    f = np.ma.masked_where(g["solid"] > 0, field)
    ext = [g["xs"][0], g["xs"][-1], g["zs"][-1], g["zs"][0]]
    im = ax.imshow(f, origin="upper", extent=ext, cmap=cmap, vmin=vmin, vmax=vmax, aspect="equal")
    solid = np.ma.masked_where(g["solid"] == 0, g["solid"])
    ax.imshow(solid, origin="upper", extent=ext, cmap="Greys", vmin=0, vmax=2, aspect="equal")
    ax.set_title(title, fontsize=9)
    ax.set_xlabel("x (m, forward)")
    ax.set_ylabel("z (m, down)")
    return im


def cmd_plane(a, plt):
    g = load(a.csv)
    U = g["U"]
    speed = np.sqrt(g["mean_u"] ** 2 + g["mean_v"] ** 2 + g["mean_w"] ** 2) / U
    phases = "phase0_u" in g
    rows = 4 if phases else 3
    fig, axes = plt.subplots(rows, 1, figsize=(11, 2.6 * rows), constrained_layout=True)
    im = imshow(axes[0], g, speed, "mean |u| / U (fig. 7.2)", "gray", 0, 1.4)
    fig.colorbar(im, ax=axes[0])
    im = imshow(axes[1], g, g["mean_u"] / -U, "mean u_x / (-U): below 0 = reversed flow", "RdBu", -1, 1)
    fig.colorbar(im, ax=axes[1])
    im = imshow(axes[2], g, g["tke"] / U ** 2, "TKE / U^2 (fig. 7.3)", "gray_r", 0, 0.1)
    fig.colorbar(im, ax=axes[2])
    if phases:
        im = imshow(axes[3], g, (g["phase1_u"] - g["phase3_u"]) / U, "phase 1/4 minus 3/4: u_x / U", "RdBu", -0.3, 0.3)
        fig.colorbar(im, ax=axes[3])
    fig.savefig(a.png, dpi=110)
    print(f"wrote {a.png}")


def on_fine(coarse, fine, field):
    from scipy.interpolate import RegularGridInterpolator

    f = RegularGridInterpolator((coarse["zs"], coarse["xs"]), coarse[field], bounds_error=False, fill_value=np.nan)
    Z, X = np.meshgrid(fine["zs"], fine["xs"], indexing="ij")
    return f(np.stack([Z.ravel(), X.ravel()], axis=1)).reshape(Z.shape)


def cmd_compare(a, plt):
    c, f = load(a.coarse), load(a.fine)
    U = f["U"]
    solid_c = on_fine(c, f, "solid")
    mask = (f["solid"] == 0) & (solid_c == 0) & np.isfinite(solid_c)
    out = []
    fig, axes = plt.subplots(3, 1, figsize=(11, 7.8), constrained_layout=True)
    for k, (field, scale, name) in enumerate([("mean_u", U, "mean u_x / U"), ("tke", U ** 2, "TKE / U^2")]):
        d = (on_fine(c, f, field) - f[field]) / scale
        rms = float(np.sqrt(np.nanmean(d[mask] ** 2)))
        big = float(np.nanmax(np.abs(d[mask])))
        out.append((name, rms, big))
        print(f"{name}: RMS difference {rms:.4f}, largest {big:.4f} over {mask.sum()} fluid points")
        if k == 0:
            im = imshow(axes[0], f, f["mean_u"] / -U, "fine: mean u_x / (-U)", "RdBu", -1, 1)
            fig.colorbar(im, ax=axes[0])
            im = imshow(axes[1], f, np.where(mask, d, np.nan), "coarse minus fine: mean u_x / U", "RdBu", -0.3, 0.3)
            fig.colorbar(im, ax=axes[1])
        else:
            im = imshow(axes[2], f, np.where(mask, d, np.nan), "coarse minus fine: TKE / U^2", "RdBu", -0.05, 0.05)
            fig.colorbar(im, ax=axes[2])
    fig.savefig(a.png, dpi=110)
    print(f"wrote {a.png}")
    if a.summary:
        with open(a.summary, "w") as s:
            s.write("quantity,rms_difference,largest_difference\n")
            for name, rms, big in out:
                s.write(f"{name},{rms:.6f},{big:.6f}\n")


def cmd_phases(a, plt):
    m, s = load(a.moving), load(a.static)
    if "phase0_u" not in m:
        sys.exit(f"plot_wake.py: {a.moving} has no phase averages (a periodic ship motion writes them)")
    if m["mean_u"].shape != s["mean_u"].shape:
        sys.exit("plot_wake.py: the two runs have different grids")
    U = m["U"]
    fig, axes = plt.subplots(4, 1, figsize=(11, 10), constrained_layout=True)
    for k in range(4):
        d = (m[f"phase{k}_u"] - s["mean_u"]) / U
        im = imshow(axes[k], m, np.where(s["solid"] > 0, np.nan, d), f"phase t = {k}/4 T: u_x - u_x static, / U (fig. 7.6)", "RdBu", -0.3, 0.3)
        fig.colorbar(im, ax=axes[k])
    fig.savefig(a.png, dpi=110)
    print(f"wrote {a.png}")


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="cmd", required=True)
    q = sub.add_parser("plane")
    q.add_argument("csv")
    q.add_argument("png")
    q = sub.add_parser("compare")
    q.add_argument("coarse")
    q.add_argument("fine")
    q.add_argument("png")
    q.add_argument("--summary")
    q = sub.add_parser("phases")
    q.add_argument("moving")
    q.add_argument("static")
    q.add_argument("png")
    a = p.parse_args()
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    {"plane": cmd_plane, "compare": cmd_compare, "phases": cmd_phases}[a.cmd](a, plt)


if __name__ == "__main__":
    main()
