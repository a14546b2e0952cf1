#!/usr/bin/env bash
# Builds ship_lrm. With ROS (catkin) installed: a catkin workspace in build/ws whose src/ship_lrm
# links to this repository's files. Without ROS (e.g. a GPU machine): the ROS-free core with plain CMake
# in build/core. CUDA is compiled when nvcc is found (/usr/local/cuda/bin or PATH).
# Extra CMake arguments are passed through, e.g. scripts/build.sh -DSHIP_LRM_CUDA=OFF
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
export PATH=/usr/bin:/bin:$PATH:/usr/local/cuda/bin
jobs="${SHIP_LRM_JOBS:-$(nproc)}"
if command -v catkin_make >/dev/null 2>&1 && [ "${SHIP_LRM_NO_ROS:-0}" != 1 ]; then
  # The package in the workspace: a directory of links to the repository's top-level entries, all but
  # build/ (a link to the repository itself would contain the workspace, and roslaunch's file search
  # would walk round that loop without end).
  pkg="$root/build/ws/src/ship_lrm"
  [ -L "$pkg" ] && rm "$pkg"
  mkdir -p "$pkg"
  find "$pkg" -maxdepth 1 -type l -delete
  for entry in "$root"/* "$root"/.clang-format; do
    name="$(basename "$entry")"
    [ -e "$entry" ] && [ "$name" != build ] && ln -sfn "$entry" "$pkg/$name"
  done
  cd "$root/build/ws"
  catkin_make -DCMAKE_BUILD_TYPE=Release -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCATKIN_ENABLE_TESTING=ON "$@" -j"$jobs"
else
  cmake -S "$root" -B "$root/build/core" -DCMAKE_BUILD_TYPE=Release -DSHIP_LRM_WITH_ROS=OFF "$@"
  cmake --build "$root/build/core" -j"$jobs"
fi
