#pragma once
// Scene keys renamed under the deprecation rule (docs/design.md section 5): the old name stays
// declared (pattern Anything, default "" = not given) next to the new one, and when a scene gives
// it, its value is used and the run's notes say so. One mechanism for every section (Beam, FEM,
// MPM); free of deal.II so that the sections' parse_parameters pass it the texts they read.
#include <optional>
#include <string>
#include <vector>

namespace fiberbridge {

/// A key of a section and the old name it replaced ("MPM", "Tip advance", "Growth step").
struct RenamedKey {
  std::string section, name, old_name;

  std::string key() const { return section + "/" + name; }
  std::string old_key() const { return section + "/" + old_name; }
};

/// The number given under the old name, or nothing when it is not given (empty text). The old
/// name's pattern is Anything (an empty default must match), so its range is checked here: throws
/// InputError "<Section/old name>: expected <expected>, got '<text>'" for anything but one number
/// in [lo, hi] (a whole number if `whole`).
std::optional<double> deprecated_number(const RenamedKey& k, const std::string& text,
                                        const std::string& expected, double lo, double hi,
                                        bool whole = false);

/// The value to use for a renamed key. `value`: the new key's value; `given`: it differs from its
/// default (a ParameterHandler does not tell a default from the same value written out, so a new
/// key at its default counts as not given). `old_value`: the old name's value in the new key's
/// meaning (deprecated_number, converted), nothing when not given. Returns `value` unless the old
/// name is given; then the old name's value, with the note "<old> is deprecated: use <new>
/// (<why>)" in `notes`. Both given with different values: InputError naming both keys with the
/// texts a scene wrote (`value_text`, `old_text`), since it is not clear which one was meant.
double resolve_renamed(const RenamedKey& k, double value, bool given, const std::string& value_text,
                       std::optional<double> old_value, const std::string& old_text,
                       const std::string& why, std::vector<std::string>& notes);

/// A key that is still declared but no longer used: when a scene gives it (`text` not empty), the
/// note "<key> is deprecated and ignored: <why>" goes into `notes`.
void note_ignored_key(const std::string& key, const std::string& text, const std::string& why,
                      std::vector<std::string>& notes);

} // namespace fiberbridge
