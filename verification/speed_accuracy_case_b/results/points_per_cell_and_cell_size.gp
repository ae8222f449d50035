# Case B (contact slope): first crest and first-wave area at X1 and X2 against the cell size,
# for 4, 9 and 16 points per cell, the pressure projection at its default.
# Data: points_per_cell_and_cell_size.csv (README.md of this case says how it was made).
# Re-draw: gnuplot points_per_cell_and_cell_size.gp
set terminal pngcairo size 1200,520 noenhanced
set output 'points_per_cell_and_cell_size.png'
set datafile separator ','
set multiplot layout 1,2 title 'Case B on a Coulomb slope: the first wave against the cell size h, for N points per cell (projection at its default)'
set grid
set key bottom left font ',9'
set xlabel 'cell size h (m)'
set xrange [0.0065:0.032]
sel(n, col) = (strcol(3) eq 'default' && $2 == n) ? column(col) : NaN
set ylabel 'first crest (mm)'
set title 'first crest'
plot for [n in '4 9 16'] 'points_per_cell_and_cell_size.csv' skip 1 using 1:(sel(n+0, 4)) with linespoints lw 2 pt 7 lc (n == '4' ? 1 : n == '9' ? 2 : 3) title 'X1, N = '.n, \
     for [n in '4 9 16'] 'points_per_cell_and_cell_size.csv' skip 1 using 1:(sel(n+0, 5)) with linespoints lw 2 pt 5 dt 2 lc (n == '4' ? 1 : n == '9' ? 2 : 3) title 'X2, N = '.n
set key bottom right
set ylabel 'first-wave area (mm s)'
set title 'first-wave area (the integral of eta over the first wave)'
plot for [n in '4 9 16'] 'points_per_cell_and_cell_size.csv' skip 1 using 1:(sel(n+0, 6)) with linespoints lw 2 pt 7 lc (n == '4' ? 1 : n == '9' ? 2 : 3) title 'X1, N = '.n, \
     for [n in '4 9 16'] 'points_per_cell_and_cell_size.csv' skip 1 using 1:(sel(n+0, 7)) with linespoints lw 2 pt 5 dt 2 lc (n == '4' ? 1 : n == '9' ? 2 : 3) title 'X2, N = '.n
unset multiplot
