# structure.gp -- structure.png of `run --engine edmd --structure`: g(r) and S(k).
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
