#!/usr/bin/env bash
# Many agents per frame (docs/performance.md): builds verve_crowd_bench, runs every configuration
# (tiny and cart-pole-shaped agents, each also with one lattice; 100 to 10,000 of them;
# separate brains or one shared brain; a plain update loop, then the batch call on 1 and 2
# threads), 3 repetitions each, and prints the median updates per second and its ratio to the
# target for 10,000 agents of its shape: 600,000/s (60 Hz) for the cart-pole shape, 2,000,000/s
# for the tiny one. Writes
# build/bench-crowd.csv (raw) and, with gnuplot, build/bench-crowd.png (updates/s vs agents).
# About 3 minutes on 2 cores.
#   ./scripts/bench_crowd.sh [extra Google Benchmark flags, e.g. --benchmark_filter=tiny]
# Beside an earlier build (its verve_crowd_bench, e.g. from a worktree of an older commit): each
# repetition runs both, one after the other, and the table gains the earlier build's median and
# the ratio new / earlier (this machine is shared: only ratios of runs made together count).
#   BASELINE=/tmp/old-build/bench/verve_crowd_bench ./scripts/bench_crowd.sh --benchmark_filter=10000
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/build.sh verve_crowd_bench >/dev/null
csv=build/bench-crowd.csv
baseline=${BASELINE:-}
[ -z "$baseline" ] || [ -x "$baseline" ] || { echo "bench_crowd.sh: BASELINE=$baseline is not an executable" >&2; exit 2; }
: >"$csv"
: >"$csv.baseline"
for rep in 1 2 3; do
  build/bench/verve_crowd_bench --benchmark_min_time=0.2 --benchmark_format=csv "$@" 2>/dev/null >>"$csv"
  if [ -n "$baseline" ]; then "$baseline" --benchmark_min_time=0.2 --benchmark_format=csv "$@" 2>/dev/null >>"$csv.baseline"; fi
done
# name = crowd/<shape>/<agents>/<brains>/<mode>; the median of its 3 runs, in the order first run.
table=build/bench-crowd.txt
awk -F, '
  function median(list,   n, v, i, j, t) {
    n = split(list, v, " ")
    for (i = 1; i <= n; i++) for (j = i + 1; j <= n; j++) if (v[j] + 0 < v[i] + 0) { t = v[i]; v[i] = v[j]; v[j] = t }
    return v[int((n + 1) / 2)]
  }
  FNR == 1 { file++ }
  /^name,/ { for (i = 1; i <= NF; i++) { h = $i; gsub(/"/, "", h); if (h == "updates_per_s") col[file] = i }; next }
  /^"crowd/ {
    name = $1; gsub(/"/, "", name); sub(/\/real_time$/, "", name)
    if (file == 1 && !(name in now)) order[++names] = name
    if (file == 1) now[name] = now[name] " " $col[file]; else before[name] = before[name] " " $col[file]
  }
  END {
    for (k = 1; k <= names; k++) {
      name = order[k]
      split(name, p, "/")
      tiny = p[2] ~ /^tiny/  # the targets for 10,000 agents (docs/performance.md): 2M/s tiny, 600k/s cart-pole
      m = median(now[name])
      line = sprintf("%-10s %6s agents  %-10s %-16s %12.0f updates/s  %5.2fx of %s/s", p[2], p[3], p[4], p[5], m,
                     m / (tiny ? 2000000 : 600000), tiny ? "2M" : "600k")
      if (name in before) { b = median(before[name]); line = line sprintf("   earlier %10.0f  now/earlier %5.2f", b, m / b) }
      print line
    }
  }' "$csv" "$csv.baseline" | tee "$table"

command -v gnuplot >/dev/null || { echo "(gnuplot missing: no plot)"; exit 0; }
# Columns per agent count: for each shape, separate/loop, separate/batch_threads:2, one_brain/batch_threads:2.
dat=build/bench-crowd.dat
awk '{ v[$2 " " $1 " " $4 " " $5] = $6; n[$2] = 1 }
  END {
    for (count in n) {
      line = count
      split("tiny cart_pole", shapes, " ")
      for (s = 1; s <= 2; s++)
        line = line " " v[count " " shapes[s] " separate loop"] " " v[count " " shapes[s] " separate batch_threads:2"] \
               " " v[count " " shapes[s] " one_brain batch_threads:2"]
      print line
    }
  }' "$table" | sort -n >"$dat"
gnuplot <<GP
if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) { set terminal pngcairo size 900,560 font 'sans,11' } else { set terminal png size 900,560 }
set output 'build/bench-crowd.png'
set title 'Agent updates per second through the C ABI (2-core machine, median of 3)'
set xlabel 'agents updated per frame'
set ylabel 'updates per second'
set logscale xy
set grid
set key below
set format y '%.0s%c'
plot '$dat' using 1:2 with linespoints lw 2 lc rgb '#e67e22' dt 2 title 'tiny, one call each', \
     '' using 1:3 with linespoints lw 2 lc rgb '#e67e22' title 'tiny, batch, 2 threads', \
     '' using 1:4 with linespoints lw 2 lc rgb '#d35400' dt 3 title 'tiny, 1 brain, batch, 2 threads', \
     '' using 1:5 with linespoints lw 2 lc rgb '#1f4e9c' dt 2 title 'cart-pole, one call each', \
     '' using 1:6 with linespoints lw 2 lc rgb '#1f4e9c' title 'cart-pole, batch, 2 threads', \
     '' using 1:7 with linespoints lw 2 lc rgb '#154360' dt 3 title 'cart-pole, 1 brain, batch, 2 threads', \
     600000 with lines lw 1 lc rgb '#c0392b' title '600k/s: 10,000 agents at 60 Hz (cart-pole target)', \
     2000000 with lines lw 1 lc rgb '#c0392b' dt 4 title '2M/s: the tiny target'
GP
echo "plot: build/bench-crowd.png"
