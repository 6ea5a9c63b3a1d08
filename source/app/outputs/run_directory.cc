#include "fiberbridge/app/outputs/run_directory.h"

#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/output_guard.h"

#include <filesystem>

namespace fiberbridge::app {

void ensure_directory(const std::string& dir) {
  if (dir.find_first_not_of(" \t") == std::string::npos)
    throw InputError("Output directory is empty; expected a directory name (e.g. output/run)");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw InputError(dir + ": cannot create output directory (" + ec.message() + ")");
}

void remove_stale_summary(const std::string& out_dir) {
  // Marker first: from here until write_run_summary() the directory says it is incomplete, so a
  // run killed at any moment leaves either this marker or a finished run's summary.json.
  write_file_atomically(
      out_dir + "/" + incomplete_marker,
      "fiberbridge has not finished a run into this directory (the run is in progress, failed or "
      "was killed): the files here may come from this run or an earlier one. summary.json is "
      "written, and this file removed, only when a run completes.\n");
  std::error_code ec;
  std::filesystem::remove(out_dir + "/summary.json", ec);
  // Temporary files of a killed run (core writers write NAME.partial, then rename).
  for (const auto& entry : std::filesystem::directory_iterator(out_dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.size() > 8 && name.compare(name.size() - 8, 8, ".partial") == 0)
      std::filesystem::remove(entry.path(), ec);
  }
}

void write_run_summary(const std::string& out_dir, const Json& summary) {
  write_json_atomically(out_dir + "/summary.json", summary);
  if (!output_enabled()) // an MPI rank other than 0 (core/output_guard.h)
    return;
  std::error_code ec;
  std::filesystem::remove(out_dir + "/" + incomplete_marker, ec);
}

} // namespace fiberbridge::app
