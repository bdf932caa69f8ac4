# Before/after curves of the cue-change task (docs/experiments.md, "A changing world"). Run from the
# repository root after writing cue-before.csv and cue-after.csv with verve-experiments.
set datafile separator ","
set terminal pngcairo size 900,420 font ",11"
set output "docs/img/changing-world-cue.png"
set title "cue-change: 8 cues, 5 actions; 4 cues change their answer at trial 1000 (20 runs)"
set xlabel "trial"
set ylabel "fraction correct"
set yrange [0:1.02]
set key bottom right noenhanced
set arrow from 1000, graph 0 to 1000, graph 1 nohead dashtype 2
plot "cue-before.csv" using 1:5 every ::1 with lines lw 1 lc rgb "#c0392b" title "defaults (no bound, tau_value 0.1 s, k 5)", \
     "cue-after.csv" using 1:5 every ::1 with lines lw 1 lc rgb "#2471a3" title "bound 10, tau_value 0.5 s, k 25"
