#!/bin/sh
# Runs the commands of docs/getting_started.md (its ```bash blocks) in a fresh folder, in order, and
# fails on the first that fails: the page's quick tour is executed, not only written. Not run: the
# install (scripts/setup.sh, source) and the ROS and rviz steps (roslaunch, rosrun: a display and a
# ROS master), as the page says.
# Usage: run_getting_started.sh SHIP_LRM_BINARY PAGE WORK_DIR
set -eu
bin="$1"; page="$2"; work="$3"
[ -x "$bin" ] || { echo "run_getting_started: no ship_lrm at $bin"; exit 1; }
[ -f "$page" ] || { echo "run_getting_started: no page $page"; exit 1; }
rm -rf "$work"; mkdir -p "$work/bin"
ln -s "$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")" "$work/bin/ship_lrm"
PATH="$work/bin:$PATH"; export PATH
awk '/^```bash$/ { on = 1; next } /^```/ { on = 0 } on' "$page" \
  | sed 's/[[:space:]]*#.*//; s/[[:space:]]*$//' | grep -v -E '^[[:space:]]*(scripts/setup\.sh|source |roslaunch |rosrun |#|$)' > "$work/commands.sh"
n=$(wc -l < "$work/commands.sh")
[ "$n" -ge 5 ] || { echo "run_getting_started: only $n commands found in $page"; exit 1; }
# README.md's quick tour shows a subset of the page's commands: each must be on the page (and so run here)
readme="$(dirname "$page")/../README.md"
if [ -f "$readme" ]; then
  sed -n '/^## Quick tour/,/^## /p' "$readme" | sed -n 's/^    \(ship_lrm [^#]*\).*/\1/p' | sed 's/[[:space:]]*$//' > "$work/tour.txt"
  [ -s "$work/tour.txt" ] || { echo "run_getting_started: no quick tour in $readme"; exit 1; }
  while IFS= read -r cmd; do
    grep -q -F -x -e "$cmd" "$work/commands.sh" || { echo "run_getting_started: README's '$cmd' is not in $page"; exit 1; }
  done < "$work/tour.txt"
fi
cd "$work"
i=0
while IFS= read -r cmd; do
  i=$((i + 1))
  echo "[$i/$n] $cmd"
  sh -c "$cmd" > "step$i.log" 2>&1 || { cat "step$i.log"; echo "run_getting_started: command $i failed: $cmd"; exit 1; }
done < commands.sh
# what the page says each step leaves behind
for f in first/approach.csv first/approach.png first/approach_summary.csv ship.stl my_wake.h5 own/approach.csv \
         sweep/inflow_sweep.csv trim/trim.csv; do
  [ -s "$f" ] || { echo "run_getting_started: $f, named on the page, was not written"; exit 1; }
done
echo "run_getting_started: $n commands ran"
