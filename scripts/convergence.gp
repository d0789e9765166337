# make convergence's plot (scripts/convergence.py): relative RMSE against CPU time of rendering,
# log-log, one curve per lab, the handout's curves of the reference solutions beside them, dashed,
# and the slope -1/2 line. CPU time (the render threads', summed over them) because other programs
# on the machine change it little, where they stretch the wall clock's seconds several-fold.
# Variables (gnuplot -e): data (convergence.csv), handout (handout.csv, or ''), out (PNG), width
# and height (its pixels), title, yours (whose labs), guide (k of k/sqrt(t)).
# Both CSVs have the columns lab, label, reference, spp, cpu_seconds, cpu_seconds_256 (6),
# samples_per_cpu_second, relative_rmse (8), ...
set terminal pngcairo size width,height font "sans,11"
set output out
set datafile separator ","
set key inside top right opaque box font "sans,9"
set logscale xy
set xlabel "CPU time of rendering (s, summed over the render threads), scaled to 256x256 pixels"
set ylabel "relative RMSE: RMSE / the reference's mean radiance"
set grid xtics ytics mxtics mytics lc rgb "#dddddd"
set title title."\n(labs 1-3 against the depth-limited image, lab 4 against the unbiased one; dashed: the handout)" font "sans,11"

# Rows of one lab; the others become undefined and are skipped.
row(name, column) = (strcol(1) eq name) ? column(column) : NaN
labs = "branching uniform importance roulette"
# The handout figure's colours for the same labs (lab 4 at continueProb 0.8 is its green).
colours = "#1b9e77 #d95f02 #7570b3 #66a61e"
name(i) = i == 1 ? "branching (lab 1)" : i == 2 ? "uniform pick (lab 2)" : \
          i == 3 ? "importance pick (lab 3)" : "roulette, continueProb 0.8 (lab 4)"

if (strlen(handout) > 0) {
    plot guide / sqrt(x) with lines dashtype 3 lw 1 lc rgb "#444444" title "slope -1/2: error proportional to 1/sqrt(t)", \
         for [i=1:4] data using (row(word(labs, i), 6)):(row(word(labs, i), 8)) skip 1 \
             with linespoints pt 7 lw 2 lc rgb word(colours, i) title name(i).", ".yours, \
         for [i=1:4] handout using (row(word(labs, i), 6)):(row(word(labs, i), 8)) skip 1 \
             with linespoints pt 6 lw 1 dt 2 lc rgb word(colours, i) title name(i).", handout"
} else {
    plot guide / sqrt(x) with lines dashtype 3 lw 1 lc rgb "#444444" title "slope -1/2: error proportional to 1/sqrt(t)", \
         for [i=1:4] data using (row(word(labs, i), 6)):(row(word(labs, i), 8)) skip 1 \
             with linespoints pt 7 lw 2 lc rgb word(colours, i) title name(i).", ".yours
}
