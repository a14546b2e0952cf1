#!/usr/bin/env bash
# The main job. Sets up and builds if needed, then runs the default scenario.
# Until the LRM domain, the flight model and the ship wake land (issues 3-6), the default job is
# the LBM core's validation flow: the Schaefer & Turek 3D-1Z cylinder (drag against the published
# reference), writing the flow field to build/cylinder.vti for ParaView.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
mkdir -p "$root/build"
"$root/scripts/setup.sh" > "$root/build/setup.log" 2>&1 || { tail -30 "$root/build/setup.log"; exit 1; }
# shellcheck disable=SC1091
source "$root/scripts/env.sh"
if [ $# -eq 0 ]; then
  set -- validate cylinder --resolution 10 --vti "$root/build/cylinder.vti"
fi
exec ship_lrm "$@"
