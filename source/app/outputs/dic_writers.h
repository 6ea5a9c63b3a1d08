#pragma once
// Writers of the dic step (dic_step.h): tables, plots and the summary block, apart from the step
// that computes (MOOSE's outputs apart from the objects that compute).
#include "fiberbridge/app/scene/item_outcome.h"
#include "fiberbridge/app/scene/step_outcomes.h"

namespace fiberbridge::app {

/// dic_frames.csv: one row per frame (image number, time, this frame's tip reading, the tracked
/// tip, a, delta_root with their standard deviations, the strain noise, points and failures).
void write_dic_frames(const std::string& out_dir, const DicStepOptions& o,
                      const dic::DicAnalysis& a);
/// dic_profiles.csv and dic_strain_profiles.png (paper Fig. 2): the crack-plane strain at up to
/// six times with the threshold line; dic_crack_and_root.png: a(t) and delta_root(t);
/// dic_field.csv and dic_field.png: the last used frame's strain field with the tip and the
/// extensometer's points. Plots are added to the report's plots.
void plot_dic(const std::string& out_dir, const DicStepOptions& o, const DicOutcome& r,
              ItemReport& report);
/// summary["dic"]: frames read and used, points used and failed, the tip rule, the extensometer,
/// the clock, the notes per frame, wall_time_s.
Json dic_summary(const DicStepOptions& o, const DicOutcome& r,
                 const std::vector<std::string>& record_notes);

} // namespace fiberbridge::app
