# Crossover N against m: a line per board and variant, each point labelled
# with its N ("<= N" where the board already wins at the sweep's smallest N)
# where cdvp placed the label, above or below the point.
plot for [i=1:n_series] $series index (i-1) using 1:2 with linespoints @series_style title series_title[i], \
     for [i=1:n_series] $series index (i-1) using 4:5:3 with labels center textcolor rgb series_lc(i) notitle
