# The water's mean force on the beads over 0.20-0.28 s against the cell size (stop 53):
# beads of 5 cm (phases not locked by the drag) converge at first order, the example's 1.5 mm
# beads do not; the diagnostic build that frees the fringe of coupled water (fringe_both) moves
# the 1.5 mm curve towards the 5 cm one's behaviour. Run: gnuplot slide_coupling_stop53.gp
set terminal pngcairo size 900,560 font ",11"
set output "slide_coupling_stop53.png"
set datafile separator ","
set key bottom left
set xlabel "cell size h (m)"
set ylabel "water's force on the beads, 0.20-0.28 s (N/m)"
set xrange [0:0.022]
set grid
f(h) = -65.32 - 543.0 * h
plot "slide_coupling_stop53.csv" using ((strcol(1) eq "default" && $2 == 0.05) ? $3 : 1/0):9 \
       with linespoints pt 7 title "5 cm beads", \
     f(x) with lines dt 2 lc rgb "gray40" title "first-order fit of the 5 cm beads: -65.3 - 543 h", \
     "slide_coupling_stop53.csv" using ((strcol(1) eq "default" && $2 == 0.0015) ? $3 : 1/0):9 \
       with linespoints pt 5 title "1.5 mm beads (the example)", \
     "slide_coupling_stop53.csv" using ((strcol(1) eq "fringe_both") ? $3 : 1/0):9 \
       with linespoints pt 9 title "1.5 mm, fringe freed (diagnostic build)"
