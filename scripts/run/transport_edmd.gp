# transport_edmd.gp -- transport.png of `run --engine edmd --transport`: the correlations
# and the running Einstein-Helfand values.
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
