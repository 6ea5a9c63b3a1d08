#pragma once
// A raw DCB test record as a testing machine writes it: load, load-line opening and crack-length
// readings in time order, sometimes a measured notch-root opening (clip gauge, DIC). SI inside.
// This struct is the hand-over between the record reader, the direct-energy and beam-theory
// reductions (`reduce`) and the identification of the law from the record (`identify`).
#include <cstddef>
#include <string>
#include <vector>

namespace fiberbridge::analysis {

struct TestRecord {
  std::string name;   ///< record label: the `record` column's value, or the file's stem
  std::string source; ///< the file it came from (for messages)
  std::vector<double> time;         ///< [s]; empty when the file has no time column
  std::vector<double> opening;      ///< load-line opening [m]
  std::vector<double> load;         ///< load on the whole specimen width [N]
  std::vector<double> crack_length; ///< crack length from the load line [m]
  std::vector<double> delta_root;   ///< measured notch-root opening [m]; empty when not measured
  std::vector<std::size_t> line;    ///< source line of each kept row (1-based, for messages)
  std::vector<std::string> cleaning; ///< what the reader did to the raw rows, one sentence each
};

} // namespace fiberbridge::analysis
