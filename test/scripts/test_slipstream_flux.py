#!/usr/bin/env python3
"""The slipstream profile (scripts/slipstream_flux.py) on synthetic planes with analytic answers: a
top-hat slipstream of radius 0.8 R (induced flux 0.64 u0 / v through any disc wider than it, half-velocity
radius 0.8 R) and a paraboloid u0 (1 - r^2 / R_w^2) (flux u0 pi R_w^2 / 2); the climb rate and v read
from inflow_sweep.csv beside the plane; a forward-flight plane, a foreign inflow_sweep.csv, a missing file
and bad radii refused."""
import csv
import math
import os
import subprocess
import sys

import tempfile

here = os.path.dirname(os.path.abspath(__file__))
script = os.path.join(here, "..", "..", "scripts", "slipstream_flux.py")
R, climb, vh = 4.92, 11.62, 11.624
v = -climb / 2 + math.sqrt(climb**2 / 4 + vh**2)
failures = []


def write_plane(path, dx_over_r, induced, ux=0.0):
    n = int(round(3.0 / dx_over_r))  # an even count: the axis between two columns
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["x_m", "z_m", "u_x_m_s", "u_y_m_s", "u_z_m_s", "wall", "rotor_radius_m"])
        for i in range(n):
            x = (i - (n - 1) / 2) * dx_over_r * R
            for k in range(5):
                z = (k - 2) * R
                w.writerow([x, z, ux, 0, climb + induced(abs(x) / R), 0, R])


def run(args):
    return subprocess.run([sys.executable, script] + args, capture_output=True, text=True)


def profile(out_csv):
    with open(out_csv) as f:
        return list(csv.DictReader(f))


with tempfile.TemporaryDirectory() as d:
    u0 = 1.3 * v
    # top hat: the slipstream's edge on a column edge, so the discs' sums are exact
    plane = os.path.join(d, "plane_V0.csv")
    write_plane(plane, 0.1, lambda r: u0 if r < 0.8 else 0.0)
    out = os.path.join(d, "p.csv")
    r = run([plane, "--climb", str(climb), "--induced", str(v), "--radii", "0.5,1,2", "--out", out, "--png", os.path.join(d, "p.png")])
    if r.returncode != 0:
        failures.append(f"top hat: exit {r.returncode}: {r.stderr}")
    else:
        row = profile(out)[2]
        checks = {
            "axis_induced_over_v": u0 / v,
            "flux_r0.5R_over_Av": 0.25 * u0 / v,
            "flux_r1R_over_Av": 0.64 * u0 / v,
            "flux_r2R_over_Av": 0.64 * u0 / v,
            "r_half_over_R": 0.8,
            "momentum_theory_m_s": v,
            "far_wake_flux_over_Av": 2 * (climb + v) / (climb + 2 * v),
        }
        for name, want in checks.items():
            if abs(float(row[name]) - want) > 1e-4 * max(1.0, abs(want)):
                failures.append(f"top hat: {name} {row[name]}, expected {want:.6g}")
        if not os.path.getsize(os.path.join(d, "p.png")) > 0:
            failures.append("top hat: no PNG")
    # paraboloid, fine columns: the annulus rule's error is O(dx^2); climb and v from inflow_sweep.csv
    write_plane(plane, 0.01, lambda r: u0 * (1 - (r / 0.9) ** 2) if r < 0.9 else 0.0)
    with open(os.path.join(d, "inflow_sweep.csv"), "w") as f:
        f.write("speed_m_s,momentum_theory_m_s,faces,climb_m_s\n")
        f.write(f"0,{v},thesis,{climb}\n")
    r = run([plane, "--out", out])
    if r.returncode != 0:
        failures.append(f"paraboloid: exit {r.returncode}: {r.stderr}")
    else:
        row = profile(out)[2]
        want = u0 * 0.81 / 2 / v
        if abs(float(row["flux_r2R_over_Av"]) - want) > 1e-3 * want:
            failures.append(f"paraboloid: flux {row['flux_r2R_over_Av']}, expected {want:.6g}")
        if abs(float(row["climb_m_s"]) - climb) > 1e-9:
            failures.append(f"paraboloid: climb {row['climb_m_s']} not read from inflow_sweep.csv")
        if abs(float(row["r_half_over_R"]) - 0.9 / math.sqrt(2)) > 2e-3:
            failures.append(f"paraboloid: r_half {row['r_half_over_R']}, expected {0.9 / math.sqrt(2):.4f}")
    # refusals: forward flight, no file, bad radii; each a message, not a traceback
    write_plane(plane, 0.1, lambda r: 0.0, ux=-10.0)
    with open(os.path.join(d, "inflow_sweep.csv"), "w") as f:
        f.write("speed,other\n0,1\n")
    for args, words in [([plane], "not an inflow_sweep.csv"), ([plane, "--climb", "0", "--induced", "11"], "not axial flight"),
                        ([os.path.join(d, "none.csv")], "no such file"),
                        ([plane, "--radii", "1,x"], "comma list"), ([plane, "--radii", "-1"], "positive")]:
        r = run(args)
        if r.returncode == 0 or words not in r.stderr or "Traceback" in r.stderr:
            failures.append(f"{args[1:]}: exit {r.returncode}, stderr {r.stderr.strip()!r} (wanted '{words}')")

if failures:
    print("\n".join(failures))
    sys.exit(1)
print("slipstream_flux.py: analytic planes and refusals as expected")
