# moments.gp -- moments.png (kurtosis of v_x and L1 distance of the speeds from MB against
# time) and speed_histogram.png (final speeds against Maxwell-Boltzmann).
set output 'moments.png'
set multiplot layout 2,1
set xlabel 'time'
set ylabel 'kurtosis of v_x (MB: 3)'
plot 'moments.csv' using 'time':'kurtosis_x' with linespoints title 'kurtosis_x', \
     3 with lines dt 2 title 'Maxwell-Boltzmann'
set ylabel 'L1 distance of speeds from MB'
set logscale y
plot 'moments.csv' using 'time':'l1_speed' with linespoints title 'L1'
unset logscale y
unset multiplot
set output 'speed_histogram.png'
set xlabel 'speed'
set ylabel 'probability density'
plot 'speed_histogram.csv' using (($1+$2)/2):'density' with histeps title 'simulation', \
     '' using (($1+$2)/2):'maxwell_density' with lines title 'Maxwell-Boltzmann'
