# Written by `lituya verify --case speed_accuracy`; re-run here: gnuplot speed_accuracy.gp
set terminal pngcairo size 1000,650 noenhanced
set output 'speed_accuracy.png'
set datafile separator ','
set logscale xy
set grid
set key below
set title 'Dam break: RMS depth error against Ritter (t = 0.4 s) vs wall time'."\n".'one knob changed at a time from cell_size=0.02_points_per_cell=4_courant=0.5_bulk_modulus=2.15e7'
set xlabel 'wall time of the solve, one thread (s)'
set ylabel 'RMS depth error / H'
set yrange [0.0376489:0.11]
set ytics (0.0001, 0.0002, 0.0005, 0.001, 0.002, 0.005, 0.01, 0.02, 0.03, 0.04, 0.05, 0.06, 0.07, 0.08, 0.1, 0.12, 0.15, 0.2, 0.3, 0.5, 1)
set arrow from graph 0, first 0.05 to graph 1, first 0.05 nohead dt 2 lc rgb 'gray40'
set arrow from graph 0, first 0.1 to graph 1, first 0.1 nohead dt 2 lc rgb 'gray40'
plot \
  'knob_cell_size.csv' skip 1 using 2:3 with linespoints lw 2 pt 7 lt 1 title 'cell size h (m)', \
  'knob_cell_size.csv' skip 1 using 2:3:(sprintf('%.3g', $1)) with labels offset 0,0.8 tc lt 1 font ',8' notitle, \
  'knob_points_per_cell.csv' skip 1 using 2:3 with linespoints lw 2 pt 7 lt 2 title 'points per cell', \
  'knob_points_per_cell.csv' skip 1 using 2:3:(sprintf('%.3g', $1)) with labels offset 0,0.8 tc lt 2 font ',8' notitle, \
  'knob_courant.csv' skip 1 using 2:3 with linespoints lw 2 pt 7 lt 3 title 'Courant number', \
  'knob_courant.csv' skip 1 using 2:3:(sprintf('%.3g', $1)) with labels offset 0,0.8 tc lt 3 font ',8' notitle, \
  'knob_bulk_modulus.csv' skip 1 using 2:3 with linespoints lw 2 pt 7 lt 4 title 'water bulk modulus (Pa)', \
  'knob_bulk_modulus.csv' skip 1 using 2:3:(sprintf('%.3g', $1)) with labels offset 0,0.8 tc lt 4 font ',8' notitle, \
  'knob_combined.csv' skip 1 using 2:3 with linespoints lw 2 pt 7 lc rgb 'black' title 'combined (each knob at its cheapest)', \
  'knob_combined.csv' skip 1 using 2:3:(sprintf('<= %.3g', $1)) with labels offset 0,0.8 tc rgb 'black' font ',8' notitle
