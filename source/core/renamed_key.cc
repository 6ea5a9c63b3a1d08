#include "fiberbridge/core/renamed_key.h"

#include "fiberbridge/core/error.h"

#include <cmath>
#include <stdexcept>

namespace fiberbridge {

std::optional<double> deprecated_number(const RenamedKey& k, const std::string& text,
                                        const std::string& expected, double lo, double hi,
                                        bool whole) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos)
    return std::nullopt;
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text.substr(first), &used);
  } catch (const std::exception&) {
    used = 0;
  }
  const bool number = used > 0 && text.find_first_not_of(" \t", first + used) == std::string::npos;
  if (!number || !std::isfinite(v) || v < lo || v > hi || (whole && v != std::round(v)))
    throw InputError(k.old_key() + ": expected " + expected + ", got '" + text + "'");
  return v;
}

double resolve_renamed(const RenamedKey& k, double value, bool given, const std::string& value_text,
                       std::optional<double> old_value, const std::string& old_text,
                       const std::string& why, std::vector<std::string>& notes) {
  if (!old_value)
    return value;
  if (given && *old_value != value)
    throw InputError(k.key() + " = " + value_text + " and " + k.old_key() + " = " + old_text +
                     " (its deprecated old name) disagree: give only " + k.key());
  notes.push_back(k.old_key() + " is deprecated: use " + k.key() + " (" + why + ")");
  return *old_value;
}

void note_ignored_key(const std::string& key, const std::string& text, const std::string& why,
                      std::vector<std::string>& notes) {
  if (!text.empty())
    notes.push_back(key + " is deprecated and ignored: " + why);
}

} // namespace fiberbridge
