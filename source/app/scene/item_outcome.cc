#include "fiberbridge/app/scene/item_outcome.h"

namespace fiberbridge::app {

void ItemReport::append(ItemReport other) {
  for (auto& [key, block] : other.blocks.items())
    blocks[key] = std::move(block);
  for (auto& p : other.plots)
    plots.push_back(std::move(p));
}

bool ItemOutcome::hands_on_analysis() const {
  return records || reduced || rdelta_root || extraction || identification || law || specimen ||
         records_from_dic;
}

void add_report_to_summary(const ItemReport& report, Json& summary) {
  for (const auto& [key, block] : report.blocks.items())
    summary[key] = block;
  for (const auto& p : report.plots)
    summary["plots"].push_back(p);
}

} // namespace fiberbridge::app
