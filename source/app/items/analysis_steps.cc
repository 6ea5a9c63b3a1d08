#include "fiberbridge/app/items/analysis_steps.h"

#include "fiberbridge/app/outputs/extraction_writers.h"
#include "fiberbridge/app/outputs/ranking_writers.h"

namespace fiberbridge::app {

ExtractionOutcome run_extraction(const ExtractionOptions& o, const std::string& out_dir,
                                 ItemReport& report) {
  ExtractionOutcome e = analysis::extract_law(o);
  write_extraction(e, o, out_dir, report);
  return e;
}

analysis::TrilinearFit run_trilinear_fit(const ExtractionOutcome& e, const FitOptions& o,
                                         const std::string& out_dir, ItemReport& report) {
  analysis::TrilinearFit fit = analysis::fit_extracted_law(e, o);
  write_trilinear_fit(fit, out_dir, report);
  return fit;
}

void run_ranking(const RankOptions& o, const std::string& out_dir, ItemReport& report) {
  write_ranking(analysis::rank_property_table(o), o, out_dir, report);
}

} // namespace fiberbridge::app
