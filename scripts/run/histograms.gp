# histograms.gp -- speed_histograms.png (--histogram-every): the speed histograms of the
# chosen instants on a log scale, coloured by time, and the Maxwell-Boltzmann density of
# the last one.
set output 'speed_histograms.png'
set title run_title
set xlabel 'speed'
set ylabel 'density'
set logscale y
set cblabel 'time'
stats 'speed_histograms.csv' using 'time' nooutput
t_last = STATS_max
plot 'speed_histograms.csv' using (0.5 * (column('lo') + column('hi'))):\
       (column('density') > 0 ? column('density') : 1/0):'time' \
       with points pt 7 ps 0.5 lc palette title 'histograms', \
     '' using (column('time') == t_last ? 0.5 * (column('lo') + column('hi')) : 1/0):\
       'maxwell_density' with lines dt 2 lw 2 lc 'black' title 'Maxwell-Boltzmann, last time'
unset logscale y
unset title
