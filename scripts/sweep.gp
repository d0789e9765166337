# make sweep's plot (scripts/sweep.py): samples per CPU-second, noise of one sample and efficiency
# (per CPU-second) against one lab parameter, the student's render beside the handout's figures of the reference solution.
# Variables (gnuplot -e): data (sweep.csv), handout (handout.csv, or '' when there is none), out
# (PNG), width and height (its pixels), title, xlabel, yours (the key of this render's line),
# pixels ("256x256"), xmin, xmax, logx (1: a logarithmic x axis, for the Phong exponent).
# Both CSVs start with the same columns: the parameter, samples_per_cpu_second, rays_per_sample,
# noise_per_sample, efficiency.
set terminal pngcairo size width,height font "sans,11"
set output out
set datafile separator ","
set key top right
set xlabel xlabel
set xrange [xmin:xmax]
if (logx) { set logscale x }
set grid lc rgb "#dddddd"
set multiplot layout 1,3 title title

# yours: set by sweep.py ("yours", or "the reference solution here" for --solution)
theirs = "handout (reference solution, its machine)"

set title "speed (by CPU time: other programs change it little)"
set ylabel "samples per CPU-second"
set yrange [0:*]
if (strlen(handout) > 0) {
    plot data using 1:2 skip 1 with linespoints pt 7 lw 2 lc rgb "#1b9e77" title yours, \
         handout using 1:2 skip 1 with linespoints pt 6 lw 1 dt 2 lc rgb "#666666" title theirs
} else {
    plot data using 1:2 skip 1 with linespoints pt 7 lw 2 lc rgb "#1b9e77" title yours
}

set title "noise of one sample (noise x sqrt(spp))"
set ylabel "relative standard deviation"
set logscale y
set yrange [*:*]
if (strlen(handout) > 0) {
    plot data using 1:4 skip 1 with linespoints pt 7 lw 2 lc rgb "#d95f02" title yours, \
         handout using 1:4 skip 1 with linespoints pt 6 lw 1 dt 2 lc rgb "#666666" title theirs
} else {
    plot data using 1:4 skip 1 with linespoints pt 7 lw 2 lc rgb "#d95f02" title yours
}

set title "efficiency (higher is better)"
set key bottom right
set ylabel "1 / (noise^2 x CPU seconds) at ".pixels
if (strlen(handout) > 0) {
    plot data using 1:5 skip 1 with linespoints pt 7 lw 2 lc rgb "#7570b3" title yours, \
         handout using 1:5 skip 1 with linespoints pt 6 lw 1 dt 2 lc rgb "#666666" title theirs
} else {
    plot data using 1:5 skip 1 with linespoints pt 7 lw 2 lc rgb "#7570b3" title yours
}

unset multiplot
