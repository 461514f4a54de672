# Speedup against N, a line per board series, and break-even (reference_y);
# the last n_marks series ring the points whose software timing was disturbed
# (a clause of their own only when there are any: gnuplot evaluates an empty
# iteration's first title).
marks = n_marks > 0 ? "for [i=n_series-n_marks+1:n_series] $series index (i-1) using 1:2 with points ".mark_style. \
                      " title series_title[i], " : ""
plot for [i=1:n_series-n_marks] $series index (i-1) using 1:2 with linespoints @series_style title series_title[i], \
     @marks reference_y with lines lc rgb "black" dt 3 lw 1.5 title "break-even (1x)"
