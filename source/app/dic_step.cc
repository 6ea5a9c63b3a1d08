// The dic step: frames + machine record -> dic_record.csv for reduce (dic_step.h).
#include "fiberbridge/app/dic_step.h"

#include "dic_writers.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/output_guard.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

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
  const std::vector<std::string> comments = {
      "Test record from DIC frames (fiberbridge dic): a = initial crack " +
          fmt(o.initial_crack * 1e3) + " mm + the shift of the " + fmt(100 * o.dic.tip.threshold) +
          " % crack-normal strain point from the notch root; delta_root by a virtual "
          "extensometer of " +
          fmt(o.dic.gauge_length * 1e3) + " mm at the notch root",
      "machine record: " + o.machine_record + "; " + std::to_string(r.rows.size()) +
          " frames inside its time span; *_sd_mm: one standard deviation"};
  dic::write_dic_record(r.record_path, r.rows, comments);
  if (!output_enabled()) {
    // Under mpirun only rank 0 writes the output directory (core/output_guard.h), but every rank
    // runs reduce after dic: the others read a private copy.
    r.record_path = (std::filesystem::temp_directory_path() /
                     ("fiberbridge_dic_record_" + std::to_string(::getpid()) + ".csv"))
                        .string();
    std::ofstream(r.record_path) << dic::dic_record_text(r.rows, comments);
    // Removed when the process ends (reduce reads it later in the same run).
    static struct RemoveAtExit {
      std::vector<std::string> paths;
      ~RemoveAtExit() {
        for (const auto& p : paths)
          std::remove(p.c_str());
      }
    } private_copies;
    private_copies.paths.push_back(r.record_path);
  }
  write_dic_frames(out_dir, o, r.analysis);
  plot_dic(out_dir, o, r, summary);
  summary["dic"] = dic_summary(o, r, notes);
  summary["dic"]["wall_time_s"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

} // namespace fiberbridge::app
