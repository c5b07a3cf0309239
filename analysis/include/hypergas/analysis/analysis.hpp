// hypergas/analysis/analysis.hpp -- the whole analysis library (link hypergas_analysis).
#pragma once

#include "hypergas/analysis/fit.hpp"
#include "hypergas/analysis/histogram.hpp"
#include "hypergas/analysis/maxwell.hpp"
#include "hypergas/analysis/moments.hpp"
#include "hypergas/analysis/moments_recorder.hpp"
#include "hypergas/analysis/output.hpp"
#include "hypergas/analysis/sample.hpp"
#include "hypergas/analysis/statistics.hpp"
#include "hypergas/analysis/vacf.hpp"
#include "hypergas/analysis/vacf_recorder.hpp"
