#!/usr/bin/env python3
"""Plot the CSV written by `ship_lrm trim` or `ship_lrm doublet` to a PNG.

usage: plot_flight.py trim TRIM.csv OUT.png [--reference MEASURED.csv]
       plot_flight.py doublet DOUBLET.csv OUT.png
       plot_flight.py sweep_inflow INFLOW_SWEEP.csv OUT.png

trim: power, the four controls and the attitudes over speed, laid out like thesis figs. 8.5-8.7.
A reference CSV (e.g. digitised flight-test points) with any of the same column names is drawn as
circles beside the model's lines.
doublet: controls, rates, attitudes, rate of descent, rotor speed and power over time (fig. 8.8).
sweep_inflow: LRM mean and cosine inflow over speed beside Pitt-Peters, both over the hover
momentum-theory velocity (thesis figs. 8.1, 8.2).
"""
import argparse
import csv
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
    for r in rows:
        for k, v in r.items():
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
    for ax, (key, label) in zip(axes.flat, panels):
        ax.plot(v, data[key], "-", color="C0", label="ship_lrm, Pitt-Peters")
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


def plot_sweep_inflow(data, out):
    v = data["speed_m_s"]
    vh = data["hover_momentum_theory_m_s"][0]
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.5))
    label = f"LRM N = {int(data['N'][0])}, a = {data['reach'][0]:g}"
    axes[0].plot(v, [x / vh for x in data["lrm_mean_m_s"]], "o-", label=label)
    axes[0].plot(v, [x / vh for x in data["pitt_peters_mean_m_s"]], "-", color="k", label="Pitt-Peters (= Glauert here)")
    axes[0].set_ylabel("mean inflow / v_h")
    axes[1].plot(v, [x / vh for x in data["lrm_cosine_m_s"]], "o-", label=label)
    axes[1].plot(v, [x / vh for x in data["pitt_peters_cosine_m_s"]], "-", color="k", label="Pitt-Peters")
    axes[1].set_ylabel("cosine inflow / v_h")
    for ax in axes:
        ax.set_xlabel("speed [m/s]")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=8)
    fig.suptitle(f"Isolated rotor, uniform thrust, zero incidence (cf. thesis figs. 8.1, 8.2); v_h = {vh:.2f} m/s")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("kind", choices=["trim", "doublet", "sweep_inflow"])
    ap.add_argument("csv")
    ap.add_argument("png")
    ap.add_argument("--reference")
    a = ap.parse_args()
    data = read(a.csv)
    if a.kind == "trim":
        plot_trim(data, a.png, read(a.reference) if a.reference else None)
    elif a.kind == "doublet":
        plot_doublet(data, a.png)
    else:
        plot_sweep_inflow(data, a.png)


if __name__ == "__main__":
    main()
