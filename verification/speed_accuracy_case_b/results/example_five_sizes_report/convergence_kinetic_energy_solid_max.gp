# Written by `lituya post`; edit and re-run in this folder: gnuplot convergence_kinetic_energy_solid_max.gp
set terminal pngcairo size 900,600 noenhanced
set output 'convergence_kinetic_energy_solid_max.png'
set datafile separator ','
set title 'kinetic_energy_solid_max against the cell size'
set xlabel 'cell size (m)'
set ylabel 'kinetic_energy_solid_max (J, per m in 2D)'
set grid
set key below
set offsets graph 0.02, graph 0.02, graph 0.05, 0
plot \
  'sweep.csv' skip 1 using 2:($8) with points pt 7 ps 1.2 lt 1 title 'each run', \
  'convergence_means.csv' skip 1 using 1:($6) with lines lw 2 lt 2 title 'mean of the runs of a size', \
  'convergence_means.csv' skip 1 using 1:($11) with points pt 7 ps 1.2 lt 3 title 'Richardson extrapolation (monotone, order at most 3)'
