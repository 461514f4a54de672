# Frame time against N: a line per board series (m and variant), a thick
# black or grey line per software baseline.
plot for [i=1:n_series] $series index (i-1) using 1:2 with linespoints @series_style title series_title[i]
