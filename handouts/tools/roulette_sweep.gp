# The Russian-roulette sweep: samples per CPU-second, relative RMSE at equal CPU time and
# efficiency over continueProb. CPU time, the render threads' (--stats' cpu_seconds), is what
# other programs on the machine change little; the wall clock's seconds are in the CSV beside it.
# Variables (gnuplot -e): data (roulette_sweep.csv), out (PNG), budget (CPU-seconds per point).
# Columns: continue_prob (1), spp, cpu_seconds, seconds, samples_per_cpu_second (5),
# samples_per_second, rays_per_sample, noise_per_sample, relative_rmse (9), efficiency (10).
set terminal pngcairo size 1500,480 font "sans,11"
set output out
set datafile separator ","
set key off
set xlabel "continueProb"
set xrange [0:1]
set grid lc rgb "#dddddd"
set multiplot layout 1,3 title sprintf("VI2 Cornell box, lab 4 (roulette), 256x256 pixels, %g CPU-seconds of rendering per point (summed over the render threads); errors against the unbiased reference", budget)

set title "speed (by CPU time: other programs change it little)"
set ylabel "samples per CPU-second (millions)"
set yrange [0:*]
plot data using 1:($5/1e6) skip 1 with linespoints pt 7 lw 2 lc rgb "#1b9e77"

set title "error at equal CPU time"
set ylabel "relative RMSE"
set logscale y
set yrange [*:*]
plot data using 1:9 skip 1 with linespoints pt 7 lw 2 lc rgb "#d95f02"

set title "efficiency (higher is better)"
set ylabel "1 / (relative MSE x CPU seconds)"
plot data using 1:10 skip 1 with linespoints pt 7 lw 2 lc rgb "#7570b3"

unset multiplot
