#pragma once
// The paper's extraction as computations, apart from their files (the app writes them:
// app/outputs/extraction_writers.h): R(delta) replicates averaged, the steady state (delta_c,
// J_tip, G_ss), the Eq. 6 and sigma = R' laws, the trilinear fit of the Eq. 6 law, and the
// degradation statistics and ranking of a property table.
#include "fiberbridge/analysis/degradation.h"
#include "fiberbridge/analysis/inverse.h"
#include "fiberbridge/analysis/rdelta_data.h"
#include "fiberbridge/analysis/steady_state.h"
#include "fiberbridge/analysis/trilinear_fit.h"

#include <memory>
#include <string>
#include <vector>

namespace fiberbridge::analysis {

struct ExtractionOptions {
  /// The R(delta) data: read from this file, or, when `data` is given, its name in the outputs
  /// and messages (the file the data were also written to).
  std::string data_file;
  /// R(delta) handed on in memory (a scene's `reduce`, SceneContext::rdelta_root); nullptr =
  /// read data_file.
  std::shared_ptr<const RDeltaData> data;
  double delta_c = 0;    ///< [m]; 0 = automatic
  double j_tip = 0;      ///< [J/m^2]; 0 = automatic
  int intervals = 100;   ///< n of Eq. 6
  int half_width = 3;    ///< smoothing half-width k (grid intervals)
  int grid_points = 401; ///< common grid for averaging replicates
};

struct ExtractionOutcome {
  RDeltaCurve curve;
  SteadyState steady;
  ExtractedLaws laws;
};

/// Reads (or takes o.data), averages, finds the steady state and extracts the Eq. 6 and R' laws.
/// InputError for Data/Intervals or Data/Smoothing half-width out of range, and for the data.
ExtractionOutcome extract_law(const ExtractionOptions& o);

struct FitOptions {
  double d1 = 0.1e-3, d2 = 1.0e-3; ///< fixed breakpoints [m] (the paper's)
  bool free_breakpoints = false;
  double d1_min = 0.02e-3, d1_max = 0.5e-3, d2_max = 0; ///< bounds when free (d2_max 0 = delta_c/2)
};

/// Trilinear fit of the Eq. 6 law with area G_ss - J_tip, breakpoints fixed or free. InputError
/// when fixed breakpoints do not satisfy 0 < Delta 1 < Delta 2 < delta_c.
TrilinearFit fit_extracted_law(const ExtractionOutcome& e, const FitOptions& o);

struct RankOptions {
  std::string table_file;
  double d1_mm = 0.1, d2_mm = 1.0; ///< for the J1/J2 consistency check
};

struct RankingOutcome {
  PropertyTable table;
  std::vector<DegradationRow> rows;     ///< one per material and property
  std::vector<MaterialRank> ranks;      ///< most durable first
  std::vector<ConsistencyIssue> issues; ///< rows whose J1/J2 disagree with the printed laws
};

/// Reads the property table, then the degradation statistics, the ranking and the consistency
/// check of each row against its trilinear law.
RankingOutcome rank_property_table(const RankOptions& o);

} // namespace fiberbridge::analysis
