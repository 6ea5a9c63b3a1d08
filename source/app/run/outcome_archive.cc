#include "fiberbridge/app/run/outcome_archive.h"

#include "fiberbridge/core/json_archive.h"
#include "fiberbridge/result/result_archive.h"

#include <stdexcept>

namespace fiberbridge {

void BinaryCodec<app::ItemOutcome>::save(BinaryWriter& out, const app::ItemOutcome& o) {
  if (o.hands_on_analysis() || !o.simulation)
    throw std::logic_error("outcome_archive: only a simulation item's outcome is archived");
  out.put(o.report.blocks);
  out.put(Json(o.report.plots));
  out.put(*o.simulation);
}

void BinaryCodec<app::ItemOutcome>::load(BinaryReader& in, app::ItemOutcome& o) {
  o = app::ItemOutcome{};
  in.get(o.report.blocks);
  Json plots;
  in.get(plots);
  o.report.plots = plots.get<std::vector<std::string>>();
  o.simulation.emplace();
  in.get(*o.simulation);
}

} // namespace fiberbridge
