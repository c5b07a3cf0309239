# plot_run.gp -- the settings shared by the plots of one `hypergas run` folder. The command
# runs it in the folder, followed by the piece of each output the run has (scripts/run/*.gp,
# in the order of the command's output list):
#   moments.gp          moments.png, speed_histogram.png (every run)
#   vacf.gp             vacf.png (EDMD)
#   transport_dsmc.gp   transport.png (DSMC --transport)
#   transport_edmd.gp   transport.png (EDMD --transport)
#   structure.gp        structure.png (EDMD --structure)
#   histograms.gp       speed_histograms.png (--histogram-every)
#   shear.gp            rheology.png (--shear-rate)
# Each piece leaves the axes linear as it found them.
# By hand: cd RUN && cat plot_run.gp run/moments.gp run/vacf.gp | gnuplot
# Reads the CSV files by column name (gnuplot >= 5.0).
set terminal pngcairo size 900,600 font ',11'
set datafile separator ','
set key autotitle columnhead
set grid
