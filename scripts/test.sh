#!/usr/bin/env bash
# Sets up and builds if needed, then runs every test (gtest through ctest). Extra arguments go to ctest,
# e.g. scripts/test.sh -R Validation
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
"$root/scripts/setup.sh"  # installs what is missing (fresh machine), then builds
if [ -d "$root/build/ws/build" ] && [ "${SHIP_LRM_NO_ROS:-0}" != 1 ]; then
  dir="$root/build/ws/build"
else
  dir="$root/build/core"
fi
export OMP_NUM_THREADS="${OMP_NUM_THREADS:-$(nproc)}"
cd "$dir"
ctest --output-on-failure --timeout 1500 "$@"
