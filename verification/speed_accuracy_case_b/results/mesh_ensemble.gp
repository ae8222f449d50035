# Case B (examples/case_b_2d, contact slope, N = 4, defaults of 7 December 2026): ten meshes,
# five around each nominal cell size (0.98 ... 1.02 times 0.01 and 0.015 m), one run each.
# gmsh's triangulation differs from mesh to mesh; the spread at one nominal size is the
# reading's own scatter under a change of mesh topology.
# Open symbols: five gmsh seeds at exactly 0.015 and 0.01 m ([mesh] seed 1-5; seed 1 is the
# 1.00 mesh), drawn 0.0001 m to the right.
# Data: mesh_ensemble.csv, mesh_seed_ensemble.csv (README.md of this case, "A mesh ensemble", says how it was made).
# Re-draw: gnuplot mesh_ensemble.gp
set terminal pngcairo size 1200,520 noenhanced
set output 'mesh_ensemble.png'
set datafile separator ','
set multiplot layout 1,2 title 'Case B: five meshes around 0.015 m and five around 0.01 m'
set grid
set xlabel 'cell size h (m)'
set xrange [0.0093:0.0158]
set key top left font ',9'
set ylabel 'first crest (mm)'
set yrange [38:56]
set title 'first crests at X1 and X2 (lines: the means of the five sizes)'
plot 'mesh_ensemble.csv' skip 1 using 2:3 with points pt 7 ps 1.3 lc 1 title 'X1, cell size 0.98-1.02 h', \
     'mesh_ensemble.csv' skip 1 using 2:4 with points pt 5 ps 1.3 lc 2 title 'X2, cell size 0.98-1.02 h', \
     'mesh_seed_ensemble.csv' skip 1 using ($1+0.0001):3 with points pt 6 ps 1.3 lc 1 title 'X1, seeds 1-5', \
     'mesh_seed_ensemble.csv' skip 1 using ($1+0.0001):4 with points pt 4 ps 1.3 lc 2 title 'X2, seeds 1-5', \
     '-' using 1:2 with lines lw 2 lc 1 title 'X1 means (sizes)', \
     '-' using 1:2 with lines lw 2 dt 2 lc 2 title 'X2 means (sizes)'
0.0097,50.77
0.0103,50.77

0.0146,48.83
0.0154,48.83
e
0.0097,47.61
0.0103,47.61

0.0146,43.45
0.0154,43.45
e
set key top right
set yrange [2.4:2.9]
set ylabel 'peak kinetic energy of the beads (J/m)'
set title 'the slide'
plot 'mesh_ensemble.csv' skip 1 using 2:7 with points pt 7 ps 1.3 lc 3 title 'cell size 0.98-1.02 h', \
     'mesh_seed_ensemble.csv' skip 1 using ($1+0.0001):7 with points pt 6 ps 1.3 lc 3 title 'seeds 1-5'
unset multiplot
