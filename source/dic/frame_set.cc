// Frame files, their order and their times (frame_set.h).
#include "fiberbridge/dic/frame_set.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"

#include <algorithm>
#include <filesystem>
#include <glob.h>
#include <map>

namespace fiberbridge::dic {

namespace {

std::vector<std::string> glob_paths(const std::string& pattern) {
  std::vector<std::string> out;
  glob_t g{};
  if (::glob(pattern.c_str(), 0, nullptr, &g) == 0)
    for (std::size_t i = 0; i < g.gl_pathc; ++i)
      out.emplace_back(g.gl_pathv[i]);
  ::globfree(&g);
  return out;
}

/// The runs of digits in a file's name without folder and extension.
std::vector<long> digit_runs(const std::string& path) {
  const std::string name = std::filesystem::path(path).stem().string();
  std::vector<long> runs;
  for (std::size_t i = 0; i < name.size();) {
    if (!std::isdigit(static_cast<unsigned char>(name[i]))) {
      ++i;
      continue;
    }
    std::size_t e = i;
    while (e < name.size() && std::isdigit(static_cast<unsigned char>(name[e])))
      ++e;
    runs.push_back(std::stol(name.substr(i, std::min<std::size_t>(e - i, 15))));
    i = e;
  }
  return runs;
}

} // namespace

std::vector<std::string> expand_frame_list(const std::string& list, const std::string& base_dir,
                                           const std::string& where) {
  std::vector<std::string> out;
  for (const auto& entry : split_list(list, ',')) {
    const bool pattern = entry.find_first_of("*?[") != std::string::npos;
    std::vector<std::string> found;
    if (pattern) {
      found = glob_paths(entry);
      if (found.empty() && !base_dir.empty() && entry.front() != '/')
        found = glob_paths(base_dir + "/" + entry);
    } else if (std::filesystem::exists(entry)) {
      found = {entry};
    } else if (!base_dir.empty() && entry.front() != '/' &&
               std::filesystem::exists(base_dir + "/" + entry)) {
      found = {base_dir + "/" + entry};
    }
    if (found.empty())
      throw InputError(where + ": '" + entry + "' " + (pattern ? "matches no file" : "not found"));
    out.insert(out.end(), found.begin(), found.end());
  }
  if (out.empty())
    throw InputError(where + ": no frame files given");
  return out;
}

std::vector<FrameFile> order_frames(const std::vector<std::string>& paths,
                                    const std::string& where) {
  std::vector<FrameFile> files;
  for (const auto& p : paths)
    files.push_back({p, -1});
  std::vector<std::vector<long>> runs;
  for (const auto& p : paths)
    runs.push_back(digit_runs(p));
  const std::size_t count = runs.empty() ? 0 : runs.front().size();
  const bool same_count = std::all_of(
      runs.begin(), runs.end(), [&](const std::vector<long>& r) { return r.size() == count; });
  if (!same_count || count == 0)
    return files;
  // The first run that differs between the files; a single file: its first run.
  std::size_t pick = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const bool varies = std::any_of(runs.begin(), runs.end(), [&](const std::vector<long>& r) {
      return r[k] != runs.front()[k];
    });
    if (varies) {
      pick = k;
      break;
    }
  }
  for (std::size_t i = 0; i < files.size(); ++i)
    files[i].number = runs[i][pick];
  std::stable_sort(files.begin(), files.end(),
                   [](const FrameFile& a, const FrameFile& b) { return a.number < b.number; });
  for (std::size_t i = 1; i < files.size(); ++i)
    if (files[i].number == files[i - 1].number)
      throw InputError(where + ": two frames carry image number " +
                       std::to_string(files[i].number) + ": " + files[i - 1].path + " and " +
                       files[i].path);
  return files;
}

FrameTimeSource parse_frame_time_source(const std::string& text, const std::string& where) {
  const std::string t = trim_blanks(text);
  if (t == "auto" || t.empty())
    return FrameTimeSource::automatic;
  if (t == "column")
    return FrameTimeSource::column;
  if (t == "name")
    return FrameTimeSource::name;
  if (t == "index")
    return FrameTimeSource::index;
  throw InputError(where + ": '" + text + "'; expected auto, column, name or index");
}

const char* frame_time_source_name(FrameTimeSource s) {
  switch (s) {
  case FrameTimeSource::column:
    return "column";
  case FrameTimeSource::name:
    return "name";
  case FrameTimeSource::index:
    return "index";
  default:
    return "auto";
  }
}

std::vector<double> frame_times(const std::vector<FrameFile>& files,
                                const std::vector<double>& column_times, const FrameClock& clock,
                                FrameTimeSource& used) {
  used = clock.source;
  const bool all_columns =
      !column_times.empty() && std::all_of(column_times.begin(), column_times.end(),
                                           [](double t) { return std::isfinite(t); });
  const bool all_numbers = !files.empty() && files.front().number >= 0;
  if (used == FrameTimeSource::automatic)
    used = all_columns   ? FrameTimeSource::column
           : all_numbers ? FrameTimeSource::name
                         : FrameTimeSource::index;
  if (used == FrameTimeSource::column && !all_columns)
    throw InputError("DIC/Frame time source = column, but frame " +
                     files[std::find_if(column_times.begin(), column_times.end(),
                                        [](double t) { return !std::isfinite(t); }) -
                           column_times.begin()]
                         .path +
                     " has no time column (map time_s in the frame Columns)");
  if (used == FrameTimeSource::name && !all_numbers)
    throw InputError("DIC/Frame time source = name, but the frame names carry no image number "
                     "that changes from file to file (e.g. " +
                     files.front().path + ")");
  if (used != FrameTimeSource::column && !(clock.frame_rate > 0))
    throw InputError("DIC/Frame rate must be positive, got " + fmt(clock.frame_rate));
  std::vector<double> t(files.size());
  for (std::size_t i = 0; i < files.size(); ++i) {
    switch (used) {
    case FrameTimeSource::column:
      t[i] = clock.first_frame_time + column_times[i] - column_times[0];
      break;
    case FrameTimeSource::name:
      t[i] = clock.first_frame_time +
             static_cast<double>(files[i].number - files[0].number) / clock.frame_rate;
      break;
    default:
      t[i] = clock.first_frame_time + static_cast<double>(i) / clock.frame_rate;
    }
    if (i > 0 && !(t[i] > t[i - 1]))
      throw InputError("frames out of time order: " + files[i].path + " (t = " + fmt(t[i]) +
                       " s) comes after " + files[i - 1].path + " (t = " + fmt(t[i - 1]) +
                       " s) in image order");
  }
  return t;
}

} // namespace fiberbridge::dic
