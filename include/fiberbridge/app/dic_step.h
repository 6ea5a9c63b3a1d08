#pragma once
// `dic` as a step shared by the command line (fiberbridge dic) and the scene item (section DIC):
// DIC frames and the machine record in, dic_record.csv (the test record `reduce` reads), the
// per-frame table, the plots and the summary block `dic` out (docs/design.md section 6,
// "DIC frames in").
#include "fiberbridge/analysis/test_record.h"
#include "fiberbridge/core/summary.h"
#include "fiberbridge/dic/dic_analysis.h"
#include "fiberbridge/dic/dic_record.h"

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace fiberbridge::app {

/// The scene's DIC section (section.h convention). Lengths in the frames' coordinates stay in
/// their units (mm or px); the rest SI after parsing.
struct DicSection {
  std::string frames;  ///< glob(s) or list, as written
  std::string format;  ///< auto | vic | dice | gom | plain
  std::string columns; ///< our frame column names mapped to the files' headers
  bool pixels = false;
  double pixel_size = 0; ///< [m] per pixel
  bool y_down = false;
  double crack_plane_y = 0, notch_root_x = 0; ///< frames' coordinates
  int growth_sign = +1;
  std::string crack_plane_points; ///< "x0, y0, x1, y1" (overrides the three above) or empty
  double frame_rate = 1, first_frame_time = 0; ///< [Hz], [s]
  std::string frame_time_source;               ///< auto | column | name | index
  double threshold = 0.01;
  double gauge_length = 2e-3; ///< [m]
  int points_per_fit = 9;

  static void declare_parameters(dealii::ParameterHandler& prm);
  void parse_parameters(dealii::ParameterHandler& prm);
  /// The analysis options (frame layout, geometry, rule, clock); InputError naming DIC/<key>.
  dic::DicOptions options() const;
};

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

/// The machine record read as `reduce` reads a record (analysis::read_test_records: any export
/// layout, units and encoding, the column map matched the same way, the same cleaning); its crack
/// and delta_root columns are not read (DIC gives them). InputError naming the file when it has
/// no time column or holds more than one record.
dic::MachineRecord read_machine_record(const std::string& path, analysis::RecordReadOptions read);

/// The frames analysed and matched by time to the machine record: what `dic` writes and what a
/// campaign's DIC set reduces (one code for both doors).
struct DicMatch {
  dic::DicAnalysis analysis;
  std::vector<dic::DicRecordRow> rows;
  std::vector<std::string> notes;
};
DicMatch match_dic_frames(const DicStepOptions& options);
/// dic_record.csv's provenance lines for the matched rows; `what` says whose record it is.
std::vector<std::string> dic_record_comments(const DicStepOptions& options, const DicMatch& match,
                                             const std::string& what);

struct DicOutcome {
  dic::DicAnalysis analysis;
  std::vector<dic::DicRecordRow> rows;
  std::string record_path; ///< dic_record.csv
};

/// Analyses the frames, matches them to the machine record, writes dic_record.csv, dic_frames.csv,
/// dic_profiles.csv, dic_field.csv and the plots, and adds summary["dic"].
DicOutcome run_dic(const DicStepOptions& options, const std::string& out_dir, Json& summary);

} // namespace fiberbridge::app
