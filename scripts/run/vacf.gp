# vacf.gp -- vacf.png: the velocity autocorrelation on log axes (EDMD).
set output 'vacf.png'
set xlabel 'time (sigma sqrt(m/kT))'
set ylabel 'VACF / VACF(0)'
set logscale xy
stats 'vacf.csv' using 'vacf' nooutput
c0 = STATS_max
plot 'vacf.csv' using 'time':(column('vacf')/c0) with linespoints title '<v(0).v(t)>', \
     '' using 'time':(column('vacf') < 0 ? -column('vacf')/c0 : 1/0) with points \
     title 'negative values (abs)'
unset logscale xy
