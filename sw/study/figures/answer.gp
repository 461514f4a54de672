# The answer's time or energy a frame against N: a line per board
# configuration that is the fastest at some N, the fastest software's thick
# black line, and the last n_marks series each a crossover: a dotted
# vertical line (two points, the plot's bottom and top) with its N written
# at the top (a clause of its own only when there is one: gnuplot evaluates
# an empty iteration's first title).
marks = n_marks > 0 ? ", for [i=n_series-n_marks+1:n_series] $series index (i-1) using 1:2 with lines " . \
                      "lc rgb '#000000' dt 3 lw 2 title series_title[i], " . \
                      "for [i=n_series-n_marks+1:n_series] $series index (i-1) using 4:5:3 with labels left " . \
                      "offset char 0.6, -0.9 notitle" : ""
plot for [i=1:n_series-n_marks] $series index (i-1) using 1:2 with linespoints @series_style title series_title[i] @marks
