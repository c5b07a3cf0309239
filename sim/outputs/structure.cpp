// sim/outputs/structure.cpp -- rdf.csv and structure_factor.csv of `run --engine edmd
// --structure`: g(r), its contact value and S(k) over the measurement window
// (analysis::StructureRecorder).
#include <optional>

#include <fmt/core.h>

#include "../output_dir.hpp"
#include "hypergas/analysis/structure_recorder.hpp"
#include "../run_summary.hpp"
#include "output.hpp"
#include "plot_structure_gp.hpp"  // generated from scripts/run/structure.gp

namespace hypergas::cli {

namespace {

class StructureOutput final : public Output {
 public:
  explicit StructureOutput(const RunSetup& s) {
    const RunOptions& o = s.options;
    analysis::StructureSettings ss;
    ss.r_max = o.rdf_max;
    ss.k_max = o.k_max;
    ss.seed = o.seed;
    recorder_.emplace(ss, o.dim, static_cast<std::size_t>(o.n), s.window_start);
  }

  Observer* sampler() override { return &*recorder_; }
  void finish() override { recorder_->finish(); }
  void write(OutputDir& out) const override {
    recorder_->write_rdf_csv(out.staged("rdf.csv").string());
    recorder_->write_structure_factor_csv(out.staged("structure_factor.csv").string());
  }
  void summarize(analysis::JsonObject& s) const override {
    s.emplace_back("contact_value_rdf", recorder_->finish().contact);
    s.emplace_back("contact_value_rdf_error", recorder_->finish().contact_error);
  }
  void report(std::string& text, const analysis::JsonObject& summary) const override {
    text += fmt::format("  g(sigma+) {:.5g} +- {:.2g} from the rdf (contact theorem from Z: {})\n",
                        recorder_->finish().contact, recorder_->finish().contact_error,
                        summary_field(summary, "contact_value_from_Z"));
  }
  std::string_view plot() const override { return embedded::plot_structure_gp; }

 private:
  // finish() caches its result, so the const accessors above may call it
  mutable std::optional<analysis::StructureRecorder> recorder_;
};

}  // namespace

namespace outputs {
constexpr std::string_view structure_files[] = {"rdf.csv", "structure_factor.csv",
                                               "structure.png"};
extern const OutputKind structure{
    .name = "structure",
    .wanted = [](const RunOptions& o,
                 registry::EngineKind e) { return o.structure && e == registry::EngineKind::edmd; },
    .make = make_output<StructureOutput>,
    // its correlations or frames are not saved: a resumed run would report a part of the
    // run as the whole
    .checkpointable = false,
    .files = structure_files};
}

}  // namespace hypergas::cli
