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
