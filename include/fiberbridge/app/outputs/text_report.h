#pragma once
// report.txt: the key numbers of a run's summary as a few lines of text.
#include <nlohmann/json.hpp>

#include <string>

namespace fiberbridge::app {

/// The key numbers of a summary as a few lines of text (report.txt, and printed after a run).
std::string text_report(const nlohmann::ordered_json& summary);

} // namespace fiberbridge::app
