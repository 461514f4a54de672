# Largest m against N, an integer: steps, not slopes. A step at a measured N
# drops to the next point's m at once, so each flat stretch is an m that fits
# every N up to its end (the largest m only falls as N grows). Series that
# share a stretch are drawn wider underneath (series_beneath), so each
# shows; each value is
# written above its point.
plot for [i=1:n_series] $series index (i-1) using 1:2 with fsteps lc rgb series_lc(i) \
         dt series_dt(i) lw series_lw(i) notitle, \
     for [i=1:n_series] $series index (i-1) using 1:2 with points lc rgb series_lc(i) pt series_pt(i) \
         ps (1.3 + 0.6 * series_beneath[i]) notitle, \
     for [i=1:n_series] $series index (i-1) using 1:2:3 with labels offset char 0,1 \
         textcolor rgb series_lc(i) notitle, \
     for [i=1:n_series] keyentry with linespoints @series_style title series_title[i]
