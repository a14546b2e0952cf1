# Source this file (`source scripts/env.sh`) to use the built ship_lrm: puts the `ship_lrm`
# program on PATH and, with ROS, sources the catkin workspace so `rospack find ship_lrm` and
# roslaunch work.
_ship_lrm_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export PATH=/usr/bin:$PATH
if [ -f "$_ship_lrm_root/build/ws/devel/setup.bash" ]; then
  # ROS's setup scripts read unset variables: relax `set -u` while they run, if it is on
  case $- in *u*) _ship_lrm_nounset=1; set +u ;; *) _ship_lrm_nounset=0 ;; esac
  # shellcheck disable=SC1091
  source "$_ship_lrm_root/build/ws/devel/setup.bash"
  [ "$_ship_lrm_nounset" = 1 ] && set -u
  unset _ship_lrm_nounset
  export PATH="$_ship_lrm_root/build/ws/devel/lib/ship_lrm:$PATH"
elif [ -d "$_ship_lrm_root/build/core/bin" ]; then
  export PATH="$_ship_lrm_root/build/core/bin:$PATH"
else
  echo "ship_lrm is not built yet: run scripts/setup.sh" >&2
fi
unset _ship_lrm_root
