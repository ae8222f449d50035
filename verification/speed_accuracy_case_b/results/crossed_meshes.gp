# Case B (contact slope, N = 4): the first crests and the beads' peak kinetic energy against
# the cell size, on gmsh's triangles (plain) and on crossed meshes ([mesh] crossed = true).
# Data: crossed_meshes.csv (README.md of this case, "Crossed meshes", says how it was made).
# Re-draw: gnuplot crossed_meshes.gp
set terminal pngcairo size 1200,520 noenhanced
set output 'crossed_meshes.png'
set datafile separator ','
set multiplot layout 1,2 title 'Case B: plain triangles against crossed meshes (each quadrangle cut into four), 4 points per cell'
set grid
set xlabel 'cell size h (m)'
set xrange [0.0065:0.032]
sel(mesh, col) = (strcol(2) eq mesh) ? column(col) : NaN
set key bottom left font ',9'
set ylabel 'first crest (mm)'
set title 'first crest at X1 and X2'
plot 'crossed_meshes.csv' skip 1 using 1:(sel('plain', 3)) with linespoints lw 2 pt 7 lc 1 title 'X1, plain', \
     'crossed_meshes.csv' skip 1 using 1:(sel('plain', 4)) with linespoints lw 2 pt 5 dt 2 lc 1 title 'X2, plain', \
     'crossed_meshes.csv' skip 1 using 1:(sel('crossed', 3)) with linespoints lw 2 pt 7 lc 2 title 'X1, crossed', \
     'crossed_meshes.csv' skip 1 using 1:(sel('crossed', 4)) with linespoints lw 2 pt 5 dt 2 lc 2 title 'X2, crossed'
set key bottom right
set yrange [2:3.6]
set ylabel 'peak kinetic energy of the beads (J/m)'
set title 'the slide (crossed at 0.03 m: 11.8 J/m, a burst, off scale)'
plot 'crossed_meshes.csv' skip 1 using 1:(sel('plain', 7)) with linespoints lw 2 pt 7 lc 1 title 'plain', \
     'crossed_meshes.csv' skip 1 using 1:(sel('crossed', 7)) with linespoints lw 2 pt 7 lc 2 title 'crossed'
unset multiplot
