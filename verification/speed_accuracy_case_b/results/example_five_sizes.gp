# examples/case_b_2d's first crests against the cell size (stop 49, the grains taking a wall's
# velocity): every run (small points) and the mean of the runs with one standard deviation.
# Data: example_five_sizes_runs.csv (one row per run), example_five_sizes_means.csv.
# Run in this folder: gnuplot example_five_sizes.gp
set terminal pngcairo size 1000,450 font ",10"
set output "example_five_sizes.png"
set datafile separator ","
set multiplot layout 1,2
set xlabel "cell size h (m)"
set ylabel "first crest (mm)"
set xrange [0.003:0.022]
set yrange [36:54]
set grid
set key bottom right
do for [g=1:2] {
  col = (g == 1) ? 4 : 5
  mcol = (g == 1) ? 3 : 5
  set title sprintf("gauge X%d", g)
  plot "example_five_sizes_runs.csv" skip 1 using 2:(1000 * column(col)) \
         with points pt 7 ps 0.6 lc rgb "#d62728" title "runs", \
       "example_five_sizes_means.csv" skip 1 using 1:(column(mcol)):(column(mcol + 1)) \
         with yerrorlines lw 2 pt 9 lc rgb "#d62728" title "mean, one sd"
}
unset multiplot
