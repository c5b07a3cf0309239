# plot_scene.gp -- the plots of the default scene (`hypergas` without a subcommand; the
# command runs it in its folder, after setting dims and threshold):
#   relaxation.png         L1 distance of the speed histogram from MB against collisions per
#                          particle, one line per D, and the stated threshold
#   kurtosis.png           kurtosis of v_x against collisions per particle
#   speed_histograms.png   final speed distribution against MB, one panel per D
# dims lists the dimensions with files relaxation_D<d>.csv and speed_histogram_D<d>.csv.
# By hand: cd results && gnuplot -e 'dims = "1 2 3 4 5 6"; threshold = 0.05' plot_scene.gp
# Reads the CSV files by column name (gnuplot >= 5.0).
if (!exists('dims')) dims = '1 2 3 4 5 6'
if (!exists('threshold')) threshold = 0.05
set terminal pngcairo size 900,600 font ',11'
set datafile separator ','
set key autotitle columnhead
set grid
set output 'relaxation.png'
set title 'Relaxation to Maxwell-Boltzmann: L1 distance of the speed histogram'
set xlabel 'collisions per particle'
set ylabel 'L1 distance from MB'
set logscale y
plot for [d in dims] sprintf('relaxation_D%s.csv', d) \
       using 'collisions_per_particle':'l1_speed' with lines lw 2 title 'D = '.d, \
     threshold with lines dt 2 lc 'black' title sprintf('threshold %g', threshold)
unset logscale y
set output 'kurtosis.png'
set title 'Kurtosis of v_x (Maxwell-Boltzmann: 3)'
set ylabel 'kurtosis'
set key outside right top  # beside the curves, which start at 3D/(D+2) and meet at 3
plot for [d in dims] sprintf('relaxation_D%s.csv', d) \
       using 'collisions_per_particle':'kurtosis_x' with lines lw 2 title 'D = '.d, \
     3 with lines dt 2 lc 'black' title 'MB'
set key inside
set terminal pngcairo size 1200,700 font ',10'
set output 'speed_histograms.png'
unset title
set multiplot layout 2,3 title 'Final speed distribution against Maxwell-Boltzmann'
set xlabel 'speed'
set ylabel 'density'
do for [d in dims] {
  set title 'D = '.d
  plot sprintf('speed_histogram_D%s.csv', d) using (($1+$2)/2):'density' with histeps \
         title 'simulation', \
       '' using (($1+$2)/2):'maxwell_density' with lines title 'MB'
}
unset multiplot
