# The convergence plot: relative RMSE against the reference versus CPU time of rendering, one
# curve per estimator. CPU time is the render threads' (--stats' cpu_seconds), summed over them:
# other programs on the machine change it little, where they stretch the wall clock's seconds.
# Variables (gnuplot -e): data (convergence.csv), out (PNG), bias (the depth limit's relative
# RMSE), guide (k of the k/sqrt(t) line), threads (the render threads).
# Columns: estimator (1), label, reference, budget_cpu_seconds, spp, cpu_seconds (6), seconds,
# samples_per_cpu_second, samples_per_second, rays_per_sample, noise, noise_per_sample,
# relative_rmse (13), ...
set terminal pngcairo size 900,640 font "sans,11"
set output out
set datafile separator ","
set key inside bottom left opaque box font "sans,10"
set logscale xy
set xrange [0.1:40]
set yrange [1e-3:30]
set xlabel sprintf("CPU time of rendering (s, summed over %d render threads), 256x256 pixels", threads)
set ylabel "relative RMSE: RMSE / the reference's mean radiance"
set grid xtics ytics mxtics mytics lc rgb "#dddddd"
set title "VI2 Cornell box: error versus CPU time\n(labs 1-3 against the depth-limited image, lab 4 against the unbiased one)" font "sans,11"

# Rows of one estimator; the others become undefined and are skipped.
row(name, column) = (strcol(1) eq name) ? column(column) : NaN

plot bias with lines dashtype 2 lw 2 lc rgb "#888888" title "bias of maxDepth 3 (labs 1-3 against the unbiased image)", \
     guide / sqrt(x) with lines dashtype 3 lw 1 lc rgb "#444444" title "slope -1/2: error proportional to 1/sqrt(t)", \
     data using (row("branching", 6)):(row("branching", 13)) with linespoints pt 7 lw 2 lc rgb "#1b9e77" title "branching (lab 1)", \
     data using (row("uniform", 6)):(row("uniform", 13)) with linespoints pt 5 lw 2 lc rgb "#d95f02" title "uniform pick (lab 2)", \
     data using (row("importance", 6)):(row("importance", 13)) with linespoints pt 9 lw 2 lc rgb "#7570b3" title "importance pick (lab 3)", \
     data using (row("roulette", 6)):(row("roulette", 13)) with linespoints pt 11 lw 2 lc rgb "#e7298a" title "roulette, continueProb 0.1 (lab 4)", \
     data using (row("roulette_p08", 6)):(row("roulette_p08", 13)) with linespoints pt 13 lw 2 lc rgb "#66a61e" title "roulette, continueProb 0.8 (lab 4)"
