#!/usr/bin/env python3
"""The slipstream of an isolated rotor in axial flight (hover or climb), read from the time-averaged
centre plane that `ship_lrm sweep inflow --speeds 0 [--climb V_C] --planes` writes (plane_V0.csv).

  slipstream_flux.py PLANE.csv [--climb V_C --induced V] [--radii 1,1.5,2] [--out CSV] [--png PNG]

For each layer of the plane (z from the hub, positive downstream) it prints and writes:
- the axial induced velocity on the axis, (w - V_c) / v, with v momentum theory's induced velocity at
  the disk for this climb rate (the sweep's momentum_theory_m_s);
- the induced volume flux through discs of radius r_c about the axis, Q(r_c) = integral over r < r_c of
  (w - V_c) 2 pi r dr, over A v (A = pi R^2), the plane taken as axisymmetric (both sides averaged);
- the half-velocity radius r_half / R, where w - V_c has fallen to half its value on the axis.

What momentum theory says of these (steady, inviscid, uniformly loaded disk): through the disk the flux
is A v; in the far wake the slipstream has contracted to R_w / R = sqrt((V_c + v) / (V_c + 2 v)) and
carries an induced velocity of 2 v, so its induced flux is 2 (V_c + v) / (V_c + 2 v) A v (1 in hover)
and stays so downstream. A flux through a wide disc that keeps growing downstream is air the
slipstream's shear layer entrains (a viscous or turbulent wake; docs/benchmarks.md at 193c1b4, 2026-12-06).

The climb rate and v are read from inflow_sweep.csv beside the plane unless both are given (its
climb_m_s and momentum_theory_m_s columns). The plane must be of axial flight: a mean in-plane velocity
u_x of more than 2 % of v is refused (a forward-flight wake is not axisymmetric).
"""
import argparse
import math
import os
import sys

import numpy as np


def fail(message):
    sys.exit(f"slipstream_flux.py: {message}")


def load_plane(path):
    if not os.path.isfile(path):
        fail(f"{path}: no such file (write it with `ship_lrm sweep inflow --speeds 0 --planes --out DIR`)")
    try:
        data = np.genfromtxt(path, delimiter=",", names=True)
    except ValueError as e:
        fail(f"{path}: not a plane CSV ({e})")
    need = ("x_m", "z_m", "u_x_m_s", "u_z_m_s", "wall", "rotor_radius_m")
    if data.dtype.names is None or any(n not in data.dtype.names for n in need):
        fail(f"{path}: not a plane CSV of `sweep inflow --planes` (needs the columns {', '.join(need)})")
    if data.size < 4:
        fail(f"{path}: has too few rows for a plane")
    xs, zs = np.unique(data["x_m"]), np.unique(data["z_m"])
    if len(xs) * len(zs) != data.size:
        fail(f"{path}: is not a full x-z plane")
    order = np.lexsort((data["z_m"], data["x_m"]))  # x major, z minor
    grid = {n: data[n][order].reshape(len(xs), len(zs)) for n in ("u_x_m_s", "u_z_m_s", "wall")}
    if not np.all(np.isfinite(grid["u_z_m_s"])):
        fail(f"{path}: holds values that are not numbers")
    return xs, zs, grid, float(data["rotor_radius_m"][0])


def sweep_values(plane_path):
    """climb_m_s and momentum_theory_m_s of the V = 0 row of inflow_sweep.csv beside the plane."""
    path = os.path.join(os.path.dirname(os.path.abspath(plane_path)), "inflow_sweep.csv")
    if not os.path.isfile(path):
        return None, None
    data = np.atleast_1d(np.genfromtxt(path, delimiter=",", names=True, dtype=None, encoding="utf-8"))
    if data.dtype.names is None or any(n not in data.dtype.names for n in ("speed_m_s", "momentum_theory_m_s", "climb_m_s")):
        fail(f"{path}: not an inflow_sweep.csv of `sweep inflow` (give --climb and --induced)")
    rows = [r for r in data if abs(float(r["speed_m_s"])) < 1e-9]
    if not rows:
        return None, None
    return float(rows[0]["climb_m_s"]), float(rows[0]["momentum_theory_m_s"])


def disc_weights(xs, radius_limit):
    """Area per plane column for the flux through a disc of radius radius_limit, the plane taken as
    axisymmetric: the column at |x| = r stands for the annulus [r - dx/2, r + dx/2] (clipped to
    [0, radius_limit]), each side of the axis for half of it; a column on the axis for the whole disc
    of radius dx/2."""
    dx = float(np.min(np.diff(xs)))
    r = np.abs(xs)
    lo = np.clip(r - dx / 2, 0, radius_limit)
    hi = np.clip(r + dx / 2, 0, radius_limit)
    on_axis = r < 1e-6 * dx
    return np.where(on_axis, 1.0, 0.5) * math.pi * (hi**2 - lo**2)


def profile(xs, zs, grid, radius, climb, v, radii):
    w = grid["u_z_m_s"] - climb  # induced axial velocity, [x, z]
    dx = float(np.min(np.diff(xs)))
    axis_cols = np.argsort(np.abs(xs))[: 1 if np.min(np.abs(xs)) < 1e-6 * dx else 2]
    rows = []
    for k, z in enumerate(zs):
        if np.any(grid["wall"][:, k] > 0):
            continue
        col = w[:, k]
        axis = float(np.mean(col[axis_cols]))
        fluxes = [float(np.sum(disc_weights(xs, rc * radius) * col)) / (math.pi * radius**2 * v) for rc in radii]
        half = float("nan")
        right = xs >= 0
        xr, wr = xs[right], col[right]
        for i in range(len(xr) - 1 if axis > 0 else 0):  # only where the axis carries induced flow
            if wr[i] >= axis / 2 > wr[i + 1]:
                half = (xr[i] + (wr[i] - axis / 2) / (wr[i] - wr[i + 1]) * (xr[i + 1] - xr[i])) / radius
                break
        rows.append((z / radius, axis / v, *fluxes, half))
    return rows


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("plane", help="plane_V0.csv of `ship_lrm sweep inflow --speeds 0 --planes`")
    p.add_argument("--climb", type=float, help="m/s, the climb rate (default: inflow_sweep.csv beside the plane)")
    p.add_argument("--induced", type=float, help="m/s, momentum theory's induced velocity at the disk (default: inflow_sweep.csv)")
    p.add_argument("--radii", default="1,1.5,2", help="disc radii / R for the flux (comma list)")
    p.add_argument("--out", help="write the profile as CSV")
    p.add_argument("--png", help="plot the profile")
    a = p.parse_args()
    try:
        radii = [float(s) for s in a.radii.split(",")]
    except ValueError:
        fail(f"--radii '{a.radii}': not a comma list of numbers")
    if not radii or any(not (r > 0 and math.isfinite(r)) for r in radii):
        fail(f"--radii '{a.radii}': every radius must be a positive number")
    xs, zs, grid, radius = load_plane(a.plane)
    climb, v = a.climb, a.induced
    if climb is None or v is None:
        sweep_climb, sweep_v = sweep_values(a.plane)
        climb = sweep_climb if climb is None else climb
        v = sweep_v if v is None else v
    if climb is None or v is None:
        fail("no inflow_sweep.csv with a V = 0 row beside the plane: give --climb and --induced")
    if not (v > 0 and climb >= 0):
        fail(f"need --induced > 0 and --climb >= 0 (got {v}, {climb})")
    fluid = grid["wall"] == 0
    mean_ux = float(np.mean(grid["u_x_m_s"][fluid]))
    if abs(mean_ux) > 0.02 * v:
        fail(f"the plane's mean u_x is {mean_ux:.3g} m/s ({abs(mean_ux) / v:.0%} of v): not axial flight")
    rows = profile(xs, zs, grid, radius, climb, v, radii)
    far_flux = 2 * (climb + v) / (climb + 2 * v)
    contraction = math.sqrt((climb + v) / (climb + 2 * v))
    names = ["z_over_R", "axis_induced_over_v"] + [f"flux_r{rc:g}R_over_Av" for rc in radii] + ["r_half_over_R"]
    # the files first, the table on stdout last: a reader that stops early (`| head`, `| grep -q`) must
    # not cost the user the files
    if a.out:
        with open(a.out, "w") as f:
            f.write(",".join(names) + f",climb_m_s,momentum_theory_m_s,far_wake_flux_over_Av\n")
            for r in rows:
                f.write(",".join(f"{x:.6g}" for x in r) + f",{climb:.6g},{v:.6g},{far_flux:.6g}\n")
    if a.png:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        data = np.array(rows)
        fig, ax = plt.subplots(figsize=(7, 4.5))
        ax.plot(data[:, 0], data[:, 1], "k-", label="axis (w - V_c) / v")
        for i, rc in enumerate(radii):
            ax.plot(data[:, 0], data[:, 2 + i], label=f"Q(r < {rc:g} R) / A v")
        ax.axhline(far_flux, color="grey", ls="--", label="inviscid far-wake flux")
        ax.axhline(2, color="grey", ls=":", label="inviscid far-wake axis (2 v)")
        ax.axvline(0, color="grey", lw=0.5)
        ax.set_xlabel("z / R (downstream of the disk)")
        ax.set_title(f"Slipstream, climb {climb:.2f} m/s (v = {v:.2f} m/s)")
        ax.legend(fontsize=8)
        ax.grid(alpha=0.3)
        fig.tight_layout()
        fig.savefig(a.png, dpi=110)
    print(f"climb {climb:.3f} m/s, momentum theory v = {v:.4f} m/s; far wake (inviscid): induced flux "
          f"{far_flux:.4f} A v, radius {contraction:.4f} R, axis 2 v")
    print("  ".join(f"{n:>14s}" for n in names))
    for r in rows:
        print("  ".join(f"{x:14.4f}" for x in r))
    for path in (a.out, a.png):
        if path:
            print(f"wrote {path}")


if __name__ == "__main__":
    try:
        main()
        sys.stdout.flush()
    except BrokenPipeError:
        # stdout's reader went away (`| head`); the files are written. Quiet, as the Python docs advise
        # (signal module, "Note on SIGPIPE"): no traceback, stdout to devnull for the exit's flush.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        sys.exit(1)
