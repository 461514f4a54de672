# What a narrower number format buys and costs, in two panels over the
# variants (x: their places, named by x_ticks): above, the lanes that fit
# (series on axis 1, integers); below, the extra pairs in % of the float32
# reference (axis 2, y2_*: a log axis whose bottom row, under zero_line, is 0 %).
set multiplot layout 2, 1
set xlabel ""
set ytics nomirror
plot for [i=1:n_series] $series index (i-1) using 1:(series_axis[i] == 1 ? $2 : NaN) with linespoints \
         @series_style title (series_axis[i] == 1 ? series_title[i] : "")
# The title was the upper panel's.
unset label 1000
set tmargin 1
set xlabel x_label offset 0, 0.4
set ylabel y2_label
unset logscale y
if (y2_log) set logscale y
set yrange [*:*]
if (exists("y2_min")) set yrange [y2_min:]
if (exists("y2_max")) set yrange [:y2_max]
if (exists("y2_ticks")) eval "set ytics ".y2_ticks
# The zero row sits under zero_line, apart from the log axis above it.
set arrow 1 from graph 0, first zero_line to graph 1, first zero_line nohead lc rgb "#909090" dt 3
plot for [i=1:n_series] $series index (i-1) using 1:(series_axis[i] == 2 ? $2 : NaN) with linespoints \
         @series_style title (series_axis[i] == 2 ? series_title[i] : "")
unset multiplot
