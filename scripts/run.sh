#!/usr/bin/env bash
# The main job. Sets up and builds if needed, then runs the default scenario: the approach of thesis
# 9.1 (a Bo 105 onto the moving NatoGD-like destroyer, LRM inflow at N = 32 fed by the default ship-wake
# table, ROS-free batch path, simulated time) into build/run/approach/ (approach.csv, approach.png,
# approach_wavelets.png, approach_summary.csv). The default wake table is made on first use (about
# 2 minutes on 2 cores) and cached in ~/.cache/ship_lrm. Then, as before: the Bo 105 trim sweep and a
# lateral doublet (build/run/trim.*, doublet_lateral.*) and the LBM core's validation flow (Schaefer &
# Turek 3D-1Z cylinder drag; build/run/cylinder.vti). The ROS launch files follow with issue 6.
# With arguments, runs `ship_lrm <arguments>` instead.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
mkdir -p "$root/build"
"$root/scripts/setup.sh" > "$root/build/setup.log" 2>&1 || { tail -30 "$root/build/setup.log"; exit 1; }
# shellcheck disable=SC1091
source "$root/scripts/env.sh"
if [ $# -gt 0 ]; then
  exec ship_lrm "$@"
fi
out="$root/build/run"
mkdir -p "$out"
ship_lrm wake --preset default
ship_lrm approach --N 32 --out "$out/approach" --overwrite
ship_lrm trim --speeds 0:5:70 --out "$out" --overwrite
ship_lrm doublet --axis lateral --speed 13.37 --out "$out" --overwrite
ship_lrm validate cylinder --resolution 10 --vti "$out/cylinder.vti"
