# The crossover N of each communication strategy against each baseline, one panel a preset
# (scripts/communication.sh: gnuplot -e "data='...dat'; out='...png'").
set terminal pngcairo size 1300,560 font "sans,10"
set output out
set multiplot layout 1,2 title "Smallest N at which the board beats software, by communication strategy (upload / pair format / interrupts; a tenth of the spheres move; no bar: none up to N = 750)"
set style data histograms
set style histogram clustered gap 1
set style fill solid 0.85 border -1
set boxwidth 0.9
set xtics rotate by -50 scale 0 font ",8"
set ylabel "crossover N (boxes)"
set grid ytics
set key top left
set yrange [0:*]
set title "adm-xrc-ii (the paper's board: PCI 32-bit/33 MHz)"
plot data index 0 using 2:xtic(1) title columnheader(2), '' index 0 using 3 title columnheader(3), \
     '' index 0 using 4 title columnheader(4), '' index 0 using 5 title columnheader(5)
set title "pcie-gen3-x8 (present-day what-if)"
plot data index 1 using 2:xtic(1) title columnheader(2), '' index 1 using 3 title columnheader(3), \
     '' index 1 using 4 title columnheader(4), '' index 1 using 5 title columnheader(5)
unset multiplot
