#!/usr/bin/env bash
# The pet's learning curves in docs/teaching.md (docs/img/teaching-pet.png): the LÖVE pet game
# (samples/love_pet) headless with its scripted teacher, seeds 1-10, 300 trials each, alone, shown
# for 30 trials, and praised for 40; steps per trial (mean over the seeds, then over 10 trials).
# Needs a build with the LuaJIT module (./scripts/build.sh), love and gnuplot. About a minute.
set -euo pipefail
cd "$(dirname "$0")/.."
for tool in love gnuplot; do
  command -v "$tool" >/dev/null || { echo "teaching_curves.sh: needs $tool (apt-get install love gnuplot)" >&2; exit 1; }
done
work=$PWD/build/teaching-curves
rm -rf "$work" && mkdir -p "$work/game" "$work/save"
cmake --install build --prefix "$work/stage" >/dev/null
cp "$work/stage/lib/lua/5.1/verve.so" "$work/stage/lib/libverve.so.0" "$work/game/"
(cd samples/love_pet && cmake -E tar cf "$work/game/verve-pet.love" --format=zip main.lua conf.lua)

TRIALS=300
for mode in alone shown praised; do
  case $mode in alone) args="" ;; shown) args="--shown 30" ;; praised) args="--praise" ;; esac
  for seed in $(seq 1 10); do
    XDG_DATA_HOME="$work/save" XDG_RUNTIME_DIR="$work/save" love "$work/game/verve-pet.love" --headless \
      --seed "$seed" --curve "$TRIALS" $args | grep '^trial,'
  done > "$work/$mode.txt"
done
# trial, then per mode the mean steps over the seeds, averaged over the 10 trials up to it.
awk -F, -v trials="$TRIALS" '
  FILENAME ~ /alone/ { a[$2] += $3 } FILENAME ~ /shown/ { s[$2] += $3 } FILENAME ~ /praised/ { p[$2] += $3 }
  END {
    print "trial,alone,shown,praised"
    for (t = 10; t <= trials; ++t) {
      sa = ss = sp = 0
      for (k = t - 9; k <= t; ++k) { sa += a[k]; ss += s[k]; sp += p[k] }
      printf "%d,%.2f,%.2f,%.2f\n", t, sa / 100, ss / 100, sp / 100
    }
  }' "$work/alone.txt" "$work/shown.txt" "$work/praised.txt" > "$work/pet-curves.csv"
gnuplot -e "data='$work/pet-curves.csv'" docs/img/teaching-pet.gp
echo "wrote docs/img/teaching-pet.png from $work/pet-curves.csv"
