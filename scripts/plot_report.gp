# plot_report.gp -- the work-precision figure of `hypergas report` (error against run time).
# Run inside a report folder (hypergas report writes a copy there and runs it):
#   cd report && gnuplot plot_report.gp          -> work_precision.png
# Reads work_precision.csv, finite_n.csv, ntc.csv, schemes.csv and slopes.gp (fitted slopes,
# the NTC detection). Error bars: +- 1 standard error of each measured error.
set datafile separator ','
set datafile columnheaders
set terminal pngcairo size 2400,1100 font ',11'
set output 'work_precision.png'
do for [d=1:6] {
  eval sprintf('slope_stat_dsmc_%d = NaN', d)
  eval sprintf('slope_maxwell_dsmc_%d = NaN', d)
  eval sprintf('slope_eos_edmd_%d = NaN', d)
}
ntc_order = -99
ntc_detected = 0
ntc_max_sig = 0
ntc_max_sig_dt = 0
load 'slopes.gp'
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set key bottom left font ',10'
set grid
set multiplot layout 2,3 title 'hypergas: error against run time (errors against exact values)'

set title 'statistical error: DSMC equilibrium <(m v^2/kT)^2> (N = 1000)'
set xlabel 'run time per replica (s, one core)'
set ylabel 'relative RMS error'
plot for [d=1:6] 'work_precision.csv' \
       using (strcol(1) eq 'stat' && $3 == d ? $5 : NaN):6:7 with yerrorlines pt 7 lc d \
       title sprintf('D = %d: slope %.2f', d, value(sprintf('slope_stat_dsmc_%d', d))), \
     'work_precision.csv' using (strcol(1) eq 'finite_n' ? $5 : NaN):6:7 with yerrorlines \
       dt 2 lw 2 pt 5 lc rgb 'black' title 'D = 3, N = 200 vs Maxwell-Boltzmann: finite-N plateau'

set title 'EDMD pressure Z (N = 1000): 1D Tonks, 2D Henderson, 3D Carnahan-Starling, 4D virial'
array eos_ref[4] = ['Tonks (exact)', 'Henderson', 'Carnahan-Starling', 'virial to B_3']
plot for [d=1:4] 'work_precision.csv' \
       using (strcol(1) eq 'eos' && $3 == d ? $5 : NaN):6:7 with yerrorlines lw 2 pt 9 lc d \
       title sprintf('D = %d vs %s: slope %.2f', d, eos_ref[d], value(sprintf('slope_eos_edmd_%d', d)))

set title 'DSMC Maxwell molecules: <v^4> relaxation rate vs exact (D-1)/(2D)'
set ylabel 'relative RMS error of the rate'
plot for [d=2:6] 'work_precision.csv' \
       using (strcol(1) eq 'maxwell' && $3 == d ? $5 : NaN):6:7 with yerrorlines pt 7 lc d \
       title sprintf('D = %d: slope %.2f', d, value(sprintf('slope_maxwell_dsmc_%d', d)))

set title 'finite-N bias of <(m v^2/kT)^2> vs Maxwell-Boltzmann (lines: exact microcanonical)'
set xlabel 'N'
set ylabel '|relative bias|'
plot for [d=2:6] 'finite_n.csv' using ($1 == d ? $2 : NaN):(abs($3)):4 with yerrorbars \
       pt 7 lc d title sprintf('D = %d', d), \
     for [d=2:6] 'finite_n.csv' using ($1 == d ? $2 : NaN):(abs($5)) with lines lc d notitle

set title (ntc_order > -90 ? sprintf('NTC time-step bias, 3D hard spheres: order %.2f', ntc_order) : \
           ntc_detected > 0 ? sprintf('NTC time-step bias, 3D: %.1f se at dt = %g, no order (needs 2 dt > 3 se)', \
                                      ntc_max_sig, ntc_max_sig_dt) \
                            : 'NTC time-step bias, 3D hard spheres: not detectable (|bias| < 3 se)')
set xlabel 'NTC step dt (mean collision times)'
set ylabel '|kurtosis(NTC) - kurtosis(exact)| / kurtosis, t = 2'
plot 'ntc.csv' using 2:(abs($3)):4 with yerrorbars pt 7 title '|bias| +- 1 se', \
     'ntc.csv' using 2:(3 * $4) with lines dt 2 title '3 se (resolution)'

set title 'choice of scheme: kurtosis at t = 2, 3D hard spheres, one run of N = 10^4, 10^5, 10^6'
set xlabel 'run time of one run (s, one core)'
set ylabel 'relative RMS error of one run'
plot 'schemes.csv' using (strcol(1) eq 'exact' ? $4 : NaN):5:6 with yerrorlines lw 2 pt 7 \
       lc rgb 'black' title 'exact', \
     'schemes.csv' using (strcol(1) eq 'ntc' && $2 == 2 ? $4 : NaN):5:6 with yerrorlines \
       lw 2 pt 5 lc 1 title 'NTC dt = 2', \
     'schemes.csv' using (strcol(1) eq 'ntc' && $2 == 0.5 ? $4 : NaN):5:6 with yerrorlines \
       lw 2 pt 9 lc 2 title 'NTC dt = 0.5', \
     'schemes.csv' using (strcol(1) eq 'lanes' ? $4 : NaN):5:6 with yerrorlines lw 2 pt 11 \
       lc 3 title 'lanes (default M)'
unset multiplot
