#!/usr/bin/env python3
"""The approach analysis (scripts/analyze_approach.py): a sinusoid of amplitude A at frequency f shows
amplitude A at f in the calibrated Morlet transform (within 3 % where the record holds many cycles),
and the script turns an approach CSV into its plots and summary with the Delta against the start-up."""
import csv
import os
import subprocess
import sys
import tempfile

import numpy as np

here = os.path.dirname(os.path.abspath(__file__))
scripts = os.path.join(here, "..", "..", "scripts")
sys.path.insert(0, scripts)
import analyze_approach as a  # noqa: E402

dt = 0.01
t = np.arange(0, 25, dt)
freqs = np.geomspace(0.01, 5, 60)
failures = []
for f0, amp in [(0.5, 2e-3), (1.5, 5e-4)]:
    k = int(np.argmin(abs(freqs - f0)))
    grid = np.array(freqs)
    grid[k] = f0  # evaluate exactly at f0
    w = a.wavelet_amplitude(amp * np.sin(2 * np.pi * f0 * t), dt, grid)
    got = np.median(w[k, len(t) // 4:3 * len(t) // 4])
    if abs(got - amp) > 0.03 * amp:
        failures.append(f"{f0} Hz: amplitude {got:.4g}, expected {amp:.4g}")

with tempfile.TemporaryDirectory() as d:
    path = os.path.join(d, "approach.csv")
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["time_s", "CT", "CMx", "CMy", "distance_to_spot_m", "height_above_deck_m", "speed_m_s"])
        for ti in t:
            w.writerow([ti, 0.004 + 1e-4 * np.sin(2 * np.pi * 0.5 * ti), 1e-5, -2e-5, 97 - 5 * ti, 8, 5 if ti < 18 else 0])
    subprocess.run([sys.executable, os.path.join(scripts, "analyze_approach.py"), path, "--out", d, "--startup", "5"], check=True)
    for name in ["approach.png", "approach_wavelets.png", "approach_summary.csv"]:
        if not os.path.getsize(os.path.join(d, name)) > 0:
            failures.append(f"{name} missing or empty")
    with open(os.path.join(d, "approach_summary.csv")) as f:
        rows = list(csv.DictReader(f))
    ct = [r for r in rows if r["coefficient"] == "CT" and r["phase"] == "approach"][0]
    # the Delta is against t = 5 s, where the sine is at zero phase: 0.004 exactly
    if abs(float(ct["value_at_startup"]) - 0.004) > 1e-9:
        failures.append(f"C_T at the start-up {ct['value_at_startup']}, expected 0.004")
    if abs(float(ct["delta_max"]) - 1e-4) > 2e-6:
        failures.append(f"largest Delta C_T {ct['delta_max']}, expected 1e-4")

    # bad input: a clear message and a failing exit, no traceback, nothing written
    for args, message in [(["--out", path], "is a file; --out names the folder"),
                          (["--out", os.path.join(d, "bad"), "--startup", "nan"], "--startup must be a finite number")]:
        r = subprocess.run([sys.executable, os.path.join(scripts, "analyze_approach.py"), path] + args, capture_output=True, text=True)
        if r.returncode == 0 or message not in r.stderr or "Traceback" in r.stderr:
            failures.append(f"{args}: exit {r.returncode}, stderr {r.stderr.strip()[-200:]!r}")
    if os.path.exists(os.path.join(d, "bad")):
        failures.append("a refused analysis made its --out folder")

if failures:
    sys.exit("FAILED: " + "; ".join(failures))
print("analyze_approach: calibration and outputs OK")
