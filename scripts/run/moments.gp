# moments.gp -- moments.png (kurtosis of v_x with its standard error, and the L1 distance
# of the speeds from MB, against time) and speed_histogram.png (final speeds against
# Maxwell-Boltzmann and the first Sonine density). A granular run (granular = 1) also gets
# cooling.png: T / T0 against Haff's law on log axes, and a2 against its first Sonine value;
# its histogram is drawn on a log scale, where the tails differ.
set output 'moments.png'
set multiplot layout 2,1 title run_title
set xlabel 'time'
set ylabel 'kurtosis of v_x (MB: 3)'
set offsets 0, 0, graph 0.1, graph 0.1  # the MB line never on the frame
set key top right opaque box
plot 'moments.csv' using 'time':'kurtosis_x':'kurtosis_x_err' with yerrorbars pt 7 ps 0.4 \
       title 'kurtosis of v_x +- standard error', \
     '' using 'time':'kurtosis_x' with lines lc 1 notitle, \
     3 with lines dt 2 lw 2 lc 'black' title 'Maxwell-Boltzmann'
set offsets 0, 0, 0, 0
set ylabel 'L1 distance of speeds from MB'
set logscale y
plot 'moments.csv' using 'time':'l1_speed' with linespoints title 'L1'
unset logscale y
unset multiplot
set key noopaque nobox
if (granular) {
  set output 'cooling.png'
  set multiplot layout 2,1 title run_title
  stats 'moments.csv' using 'T' every ::0::0 nooutput
  T0 = STATS_min
  set xlabel sprintf('real time (%s)', time_unit)
  set ylabel 'T / T0'
  set logscale xy
  plot 'moments.csv' using (column('real_time') > 0 ? column('real_time') : 1/0):(column('T')/T0) \
         with points pt 7 ps 0.5 title 'simulation', \
       (x > haff_from ? 1/(1 + (x - haff_from)/haff_t0)**2 : 1/0) with lines lw 2 \
         title sprintf("Haff's law, t0 = %.4g", haff_t0)
  unset logscale xy
  set ylabel 'a2 (Sonine cumulant)'
  set key bottom right
  plot 'moments.csv' using 'real_time':'a2' with linespoints pt 7 ps 0.4 title 'a2', \
       a2_sonine with lines dt 2 lw 2 lc 'black' title sprintf('first Sonine %.4g', a2_sonine)
  unset multiplot
  set key top right
}
set output 'speed_histogram.png'
set title run_title
set xlabel 'speed'
set ylabel 'probability density'
if (granular) {
  set logscale y
  plot 'speed_histogram.csv' using (($1+$2)/2):'density' with histeps title 'simulation', \
       '' using (($1+$2)/2):'maxwell_density' with lines title 'Maxwell-Boltzmann', \
       '' using (($1+$2)/2):'sonine_density' with lines dt 2 title 'first Sonine'
  unset logscale y
} else {
  plot 'speed_histogram.csv' using (($1+$2)/2):'density' with histeps title 'simulation', \
       '' using (($1+$2)/2):'maxwell_density' with lines title 'Maxwell-Boltzmann'
}
unset title
