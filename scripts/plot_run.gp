# plot_run.gp -- the plots of one `hypergas run` folder (the command runs it there, after
# setting vacf):
#   moments.png           kurtosis of v_x and L1 distance of the speeds from MB against time
#   speed_histogram.png   final speed distribution against Maxwell-Boltzmann
#   vacf.png              velocity autocorrelation (only with vacf = 1: EDMD runs)
#   transport.png         flux correlations (transport = 1: DSMC; 2: EDMD, with the running
#                         Einstein-Helfand values)
#   structure.png         g(r) and S(k) (structure = 1: EDMD --structure)
# By hand: cd RUN && gnuplot -e 'vacf = 1' plot_run.gp
# Reads the CSV files by column name (gnuplot >= 5.0).
if (!exists('vacf')) vacf = 0
if (!exists('transport')) transport = 0
if (!exists('structure')) structure = 0
set terminal pngcairo size 900,600 font ',11'
set datafile separator ','
set key autotitle columnhead
set grid
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
if (vacf) {
  set output 'vacf.png'
  set xlabel 'time (sigma sqrt(m/kT))'
  set ylabel 'VACF / VACF(0)'
  set logscale xy
  stats 'vacf.csv' using 'vacf' nooutput
  c0 = STATS_max
  plot 'vacf.csv' using 'time':(column('vacf')/c0) with linespoints title '<v(0).v(t)>', \
       '' using 'time':(column('vacf') < 0 ? -column('vacf')/c0 : 1/0) with points \
       title 'negative values (abs)'
}
if (transport == 1) {
  set output 'transport.png'
  set key top right
  set xlabel 'time (mean collision times)'
  set ylabel 'C(t) / C(0)'
  unset logscale x
  set logscale y
  set yrange [1e-3:1.2]
  plot 'correlations.csv' using 'time':'viscosity' with lines lw 2 title 'stress (viscosity)', \
       '' using 'time':'viscosity_sonine' with lines dt 2 lc 1 title 'first Sonine', \
       '' using 'time':'thermal_conductivity' with lines lw 2 title 'heat flux (conductivity)', \
       '' using 'time':'thermal_conductivity_sonine' with lines dt 2 lc 2 title 'first Sonine', \
       '' using 'time':'self_diffusion' with lines lw 2 title 'tagged velocity (self-diffusion)', \
       '' using 'time':'self_diffusion_sonine' with lines dt 2 lc 3 title 'first Sonine'
}
if (transport == 2) {
  set output 'transport.png'
  set multiplot layout 2,1
  set key top right
  set xlabel 'time (sigma sqrt(m/kT))'
  set ylabel 'C(t) / C(0)'
  unset logscale x
  set logscale y
  set yrange [1e-3:1.2]
  plot 'correlations.csv' using 'time':'viscosity' with lines lw 2 title 'stress (interval averages)', \
       '' using 'time':'thermal_conductivity' with lines lw 2 title 'heat flux (interval averages)', \
       '' using 'time':'self_diffusion' with lines lw 2 title 'tagged velocity'
  unset logscale y
  set yrange [*:*]
  set ylabel 'MSD of Helfand moment / (2 t)'
  plot 'correlations.csv' using 'time':'viscosity_helfand' with lines lw 2 title 'viscosity', \
       '' using 'time':'thermal_conductivity_helfand' with lines lw 2 title 'thermal conductivity'
  unset multiplot
}
if (structure) {
  set output 'structure.png'
  set multiplot layout 2,1
  unset logscale xy
  set yrange [*:*]
  set key top right
  set xlabel 'r / sigma'
  set ylabel 'g(r)'
  plot 'rdf.csv' using 'r':'g' with lines lw 2 title 'g(r)', 1 with lines dt 2 title ''
  set xlabel 'k sigma'
  set ylabel 'S(k)'
  plot 'structure_factor.csv' using 'k':'S':'error' with yerrorbars pt 7 ps 0.5 title 'S(k)', \
       1 with lines dt 2 title ''
  unset multiplot
}
