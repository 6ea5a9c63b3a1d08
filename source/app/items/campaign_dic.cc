// DIC sets in a campaign's manifest (campaign_dic.h).
#include "fiberbridge/app/items/campaign_dic.h"

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
  o.where = set;
  o.dic = sets.dic.options();
  o.frames = dic::expand_frame_list(list, "", set + ": DIC/Frames");
  o.machine_record = (fs::path(row.file) / sets.test.files.front()).string();
  if (!fs::is_regular_file(o.machine_record))
    throw InputError(set + ": Test/Files: machine record '" + sets.test.files.front() +
                     "' not found in the set's folder");
  o.machine_read = sets.read;
  o.initial_crack = std::isfinite(row.initial_crack) ? row.initial_crack : sets.scene_initial_crack;
  // The DIC step's own code (dic_step.h) without its files (run_dic writes them for a scene's dic).
  const DicMatch match = match_dic_frames(o);
  record_text = dic::dic_record_text(
      match.rows,
      dic_record_comments(o, match,
                          "Test record of " + row.material + " at " + fmt(row.cycles) +
                              " cycles, specimen " + row.specimen + ", from the DIC set " +
                              row.file_as_written + " (fiberbridge campaign)"));
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
