#!/usr/bin/env bash
# GPU check: builds the ROS-free core with CUDA on a GPU machine (CUDA + CMake, no ROS), runs the
# device tests (CUDA against CPU) and the GPU benchmarks, and writes the results to $OUT (or
# build/gpu/results). On a machine without CLI11 / GoogleTest, first run
# scripts/prepare_gpu_carry.sh on a Debian machine and carry the .carry folder along.
# With PREBUILT=DIR it skips the build and runs DIR's ship_lrm and test binaries (built elsewhere
# with -DSHIP_LRM_CUDA=ON; shared libraries the GPU machine lacks, such as HDF5, in .carry/lib); a
# .carry/pack/carry.tar.xz made by scripts/pack_gpu_binaries.sh is unpacked and used that way.
#
# Device time is scarce (a lent machine: about 15 minutes a session, its start-up included), so the
# checks run in order of what they decide, each under its own time limit, and a failing or hanging
# one does not stop the rest:
#   1. the device tests: CudaBackend.* (CUDA against CPU), CudaLrmDomain.* (the LRM domain on both),
#      WakeFaceFeed.* (the face feed on the device against the host's), and a short approach on each backend (identical CSVs);
#      where .carry/pack/trace.tar.xz is packed, the LRM device tests again from the diagnostics build, which
#      prints pass 1 of the open boundaries at one cell on both backends (lrm_trace.log);
#   2. GPU target: the coupled step at N = 64, a = 1.25 (goal t_clock / t_sim <= 0.05);
#   3. face-feed cost target: serving the faces of that domain from the default table (goal <= 5 % of
#      its step), with the table made here on the GPU (also the precompute's MLUPS);
#   4. with FULL=1 (or FULL unset and time to spare: FULL=auto, the default, runs it when steps 1 - 3
#      took less than 4 minutes): every test binary in full, the LBM benchmarks, N = 128, the
#      precompute at N = 96 and the collision's stream stability on the device.
# summary.txt in $OUT lists each step with its exit code and seconds.
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
export PATH=$PATH:/usr/local/cuda/bin
out="${OUT:-$root/build/gpu/results}"
mkdir -p "$out"
summary="$out/summary.txt"
: > "$summary"
failed=0
started=$SECONDS

# step NAME SECONDS COMMAND...: runs COMMAND under a time limit, its output to $out/NAME.log (and
# the console), and notes its exit code and duration; 124 is a timeout.
step() {
  local name=$1 limit=$2
  shift 2
  local t0=$SECONDS
  echo "== $name (limit ${limit} s)"
  timeout --kill-after=10 "$limit" "$@" 2>&1 | tee "$out/$name.log"
  local rc=${PIPESTATUS[0]}
  echo "$name rc=$rc ${limit}s-limit $((SECONDS - t0))s" | tee -a "$summary"
  return "$rc"
}

{
  nvidia-smi --query-gpu=name,driver_version,memory.total,clocks.max.sm,clocks.max.mem --format=csv || true
  nvcc --version | tail -1 || true
  echo "commit $(git rev-parse --short HEAD 2>/dev/null || echo unknown)"
} | tee "$out/device.txt"

# binaries packed on another machine (scripts/pack_gpu_binaries.sh): unpack and run those
if [ -z "${PREBUILT:-}" ] && [ -f .carry/pack/carry.tar.xz ]; then
  python3 -c "import tarfile; tarfile.open('.carry/pack/carry.tar.xz').extractall('.carry')" && chmod +x .carry/bin/* && PREBUILT=.carry/bin
fi
bin="${PREBUILT:-build/gpu/bin}"
if [ -z "${PREBUILT:-}" ]; then
  extra=()
  [ -d .carry/include/CLI ] && extra+=(-DSHIP_LRM_EXTRA_INCLUDE="$root/.carry/include")
  [ -f .carry/lib/libyaml-cpp.a ] && extra+=(-DSHIP_LRM_EXTRA_LIB="$root/.carry/lib")
  [ -f .carry/googletest/CMakeLists.txt ] && extra+=(-DSHIP_LRM_GTEST_SOURCE="$root/.carry/googletest")
  cmake -S . -B build/gpu -DCMAKE_BUILD_TYPE=Release -DSHIP_LRM_WITH_ROS=OFF -DSHIP_LRM_CUDA=ON \
    -DCMAKE_CUDA_ARCHITECTURES="${CUDA_ARCH:-90}" "${extra[@]}" > "$out/configure.log" || { echo "configure failed: $out/configure.log"; exit 1; }
  # the programs the first three steps need first; the others after
  step build 480 cmake --build build/gpu -j"$(nproc)" --target ship_lrm_cli test_lbm || exit 1
  cmake --build build/gpu -j"$(nproc)" --target test_wake test_lrm > "$out/build_wake.log" 2>&1 || true
fi
[ -d .carry/lib ] && export LD_LIBRARY_PATH="$root/.carry/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export OMP_NUM_THREADS="${OMP_NUM_THREADS:-$(nproc)}"
bench="$bin/ship_lrm"

# 1. device tests
step cuda_tests 240 "$bin/test_lbm" --gtest_filter="CudaBackend.*:BadInput.Cuda*" || failed=1
if [ -x "$bin/test_wake" ]; then step wake_feed_tests 240 "$bin/test_wake" --gtest_filter="WakeFaceFeed.*" || failed=1; fi
if [ -x "$bin/test_lrm" ]; then step lrm_cuda_tests 240 "$bin/test_lrm" --gtest_filter="CudaLrmDomain.*" || failed=1; fi
# 1a. the diagnostics variant, where packed (TRACE_CELL=0,5,5 scripts/pack_gpu_binaries.sh build/gpu-trace): the
# same LRM device tests, printing pass 1 of the open boundaries at that cell on both backends
if [ -f .carry/pack/trace.tar.xz ]; then
  python3 -c "import tarfile; tarfile.open('.carry/pack/trace.tar.xz').extractall('.carry/trace')" && chmod +x .carry/trace/bin/* &&
    LD_LIBRARY_PATH="$root/.carry/trace/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" step lrm_trace 120 .carry/trace/bin/test_lrm \
      --gtest_filter="CudaLrmDomain.LatticeOfATurningDomainMatchesCpuOnBareSolvers:CudaLrmDomain.MatchesCpuInATurningStreamWithRotorForces"
fi

# 1b. end to end: a short approach over the tiny table on each backend; the backends are bit-identical,
# so the two CSVs must be too (the device face feed, the frame motion and the disk exchange included).
# Without the ship: a wall change restarts the CUDA backend's flow from its macroscopic fields (a new
# solver) where the CPU's keeps its populations (LrmDomain::rebuild), so with walls they part by design.
wake_dir="$(mktemp -d)"
step wake_tiny 120 "$bench" wake --preset tiny --no-plot --out "$wake_dir/tiny.h5"
approach_args=(approach --wake "$wake_dir/tiny.h5" --N 16 --duration 2 --startup 0.2 --start-distance 10 --height 5 --no-ship --no-plot)
step approach_cpu 180 "$bench" "${approach_args[@]}" --backend cpu --out "$wake_dir/approach_cpu"
step approach_cuda 180 "$bench" "${approach_args[@]}" --backend cuda --out "$wake_dir/approach_cuda"
step approach_identical 10 cmp "$wake_dir/approach_cpu/approach.csv" "$wake_dir/approach_cuda/approach.csv" || failed=1

# 2. the coupled step at N = 64 (GPU target)
step bench_lrm_64 240 "$bench" bench lrm --backend cuda --N 64 --reach 1.25 --seconds 5 --json

# 3. the face feed from the default table (face-feed cost target), the table made here
step wake_default 300 "$bench" wake --preset default --backend cuda --no-plot --out "$wake_dir/default.h5"
if [ -f "$wake_dir/default.h5" ]; then
  step bench_wake_cuda 180 "$bench" bench wake --table "$wake_dir/default.h5" --N 64 --steps 200 --backend cuda --json
  step bench_wake_cpu 180 "$bench" bench wake --table "$wake_dir/default.h5" --N 64 --steps 100 --backend cpu --json
fi

# 4. the rest
full="${FULL:-auto}"
if [ "$full" = auto ]; then [ $((SECONDS - started)) -lt 240 ] && full=1 || full=0; fi
if [ "$full" = 1 ]; then
  step test_lbm 600 "$bin/test_lbm" --gtest_filter="${TEST_FILTER:-*-BluffBody.*}" || failed=1
  for t in test_flight test_lrm test_wake; do # built when Eigen and yaml-cpp (and HDF5) were found or carried
    if [ -z "${PREBUILT:-}" ]; then cmake --build build/gpu -j"$(nproc)" --target "$t" > "$out/build_$t.log" 2>&1 || true; fi
    if [ -x "$bin/$t" ]; then step "$t" 600 "$bin/$t" || failed=1; fi
  done
  step bench_lbm 300 bash -c "for a in '--size 256' '--size 80' '--size 80 --smagorinsky 0.05' '--size 128'; do \
    \"$bench\" bench lbm --backend cuda \$a --json; done; \"$bench\" bench lbm --backend cpu --size 128 --json"
  step bench_lrm_128 240 "$bench" bench lrm --backend cuda --N 128 --reach 1.25 --seconds 2 --json
  step wake_m96 300 "$bench" wake --ship natogd --scale model --N 96 --motion static --wind 9.77 --duration 0.5 --interval 0.05 \
    --backend cuda --no-plot --out "$wake_dir/m96.h5"
  # the collision's stability in a disturbed stream on the device (the same table as the CPU's: the
  # backends are bit-identical; docs/benchmarks.md at 193c1b4, "Stream stability of the collision")
  step stream_stability 300 "$bench" validate stream-stability --backend cuda --mach 0.15,0.225,0.3
  # the recursive regularised collision and the characteristic inlet on the device (2026-12-04)
  step stream_stability_rr 300 "$bench" validate stream-stability --backend cuda --mach 0.3 --collision recursive
  step inlet_outlet 300 "$bench" validate stream-stability --backend cuda --faces inlet-outlet --characteristic-inlet \
    --mach 0.078,0.173 --steps 8000 --smagorinsky 0.025 --nu 2.39e-5
else
  echo "(step 4, the full tests and the other benchmarks, skipped: FULL=1 runs them)" | tee -a "$summary"
fi
rm -rf "$wake_dir"
echo "== summary ($((SECONDS - started)) s)"
cat "$summary"
echo "tests exit code: $failed"
exit "$failed"
