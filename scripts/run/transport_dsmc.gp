# transport_dsmc.gp -- transport.png of `run --engine dsmc --transport`: the normalised
# flux correlations beside their first Sonine exponentials.
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
unset logscale y
