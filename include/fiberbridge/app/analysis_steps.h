#pragma once
// The analysis chain as steps shared by the command line (extract, rank) and the scene items
// (extract, fit, rank, bridging): one implementation, two front ends.
#include "fiberbridge/analysis/inverse.h"
#include "fiberbridge/analysis/rdelta_data.h"
#include "fiberbridge/analysis/steady_state.h"
#include "fiberbridge/analysis/trilinear_fit.h"
#include "fiberbridge/core/summary.h"

#include <memory>
#include <string>

namespace fiberbridge::app {

struct ExtractionOptions {
  /// The R(delta) data: read from this file, or, when `data` is given, its name in the outputs
  /// and messages (the file the data were also written to).
  std::string data_file;
  /// R(delta) handed on in memory (a scene's `reduce`, SceneContext::rdelta_root); nullptr =
  /// read data_file.
  std::shared_ptr<const analysis::RDeltaData> data;
  double delta_c = 0;    ///< [m]; 0 = automatic
  double j_tip = 0;      ///< [J/m^2]; 0 = automatic
  int intervals = 100;   ///< n of Eq. 6
  int half_width = 3;    ///< smoothing half-width k (grid intervals)
  int grid_points = 401; ///< common grid for averaging replicates
};

struct ExtractionOutcome {
  analysis::RDeltaCurve curve;
  analysis::SteadyState steady;
  analysis::ExtractedLaws laws;
};

/// Reads (or takes o.data), averages, finds the steady state, extracts Eq. 6 and R' laws; writes
/// rdelta_averaged.csv, cohesive_law_eq5.csv, cohesive_law_dRdd.csv; adds the top-level keys of
/// docs/design.md section 5 to `summary` (J_tip_J_m2, G_ss_J_m2, delta_c_mm, peak_sigma_eq5_kPa,
/// peak_sigma_dRdd_kPa, extract{}).
ExtractionOutcome run_extraction(const ExtractionOptions& o, const std::string& out_dir,
                                 Json& summary);

struct FitOptions {
  double d1 = 0.1e-3, d2 = 1.0e-3; ///< fixed breakpoints [m] (the paper's)
  bool free_breakpoints = false;
  double d1_min = 0.02e-3, d1_max = 0.5e-3, d2_max = 0; ///< bounds when free (d2_max 0 = delta_c/2)
};

/// Trilinear fit of the Eq. 6 law with area G_ss - J_tip; writes trilinear_fit.csv and the
/// summary's `trilinear` block; plots R(delta) with the fitted forward curve and the three laws.
analysis::TrilinearFit run_trilinear_fit(const ExtractionOutcome& e, const FitOptions& o,
                                         const std::string& out_dir, Json& summary);

/// Plots of the extraction alone (when no fit follows): R(delta) and the two laws.
void plot_extraction(const ExtractionOutcome& e, const analysis::TrilinearFit* fit,
                     const std::string& out_dir, Json& summary);

struct RankOptions {
  std::string table_file;
  double d1_mm = 0.1, d2_mm = 1.0; ///< for the J1/J2 consistency check
};

/// Degradation statistics, ranking and consistency check; writes degradation.csv, ranking.csv,
/// PNGs per material; adds `ranking`, `degradation`, `consistency` to summary.
void run_ranking(const RankOptions& o, const std::string& out_dir, Json& summary);

/// Name of the file that marks an output directory as holding no complete run.
inline constexpr const char* incomplete_marker = "RUN_INCOMPLETE.txt";
/// At the start of a run: writes the incomplete marker, then removes a stale summary.json (so a
/// failed or killed run never leaves an old one looking current) and leftover *.partial files.
void remove_stale_summary(const std::string& out_dir);
/// The end of a successful run: writes summary.json (atomically), then removes the incomplete
/// marker. Every command that writes a summary ends through here.
void write_run_summary(const std::string& out_dir, const Json& summary);
/// Creates the directory (and parents); InputError when impossible.
void ensure_directory(const std::string& dir);

} // namespace fiberbridge::app
