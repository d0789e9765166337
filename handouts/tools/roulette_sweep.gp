# The Russian-roulette sweep: samples/s, relative RMSE at equal time and efficiency over
# continueProb.
# Variables (gnuplot -e): data (roulette_sweep.csv), out (PNG).
set terminal pngcairo size 1500,480 font "sans,11"
set output out
set datafile separator ","
set key off
set xlabel "continueProb"
set xrange [0:1]
set grid lc rgb "#dddddd"
set multiplot layout 1,3 title "VI2 Cornell box, lab 4 (roulette), 256x256 pixels, equal render time per point; errors against the unbiased reference"

set title "speed"
set ylabel "samples per second (millions)"
set yrange [0:*]
plot data using 1:($4/1e6) skip 1 with linespoints pt 7 lw 2 lc rgb "#1b9e77"

set title "error at equal time"
set ylabel "relative RMSE"
set logscale y
set yrange [*:*]
plot data using 1:7 skip 1 with linespoints pt 7 lw 2 lc rgb "#d95f02"

set title "efficiency (higher is better)"
set ylabel "1 / (relative MSE x seconds)"
plot data using 1:8 skip 1 with linespoints pt 7 lw 2 lc rgb "#7570b3"

unset multiplot
