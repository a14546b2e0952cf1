#!/usr/bin/env bash
# One-time set-up on a fresh Debian 12 machine: installs every Debian package ship_lrm needs
# (as root, or through sudo) and builds the catkin package. Safe to run again.
set -euo pipefail
cd "$(dirname "$0")/.."
export PATH=/usr/bin:/bin:$PATH  # Debian's python3 for catkin, not a pyenv one

PACKAGES=(
  build-essential cmake clang-format
  libeigen3-dev libcli11-dev libgtest-dev libgmock-dev libyaml-cpp-dev libhdf5-dev nlohmann-json3-dev
  catkin ros-core-dev libroscpp-dev ros-message-generation ros-message-runtime
  libnodelet-dev libnodeletlib-dev libnodeletlib-tools pluginlib-dev python3-rostest librostest-dev
  libtf2-ros-dev libdiagnostic-updater-dev libstd-msgs-dev libgeometry-msgs-dev libsensor-msgs-dev libnav-msgs-dev
  libvisualization-msgs-dev libros-rosgraph-msgs-dev python3-rospy python3-roslib python3-roslaunch python3-rosbag
  python3-tf2-ros python3-std-msgs python3-geometry-msgs python3-sensor-msgs python3-nav-msgs python3-diagnostic-msgs
  python3-matplotlib python3-numpy python3-scipy python3-pywt
  rviz xvfb xauth imagemagick libgl1-mesa-dri rosbash
)
missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  echo "setup: installing ${missing[*]}"
  $SUDO apt-get update -q
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
scripts/build.sh
