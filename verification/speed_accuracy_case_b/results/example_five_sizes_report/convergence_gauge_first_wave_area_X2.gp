# Written by `lituya post`; edit and re-run in this folder: gnuplot convergence_gauge_first_wave_area_X2.gp
set terminal pngcairo size 900,600 noenhanced
set output 'convergence_gauge_first_wave_area_X2.png'
set datafile separator ','
set title 'gauge_first_wave_area:X2 against the cell size'
set xlabel 'cell size (m)'
set ylabel 'gauge_first_wave_area:X2 (m s)'
set grid
set key below
set offsets graph 0.02, graph 0.02, graph 0.05, 0
plot \
  'sweep.csv' skip 1 using 2:($7) with points pt 7 ps 1.2 lt 1 title 'each run', \
  'convergence_means.csv' skip 1 using 1:($5) with lines lw 2 lt 2 title 'mean of the runs of a size', \
  'convergence_means.csv' skip 1 using 1:($10) with points pt 7 ps 1.2 lt 3 title 'Richardson extrapolation (monotone, order at most 3)'
