#pragma once
// The hand-over to `reduce`: the testing machine's record (time, load-line opening, load) and the
// DIC readings (crack length, delta_root) matched by time into one test record, one row per frame
// inside the machine record's time span (dic_record.csv: time_s, opening_mm, load_N, a_mm,
// delta_root_mm, a_sd_mm, delta_root_sd_mm).
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace fiberbridge::dic {

/// The machine record's channels in time order; the app reads it as `reduce` reads a record
/// (app/items/dic_step.h, read_machine_record), so that one column map and one reader serve both.
struct MachineRecord {
  std::string source;
  std::vector<double> time;    ///< [s], not decreasing
  std::vector<double> opening; ///< [m]
  std::vector<double> load;    ///< [N]
};

/// Linear interpolation of the record at t (inside [time.front(), time.back()]).
void machine_at(const MachineRecord& record, double t, double& opening, double& load);

struct DicRecordRow {
  double time = NAN;                            ///< [s]
  double opening = NAN;                         ///< [m]
  double load = NAN;                            ///< [N]
  double a = NAN, a_sd = NAN;                   ///< [m]
  double delta_root = NAN, delta_root_sd = NAN; ///< [m]
  std::size_t frame = 0;                        ///< index of the frame it came from
};

/// The text of dic_record.csv (mm and N, as the records reduce reads) with provenance comments.
std::string dic_record_text(const std::vector<DicRecordRow>& rows,
                            const std::vector<std::string>& comments);
/// Writes it atomically (core/csv.h; nothing on MPI ranks other than 0, core/output_guard.h).
void write_dic_record(const std::string& path, const std::vector<DicRecordRow>& rows,
                      const std::vector<std::string>& comments);

} // namespace fiberbridge::dic
