# The phases of a frame as stacked shares of it, a bar per point: a series
# per phase, a point per bar (x: the bar's place; from base to y: its share).
# Each bar's tick names its N, m and variant and gives the whole frame's time.
set xtics rotate by 90 right font ",8" nomirror
set ytics nomirror
set grid noxtics ytics
set style fill solid 0.9 border lc rgb "#303030"
plot for [i=1:n_series] $series index (i-1) using 1:2:($1 - 0.4):($1 + 0.4):6:2 with boxxyerror \
         lc rgb series_lc(i) title series_title[i]
