#!/usr/bin/env python3
"""Spectra and histograms of the velocity at the probes of a ship-wake run.

  plot_probes.py FILE_probes.csv [--wind U] [--png OUT.png]

Reads the series `ship_lrm wake --probes` (or `ship_lrm validate nrc-deck`) writes (time_s, then
pK_u, pK_v, pK_w per probe, m/s, ship frame) and writes beside it
  FILE_probes_psd.csv        frequency_hz, then pK_u, pK_v, pK_w: one-sided power spectral density
                             (m^2/s^2/Hz), Welch's method (scipy.signal.welch, Hann windows of 1/4 of
                             the series, half overlapping)
  FILE_probes_histogram.csv  probe, component, bin_low, bin_high, density (1/(m/s)): 40 bins over
                             the component's range
  FILE_probes.png            both, one row per probe
and prints per probe the mean, variance and TKE (with --wind also TKE / U^2 and its standard error
from five batch means). --window T0,T1 restricts everything to samples with T0 <= t <= T1 (two runs
compared over the same averaging time). Samples where a probe was not in the fluid (NaN) are left out.
"""
import argparse
import os
import sys

import numpy as np


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("csv")
    ap.add_argument("--wind", type=float, default=None, help="wind speed U (m/s): spectra also as f U^-2 and axes in U")
    ap.add_argument("--png", default=None)
    ap.add_argument("--window", default=None, help="T0,T1: only the samples in this time window (s)")
    a = ap.parse_args()
    try:
        data = np.genfromtxt(a.csv, delimiter=",", names=True)
    except (OSError, ValueError) as e:
        sys.exit(f"plot_probes.py: cannot read {a.csv}: {e}")
    names = data.dtype.names or ()
    if "time_s" not in names:
        sys.exit(f"plot_probes.py: {a.csv} has no time_s column")
    probes = sorted({int(n[1:].split("_")[0]) for n in names if n.startswith("p") and n.endswith(("_u", "_v", "_w"))})
    if not probes or data.size < 8:
        sys.exit(f"plot_probes.py: {a.csv} holds no probe series of at least 8 samples")
    t = np.atleast_1d(data["time_s"])
    if a.window:
        try:
            t0, t1 = (float(v) for v in a.window.split(","))
        except ValueError:
            sys.exit(f"plot_probes.py: --window must be T0,T1, got '{a.window}'")
        keep = (t >= t0) & (t <= t1)
        if keep.sum() < 8:
            sys.exit(f"plot_probes.py: fewer than 8 samples in the window {a.window}")
        data, t = np.atleast_1d(data)[keep], t[keep]
    dt = float(np.median(np.diff(t)))
    if not dt > 0:
        sys.exit(f"plot_probes.py: {a.csv}: the times do not increase")
    from scipy.signal import welch

    print(f"{len(t)} samples from {t[0]:.4f} to {t[-1]:.4f} s")
    for p in probes:
        u = np.stack([np.atleast_1d(data[f"p{p}_{c}"]) for c in "uvw"], axis=1)
        u = u[np.all(np.isfinite(u), axis=1)]
        if len(u) < 2:
            print(f"probe {p}: no samples in the fluid")
            continue
        var = u.var(axis=0)
        k = 0.5 * var.sum()
        fmt = lambda v: "[" + ", ".join(f"{x:.4g}" for x in v) + "]"
        line = f"probe {p}: mean {fmt(u.mean(axis=0))} m/s, variance {fmt(var)} m^2/s^2, TKE {k:.4g} m^2/s^2"
        if a.wind:
            batches = [0.5 * b.var(axis=0).sum() for b in np.array_split(u, 5)]
            err = np.std(batches, ddof=1) / np.sqrt(5)
            line += f", TKE/U^2 {k / a.wind ** 2:.5g} +- {err / a.wind ** 2:.2g}"
        print(line)

    stem = os.path.splitext(a.csv)[0]
    psd_cols, hist_rows, freqs = {}, [], None
    for p in probes:
        for c in "uvw":
            x = np.atleast_1d(data[f"p{p}_{c}"])
            x = x[np.isfinite(x)]
            if x.size < 8:
                continue
            nper = max(8, x.size // 4)
            f, s = welch(x - x.mean(), fs=1.0 / dt, window="hann", nperseg=nper, noverlap=nper // 2, detrend=False)
            if freqs is None or len(f) < len(freqs):
                freqs = f
            psd_cols[(p, c)] = (f, s)
            dens, edges = np.histogram(x, bins=40, density=True)
            for k in range(len(dens)):
                hist_rows.append((p, c, edges[k], edges[k + 1], dens[k]))
    if freqs is None:
        sys.exit(f"plot_probes.py: {a.csv}: no probe has 8 samples in the fluid")
    with open(stem + "_psd.csv", "w") as out:
        keys = sorted(psd_cols)
        out.write("frequency_hz," + ",".join(f"p{p}_{c}" for p, c in keys) + "\n")
        for k, fk in enumerate(freqs):
            out.write(f"{fk:.6g}," + ",".join(f"{np.interp(fk, *psd_cols[key]):.6g}" for key in keys) + "\n")
    with open(stem + "_histogram.csv", "w") as out:
        out.write("probe,component,bin_low,bin_high,density\n")
        for row in hist_rows:
            out.write("%d,%s,%.6g,%.6g,%.6g\n" % row)
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(len(probes), 2, figsize=(11, 3.2 * len(probes)), squeeze=False, constrained_layout=True)
    for r, p in enumerate(probes):
        for c, colour in zip("uvw", ("C0", "C1", "C2")):
            if (p, c) not in psd_cols:
                continue
            f, s = psd_cols[(p, c)]
            axes[r][0].loglog(f[1:], s[1:], colour, label=c)
            rows = [h for h in hist_rows if h[0] == p and h[1] == c]
            centres = [0.5 * (h[2] + h[3]) for h in rows]
            axes[r][1].plot(centres, [h[4] for h in rows], colour, label=c)
        axes[r][0].set_title(f"probe {p}: power spectral density", fontsize=9)
        axes[r][0].set_xlabel("f (Hz)")
        axes[r][0].set_ylabel("PSD (m^2/s^2/Hz)")
        axes[r][0].legend(fontsize=8)
        axes[r][1].set_title(f"probe {p}: velocity histogram (ship frame)", fontsize=9)
        axes[r][1].set_xlabel("velocity (m/s)")
        axes[r][1].set_ylabel("density (1/(m/s))")
    png = a.png or stem + ".png"
    fig.savefig(png, dpi=110)
    print(f"wrote {stem}_psd.csv, {stem}_histogram.csv, {png}")


if __name__ == "__main__":
    main()
