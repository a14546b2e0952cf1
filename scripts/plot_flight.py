#!/usr/bin/env python3
"""Plot the CSV written by `ship_lrm trim` or `ship_lrm doublet` to a PNG.

usage: plot_flight.py trim TRIM.csv OUT.png [--reference MEASURED.csv]
       plot_flight.py doublet DOUBLET.csv OUT.png
       plot_flight.py sweep_inflow INFLOW_SWEEP.csv OUT.png
       plot_flight.py sweep_ground GROUND_SWEEP.csv OUT.png [--also MORE_HOVER_SWEEPS.csv ...]
       plot_flight.py sweep_free_wake FREE_WAKE_SWEEP.csv OUT.png [--reference INFLOW_SWEEP.csv]
       plot_flight.py plane PLANE.csv OUT.png
       plot_flight.py resolution FORWARD_RESOLUTION.csv OUT.png [--climb CLIMB.csv] [--also INFLOW_SWEEP.csv ...]

trim: power, the four controls and the attitudes over speed, laid out like thesis figs. 8.5-8.7.
A reference CSV (e.g. digitised flight-test points) with any of the same column names is drawn as
circles beside the model's lines.
doublet: controls, rates, attitudes, rate of descent, rotor speed and power over time (fig. 8.8).
sweep_inflow: LRM mean and cosine inflow over speed beside Pitt-Peters, both over the hover
momentum-theory velocity (thesis figs. 8.1, 8.2).
sweep_ground: hover, v_mean / v_mean(OGE) over z/R beside Cheeseman-Bennett and Hayden (fig. 8.9);
forward, v_mean over speed per height beside Glauert times the forward-flight Cheeseman-Bennett
factor (fig. 8.11), and the ratio v_mean / v_mean(OGE) over speed beside Cheeseman-Bennett.
sweep_free_wake: the free vortex-ring wake's mean induced velocity over speed beside Glauert's, with
an LRM `sweep inflow` CSV as the reference if given.
resolution: grid convergence of the isolated rotor's mean inflow at a = 1.25 and the default lattice
velocity: over N, per edgewise speed against Glauert (the rows of a resolution CSV and of `sweep
inflow` CSVs given with --also; the free wake's finest value as a dashed line), and in an axial climb
and in hover against momentum theory (a `--climb` CSV).
plane: a sweep case's time-averaged x-z plane through the hub (`--planes`), or the approach's
(`--plane-mean-from`) beside the wake table's air at the same points and their difference.
"""
import argparse
import csv
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"plot_flight.py: {path} has no data rows")
    cols = {k: [] for k in rows[0]}
    cols["_text"] = {k: [r[k] for r in rows] for k in rows[0]}  # the raw text (labels such as the faces)
    for r in rows:
        for k, v in r.items():
            if k is None:  # more fields than the header names
                sys.exit(f"plot_flight.py: {path}: a row has more fields than its header")
            try:
                cols[k].append(float(v))
            except (TypeError, ValueError):
                cols[k].append(float("nan"))
    return cols


def plot_trim(data, out, reference):
    panels = [
        ("total_power_kW", "total power [kW]"),
        ("collective_pct", "collective [%]"),
        ("longitudinal_pct", "longitudinal cyclic [%] (100 = forward)"),
        ("lateral_pct", "lateral cyclic [%] (100 = right)"),
        ("pedal_pct", "pedal [%] (100 = right)"),
        ("pitch_deg", "pitch attitude [deg]"),
        ("roll_deg", "roll attitude [deg]"),
        ("main_power_kW", "main-rotor power [kW]"),
    ]
    fig, axes = plt.subplots(2, 4, figsize=(16, 7.5), sharex=True)
    v = data["speed_m_s"]
    ok = [c > 0.5 for c in data["converged"]]
    lrm = "pp_total_power_kW" in data  # a coupled LRM trim, written beside Pitt-Peters
    for ax, (key, label) in zip(axes.flat, panels):
        ax.plot(v, data[key], "-o" if lrm else "-", color="C0", label="ship_lrm, LRM inflow" if lrm else "ship_lrm, Pitt-Peters")
        if lrm and "pp_" + key in data:
            ax.plot(v, data["pp_" + key], "--", color="C1", label="ship_lrm, Pitt-Peters")
        bad = [(x, y) for x, y, g in zip(v, data[key], ok) if not g]
        if bad:
            ax.plot([b[0] for b in bad], [b[1] for b in bad], "x", color="C3", label="not converged")
        if reference and key in reference and "speed_m_s" in reference:
            ax.plot(reference["speed_m_s"], reference[key], "o", mfc="none", color="k", label="reference")
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
    for ax in axes[1]:
        ax.set_xlabel("speed [m/s]")
    axes[0, 0].legend(fontsize=8)
    fig.suptitle("Bo 105 trim in level flight (cf. thesis figs. 8.5-8.7)")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def plot_doublet(data, out):
    t = data["time_s"]
    rows = [
        [("collective_pct", "collective [%]"), ("longitudinal_pct", "longitudinal [%]"), ("lateral_pct", "lateral [%]"), ("pedal_pct", "pedal [%]")],
        [("p_deg_s", "p [deg/s]"), ("q_deg_s", "q [deg/s]"), ("r_deg_s", "r [deg/s]"), None],
        [("roll_deg", "roll [deg]"), ("pitch_deg", "pitch [deg]"), ("yaw_deg", "yaw [deg]"), None],
        [("rate_of_descent_m_s", "rate of descent [m/s]"), ("rotor_speed_ratio", "rotor speed / reference"), ("main_power_kW", "main-rotor power [kW]"),
         ("engine_power_kW", "engine power [kW]")],
    ]
    fig, axes = plt.subplots(4, 4, figsize=(16, 11), sharex=True)
    for i, row in enumerate(rows):
        for j, item in enumerate(row):
            ax = axes[i, j]
            if item is None:
                ax.axis("off")
                continue
            key, label = item
            ax.plot(t, data[key], color="C0")
            ax.set_ylabel(label)
            ax.grid(True, alpha=0.3)
    for ax in axes[3]:
        ax.set_xlabel("time [s]")
    fig.suptitle("Bo 105 doublet response (cf. thesis fig. 8.8)")
    fig.tight_layout()
    fig.savefig(out, dpi=100)


def finish_speed_panels(fig, axes, title, out):
    for ax in axes:
        ax.set_xlabel("speed [m/s]")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def climb_note(data):
    """', climb 11.6 m/s' for a sweep run with --climb (older CSVs have no such column)."""
    climb = data.get("climb_m_s", [0])[0]
    return f", climb {climb:g} m/s" if climb > 0 else ""


def plot_sweep_inflow(data, out):
    v = data["speed_m_s"]
    vh = data["hover_momentum_theory_m_s"][0]
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5))
    label = f"LRM N = {int(data['N'][0])}, a = {data['reach'][0]:g}"
    axes[0].plot(v, [x / vh for x in data["lrm_mean_m_s"]], "o-", label=label)
    axes[0].plot(v, [x / vh for x in data["pitt_peters_mean_m_s"]], "_-", ms=16, color="k", label="Pitt-Peters (= momentum theory here)")
    axes[0].set_ylabel("mean inflow / v_h")
    axes[1].plot(v, [x / vh for x in data["lrm_cosine_m_s"]], "o-", label=label)
    axes[1].plot(v, [x / vh for x in data["pitt_peters_cosine_m_s"]], "_-", ms=16, color="k", label="Pitt-Peters")
    axes[1].set_ylabel("cosine inflow / v_h")
    finish_speed_panels(fig, axes, f"Isolated rotor, uniform thrust, zero incidence{climb_note(data)} (cf. thesis figs. 8.1, 8.2); "
                        f"v_h = {vh:.2f} m/s", out)


def plot_sweep_free_wake(data, out, lrm):
    v = data["speed_m_s"]
    vh = data["hover_momentum_theory_m_s"][0]
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5))
    axes[0].plot(v, [x / vh for x in data["free_wake_mean_m_s"]], "s-", label="free vortex-ring wake")
    reference = "momentum theory" if climb_note(data) else "Glauert"
    axes[0].plot(v, [x / vh for x in data["momentum_theory_m_s"]], "_-", ms=16, color="k", label=reference)
    axes[1].plot(v, data["mean_over_momentum_theory"], "s-", label="free vortex-ring wake")
    if lrm:
        label = f"LRM N = {int(lrm['N'][0])}, a = {lrm['reach'][0]:g}"
        axes[0].plot(lrm["speed_m_s"], [x / vh for x in lrm["lrm_mean_m_s"]], "o-", label=label)
        axes[1].plot(lrm["speed_m_s"], [m / g for m, g in zip(lrm["lrm_mean_m_s"], lrm["momentum_theory_m_s"])], "o-", label=label)
    axes[1].axhline(1.0, color="k", lw=1)
    for y in (0.95, 1.05):
        axes[1].axhline(y, color="k", lw=0.5, ls=":")
    axes[0].set_ylabel("mean induced velocity / v_h")
    axes[1].set_ylabel(f"mean induced velocity / {reference}")
    finish_speed_panels(fig, axes, f"Uniformly loaded actuator disk, zero incidence{climb_note(data)}; v_h = {vh:.2f} m/s", out)


def rows_of(data, needed, path):
    """The rows of a CSV read by read() as dicts; stops with a message if a needed column is missing."""
    missing = [k for k in needed if k not in data]
    if missing:
        sys.exit(f"plot_flight.py: {path} has no column {', '.join(missing)}")
    keys = [k for k in data if k != "_text"]
    return [dict(zip(keys, vals)) for vals in zip(*(data[k] for k in keys))]


def plot_resolution(data, out, climb, sweeps):
    """mean inflow / exact reference over N (a = 1.25, rotor far field, default lattice velocity)."""
    rows = rows_of(data, ("speed_m_s", "N", "reach", "lattice_velocity_m_s", "mean_over_glauert", "spacing_R", "ring_points"),
                   "the resolution CSV")
    series = {}  # speed -> {N: ratio}
    for r in rows:
        if r["reach"] == 1.25 and r["lattice_velocity_m_s"] == max(30.0, r["speed_m_s"]):
            series.setdefault(r["speed_m_s"], {})[int(r["N"])] = r["mean_over_glauert"]
    for s in sweeps:
        for r in rows_of(s, ("speed_m_s", "N", "reach", "lrm_mean_m_s", "momentum_theory_m_s"), "an --also CSV"):
            if r["reach"] == 1.25 and r["speed_m_s"] > 0:
                series.setdefault(r["speed_m_s"], {}).setdefault(int(r["N"]), r["lrm_mean_m_s"] / r["momentum_theory_m_s"])
    fig, axes = plt.subplots(1, 2 if climb else 1, figsize=(12 if climb else 7, 4.5), squeeze=False)
    ax = axes[0][0]
    for v in sorted(series):
        ns = sorted(series[v])
        line, = ax.plot(ns, [series[v][n] for n in ns], "o-", label=f"LRM, {v:g} m/s")
        free = [r for r in rows if r["speed_m_s"] == v and r["ring_points"] > 0]
        if free:
            finest = min(free, key=lambda r: (r["spacing_R"], -r["ring_points"]))
            ax.axhline(finest["mean_over_glauert"], color=line.get_color(), ls="--", lw=1,
                       label=f"free vortex-ring wake, {v:g} m/s")
    ax.set_ylabel("mean inflow / Glauert")
    ax.set_title("edgewise flight (zero incidence)")
    panels = [ax]
    if climb:
        ax2 = axes[0][1]
        for vc, name in ((11.62, "axial climb V_c = v_h"), (0.0, "hover")):
            pts = sorted((int(r["N"]), r["lrm_over_momentum_theory"]) for r in rows_of(climb, ("N", "reach", "climb_m_s", "rotor_far_field", "smagorinsky",
                                                                  "lattice_velocity_m_s", "lrm_over_momentum_theory"), "the --climb CSV")
                         if r["reach"] == 1.25 and r["climb_m_s"] == vc and r["rotor_far_field"] == 1
                         and r["smagorinsky"] == 0.05 and r["lattice_velocity_m_s"] == 30)
            best = {}
            for n, x in pts:  # one value per N (the first, the longest average, is listed first)
                best.setdefault(n, x)
            ax2.plot(sorted(best), [best[n] for n in sorted(best)], "o-", label=f"LRM, {name}")
        ax2.set_ylabel("mean inflow / momentum theory")
        ax2.set_title("axial flow")
        panels.append(ax2)
    for a in panels:
        a.axhline(1.0, color="k", lw=1)
        for y in (0.95, 1.05):
            a.axhline(y, color="k", lw=0.5, ls=":")
        a.set_xlabel("N (lattice nodes per 4 R)")
        a.set_xscale("log", base=2)
        a.grid(True, alpha=0.3)
        a.legend(fontsize=7)
    fig.suptitle("Isolated rotor, uniform thrust, a = 1.25, rotor far field at the faces: grid convergence")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def ground_label(data):
    label = f"LRM N = {int(data['N'][0])}, a = {data['reach'][0]:g}"
    if "slip-ground" in data["_text"].get("faces", [""])[0]:
        label += ", slip ground"
    return label


def plot_sweep_ground(data, out, more=()):
    label = ground_label(data)
    hover = all(v == 0 for v in data["speed_m_s"])
    if more and not (hover and all(all(v == 0 for v in d["speed_m_s"]) for d in more)):
        sys.exit("plot_flight.py: --also takes hover sweeps only, beside a hover sweep")
    if hover:
        fig, ax = plt.subplots(figsize=(7, 5))
        z = data["z_over_R"]
        # half-window differences of the two means (older CSVs have none)
        for d in (data, *more):
            ax.errorbar(d["z_over_R"], d["ratio"], yerr=d.get("ratio_uncertainty"), fmt="o-", capsize=3, label=ground_label(d))
        ax.plot(z, data["cheeseman_bennett"], "--", color="k", label="Cheeseman & Bennett 1955")
        ax.plot(z, data["hayden"], ":", color="k", label="Hayden 1976 (power ratio)")
        ax.axhline(1.0, color="grey", lw=0.8)
        ax.set_xlabel("z / R (hub over ground)")
        ax.set_ylabel("v_mean / v_mean,OGE")
        ax.set_title("Hover in ground effect, equal thrust (cf. thesis fig. 8.9)")
    else:
        fig, (ax_v, ax) = plt.subplots(1, 2, figsize=(13, 5))
        heights = sorted(set(data["z_over_R"]))
        n = len(data["speed_m_s"])
        rows = list(zip(data["speed_m_s"], data["z_over_R"], data["lrm_mean_m_s"], data["lrm_mean_oge_m_s"],
                        data["cheeseman_bennett"], data["momentum_theory_oge_m_s"],
                        data.get("lrm_half_difference_m_s", [0.0] * n), data["ratio"],
                        data.get("ratio_uncertainty", [0.0] * n)))
        oge = sorted({(r[0], r[3], r[5]) for r in rows})
        ax_v.plot([o[0] for o in oge], [o[1] for o in oge], "o-", color="k", label=f"{label}, OGE")
        ax_v.plot([o[0] for o in oge], [o[2] for o in oge], "--", color="k", label="Glauert, OGE")
        for i, h in enumerate(heights):
            sel = sorted((r for r in rows if r[1] == h), key=lambda r: r[0])
            c = f"C{i}"
            speeds = [r[0] for r in sel]
            ax_v.errorbar(speeds, [r[2] for r in sel], yerr=[abs(r[6]) for r in sel], fmt="o-", color=c, capsize=3,
                          label=f"LRM z/R = {h:g}")
            ax_v.plot(speeds, [r[5] * r[4] for r in sel], "--", color=c, label=f"Glauert x Cheeseman-Bennett, z/R = {h:g}")
            ax.errorbar(speeds, [r[7] for r in sel], yerr=[abs(r[8]) for r in sel], fmt="o-", color=c, capsize=3,
                        label=f"LRM z/R = {h:g}")
            ax.plot(speeds, [r[4] for r in sel], "--", color=c, label=f"Cheeseman-Bennett z/R = {h:g}")
        ax_v.set_xlabel("speed [m/s]")
        ax_v.set_ylabel("mean inflow v_mean [m/s]")
        ax_v.set_title("Forward flight in ground effect (cf. thesis fig. 8.11)")
        ax_v.grid(True, alpha=0.3)
        ax_v.legend(fontsize=7)
        ax.axhline(1.0, color="grey", lw=0.8)
        ax.set_xlabel("speed [m/s]")
        ax.set_ylabel("v_mean / v_mean,OGE at the same speed")
        ax.set_title("Ratio to out of ground effect (error bars: half-window differences)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def plot_plane(path, out):
    """Time-averaged x-z plane through the hub (sweep --planes, approach --plane-mean-from): downwash
    colour, in-plane streamlines relative to the rotor, walls grey; z points down (FRD), the rotor disk
    is the black bar. With the undisturbed air's columns (the approach: the wake table's air at the
    same points) also that field and the LRM's minus it, like thesis fig. 9.3 (c)."""
    import numpy as np

    from plot_wake import imshow  # the centre-plane field with its walls masked, as for the ship wake

    d = np.genfromtxt(path, delimiter=",", names=True)
    xs, zs = np.unique(d["x_m"]), np.unique(d["z_m"])
    ix, iz = np.searchsorted(xs, d["x_m"]), np.searchsorted(zs, d["z_m"])
    names = [k for k in d.dtype.names if k.endswith("_m_s") or k == "wall"]
    grid = {k: np.full((zs.size, xs.size), np.nan) for k in names}
    for k in grid:
        grid[k][iz, ix] = d[k]
    wall = grid["wall"] > 0.5
    walls = {"solid": wall.astype(float), "xs": xs, "zs": zs}
    panels = [("u", f"{os.path.basename(path)}: LRM mean flow relative to the rotor")]
    if "undisturbed_u_x_m_s" in grid:
        panels += [("undisturbed_u", "the air the faces take (wake table), same points"),
                   ("difference", "LRM minus the faces' air")]
        for c in ("x", "z"):
            grid[f"difference_{c}_m_s"] = grid[f"u_{c}_m_s"] - grid[f"undisturbed_u_{c}_m_s"]
    fig, axes = plt.subplots(len(panels), 1, figsize=(8, 6.5 * len(panels)), squeeze=False)
    r = d["rotor_radius_m"][0]
    for ax, (key, title) in zip(axes[:, 0], panels):
        ux, uz = np.where(wall, 0.0, grid[f"{key}_x_m_s"]), np.where(wall, 0.0, grid[f"{key}_z_m_s"])
        lim = np.nanmax(np.abs(uz)) or 1.0
        im = imshow(ax, walls, uz, title, "RdBu_r", -lim, lim)
        fig.colorbar(im, ax=ax, label="u_z [m/s] (positive down)")
        # the CSV's 6 digits make the spacing uneven in the last place; streamplot wants it exact
        ax.streamplot(np.linspace(xs[0], xs[-1], xs.size), np.linspace(zs[0], zs[-1], zs.size), ux, uz,
                      color="k", linewidth=0.6, density=1.6, arrowsize=0.7)
        ax.plot([-r, r], [0, 0], color="k", lw=4)
        ax.set_xlim(xs[0], xs[-1])
        ax.set_ylim(zs[-1], zs[0])  # z down
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("kind", choices=["trim", "doublet", "sweep_inflow", "sweep_ground", "sweep_free_wake", "plane", "resolution"])
    ap.add_argument("csv")
    ap.add_argument("png")
    ap.add_argument("--reference")
    ap.add_argument("--also", nargs="+", default=[], help="sweep_ground: more hover sweeps on the same axes; resolution: inflow sweeps")
    ap.add_argument("--climb", help="resolution: a climb CSV (N, reach, climb_m_s, lrm_over_momentum_theory, ...)")
    a = ap.parse_args()
    if a.kind == "plane":
        return plot_plane(a.csv, a.png)
    data = read(a.csv)
    if a.kind == "trim":
        plot_trim(data, a.png, read(a.reference) if a.reference else None)
    elif a.kind == "doublet":
        plot_doublet(data, a.png)
    elif a.kind == "sweep_ground":
        plot_sweep_ground(data, a.png, [read(c) for c in a.also])
    elif a.kind == "resolution":
        plot_resolution(data, a.png, read(a.climb) if a.climb else None, [read(c) for c in a.also])
    elif a.kind == "sweep_free_wake":
        plot_sweep_free_wake(data, a.png, read(a.reference) if a.reference else None)
    else:
        plot_sweep_inflow(data, a.png)


if __name__ == "__main__":
    main()
