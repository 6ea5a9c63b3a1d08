// DIC sets in a campaign's manifest (campaign_dic.h).
#include "fiberbridge/app/campaign_dic.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/dic/dic_analysis.h"
#include "fiberbridge/dic/dic_record.h"
#include "fiberbridge/dic/frame_set.h"

#include <atomic>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace fiberbridge::app {

namespace fs = std::filesystem;

analysis::TestRecord read_campaign_dic_set(const analysis::CampaignRow& row,
                                           const CampaignDicSets& sets, std::string& record_text) {
  // Errors get the manifest line from load_campaign_specimen; messages of the DIC step name it.
  const std::string set = "DIC set '" + row.file_as_written + "'";
  if (trim_blanks(sets.dic.frames).empty())
    throw InputError(set + ": DIC/Frames must name the frames inside each set's folder (a glob "
                           "relative to it, e.g. frames/*.csv)");
  if (sets.test.files.size() != 1)
    throw InputError(set + ": Test/Files must name the one machine record (time, opening, load) "
                           "inside each set's folder, e.g. machine.csv");
  // Entries relative to the set's folder (expand_frame_list would try them as given first).
  std::string list;
  for (std::size_t b = 0; b <= sets.dic.frames.size();) {
    auto e = sets.dic.frames.find(',', b);
    if (e == std::string::npos)
      e = sets.dic.frames.size();
    const std::string entry = trim_blanks(sets.dic.frames.substr(b, e - b));
    b = e + 1;
    if (!entry.empty())
      list += (list.empty() ? "" : ",") +
              (fs::path(entry).is_absolute() ? entry : (fs::path(row.file) / entry).string());
  }
  DicStepOptions o;
  o.dic = sets.dic.options();
  o.frames = dic::expand_frame_list(list, "", set + ": DIC/Frames");
  o.machine_record = (fs::path(row.file) / sets.test.files.front()).string();
  if (!fs::is_regular_file(o.machine_record))
    throw InputError(set + ": Test/Files: machine record '" + sets.test.files.front() +
                     "' not found in the set's folder");
  o.machine_columns = sets.test.columns;
  o.initial_crack = std::isfinite(row.initial_crack) ? row.initial_crack : sets.scene_initial_crack;
  // The DIC step without its files (dic_step.cc: run_dic writes them for a scene's own dic).
  const auto files = dic::order_frames(o.frames, set + ": DIC/Frames");
  const dic::DicAnalysis analysis = dic::analyse_frames(files, o.dic);
  const dic::MachineRecord machine =
      dic::read_machine_record(o.machine_record, o.machine_columns, set + ": Test/Columns");
  std::vector<std::string> notes;
  const auto rows = dic::match_to_machine(analysis, machine, o.initial_crack, notes);
  record_text = dic::dic_record_text(
      rows, {"Test record of " + row.material + " at " + fmt(row.cycles) + " cycles, specimen " +
                 row.specimen + ", from the DIC set " + row.file_as_written +
                 " (fiberbridge campaign): a = a0 " + fmt(o.initial_crack * 1e3) +
                 " mm + the shift of the " + fmt(100 * o.dic.tip.threshold) +
                 " % crack-normal strain point; delta_root by a virtual extensometer of " +
                 fmt(o.dic.gauge_length * 1e3) + " mm",
             "machine record: " + o.machine_record + "; " + std::to_string(rows.size()) +
                 " frames inside its time span"});
  // Read back as reduce reads dic_record.csv (our column names, the Test section's cleaning):
  // through a private file, removed at once.
  static std::atomic<unsigned> serial{0};
  const fs::path tmp =
      fs::temp_directory_path() / ("fiberbridge_campaign_dic_" + std::to_string(::getpid()) + "_" +
                                   std::to_string(serial++) + ".csv");
  std::ofstream(tmp) << record_text;
  analysis::RecordReadOptions read = sets.read;
  read.columns = {};
  std::vector<analysis::TestRecord> records;
  try {
    records = analysis::read_test_records(tmp.string(), read);
  } catch (...) {
    fs::remove(tmp);
    throw;
  }
  fs::remove(tmp);
  if (records.size() != 1)
    throw InputError(set + ": the DIC step gave " + std::to_string(records.size()) + " records");
  records.front().name = row.specimen;
  records.front().source = row.file;
  return records.front();
}

} // namespace fiberbridge::app
