# First crest along the flume, Case B (examples/case_b_2d), stop 54:
# gnuplot crests_along_flume_stop54.gp  ->  crests_along_flume_stop54.png
set terminal pngcairo size 900,560
set output 'crests_along_flume_stop54.png'
set datafile separator ' '
set xlabel 'gauge position x (m); X1 = 0.3, X2 = 0.6'
set ylabel 'first crest (mm): mean, bars the range of the runs'
set key top right
set grid
set xrange [0.1:1.1]
labels = "'plain 0.015 m' 'plain 0.01 m' 'plain, 0.01 m at the impact, 0.015 m beyond' 'plain, 0.015 m at the impact, 0.01 m beyond' 'crossed 0.015 m' 'crossed 0.01 m'"
plot for [i=0:5] 'crests_along_flume_stop54.dat' index i using 1:2:3:4 with yerrorlines lw 2 title word(labels, i+1)
