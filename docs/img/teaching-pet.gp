# The pet's learning curves (docs/teaching.md): scripts/teaching_curves.sh writes the CSV and runs this.
set datafile separator ","
set terminal pngcairo size 900,420 font ",11"
set output "docs/img/teaching-pet.png"
set title "The pet's trick (samples/love_pet), seeds 1-10: steps per trial, mean of the last 10 trials" noenhanced
set xlabel "trial"
set ylabel "steps per trial (100: cut off)"
set yrange [0:105]
set key top right noenhanced
set arrow from 30, graph 0 to 30, graph 1 nohead dashtype 2 lc rgb "#2471a3"
set arrow from 40, graph 0 to 40, graph 1 nohead dashtype 3 lc rgb "#27ae60"
plot data using 1:2 every ::1 with lines lw 2 lc rgb "#c0392b" title "alone", \
     data using 1:3 every ::1 with lines lw 2 lc rgb "#2471a3" title "the teacher at the controls for trials 1-30", \
     data using 1:4 every ::1 with lines lw 2 lc rgb "#27ae60" title "praised or scolded after each sit, trials 1-40"
