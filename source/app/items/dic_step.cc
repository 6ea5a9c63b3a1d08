// The dic step: frames + machine record -> dic_record.csv for reduce (dic_step.h).
#include "fiberbridge/app/items/dic_step.h"

#include "fiberbridge/app/scene/dic_section.h"
#include "fiberbridge/app/scene/test_section.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/output_guard.h"
#include "outputs/dic_writers.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace fiberbridge::app {

dic::MachineRecord read_machine_record(const std::string& path, analysis::RecordReadOptions read) {
  read.columns.file_header.erase("a_mm");
  read.columns.file_header.erase("delta_root_mm");
  read.crack_length = analysis::CrackLengthSource::equivalent;
  auto records = analysis::read_test_records(path, read);
  if (records.size() != 1)
    throw InputError(path + ": the machine record holds " + std::to_string(records.size()) +
                     " records (a 'record' column); give one specimen's record");
  analysis::TestRecord& r = records.front();
  if (r.time.empty())
    throw InputError(path + ": the machine record has no time column (time_s, or map it in "
                            "Test/Columns, e.g. 'time_s: Time'): DIC frames are matched by time");
  dic::MachineRecord m;
  m.source = path;
  m.time = std::move(r.time);
  m.opening = std::move(r.opening);
  m.load = std::move(r.load);
  return m;
}

DicMatch match_dic_frames(const DicStepOptions& o) {
  DicMatch m;
  const auto files = dic::order_frames(o.frames, o.where + ": DIC/Frames");
  m.analysis = dic::analyse_frames(files, o.dic);
  const dic::MachineRecord machine = read_machine_record(o.machine_record, o.machine_read);
  m.rows = dic::match_to_machine(m.analysis, machine, o.initial_crack, m.notes);
  return m;
}

std::vector<std::string> dic_record_comments(const DicStepOptions& o, const DicMatch& m,
                                             const std::string& what) {
  return {what + ": a = initial crack " + fmt(o.initial_crack * 1e3) + " mm + the shift of the " +
              fmt(100 * o.dic.tip.threshold) +
              " % crack-normal strain point from the notch root; delta_root by a virtual "
              "extensometer of " +
              fmt(o.dic.gauge_length * 1e3) + " mm at the notch root",
          "machine record: " + o.machine_record + "; " + std::to_string(m.rows.size()) +
              " frames inside its time span; *_sd_mm: one standard deviation"};
}

DicOutcome run_dic(const DicStepOptions& o, const std::string& out_dir, ItemReport& report) {
  const auto t0 = std::chrono::steady_clock::now();
  DicMatch match = match_dic_frames(o);
  const std::vector<std::string> comments =
      dic_record_comments(o, match, "Test record from DIC frames (fiberbridge dic)");
  DicOutcome r;
  r.analysis = std::move(match.analysis);
  r.rows = std::move(match.rows);
  const std::vector<std::string>& notes = match.notes;
  r.record_path = out_dir + "/dic_record.csv";
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
  plot_dic(out_dir, o, r, report);
  report["dic"] = dic_summary(o, r, notes);
  report["dic"]["wall_time_s"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

/// The DIC and Test sections as the item uses them; every file must exist.
DicStepOptions dic_step_options(const SceneContext& ctx) {
  const auto& d = ctx.parameters().section<DicSection>("DIC");
  const auto& t = ctx.parameters().section<TestSection>("Test");
  DicStepOptions o;
  o.where = ctx.scene_file;
  o.dic = d.options();
  if (d.frames.empty())
    throw InputError(ctx.scene_file + ": DIC/Frames names no frame; give a glob or a list");
  o.frames =
      dic::expand_frame_list(d.frames, std::filesystem::path(ctx.scene_file).parent_path().string(),
                             ctx.scene_file + ": DIC/Frames");
  const auto machine = t.resolved_files(ctx.scene_file);
  if (machine.size() != 1)
    throw InputError(ctx.scene_file +
                     ": Test/Files must name the one machine record (time, "
                     "opening, load) that the DIC frames belong to; it lists " +
                     std::to_string(machine.size()));
  o.machine_record = machine.front();
  o.machine_read = ctx.record_chain().read;
  o.initial_crack = ctx.specimen().initial_crack;
  return o;
}

} // namespace fiberbridge::app
