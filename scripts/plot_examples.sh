#!/usr/bin/env bash
# Plots the CSV files the examples write (examples/NN-topic/README.md) as PNG with gnuplot.
# Usage: bash scripts/plot_examples.sh [BUILD_EXAMPLES_DIR]   (default build/examples)
# Looks for each CSV in the folder itself and in its NN-topic/ subfolders (where ctest runs
# the examples); writes the PNG next to the CSV. Missing CSVs are skipped.
set -euo pipefail
dir=${1:-build/examples}
command -v gnuplot >/dev/null || { echo "plot_examples: gnuplot not found" >&2; exit 1; }

plot() {  # plot CSV_NAME PNG_NAME GNUPLOT_BODY
  local csv found
  for csv in "$dir/$1" "$dir"/*/"$1"; do
    [ -f "$csv" ] || continue
    found=1
    (cd "$(dirname "$csv")" && gnuplot <<GP
set terminal pngcairo size 900,600 noenhanced
set output '$2'
set datafile separator ','
set key autotitle columnhead
set grid
$3
GP
    ) && echo "wrote $(dirname "$csv")/$2"
  done
  [ -n "${found:-}" ] || echo "plot_examples: no $1 under $dir (run the example first)" >&2
}

plot two_mass_1d.csv two_mass_1d.png "
set xlabel 'time (mean collision times)'; set ylabel 'kurtosis of v_x (MB: 3)'
plot 'two_mass_1d.csv' u 'time':'kurtosis_equal_mass' w l lw 2, '' u 'time':'kurtosis_two_mass' w l lw 2, 3 w l dt 2 t 'MB'"
plot two_beams_2d.csv two_beams_2d.png "
set xlabel 'time (mean collision times)'; set ylabel 'kT units'; set y2label 'kurtosis'; set y2tics
plot 'two_beams_2d.csv' u 'time':'T_x' w l lw 2, '' u 'time':'T_y' w l lw 2, '' u 'time':'kurtosis_x' axes x1y2 w l lw 2"
plot bkw_3d.csv bkw_3d.png "
set xlabel 'time (mean collision times)'; set ylabel '<|v|^4>'
plot 'bkw_3d.csv' u 'time':'m4':'m4_err' w yerr t 'DSMC', '' u 'time':'m4_bkw' w l lw 2 t 'BKW exact'"
plot eos_4d.csv eos_4d.png "
set xlabel 'packing fraction eta'; set ylabel 'Z = PV/NkT'; set key left
plot 'eos_4d.csv' u 'eta':'Z':'Z_err' w yerr t 'virial', '' u 'eta':'Z_from_rate' w p t 'collision rate', '' u 'eta':'Z_virial_B4' w l t 'virial series to B4'"
plot maxwell_moments_5d.csv maxwell_moments_5d.png "
set xlabel 'time (mean collision times)'; set ylabel '35 - <|v|^4>'; set logscale y
plot 'maxwell_moments_5d.csv' u 'time':(35-column('m4')) w p t 'DSMC', '' u 'time':(35-column('m4_theory')) w l t 'exp(-0.4 t)'"
plot vacf_6d.csv vacf_6d.png "
set xlabel 'time'; set ylabel '|C(t)| / C(0)'; set logscale xy
stats 'vacf_6d.csv' u 'vacf' nooutput
plot 'vacf_6d.csv' u 'time':(abs(column('vacf'))/STATS_max) w lp t 'VACF', '' u 'time':(0.05*(column('time')/0.05)**-3) w l dt 2 t 't^-3'"
plot rdf_3d.csv rdf_3d_6d.png "
set xlabel 'r / sigma'; set ylabel 'g(r)'; set xrange [0.9:*]
plot 'rdf_3d.csv' u 'r':'g' w l lw 2 t '3D, eta = 0.30, Z = 4', 'rdf_6d.csv' u 'r':'g' w l lw 2 t '6D at Z = 4', 1 w l dt 2 t ''"
plot viscosity_3d.csv viscosity_3d.png "
set xlabel 'packing fraction eta'; set ylabel 'eta / eta_0'; set key left; set logscale y
plot 'viscosity_3d.csv' u 'packing':'eta_over_eta0':'error' w yerr pt 7 t 'EDMD (Einstein-Helfand)', '' u 'packing':'enskog_over_eta0' w lp dt 2 t 'Enskog'"
plot a2_vs_alpha.csv a2_vs_alpha.png "
set xlabel 'coefficient of restitution alpha'; set ylabel 'a2 of the homogeneous cooling state'; set key right top
set xrange [0:1]; set samples 400; set arrow from 1/sqrt(2),graph 0 to 1/sqrt(2),graph 1 nohead dt 3; set xzeroaxis lt -1
# first and second Sonine a2 (include/hypergas/granular/theory.hpp: a2_hcs, hcs_second_sonine)
s1(a,D) = 16*(1-a)*(1-2*a**2)/(9+24*D-a*(41-8*D)+30*(1-a)*a**2)
A0(a,D) = (a**2-1)*(2*a**2-1)
A2(a,D) = -(1+a)*(8*D*a+24*D-30*a**3+30*a**2-41*a+9)/16
A3(a,D) = -(1+a)*(12*D*a-44*D+10*a**3-10*a**2+91*a-59)/64
B0(a,D) = 3*(a**2-1)*(8*D*a**2-4*D+8*a**4+20*a**2-13)/4
B2(a,D) = -3*(1+a)*(32*D**2*a+96*D**2-280*D*a**3+536*D*a**2-20*D*a+212*D-280*a**5+280*a**4-1500*a**3+1244*a**2+23*a-343)/64
B3(a,D) = 3*(1+a)*(16*D**2*a+368*D**2-280*D*a**3+1048*D*a**2-820*D*a+1396*D-280*a**5+280*a**4-3100*a**3+2332*a**2-1481*a+521)/256
s2(a,D) = (-A0(a,D)*B3(a,D)+A3(a,D)*B0(a,D))/(A2(a,D)*B3(a,D)-A3(a,D)*B2(a,D))
plot for [d in '2 3 6'] 'a2_vs_alpha.csv' u 'alpha':(column('dim')==d+0?column('a2'):1/0):'a2_error' w yerr pt 7 lc (d+0==2?1:(d+0==3?2:4)) t 'DSMC '.d.'D', \
     for [d in '2 3 6'] s1(x,d+0) w l lw 2 lc (d+0==2?1:(d+0==3?2:4)) t 'first Sonine '.d.'D', \
     for [d in '2 3 6'] s2(x,d+0) w l dt 2 lw 2 lc (d+0==2?1:(d+0==3?2:4)) t 'second Sonine '.d.'D'"
plot haff.csv haff.png "
set terminal pngcairo size 900,800 noenhanced; set output 'haff.png'
set multiplot
set xlabel 't (mean collision times at T0)'; set logscale x; set xrange [0.1:2000]
set origin 0,0.35; set size 1,0.65; set ylabel 'T / T0'; set logscale y; set key left bottom; unset xlabel
plot 'haff.csv' u 't':(column('engine')==0?column('T_over_T0'):1/0) w l lw 3 t 'DSMC', \
     '' u 't':(column('engine')==1?column('T_over_T0'):1/0) w p pt 6 ps 0.7 t 'EDMD, packing 0.02, time x nu', \
     '' u 't':(column('engine')==0?column('haff_sonine'):1/0) w l dt 2 lw 2 lc rgb 'black' t 'Haff: 1/(1+t/t0)^2, Sonine t0'
set origin 0,0; set size 1,0.37; unset logscale y; set ylabel 'T / Haff'; set xlabel 't (mean collision times at T0)'; unset key
plot 'haff.csv' u 't':(column('engine')==0?column('T_over_T0')/column('haff_sonine'):1/0) w l lw 3, \
     '' u 't':(column('engine')==1?column('T_over_T0')/column('haff_sonine'):1/0) w p pt 6 ps 0.7, 1 w l dt 2 lc rgb 'black'
unset multiplot"
plot snapshot_1.csv clustering.png "
set terminal pngcairo size 1400,1400 noenhanced; set output 'clustering.png'
unset grid; set size ratio -1; unset key; set cbrange [0:0.9]; set palette defined (0 '#f7fbff', 0.2 '#6baed6', 0.4 '#2171b5', 0.6 '#e6550d', 0.9 '#7f0000')
array C[4]; do for [k=1:4] { stats sprintf('snapshot_%d.csv', k) u 'collisions_per_particle' nooutput; C[k] = STATS_max }
stats 'snapshot_1.csv' u 'x' nooutput; L = ceil(STATS_max); set xrange [0:L]; set yrange [0:L]
set multiplot layout 2,2 title 'inelastic disks (alpha = 0.8, packing 0.25): colour = local packing fraction within 3 sigma'
do for [k=1:4] {
  set title sprintf('%.0f collisions per particle after the quench', C[k])
  plot sprintf('snapshot_%d.csv', k) u 'x':'y':'density' w p pt 7 ps 0.22 lc palette
}
unset multiplot"
