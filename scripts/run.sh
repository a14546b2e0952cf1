#!/usr/bin/env bash
# The main job. Sets up and builds if needed, then runs the default scenario.
# Until the ROS layer and the approach scenario land (issue 6), the default job runs what exists: the
# Bo 105 flight model's trim sweep (build/run/trim.csv, trim.png) and a lateral doublet
# (build/run/doublet_lateral.*), the LBM core's validation flow (the Schaefer & Turek 3D-1Z cylinder:
# drag against the published reference; flow field in build/run/cylinder.vti for ParaView), and the
# approach scenario's default ship-wake table (made once, about 2 minutes on 2 cores, then cached in
# ~/.cache/ship_lrm; its centre-plane plot beside it).
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
ship_lrm trim --speeds 0:5:70 --out "$out" --overwrite
ship_lrm doublet --axis lateral --speed 13.37 --out "$out" --overwrite
ship_lrm validate cylinder --resolution 10 --vti "$out/cylinder.vti"
ship_lrm wake --preset default
