#include "fiberbridge/core/summary.h"

#include "fiberbridge/core/csv.h"

namespace fiberbridge {

void write_json_atomically(const std::string& path, const Json& j) {
  write_file_atomically(path, j.dump(2) + "\n");
}

} // namespace fiberbridge
