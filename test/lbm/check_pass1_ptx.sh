#!/bin/sh
# Compiles pass 1 of the open boundaries for the device (pass1_ptx_probe.cu, the build's CUDA flags)
# and fails if its PTX uses local memory. The CUDA/CPU difference of 2026-12-04 came from a stack slot there
# that nvcc shared between the boundary state and other local arrays (docs/design.md, "The device's
# stack slot"); kept in registers the state cannot be overwritten. Needs nvcc only, no GPU.
# Usage: check_pass1_ptx.sh NVCC INCLUDE_DIR OUT_DIR [ARCH]
set -eu
nvcc=$1
include=$2
out=$3
arch=${4:-90}
ptx="$out/pass1_ptx_probe.ptx"
"$nvcc" -I"$include" -O3 -arch=compute_"$arch" --fmad=false -std=c++17 -ptx "$(dirname "$0")/pass1_ptx_probe.cu" -o "$ptx"
if grep -q '__local_depot' "$ptx"; then
  echo "pass 1 of the open boundaries uses local memory on the device (PTX: $ptx):"
  grep '__local_depot' "$ptx" | head -3
  echo "keep its small vectors in registers: component()/set_component() in hd.hpp, no run-time index into local arrays"
  exit 1
fi
echo "pass 1 of the open boundaries: no local memory in the PTX (compute_$arch)"
