#!/usr/bin/env bash
# Copies the header-only CLI11 and the GoogleTest sources of this (Debian) machine into .carry/,
# for a GPU machine that has CUDA and CMake but neither of them (see scripts/gpu_check.sh).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
mkdir -p "$root/.carry/include"
cp -r /usr/include/CLI "$root/.carry/include/"
rm -rf "$root/.carry/googletest"
cp -r /usr/src/googletest "$root/.carry/googletest"
du -sh "$root/.carry"
