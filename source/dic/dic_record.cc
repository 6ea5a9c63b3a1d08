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
