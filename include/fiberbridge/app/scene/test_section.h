#pragma once
// The scene's `Test` section (raw DCB records), a step-44 section struct (section.h) read by both
// `reduce` and `identify`, so that the two items see the same records the same way.
#include "fiberbridge/analysis/record_chain.h"
#include "fiberbridge/analysis/test_record.h"
#include "fiberbridge/specimen/specimen.h"

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace fiberbridge::app {

struct TestSection {
  std::vector<std::string> files; ///< as written in the scene (trimmed, empty entries dropped)
  std::string columns;            ///< the column map as written (read_options parses it)
  std::string encoding = "auto";  ///< the files' text encoding: auto or an iconv name
  /// "auto" (the crack column when there is one), "measured" (required) or "equivalent" (any
  /// crack column ignored: R against the compliance's equivalent crack length)
  std::string crack_length = "auto";
  double crack_back_tolerance = 1e-3; ///< [m]
  bool use_specimen_initial_crack = false;
  double smoothing_window = 0; ///< [m]; 0: automatic
  bool large_displacement_correction = true;
  double pin_to_arm_midplane = 0, pin_to_block_edge = 0; ///< [m]; 0: the default of each
  double plateau_fraction = 1.0 / 3.0;

  static void declare_parameters(dealii::ParameterHandler& prm);
  void parse_parameters(dealii::ParameterHandler& prm);

  /// The records' paths resolved against the scene's folder; each must exist (InputError naming
  /// the scene and Test/Files). An empty list is returned as such: the items say what they need.
  std::vector<std::string> resolved_files(const std::string& scene_file) const;
  /// The one chain's settings (analysis/record_chain.h) from this section, the Specimen's
  /// geometry (a0 only with `use_specimen_initial_crack`, and as the a0 of records without
  /// readings) and the Material's G_LT and E_T (CBBM). Every scene door reads and reduces with it.
  analysis::RecordChainOptions chain_options(const std::string& scene_file,
                                             const specimen::Specimen& specimen,
                                             const specimen::Material& material) const;
  /// How the records are read: the column map (errors name the scene and Test/Columns), where
  /// the crack lengths come from and the crack-back tolerance.
  analysis::RecordReadOptions read_options(const std::string& scene_file) const;
};

} // namespace fiberbridge::app
