# conservation.gp -- conservation.png: the energy's relative change and the momentum's drift
# against the first sampling instant (conservation.csv) on a log axis, floored at 1e-18 so
# that the first row's exact zero is drawn: round-off grows as a random walk from there.
set output 'conservation.png'
set xlabel 'time'
set ylabel 'relative change'
set logscale y
set format y '10^{%L}'
plot 'conservation.csv' using 'time':(abs(column('energy_rel_change')) + 1e-18) \
       with linespoints title '|E - E_1| / E_1', \
     '' using 'time':(column('momentum_drift') + 1e-18) with linespoints \
       title '|P - P_1| / sum m|v|'
unset logscale y
set format y
