# Case B at h = 0.015 m: the gauge records of six runs per mesh whose release Courant numbers
# differ by at most 1e-3 (0.5 ... 0.4995). Data: crossed_scatter_gauges.csv (README.md,
# "Crossed meshes: X1's first crest is chaotic"). Run: gnuplot crossed_scatter_gauges.gp
set datafile separator ","
set terminal pngcairo size 1100,800 font ",11"
set output "crossed_scatter_gauges.png"
set multiplot layout 2,1 title "Case B, h = 0.015 m: six runs per mesh, Courant 0.5 to 0.4995"
set xrange [0.2:0.9]
set xlabel "time (s)"
set ylabel "surface elevation (mm)"
set grid
set key top left
set title "gauge X1"
plot for [c=2:7] "crossed_scatter_gauges.csv" every ::1 using 1:(1000*column(c)) with lines lc rgb "#1f77b4" title (c == 2 ? "plain" : ""), \
     for [c=8:13] "" every ::1 using 1:(1000*column(c)) with lines lc rgb "#d62728" title (c == 8 ? "crossed" : "")
set title "gauge X2"
plot for [c=14:19] "crossed_scatter_gauges.csv" every ::1 using 1:(1000*column(c)) with lines lc rgb "#1f77b4" title (c == 14 ? "plain" : ""), \
     for [c=20:25] "" every ::1 using 1:(1000*column(c)) with lines lc rgb "#d62728" title (c == 20 ? "crossed" : "")
unset multiplot
