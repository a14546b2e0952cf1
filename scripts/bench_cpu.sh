#!/usr/bin/env bash
# The CPU benchmark set behind the CPU table of docs/benchmarks.md: the LBM step (periodic boxes,
# against the memory bandwidth measured in the same run), the flight model, the coupled step at
# N = 32 and N = 64 (t_clock / t_sim, thesis 8.3.1), real-time pacing at N = 32 (lock-step and
# pipelined), and the face feed from the default wake table. Each benchmark is run REPEAT times (default 3), so the table can
# give a range: these are shared machines.
# Usage: scripts/bench_cpu.sh [OUT_DIR]   (default build/bench_cpu); one JSON object per line in
# OUT_DIR/bench.jsonl, each tagged with its command, plus machine.txt (CPU, threads, commit, date).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
# shellcheck disable=SC1091
source "$root/scripts/env.sh"
out="${1:-$root/build/bench_cpu}"
repeat="${REPEAT:-3}"
mkdir -p "$out"
: > "$out/bench.jsonl"
export OMP_NUM_THREADS="${OMP_NUM_THREADS:-$(nproc)}"
{
  echo "date $(date -u +%Y-%m-%d)"
  echo "commit $(git -C "$root" rev-parse --short HEAD)"
  echo "cpu $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
  echo "cores $(nproc) threads $OMP_NUM_THREADS"
  echo "flags $(grep -m1 -o -w -E 'avx512f|avx2' /proc/cpuinfo | sort -u | tr '\n' ' ')"
  echo "os $(. /etc/os-release && echo "$PRETTY_NAME")"
  echo "compiler $(c++ --version | head -1)"
} | tee "$out/machine.txt"

# run ARGS...: `ship_lrm ARGS` REPEAT times, each JSON line tagged with its command
run() {
  local i line
  for ((i = 0; i < repeat; i++)); do
    line=$(ship_lrm "$@" | tail -1)
    echo "{\"command\": \"ship_lrm $*\", \"result\": $line}" | tee -a "$out/bench.jsonl"
  done
}

ship_lrm wake --preset default > /dev/null # the default table, cached after the first use
table=$(ls -t "$HOME"/.cache/ship_lrm/wake_default_v*.h5 | head -1) # where `ship_lrm wake --preset default` caches it

run bench lbm --backend cpu --size 128 --json
run bench lbm --backend cpu --size 80 --json
run bench lbm --backend cpu --size 80 --smagorinsky 0.05 --json
run bench flight --seconds 20 --json
run bench lrm --backend cpu --N 32 --seconds 4 --json
run bench lrm --backend cpu --N 64 --seconds 2 --json
run bench lrm --backend cpu --N 32 --seconds 10 --realtime --json
run bench lrm --backend cpu --N 32 --seconds 10 --realtime --pipelined --json
run bench wake --table "$table" --N 64 --steps 100 --backend cpu --json
