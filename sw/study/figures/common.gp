# What every figure of cdvp shares: the terminal, the palettes, the title and
# the axes. cdvp compiles these files in (sw/study/figures/*.gp) and writes,
# before this one, the figure's values:
#   output_path, width, height, title_text (lines joined by \n), title_lines,
#   key_beside (1: the key in a column right of the plot, 0: under it)
#   for each axis A of x, y and y2: A_label, A_log (0 or 1) and, where the
#     figure fixes them, A_min, A_max and A_ticks ('("text" value, ...)')
#   n_series and, for series i: series_title[i], series_family[i] (1 board,
#     2 software baseline, 3 a mark: points alone, the last n_marks series), series_colour[i], series_shape[i], series_dash[i],
#     series_filled[i] (places in the palettes below), series_axis[i] (1, or
#     2 for the second y axis or panel), series_beneath[i] (how many later
#     series cover it along some stretch)
#   $series: a block per series, two blank lines apart, a line per point:
#     x y "label" label_x label_y base
# and the few numbers a figure's own template needs (it names them).
set terminal pngcairo noenhanced size width, height font 'sans,10'
set output output_path

# Okabe and Ito's colour-blind-safe palette without its yellow (unreadable
# on white), in an order whose neighbours differ in grey as well as hue.
array palette[6] = ["#0072B2", "#E69F00", "#009E73", "#D55E00", "#56B4E9", "#CC79A7"]
# Circle, square, triangle up, triangle down, diamond, pentagon: filled and open.
array shape_filled[6] = [7, 5, 9, 11, 13, 15]
array shape_open[6] = [6, 4, 8, 10, 12, 14]
# Solid, dashed, dash-dot, dash-dot-dot, dotted.
array dash_type[5] = [1, 2, 4, 5, 3]
# Software baselines: black and dark grey, thick, with dashes and shapes
# (plus, cross, star) of their own, so none looks like the board or another.
array baseline_colour[4] = ["#000000", "#505050", "#000000", "#505050"]
array baseline_shape[4] = [1, 2, 3, 1]
array baseline_dash[4] = [2, 4, 5, 3]

series_lc(i) = series_family[i] == 3 ? "#000000" : \
               series_family[i] == 2 ? baseline_colour[series_colour[i]] : palette[series_colour[i]]
series_pt(i) = series_family[i] == 3 ? 6 : series_family[i] == 2 ? baseline_shape[series_shape[i]] : \
               (series_filled[i] ? shape_filled[series_shape[i]] : shape_open[series_shape[i]])
series_dt(i) = series_family[i] == 2 ? baseline_dash[series_dash[i]] : dash_type[series_dash[i]]
series_lw(i) = (series_family[i] == 2 ? 2.5 : 1.5) + 2 * series_beneath[i]
# Use as: plot ... with linespoints @series_style title series_title[i]
series_style = "lc rgb series_lc(i) pt series_pt(i) dt series_dt(i) lw series_lw(i) ps 1.3"
# A mark (family 3) rings the point it marks, large enough to show around any series' own shape.
# Use as: plot ... with points @mark_style title series_title[i]
mark_style = "lc rgb series_lc(i) pt series_pt(i) lw 1.5 ps 2.6"

# The title across the whole picture, from its left edge: its lines are
# long (board, engine, frames, host factor) and a key beside the plot would
# push a centred title off the left edge.
set tmargin title_lines + 2
set label 1000 title_text at screen 0.012, screen 1 - 0.9 * 10.0 / height left front offset 0, -0.4
set xlabel x_label offset 0, 0.4
set ylabel y_label
if (x_log) set logscale x
if (y_log) set logscale y
if (exists("x_min")) set xrange [x_min:]
if (exists("x_max")) set xrange [:x_max]
if (exists("y_min")) set yrange [y_min:]
if (exists("y_max")) set yrange [:y_max]
if (exists("x_ticks")) eval "set xtics ".x_ticks
if (exists("y_ticks")) eval "set ytics ".y_ticks
set grid lc rgb "#d0d0d0"
# A few series read best in a key under the plot, which leaves it the whole
# width; many would leave it no height, so cdvp sets key_beside and they go
# in a column beside it.
if (key_beside) {
    set key outside right top vertical Left reverse maxcols 1 samplen 3
} else {
    set key outside below left Left reverse maxcols 3 samplen 3 height 1
}
set key spacing 1.1 width 2
