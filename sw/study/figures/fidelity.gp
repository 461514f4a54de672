# Simulator cost against timing error, a point per modelling level. Each label
# sits where cdvp placed it (label_x, label_y) so that no two meet, joined to
# its point by a leader: levels with the same error and nearly the same cost
# would otherwise hide one another.
set clip two
unset clip points
plot for [i=1:n_series] $series index (i-1) using 1:2:($4 - $1):($5 - $2) with vectors nohead \
         lc rgb series_lc(i) lw 0.8 notitle, \
     for [i=1:n_series] $series index (i-1) using 1:2 with points lc rgb series_lc(i) pt series_pt(i) ps 2 title series_title[i], \
     for [i=1:n_series] $series index (i-1) using 4:5:3 with labels left offset char 0.6,0 \
         textcolor rgb series_lc(i) notitle
