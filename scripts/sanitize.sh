#!/usr/bin/env bash
# Builds the ROS-free core and its test programs with the compiler's run-time checkers and runs the
# tests under them (not part of scripts/test.sh: on 2 cores the build takes 13 - 21 minutes and the tests
# under AddressSanitizer longer than the whole CI run).
#   SANITIZER=address (default): AddressSanitizer + UndefinedBehaviorSanitizer (out-of-bounds and
#     use-after-free accesses, leaks, signed overflow, misaligned or null accesses, bad shifts and
#     casts); any report fails the run. Build folder build/asan.
#   SANITIZER=thread: ThreadSanitizer on the tests that run threads of their own (the real-time LRM
#     inflow, the inflow link, the wake table's read-ahead). Build folder build/tsan. OpenMP runs one
#     thread there (libgomp is not instrumented, so its own barriers would be reported as races).
# Usage: scripts/sanitize.sh [GTEST_FILTER]   (default: every test but the bluff-body validation under
# AddressSanitizer, it takes minutes there and runs nothing the other tests do not; the threaded tests above
# under ThreadSanitizer)
# CUDA is off in these builds: the device code is checked by scripts/gpu_check.sh on a GPU.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
export PATH=/usr/bin:$PATH
kind="${SANITIZER:-address}"
case "$kind" in
  address)
    build="$root/build/asan"
    flags="-g1 -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=undefined"
    programs=(test_lbm test_flight test_lrm test_wake)
    filter="${1:-*-BluffBody.*}"
    export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0:halt_on_error=1}"
    export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
    ;;
  thread)
    build="$root/build/tsan"
    flags="-g1 -fsanitize=thread"
    programs=(test_lrm test_wake)
    filter="${1:-RealTimeInflow.*:LrmInflow.*:InflowLink.*:DeadlineWatch.*:WakeTable.*:WakeFaceFeed.*:ShipApproach.RealTime*}"
    export OMP_NUM_THREADS=1
    export TSAN_OPTIONS="${TSAN_OPTIONS:-halt_on_error=1:second_deadlock_stack=1}"
    ;;
  *)
    echo "scripts/sanitize.sh: SANITIZER must be address or thread, got '$kind'" >&2
    exit 2
    ;;
esac
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=None -DSHIP_LRM_WITH_ROS=OFF -DSHIP_LRM_CUDA=OFF \
  -DSHIP_LRM_CORE_OPTIMIZE=-O1 -DCMAKE_CXX_FLAGS="-O1 $flags" -DCMAKE_EXE_LINKER_FLAGS="${flags#-g1 }" -DCMAKE_SHARED_LINKER_FLAGS="${flags#-g1 }" > "$build.configure.log" ||
  { cat "$build.configure.log"; exit 1; }
cmake --build "$build" -j"$(nproc)" --target "${programs[@]}"
failed=0
for p in "${programs[@]}"; do
  [ -x "$build/bin/$p" ] || continue
  echo "== $p ($kind sanitizer, filter $filter)"
  (cd "$build" && "$build/bin/$p" --gtest_filter="$filter" --gtest_brief=1) || failed=1
done
exit "$failed"
