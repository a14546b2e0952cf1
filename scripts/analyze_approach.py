#!/usr/bin/python3
"""Rotor loads of a ship approach (thesis 9.2): time series of Delta C_T, C_Mx, C_My against their
values at the end of the start-up (fig. 9.4), their amplitude over time and frequency from a
continuous wavelet transform with complex Morlet wavelets of centre frequency and bandwidth 1 Hz
(pywt 'cmor1.0-1.0', fig. 9.5), and a summary CSV.

    analyze_approach.py approach.csv --out DIR [--startup 5]
    analyze_approach.py approach.bag --out DIR [--startup 5] [--topic /rotor/loads]

Input: the CSV of `ship_lrm approach` (columns time_s, CT, CMx, CMy, distance_to_spot_m,
height_above_deck_m, speed_m_s), or a rosbag recorded by `roslaunch ship_lrm approach.launch
record:=true` (ship_lrm/RotorLoads on /rotor/loads; needs Debian's python3-rosbag). Output in DIR:
approach.png, approach_wavelets.png, approach_summary.csv; from a bag also approach_loads.csv, the
loads as a table (time_s, CT, CMx, CMy, ..., inflow_model, fallback).

The wavelet amplitude is calibrated so that a sinusoid of amplitude A shows A at its frequency (the
response to a unit sinusoid at one reference frequency, carried to every scale by the transform's
sqrt(scale) normalisation). The series is mirrored at both ends before the transform, the smooth
continuation the thesis assumes. Below two cycles per record (hatched) the amplitudes are not reliable.
"""
import argparse
import csv
import math
import os
import sys

import numpy as np

COEFFS = [("CT", r"$\Delta C_T$"), ("CMx", r"$\Delta C_{Mx}$"), ("CMy", r"$\Delta C_{My}$")]
BAND = (0.02, 2.0)  # Hz, the band that matters for pilot-induced oscillations (thesis 9.2)
WAVELET = "cmor1.0-1.0"  # bandwidth 1, centre frequency 1 Hz (thesis 9.2)


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"analyze_approach: {path} has no rows")
    need = ["time_s", "CT", "CMx", "CMy", "distance_to_spot_m", "height_above_deck_m", "speed_m_s"]
    missing = [c for c in need if c not in rows[0]]
    if missing:
        sys.exit(f"analyze_approach: {path} lacks the columns {', '.join(missing)} (not a `ship_lrm approach` CSV?)")
    try:
        data = {c: np.array([float(r[c]) for r in rows]) for c in need}
    except ValueError as e:
        sys.exit(f"analyze_approach: {path}: {e}")
    return check_times(data, path)


BAG_COLUMNS = [("time_s", "time"), ("thrust_N", "thrust"), ("CT", "ct"), ("CMx", "cmx"), ("CMy", "cmy"),
               ("main_power_W", "main_power"), ("distance_to_spot_m", "distance"),
               ("height_above_deck_m", "height_above_deck"), ("speed_m_s", "speed")]


def read_bag(path, topic, out_dir):
    """The ship_lrm/RotorLoads of `topic` in a bag, in the CSV's column names; also written to
    out_dir/approach_loads.csv (with the inflow model and the fallback flag of each sample)."""
    try:
        import rosbag
    except ImportError:
        sys.exit("analyze_approach: reading a bag needs Debian's python3-rosbag (scripts/setup.sh installs it); "
                 "run with /usr/bin/python3")
    try:
        bag = rosbag.Bag(path)
    except Exception as e:  # rosbag raises its own ROSBagException, ROSBagUnindexedException, IOError
        sys.exit(f"analyze_approach: cannot read the bag {path}: {e}")
    with bag:
        info = bag.get_type_and_topic_info().topics
        if topic not in info:
            have = ", ".join(f"{t} ({i.msg_type})" for t, i in sorted(info.items())) or "nothing"
            sys.exit(f"analyze_approach: {path} has no {topic}; it holds {have}")
        if info[topic].msg_type != "ship_lrm/RotorLoads":
            sys.exit(f"analyze_approach: {topic} in {path} is {info[topic].msg_type}, not ship_lrm/RotorLoads")
        msgs = [m for _, m, _ in bag.read_messages(topics=[topic])]
    if not msgs:
        sys.exit(f"analyze_approach: {path} has no messages on {topic}")
    msgs.sort(key=lambda m: m.time)
    os.makedirs(out_dir, exist_ok=True)
    with open(os.path.join(out_dir, "approach_loads.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow([c for c, _ in BAG_COLUMNS] + ["inflow_model", "fallback"])
        for m in msgs:
            w.writerow([repr(float(getattr(m, a))) for _, a in BAG_COLUMNS] + [m.inflow_model, int(m.fallback)])
    data = {c: np.array([float(getattr(m, a)) for m in msgs]) for c, a in BAG_COLUMNS}
    fallback = [m.time for m in msgs if m.fallback]
    if fallback:
        print(f"analyze_approach: warning: the LRM was lost at t = {fallback[0]:g} s; Pitt-Peters served from there",
              file=sys.stderr)
    return check_times(data, path)


def check_times(data, path):
    t = data["time_s"]
    if not np.all(np.isfinite(t)) or np.any(np.diff(t) <= 0):
        sys.exit(f"analyze_approach: {path}: time_s must increase strictly")
    for c, _ in COEFFS:
        if not np.all(np.isfinite(data[c])):
            bad = t[~np.isfinite(data[c])][0]
            sys.exit(f"analyze_approach: {path}: {c} is not finite from t = {bad:g} s")
    return data


def uniform(t, y):
    """Resample onto a uniform grid of the median spacing (the CSV rows are nearly uniform)."""
    dt = float(np.median(np.diff(t)))
    tu = np.arange(t[0], t[-1] + 0.5 * dt, dt)
    return tu, np.interp(tu, t, y), dt


def wavelet_amplitude(y, dt, freqs):
    import pywt

    fc = pywt.central_frequency(WAVELET)
    scales = fc / (freqs * dt)
    n = len(y)
    pad = min(n - 1, int(np.ceil(3.0 / (freqs.min() * dt))))  # mirror: the smooth continuation
    def cwt(x):
        xp = np.concatenate([x[pad:0:-1], x, x[-2:-pad - 2:-1]]) if pad > 0 else x
        c, _ = pywt.cwt(xp, scales, WAVELET, sampling_period=dt, method="fft")
        return np.abs(c[:, pad:pad + n])
    amp = cwt(y - np.mean(y))
    # calibration: the response to a unit sinusoid at a reference frequency the series holds many
    # periods of (the middle half of the record, away from its ends), carried to the other scales by the
    # transform's sqrt(scale) normalisation: dividing by each scale's own response on a short record
    # would blow up the frequencies the record cannot hold.
    t = np.arange(n) * dt
    f_ref = min(max(freqs.max() / 4, 20.0 / (n * dt)), freqs.max())
    s_ref = fc / (f_ref * dt)
    c, _ = pywt.cwt(np.sin(2 * np.pi * f_ref * t), [s_ref], WAVELET, sampling_period=dt, method="fft")
    g_ref = np.median(np.abs(c[0, n // 4:3 * n // 4]))
    gain = g_ref * np.sqrt(scales / s_ref)
    return amp / gain[:, None]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("input", help="approach.csv of `ship_lrm approach`, or a bag of approach.launch record:=true")
    ap.add_argument("--out", required=True)
    ap.add_argument("--startup", type=float, default=5.0, help="s: the Delta is taken against this time (thesis 9.2)")
    ap.add_argument("--topic", default="/rotor/loads", help="bag input: the ship_lrm/RotorLoads topic")
    a = ap.parse_args()
    if not os.path.isfile(a.input):
        sys.exit(f"analyze_approach: {a.input} does not exist")
    if os.path.exists(a.out) and not os.path.isdir(a.out):
        sys.exit(f"analyze_approach: --out {a.out} is a file; --out names the folder the results go to")
    if not (math.isfinite(a.startup) and a.startup >= 0):
        sys.exit(f"analyze_approach: --startup must be a finite number >= 0 s, got {a.startup}")
    with open(a.input, "rb") as f:
        is_bag = f.read(13) == b"#ROSBAG V2.0\n"
    d = read_bag(a.input, a.topic, a.out) if is_bag else read_csv(a.input)
    t = d["time_s"]
    if a.startup >= t[-1]:
        sys.exit(f"analyze_approach: the start-up {a.startup} s is not before the end of the series ({t[-1]} s)")
    os.makedirs(a.out, exist_ok=True)
    k0 = int(np.searchsorted(t, a.startup))
    after = t >= a.startup
    delta = {c: d[c] - d[c][k0] for c, _ in COEFFS}

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(4, 1, figsize=(9, 10), sharex=True)
    ax[0].plot(t, d["distance_to_spot_m"], label="distance behind the landing spot (m)")
    ax[0].plot(t, d["height_above_deck_m"], label="cg above the deck (m)")
    ax[0].legend(loc="upper right")
    for i, (c, label) in enumerate(COEFFS):
        ax[i + 1].plot(t, delta[c], lw=0.8)
        ax[i + 1].set_ylabel(label)
    for x in ax:
        x.axvspan(t[0], a.startup, color="r", alpha=0.12, lw=0)
        x.grid(alpha=0.3)
    ax[-1].set_xlabel("t (s)")
    ax[0].set_title(f"Approach: rotor loads against their values at t = {a.startup:g} s (start-up shaded; thesis fig. 9.4)")
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "approach.png"), dpi=110)
    plt.close(fig)

    summary = []
    have_pywt = True
    try:
        import pywt  # noqa: F401
    except ImportError:
        have_pywt = False
        print("analyze_approach: warning: python3-pywt is missing; no wavelet plot", file=sys.stderr)
    tu = None
    if have_pywt and after.sum() > 16:
        ta = t[after]
        fmax = min(5.0, 0.4 / float(np.median(np.diff(ta))))
        freqs = np.geomspace(0.01, fmax, 60)
        fig, ax = plt.subplots(3, 1, figsize=(9, 9), sharex=True)
        for i, (c, label) in enumerate(COEFFS):
            tu, yu, dt = uniform(ta, delta[c][after])
            amp = wavelet_amplitude(yu, dt, freqs)
            m = ax[i].pcolormesh(tu, freqs, amp, shading="auto", cmap="viridis")
            ax[i].set_yscale("log")
            for f in BAND:
                ax[i].axhline(f, color="r", ls="--", lw=1)
            short = 2.0 / (tu[-1] - tu[0])  # fewer than two cycles in the record below this
            ax[i].axhspan(freqs[0], short, facecolor="none", edgecolor="w", hatch="//", lw=0)
            ax[i].set_ylabel(f"{label}\nfrequency (Hz)")
            fig.colorbar(m, ax=ax[i], label="amplitude")
            inband = (freqs >= BAND[0]) & (freqs <= BAND[1])
            upper = (freqs >= 0.2) & (freqs <= BAND[1])
            summary.append((c, np.nanmean(amp[inband]), np.nanmean(amp[upper])))
        ax[-1].set_xlabel("t (s)")
        ax[0].set_title("Wavelet amplitude, complex Morlet 1 Hz / 1 Hz (thesis fig. 9.5); red: 0.02-2 Hz")
        fig.tight_layout()
        fig.savefig(os.path.join(a.out, "approach_wavelets.png"), dpi=110)
        plt.close(fig)

    # phases: the start-up, the approach (moving), the hover (thesis 9.1)
    moving = t[(t >= a.startup) & (d["speed_m_s"] > 1e-9)]
    hover_from = moving[-1] if len(moving) else a.startup
    phases = [("start-up", t[0], a.startup), ("approach", a.startup, hover_from), ("hover", hover_from, t[-1] + 1)]
    with open(os.path.join(a.out, "approach_summary.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["coefficient", "value_at_startup", "phase", "t_from_s", "t_to_s", "delta_mean", "delta_std", "delta_min", "delta_max",
                    "wavelet_mean_amplitude_after_startup_0.02_2Hz", "wavelet_mean_amplitude_after_startup_0.2_2Hz"])
        for c, _ in COEFFS:
            wav = next(((b, u) for n, b, u in summary if n == c), (float("nan"), float("nan")))
            for name, lo, hi in phases:
                sel = (t >= lo) & (t < hi)
                if not sel.any() or hi <= lo:
                    continue
                x = delta[c][sel]
                w.writerow([c, f"{d[c][k0]:.9g}", name, f"{lo:g}", f"{min(hi, t[-1]):g}", f"{x.mean():.4g}", f"{x.std():.4g}",
                            f"{x.min():.4g}", f"{x.max():.4g}", f"{wav[0]:.4g}", f"{wav[1]:.4g}"])
    names = ["approach.png", "approach_wavelets.png", "approach_summary.csv"] + (["approach_loads.csv"] if is_bag else [])
    print("wrote", ", ".join(os.path.join(a.out, n) for n in names))


if __name__ == "__main__":
    main()
