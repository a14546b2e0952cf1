#!/usr/bin/env bash
# Builds ship_lrm and the test programs with CUDA on this (Debian) machine and packs them, stripped,
# with the shared libraries they need beyond glibc, into .carry/pack/carry.tar.xz (about 16 MB; the
# device tool carries at most 64 MiB). On the GPU machine, scripts/gpu_check.sh unpacks it when it
# finds it (with Python's tarfile: no xz program needed there) and runs the binaries (PREBUILT).
# Usage: scripts/pack_gpu_binaries.sh [BUILD_DIR]   (default build/gpu-carry; CUDA_ARCH, default 90;
# TRACE_CELL=x,y,z builds the diagnostics variant that prints pass 1 of the open boundaries at that
# cell, lattice_view.hpp: use its own BUILD_DIR, e.g. build/gpu-trace)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build/gpu-carry}"
export PATH=/usr/bin:$PATH:/usr/local/cuda/bin
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSHIP_LRM_WITH_ROS=OFF -DSHIP_LRM_CUDA=ON -DSHIP_LRM_NATIVE=OFF \
  -DCMAKE_CXX_FLAGS=-march=x86-64-v3 -DCMAKE_CUDA_ARCHITECTURES="${CUDA_ARCH:-90}" -DSHIP_LRM_TRACE_CELL="${TRACE_CELL:-}" > /dev/null
programs=(ship_lrm test_lbm test_lrm test_wake test_flight)
pack=carry
if [ -n "${TRACE_CELL:-}" ]; then  # the diagnostics variant: the LRM tests only, in a pack of its own
  programs=(test_lrm)
  pack=trace
  cmake --build "$build" -j"$(nproc)" --target test_lrm
else
  cmake --build "$build" -j"$(nproc)" --target ship_lrm_cli "${programs[@]:1}"
fi
rm -rf "$root/.carry/bin" "$root/.carry/lib" "$root/.carry/pack/$pack.tar.xz"
mkdir -p "$root/.carry/bin" "$root/.carry/lib" "$root/.carry/pack"
for p in "${programs[@]}"; do strip -o "$root/.carry/bin/$p" "$build/bin/$p"; done
# every shared library they load except glibc's and the compiler's own (the GPU machine has newer ones)
for p in "$root"/.carry/bin/*; do ldd "$p"; done | awk '/=>/ {print $3}' | sort -u |
  grep -v -E '/(libc|libm|libdl|librt|libpthread|ld-linux[^/]*|libstdc\+\+|libgcc_s)\.so' | xargs -r -I{} cp -L {} "$root/.carry/lib/"
tar -C "$root/.carry" -cf - bin lib | xz -9 -T1 > "$root/.carry/pack/$pack.tar.xz"
rm -rf "$root/.carry/bin" "$root/.carry/lib"
ls -la "$root/.carry/pack/$pack.tar.xz"
echo "device run: carry [\".carry/pack\"], command: bash scripts/gpu_check.sh"
