#pragma once
// What the records-to-law steps take and hand over: their options and typed outcomes. Items
// compute them (items/), the writers write them (outputs/), resume keeps them (run/); so they
// live here, below all three.
#include "fiberbridge/analysis/record_chain.h"
#include "fiberbridge/analysis/record_reduction.h"
#include "fiberbridge/analysis/test_record.h"
#include "fiberbridge/dic/dic_analysis.h"
#include "fiberbridge/dic/dic_record.h"
#include "fiberbridge/specimen/specimen.h"

#include <cmath>
#include <string>
#include <vector>

namespace fiberbridge::app {

// reduce (items/reduce_step.h)
/// The files and the one chain's settings (analysis/record_chain.h): a scene's from
/// record_chain_options (test_section.h), the command line's from its options.
struct ReduceStepOptions : analysis::RecordChainOptions {
  std::vector<std::string> files;
  std::string where = "reduce"; ///< names the geometry's origin in messages (scene or CLI)
};

struct ReduceOutcome {
  std::vector<analysis::TestRecord> records;
  std::vector<analysis::ReducedRecord> reduced;
  analysis::ReducedMean mean;
};

// dic (items/dic_step.h)
struct DicStepOptions {
  std::vector<std::string> frames; ///< existing paths (any order; sorted by image number)
  dic::DicOptions dic;
  std::string machine_record; ///< the testing machine's record (time, opening, load)
  /// How it is read: the one chain's read options (analysis/record_chain.h; Test/Columns,
  /// Test/Encoding), so that it is matched and converted exactly as `reduce` reads a record.
  analysis::RecordReadOptions machine_read;
  double initial_crack = 0; ///< [m] a at the notch root
  std::string where = "dic";
};

/// The frames analysed and matched by time to the machine record: what `dic` writes and what a
/// campaign's DIC set reduces (one code for both doors).
struct DicMatch {
  dic::DicAnalysis analysis;
  std::vector<dic::DicRecordRow> rows;
  std::vector<std::string> notes;
};

struct DicOutcome {
  dic::DicAnalysis analysis;
  std::vector<dic::DicRecordRow> rows;
  std::string record_path; ///< dic_record.csv
};

// The campaign's laws back in the specimen (items/campaign_simulation.h): one group's simulation.
struct GroupSimulation {
  std::string material, model;
  double cycles = 0;
  bool ran = false;
  std::string failure;
  std::vector<double> delta_root, R; ///< simulated, R_energy (R_J where absent) [m], [J/m^2]
  double G_ss = NAN;                 ///< simulated plateau [J/m^2]
  /// RMS of simulated minus measured R over the measured delta range (up to the simulation's
  /// last delta_root), relative to the group's G_B = G_ss - J_tip.
  double misfit_rel = NAN;
  /// Fraction of those points where the simulation lies within 2 standard deviations of the
  /// measured replicates (the specimens' scatter).
  double within_scatter = NAN;
  double wall_time_s = NAN;
  specimen::Specimen specimen; ///< the geometry simulated (campaign_group_specimen)
  std::string geometry_note;   ///< non-empty when the group's rows differ in geometry
  double a_start = NAN;        ///< the simulation's first crack length [m] (its a0)
};

} // namespace fiberbridge::app
