# Energy a frame against N: the board (the fastest m that fits) and the software on its host, one
# panel a set-up (scripts/energy-answers.sh: gnuplot -e "data='...dat'; out='...png'").
# Means over the frames after the warm-up; both axes logarithmic, ticks at whole decades.
set terminal pngcairo size 1300,560 font "sans,10" noenhanced
set output out
set multiplot layout 1,2 title "Energy a frame: the board against the software on its host (mean of frames 2-11; below the board's line the software takes less)"
set logscale xy
set format x "%.0f"
set format y "%g"
set xlabel "N (boxes)"
set ylabel "energy a frame (mJ)"
set grid xtics ytics mxtics mytics lc rgb "#dddddd"
set key top left
set style line 1 lc rgb "#1f3a93" lw 2.5 pt 7 ps 0.8
set style line 2 lc rgb "#000000" lw 2 dt 2 pt 5 ps 0.7
set style line 3 lc rgb "#c0392b" lw 2 dt 3 pt 9 ps 0.8
set style line 4 lc rgb "#1e8449" lw 2 dt 4 pt 11 ps 0.8
stats data index 0 using 1 nooutput
set xrange [STATS_min * 0.9 : STATS_max * 1.1]
set title "2007: ADM-XRC-II on 32-bit PCI, Pentium 4 1.8 GHz (one core)"
plot data index 0 using 1:2 with linespoints ls 1 title "board (m = 11 or 24)", \
     '' index 0 using 1:3 with linespoints ls 2 title "sap (Bullet), 1 core", \
     '' index 0 using 1:4 with linespoints ls 3 title "sap_mt, 1 core (all)"
stats data index 1 using 1 nooutput
set xrange [STATS_min * 0.9 : STATS_max * 1.1]
set title "today: Alveo U250 on PCIe Gen3 x16, AMD EPYC (two cores)"
# The key under the lines, bottom right: the software's climb fills the top right.
set key bottom right
plot data index 1 using 1:2 with linespoints ls 1 title "board (m = 32)", \
     '' index 1 using 1:3 with linespoints ls 2 title "sap (Bullet), 1 core", \
     '' index 1 using 1:4 with linespoints ls 3 title "sap_mt, 1 thread", \
     '' index 1 using 1:5 with linespoints ls 4 title "sap_mt, 2 threads (all cores; wall time, loaded machine)"
unset multiplot
