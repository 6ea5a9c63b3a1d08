// The machine record and the matched test record (dic_record.h).
#include "fiberbridge/dic/dic_record.h"

#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/units.h"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace fiberbridge::dic {

namespace {

std::string trim(const std::string& s) {
  return trim_blanks(s);
}

/// our name -> file header, from "ours: theirs, ..." (entries for other names are ignored).
std::map<std::string, std::string> parse_columns(const std::string& text,
                                                 const std::string& where) {
  std::map<std::string, std::string> map;
  for (const auto& entry : split_list(text, ',')) {
    const auto colon = entry.find(':');
    if (colon == std::string::npos)
      throw InputError(where + ": entry '" + entry + "' has no ':' (expected 'our_name: header')");
    map[trim(entry.substr(0, colon))] = trim(entry.substr(colon + 1));
  }
  return map;
}

} // namespace

MachineRecord read_machine_record(const std::string& path, const std::string& columns,
                                  const std::string& where) {
  const auto map = parse_columns(columns, where);
  const auto header = [&](const char* ours) {
    const auto it = map.find(ours);
    return it == map.end() ? std::string(ours) : it->second;
  };
  const CsvTable table = CsvTable::read(path);
  MachineRecord r;
  r.source = path;
  r.time = table.numeric(header("time_s"));
  r.opening = table.numeric(header("opening_mm"));
  r.load = table.numeric(header("load_N"));
  for (auto& o : r.opening)
    o *= units::mm;
  if (r.time.size() < 2)
    throw InputError(path + ": the machine record needs at least 2 rows");
  for (std::size_t i = 1; i < r.time.size(); ++i)
    if (r.time[i] < r.time[i - 1])
      throw InputError(path + ":" + std::to_string(table.line_of_row(i)) +
                       ": time decreases (machine record rows must be in time order)");
  return r;
}

void machine_at(const MachineRecord& r, double t, double& opening, double& load) {
  const auto it = std::upper_bound(r.time.begin(), r.time.end(), t);
  std::size_t j = static_cast<std::size_t>(it - r.time.begin());
  j = std::clamp<std::size_t>(j, 1, r.time.size() - 1);
  const double t0 = r.time[j - 1], t1 = r.time[j];
  const double w = t1 > t0 ? std::clamp((t - t0) / (t1 - t0), 0.0, 1.0) : 1.0;
  opening = r.opening[j - 1] + w * (r.opening[j] - r.opening[j - 1]);
  load = r.load[j - 1] + w * (r.load[j] - r.load[j - 1]);
}

std::string dic_record_text(const std::vector<DicRecordRow>& rows,
                            const std::vector<std::string>& comments) {
  std::ostringstream s;
  s << std::setprecision(10);
  for (const auto& c : comments)
    s << "# " << c << "\n";
  s << "time_s,opening_mm,load_N,a_mm,delta_root_mm,a_sd_mm,delta_root_sd_mm\n";
  for (const auto& r : rows)
    s << r.time << ',' << r.opening / units::mm << ',' << r.load << ',' << r.a / units::mm << ','
      << r.delta_root / units::mm << ',' << r.a_sd / units::mm << ',' << r.delta_root_sd / units::mm
      << '\n';
  return s.str();
}

void write_dic_record(const std::string& path, const std::vector<DicRecordRow>& rows,
                      const std::vector<std::string>& comments) {
  write_file_atomically(path, dic_record_text(rows, comments));
}

} // namespace fiberbridge::dic
