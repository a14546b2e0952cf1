#!/bin/sh
# Bad input on the command line is refused (exit code 2, a message naming the option) before any
# work. Numbers: NaN passes CLI11's range checks (every comparison with it is false), "inf" the
# unbounded options, an empty entry of a list used to read as 0, and a negative start-up or sample
# interval of `wake` used to mean "the default". Paths: a file where a folder is meant or the reverse,
# and an existing file that --vti, --csv or --mesh used to replace without --overwrite (the user's
# file must stay as it was). Usage: bad_input.sh SHIP_LRM_BINARY SCRATCH_DIR
bin=$1
dir=$2
rm -rf "$dir" && mkdir -p "$dir" || exit 1
printf 'name,value\n1,2\n' > "$dir/other.csv"
failed=0
expect() {  # expect 'what the message must say' ARGS...
  want=$1
  shift
  out=$(timeout 20 "$bin" "$@" 2>&1 < /dev/null)
  rc=$?
  if [ $rc -ne 2 ] || ! printf '%s' "$out" | grep -q -- "$want"; then
    echo "FAILED (exit $rc, wanted 2 and '$want'): ship_lrm $*"
    printf '%s\n' "$out" | tail -3
    failed=1
  fi
}
expect "--warm-up: 'nan' is not a finite number" trim --inflow lrm --N 16 --speeds 10 --warm-up nan --out "$dir/a"
expect "--speed: 'nan' is not a finite number" bench flight --speed nan --seconds 1
expect "--seconds: 'NaN' is not a finite number" bench lbm --size 8 --steps 0 --seconds NaN
expect "--tolerance: 'nan' is not a finite number" validate cylinder --resolution 4 --max-steps 10 --tolerance nan
expect "--lateral: 'inf' is not a finite number" approach --lateral inf --out "$dir/b"
expect "--height: '-inf' is not a finite number" approach --height -inf --out "$dir/b"
expect "--startup: 'nan' is not a finite number" wake --preset tiny --startup nan --out "$dir/w.h5"
expect "--startup" wake --preset tiny --startup -1 --out "$dir/w.h5"
expect "--stats-interval" wake --preset tiny --stats-interval -1 --out "$dir/w.h5"
expect "--checkpoint-every" wake --preset tiny --checkpoint-every 0 --out "$dir/w.h5"
expect "--speeds: an empty entry in '5,,10'" trim --speeds 5,,10 --out "$dir/c"
expect "--speeds: an empty entry in '5,10,'" trim --speeds 5,10, --out "$dir/c"
expect "--heights: values must lie in" sweep ground --heights=-1 --N 16 --out "$dir/d"
expect "--speeds applies to --mode forward" sweep ground --mode hover --speeds 10 --N 16 --out "$dir/d"
expect "--climb: Value -1 not in range" sweep inflow --climb -1 --speeds 0 --N 16 --out "$dir/d"
expect "--climb: 'nan' is not a finite number" sweep free-wake --climb nan --speeds 0 --out "$dir/f"
expect "--smagorinsky: Value -0.1 not in range" sweep inflow --smagorinsky -0.1 --speeds 10 --N 16 --out "$dir/d"
expect "--smagorinsky: 'nan' is not a finite number" sweep ground --smagorinsky nan --N 16 --out "$dir/d"
expect "--ground: free not in {slip,no-slip}" sweep ground --ground free --N 16 --out "$dir/d"
# a ground under the disk's cells or below the domain: refused before the run out of ground effect
# (at z/R = 0.01 and N = 64, a = 2, the disk sat on the ground and the sweep gave a ratio of 0.024; a
# ground on the disk's cells was found only after that run, and left a CSV that blocked the rerun)
expect "--heights: z/R must be at least 0.25" sweep ground --heights 0.5,0.01 --N 64 --reach 2 --out "$dir/d"
expect "--heights: z/R = 100 at N = 16, a = 1.25: isolated rotor: a ground 492 m below the hub lies outside the domain" sweep ground --heights 100 --N 16 --out "$dir/d"
expect "--smagorinsky: applies to the LRM only" trim --smagorinsky 0.1 --speeds 10 --out "$dir/c"
printf 'N,reach,speed_m_s,lrm_mean_m_s,momentum_theory_m_s,climb_m_s\n64,1.25,0,7.18,7.19,11.62\n' > "$dir/climb.csv"
expect "was swept at a climb of 11.62 m/s" sweep free-wake --speeds 0 --lrm "$dir/climb.csv" --out "$dir/f"
expect "--reference: '$dir/other.csv' has no column 'speed_m_s'" trim --speeds 10 --reference "$dir/other.csv" --out "$dir/e"
expect "--lrm: '$dir/other.csv' has no column 'N'" sweep free-wake --speeds 40 --lrm "$dir/other.csv" --out "$dir/f"
expect "is a directory, not a parameter file" trim --speeds 10 --config "$dir" --out "$dir/g"
printf 'the user'"'"'s\n' > "$dir/mine.txt"
expect "--out: '$dir/mine.txt' is a file" trim --speeds 10 --out "$dir/mine.txt"
expect "--out: '$dir' is a folder" wake --preset tiny --out "$dir" --overwrite
expect "--vti: '$dir/mine.txt' exists; pass --overwrite" validate cylinder --resolution 4 --max-steps 10 --vti "$dir/mine.txt"
expect "--csv: '$dir/mine.txt' exists; pass --overwrite" validate stream-stability --size 4 --steps 5 --csv "$dir/mine.txt"
expect "--mesh: '$dir/mine.txt' exists; pass --overwrite" wake --preset tiny --out "$dir/w.h5" --mesh "$dir/mine.txt"
# a fine region and probes that cannot be: refused before any step, nothing written
printf 'x,y,z\n0,0,5\n' > "$dir/in_hull.csv"
expect "--fine-ratio: Value 17 not in range" wake --preset tiny --fine-ratio 17 --out "$dir/w.h5"
expect "--fine-box: needs --fine-ratio" wake --preset tiny --fine-box=-0.4,0.3,0.15,0.3 --out "$dir/w.h5"
expect "does not fit inside the wake domain" wake --preset tiny --fine-ratio 2 --fine-box=-0.4,0.3,0.9,0.3 --out "$dir/w.h5"
expect "aft face cuts the ship" wake --preset tiny --N 32 --fine-ratio 2 --fine-box=-0.05,0.1,0.13,0.17 --out "$dir/w.h5"
expect "reaches outside the tabulated region" wake --preset tiny --N 32 --fine-ratio 2 --fine-box=-0.3,0.8,0.35,0.35 --out "$dir/w.h5"
expect "--fine-stored: needs --fine-ratio" wake --preset tiny --fine-stored=-0.3,0.0,0.1 --out "$dir/w.h5"
expect "the stored part .* must lie inside the box" wake --preset tiny --N 32 --fine-ratio 2 --fine-box=-0.3,0.1,0.13,0.17 --fine-stored=-0.3,0.3,0.1 --out "$dir/w.h5"
expect "wake table 'nowhere.h5' not found" approach --wake nowhere.h5 --out "$dir/b"
expect "unknown wake preset 'huge'" wake --preset huge --out "$dir/w.h5"
expect "expected three numbers" wake --preset tiny --probes "$dir/other.csv" --out "$dir/w.h5"
expect "is not in the fluid" wake --preset tiny --probes "$dir/in_hull.csv" --probe-frame ship --out "$dir/w.h5"
expect "do not nest" validate nrc-deck --cells-per-length 997 --out "$dir/g"
expect "--motion" validate nrc-deck --motion roll --out "$dir/g"
if [ "$(cat "$dir/mine.txt")" != "the user's" ]; then
  echo "FAILED: a refused run changed the user's file"
  failed=1
fi
# nothing was made by the refused runs
for made in a b c d e f g w.h5; do
  if [ -e "$dir/$made" ]; then
    echo "FAILED: a refused run left $dir/$made"
    failed=1
  fi
done
exit $failed
