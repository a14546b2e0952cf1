#!/usr/bin/env bash
# Copies the header-only CLI11 and Eigen, yaml-cpp (headers and static library) and the GoogleTest
# sources of this (Debian) machine into .carry/, for a GPU machine that has CUDA and CMake but none
# of them (see scripts/gpu_check.sh).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
mkdir -p "$root/.carry/include"
cp -r /usr/include/CLI "$root/.carry/include/"
rm -rf "$root/.carry/include/eigen3" "$root/.carry/include/yaml-cpp"
cp -r /usr/include/eigen3 /usr/include/yaml-cpp "$root/.carry/include/"
mkdir -p "$root/.carry/lib"
cp /usr/lib/x86_64-linux-gnu/libyaml-cpp.a "$root/.carry/lib/"
rm -rf "$root/.carry/googletest"
cp -r /usr/src/googletest "$root/.carry/googletest"
du -sh "$root/.carry"
