// sim/plot_scripts.cpp -- gnuplot script text.
#include "plot_scripts.hpp"

#include <fmt/core.h>

namespace hypergas::cli {

namespace {
constexpr const char* preamble =
    "set terminal pngcairo size 900,600 font ',11'\n"
    "set datafile separator ','\n"
    "set key autotitle columnhead\n"
    "set grid\n";
}

std::string run_plot_script(bool vacf) {
  std::string s = preamble;
  s += "set output 'moments.png'\n"
       "set multiplot layout 2,1\n"
       "set xlabel 'time'\n"
       "set ylabel 'kurtosis of v_x (MB: 3)'\n"
       "plot 'moments.csv' using 'time':'kurtosis_x' with linespoints title 'kurtosis_x', "
       "3 with lines dt 2 title 'Maxwell-Boltzmann'\n"
       "set ylabel 'L1 distance of speeds from MB'\n"
       "set logscale y\n"
       "plot 'moments.csv' using 'time':'l1_speed' with linespoints title 'L1'\n"
       "unset logscale y\n"
       "unset multiplot\n"
       "set output 'speed_histogram.png'\n"
       "set xlabel 'speed'\n"
       "set ylabel 'probability density'\n"
       "plot 'speed_histogram.csv' using (($1+$2)/2):'density' with histeps title 'simulation', "
       "'' using (($1+$2)/2):'maxwell_density' with lines title 'Maxwell-Boltzmann'\n";
  if (vacf)
    s += "set output 'vacf.png'\n"
         "set xlabel 'time (sigma sqrt(m/kT))'\n"
         "set ylabel 'VACF / VACF(0)'\n"
         "set logscale xy\n"
         "stats 'vacf.csv' using 'vacf' nooutput\n"
         "c0 = STATS_max\n"
         "plot 'vacf.csv' using 'time':(column('vacf')/c0) with linespoints title '<v(0).v(t)>', "
         "'' using 'time':(column('vacf') < 0 ? -column('vacf')/c0 : 1/0) with points "
         "title 'negative values (abs)'\n";
  return s;
}

std::string scene_plot_script(const std::vector<int>& dims, double threshold) {
  std::string s = preamble;
  std::string l1, kurt;
  for (int d : dims) {
    const char* sep = l1.empty() ? "" : ", ";
    l1 += fmt::format("{}'relaxation_D{}.csv' using 'collisions_per_particle':'l1_speed' with "
                      "lines lw 2 title 'D = {}'",
                      sep, d, d);
    kurt += fmt::format("{}'relaxation_D{}.csv' using 'collisions_per_particle':'kurtosis_x' "
                        "with lines lw 2 title 'D = {}'",
                        sep, d, d);
  }
  s += "set output 'relaxation.png'\n"
       "set title 'Relaxation to Maxwell-Boltzmann: L1 distance of the speed histogram'\n"
       "set xlabel 'collisions per particle'\n"
       "set ylabel 'L1 distance from MB'\n"
       "set logscale y\n";
  s += fmt::format("plot {}, {} with lines dt 2 lc 'black' title 'threshold {}'\n", l1,
                   threshold, threshold);
  s += "unset logscale y\n"
       "set output 'kurtosis.png'\n"
       "set title 'Kurtosis of v_x (Maxwell-Boltzmann: 3)'\n"
       "set ylabel 'kurtosis'\n";
  s += fmt::format("plot {}, 3 with lines dt 2 lc 'black' title 'MB'\n", kurt);
  s += "set terminal pngcairo size 1200,700 font ',10'\n"
       "set output 'speed_histograms.png'\n"
       "unset title\n"
       "set multiplot layout 2,3 title 'Final speed distribution against Maxwell-Boltzmann'\n"
       "set xlabel 'speed'\n"
       "set ylabel 'density'\n";
  for (int d : dims)
    s += fmt::format("set title 'D = {}'\n"
                     "plot 'speed_histogram_D{}.csv' using (($1+$2)/2):'density' with histeps "
                     "title 'simulation', '' using (($1+$2)/2):'maxwell_density' with lines "
                     "title 'MB'\n",
                     d, d);
  s += "unset multiplot\n";
  return s;
}

}  // namespace hypergas::cli
