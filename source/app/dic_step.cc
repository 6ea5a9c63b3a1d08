// The dic step: frames + machine record -> dic_record.csv for reduce (dic_step.h).
#include "fiberbridge/app/dic_step.h"

#include "dic_writers.h"
#include "fiberbridge/core/format.h"

#include <chrono>

namespace fiberbridge::app {

DicOutcome run_dic(const DicStepOptions& o, const std::string& out_dir, Json& summary) {
  const auto t0 = std::chrono::steady_clock::now();
  DicOutcome r;
  const auto files = dic::order_frames(o.frames, o.where + ": DIC/Frames");
  r.analysis = dic::analyse_frames(files, o.dic);
  const dic::MachineRecord machine =
      dic::read_machine_record(o.machine_record, o.machine_columns, o.where + ": Test/Columns");
  std::vector<std::string> notes;
  r.rows = dic::match_to_machine(r.analysis, machine, o.initial_crack, notes);
  r.record_path = out_dir + "/dic_record.csv";
  dic::write_dic_record(
      r.record_path, r.rows,
      {"Test record from DIC frames (fiberbridge dic): a = initial crack " +
           fmt(o.initial_crack * 1e3) + " mm + the shift of the " + fmt(100 * o.dic.tip.threshold) +
           " % crack-normal strain point from the notch root; delta_root by a virtual "
           "extensometer of " +
           fmt(o.dic.gauge_length * 1e3) + " mm at the notch root",
       "machine record: " + o.machine_record + "; " + std::to_string(r.rows.size()) +
           " frames inside its time span; *_sd_mm: one standard deviation"});
  write_dic_frames(out_dir, o, r.analysis);
  plot_dic(out_dir, o, r, summary);
  summary["dic"] = dic_summary(o, r, notes);
  summary["dic"]["wall_time_s"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

} // namespace fiberbridge::app
