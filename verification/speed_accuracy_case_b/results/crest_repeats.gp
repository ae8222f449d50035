# Case B's first crests against the cell size, both slopes, each size run 3-6 times with the
# release's Courant number changed in its fourth digit: every run (small points) and the mean
# with one standard deviation (error bars). Data: crest_repeats.csv, crest_repeats_means.csv.
# Run in this folder: gnuplot crest_repeats.gp
set terminal pngcairo size 1000,450 font ",10"
set output "crest_repeats.png"
set datafile separator ","
set multiplot layout 1,2
set xlabel "cell size h (m)"
set ylabel "first crest (mm)"
set xrange [0.006:0.016]
set yrange [36:54]
set grid
set key bottom right
do for [g=1:2] {
  col = (g == 1) ? 5 : 6
  mcol = (g == 1) ? 4 : 6
  set title sprintf("gauge X%d", g)
  plot "crest_repeats.csv" skip 1 using ($2):(strcol(1) eq "fixed" ? column(col) : 1/0) \
         with points pt 7 ps 0.5 lc rgb "#1f77b4" notitle, \
       "crest_repeats_means.csv" skip 1 using ($2):(strcol(1) eq "fixed" ? column(mcol) : 1/0):(column(mcol+1)) \
         with yerrorlines lw 2 pt 5 lc rgb "#1f77b4" title "fixed slope (examples/case\\_b\\_2d)", \
       "crest_repeats.csv" skip 1 using ($2):(strcol(1) eq "contact" ? column(col) : 1/0) \
         with points pt 7 ps 0.5 lc rgb "#d62728" notitle, \
       "crest_repeats_means.csv" skip 1 using ($2):(strcol(1) eq "contact" ? column(mcol) : 1/0):(column(mcol+1)) \
         with yerrorlines lw 2 pt 9 lc rgb "#d62728" title "contact slope, mu = sin 15 deg"
}
unset multiplot
