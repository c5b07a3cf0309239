# shear.gp -- rheology.png (--shear-rate): from pressure_tensor.csv against real time (the
# unit of the shear rate), the reduced shear stress -P_xy/p (with its standard error over
# the particles where the rows have one: DSMC), the normal stress differences
# (P_xx - P_yy)/p and, for D >= 3, (P_yy - P_zz)/p, and T/T0 on a log scale. The black
# lines are the steady state's means, drawn over its rows (time >= shear_from, the second
# half of the run): the summary's shear_stress and the differences of its normal stresses.
# The command sets before it: shear_dim, shear_errors (1: the _err columns are filled),
# shear_time_unit, shear_from, shear_stress, shear_n1, shear_n2 (NaN: no steady state).
set output 'rheology.png'
set multiplot layout 3,1 title run_title
set xlabel sprintf('real time (%s)', shear_time_unit)
set key top right opaque box
set ylabel '-P_{xy} / p'
plot 'pressure_tensor.csv' \
       using 'real_time':(-column('P_xy')):(shear_errors ? column('P_xy_err') : 0) \
       with yerrorbars pt 7 ps 0.4 lc 1 \
       title (shear_errors ? '-P_{xy}/p +- standard error' : '-P_{xy}/p'), \
     '' using 'real_time':(-column('P_xy')) with lines lc 1 notitle, \
     '' using 'real_time':(column('time') >= shear_from ? -shear_stress : 1/0) \
       with lines lw 2 lc 'black' title sprintf('steady state %.4g', -shear_stress)
set ylabel 'normal stress differences'
plot 'pressure_tensor.csv' using 'real_time':((column('P_xx') - column('P_yy'))) \
       with linespoints pt 7 ps 0.4 lc 2 title '(P_{xx} - P_{yy})/p', \
     '' using 'real_time':(shear_dim >= 3 ? column('P_yy') - column('P_zz') : 1/0) \
       with linespoints pt 7 ps 0.4 lc 3 title (shear_dim >= 3 ? '(P_{yy} - P_{zz})/p' : ''), \
     '' using 'real_time':(column('time') >= shear_from ? shear_n1 : 1/0) \
       with lines lw 2 lc 'black' title 'steady state', \
     '' using 'real_time':(column('time') >= shear_from ? shear_n2 : 1/0) \
       with lines lw 2 lc 'black' notitle
set ylabel 'T / T0'
set logscale y
plot 'pressure_tensor.csv' using 'real_time':'temperature_ratio' with linespoints pt 7 \
       ps 0.4 lc 4 title 'T/T0 (peculiar velocities)'
unset logscale y
unset multiplot
set key noopaque nobox
