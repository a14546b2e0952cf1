#!/usr/bin/env bash
# The main job. Sets up and builds if needed, then runs the default scenario: the approach of thesis
# 9.1 (a Bo 105 onto the moving NatoGD-like destroyer, LRM inflow at N = 32 fed by the default ship-wake
# table) as ROS nodelets, headless, in simulated time (`roslaunch ship_lrm approach.launch
# record:=true`), leaving in build/run/approach/ the bag (approach.bag), the plots (approach.png,
# approach_wavelets.png) and the summary (approach_summary.csv, approach_loads.csv) made from the bag
# by scripts/analyze_approach.py. The default wake table is made on first use (about a minute on
# 2 cores) and cached in ~/.cache/ship_lrm. Without ROS (SHIP_LRM_NO_ROS=1 or no catkin workspace)
# the ROS-free batch tool `ship_lrm approach` runs the same approach into the same folder instead.
# Then, as before: the Bo 105 trim sweep and a lateral doublet (build/run/trim.*, doublet_lateral.*)
# and the LBM core's validation flow (Schaefer & Turek 3D-1Z cylinder drag; build/run/cylinder.vti).
# SHIP_LRM_WAKE=realistic flies it on the realistic table instead (the deck region at 364 cells per
# ship length, turbulent: `ship_lrm wake --preset realistic`, made on first use, 41 min on
# 2 cores, cached beside the default). With arguments, runs `ship_lrm <arguments>` instead.
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
wake="${SHIP_LRM_WAKE:-default}"
case "$wake" in
  default | realistic) ;;
  *) echo "run.sh: SHIP_LRM_WAKE must be default or realistic, got '$wake'" >&2; exit 2 ;;
esac
ship_lrm wake --preset "$wake"
if command -v roslaunch > /dev/null && [ "${SHIP_LRM_NO_ROS:-0}" != 1 ]; then
  mkdir -p "$out/approach"
  # its own ROS master on a free port, so a roscore the user has running is not disturbed
  port=$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("localhost", 0)); print(s.getsockname()[1])')
  ROS_MASTER_URI="http://localhost:$port" roslaunch -p "$port" ship_lrm approach.launch N:=32 record:=true \
    wake_file:="$wake" bag:="$out/approach/approach.bag"
  "$root/scripts/analyze_approach.py" "$out/approach/approach.bag" --out "$out/approach"
else
  ship_lrm approach --N 32 --wake "$wake" --out "$out/approach" --overwrite
fi
ship_lrm trim --speeds 0:5:70 --out "$out" --overwrite
ship_lrm doublet --axis lateral --speed 13.37 --out "$out" --overwrite
ship_lrm validate cylinder --resolution 10 --vti "$out/cylinder.vti" --overwrite
