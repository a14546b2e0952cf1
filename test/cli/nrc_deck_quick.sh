#!/bin/sh
# `ship_lrm validate nrc-deck --quick --json`: the NRC deck case's whole pipeline (nested precompute,
# probes in the wind-tunnel frame, statistics, JSON) at 64 cells per ship length: one JSON object on
# stdout with the thesis' two probes (7.1) at their places, every sample of 0.3 s taken in the fluid,
# finite statistics; the run's files beside it; a second run into the same folder is refused.
# Usage: nrc_deck_quick.sh SHIP_LRM_BINARY SCRATCH_DIR
bin=$1
dir=$2
rm -rf "$dir" && mkdir -p "$dir" || exit 1
"$bin" validate nrc-deck --quick --json --backend cpu --out "$dir/run" > "$dir/out.json" 2> "$dir/err.txt" || { cat "$dir/err.txt"; exit 1; }
/usr/bin/python3 - "$dir/out.json" "$dir/run" <<'PY' || exit 1
import json, math, os, sys
j = json.loads(open(sys.argv[1]).read())
def check(ok, what):
    if not ok:
        sys.exit("FAILED: " + what + "\n" + json.dumps(j, indent=1)[:3000])
check(j["motion"] == "static" and j["cells_per_length"] == 64 and j["ratio"] == 2, "the quick setting")
check(abs(j["wind_m_s"] - 9.77) < 1e-12 and abs(j["statistics_s"] - 0.3) < 1e-12, "wind and statistics time")
p = j["probes"]
check(len(p) == 2, "two probes")
check([(q["x"], q["y"], q["z"]) for q in p] == [(0.3, 0.0, 0.07), (0.3, 0.06, 0.07)], "the thesis' probe points")
for q in p:
    check(q["samples"] in (150, 151), "a sample every 2 ms over 0.3 s, all in the fluid")
    check(all(math.isfinite(v) and abs(v) < 2 * 9.77 for v in q["mean"]), "finite mean velocities below twice the wind")
    check(all(v >= 0 for v in q["variance"]) and q["tke_over_u2"] >= 0, "non-negative variances")
check(j["deck_region"]["points"] > 0, "the deck region has fluid points")
for f in ("table", "fine_centre_plane_csv", "centre_plane_csv", "probes_csv"):
    check(os.path.exists(j[f]), f + " written")
check(os.path.exists(os.path.join(sys.argv[2], "nrc_deck.json")), "nrc_deck.json written")
PY
# the run's table is the user's now: the same command again is refused, the table kept
"$bin" validate nrc-deck --quick --json --backend cpu --out "$dir/run" > /dev/null 2>&1
rc=$?
[ $rc -eq 1 ] || [ $rc -eq 2 ] || { echo "FAILED: a second run into the same folder exited $rc"; exit 1; }
ls "$dir/run"/nrc_deck_static_N64.h5 > /dev/null || exit 1
echo "nrc-deck quick: passed"
