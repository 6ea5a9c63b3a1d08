#pragma once
// `dic` as a step shared by the command line (fiberbridge dic) and the scene item (section DIC):
// DIC frames and the machine record in, dic_record.csv (the test record `reduce` reads), the
// per-frame table, the plots and the summary block `dic` out (docs/design.md section 6,
// "DIC frames in").
#include "fiberbridge/app/scene/item_outcome.h"
#include "fiberbridge/app/scene/scene_context.h"
#include "fiberbridge/app/scene/step_outcomes.h"
#include "fiberbridge/dic/dic_analysis.h"
#include "fiberbridge/dic/dic_record.h"

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace fiberbridge::app {

/// The machine record read as `reduce` reads a record (analysis::read_test_records: any export
/// layout, units and encoding, the column map matched the same way, the same cleaning); its crack
/// and delta_root columns are not read (DIC gives them). InputError naming the file when it has
/// no time column or holds more than one record.
dic::MachineRecord read_machine_record(const std::string& path, analysis::RecordReadOptions read);

/// The DIC and Test sections as the scene's `dic` uses them (the frames, the machine record, the
/// specimen's a0); every file must exist. Throws InputError naming the scene and key.
DicStepOptions dic_step_options(const SceneContext& ctx);

/// The frames analysed and matched by time to the machine record: what `dic` writes and what a
/// campaign's DIC set reduces (one code for both doors).
DicMatch match_dic_frames(const DicStepOptions& options);
/// dic_record.csv's provenance lines for the matched rows; `what` says whose record it is.
std::vector<std::string> dic_record_comments(const DicStepOptions& options, const DicMatch& match,
                                             const std::string& what);

/// Analyses the frames, matches them to the machine record, writes dic_record.csv, dic_frames.csv,
/// dic_profiles.csv, dic_field.csv and the plots, and adds summary["dic"].
DicOutcome run_dic(const DicStepOptions& options, const std::string& out_dir, ItemReport& report);

} // namespace fiberbridge::app
