# Speedup against N, a line per board series, and break-even (reference_y).
plot for [i=1:n_series] $series index (i-1) using 1:2 with linespoints @series_style title series_title[i], \
     reference_y with lines lc rgb "black" dt 3 lw 1.5 title "break-even (1x)"
