// The table of DIC layouts (layouts.h): the registration list made into entries, and the lookups
// the reader, the virtual writer and the sections share.
#include "fiberbridge/dic/layouts.h"

#include "fiberbridge/core/error.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>

namespace fiberbridge::dic {

const std::vector<const LayoutEntry*>& layouts() {
#define FIBERBRIDGE_DIC_LAYOUT_ENTRY(name) &name##_layout(),
  static const std::vector<const LayoutEntry*> all{
      FIBERBRIDGE_DIC_LAYOUTS(FIBERBRIDGE_DIC_LAYOUT_ENTRY)};
#undef FIBERBRIDGE_DIC_LAYOUT_ENTRY
  return all;
}

const LayoutEntry& layout_entry(Layout layout) {
  for (const auto* e : layouts())
    if (e->id == layout)
      return *e;
  throw std::logic_error("dic::layout_entry: no entry for this layout");
}

const LayoutEntry* find_layout(std::string_view name) {
  for (const auto* e : layouts())
    if (name == e->name)
      return e;
  return nullptr;
}

namespace {

bool writes(const LayoutEntry& e) {
  return e.write_header && e.write_point;
}

std::string lower_trimmed(const std::string& text) {
  const auto b = text.find_first_not_of(" \t\r\n");
  const auto e = text.find_last_not_of(" \t\r\n");
  std::string t = b == std::string::npos ? "" : text.substr(b, e - b + 1);
  for (auto& c : t)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return t;
}

} // namespace

std::string layout_names(const char* sep, bool writable) {
  std::string s;
  for (const auto* e : layouts())
    if (!writable || writes(*e))
      s += (s.empty() ? "" : sep) + std::string(e->name);
  return s;
}

std::string layout_descriptions(bool writable) {
  std::string s;
  for (const auto* e : layouts())
    if (!writable || writes(*e))
      s += (s.empty() ? "" : ", ") + std::string(e->name) + " (" + e->description + ")";
  return s;
}

Layout parse_layout(const std::string& text, const std::string& where) {
  const std::string t = lower_trimmed(text);
  if (t == "auto" || t.empty())
    return Layout::automatic;
  if (const auto* e = find_layout(t))
    return e->id;
  throw InputError(where + ": '" + text + "' is not a frame layout; expected auto, " +
                   layout_names(", "));
}

Layout parse_written_layout(const std::string& text, const std::string& where) {
  const auto* e = find_layout(text);
  if (!e || !writes(*e))
    throw InputError(where + ": '" + text + "' is not a DIC layout; expected " +
                     layout_names(", ", true));
  return e->id;
}

const char* layout_name(Layout layout) {
  return layout == Layout::automatic ? "auto" : layout_entry(layout).name;
}

void append_values(std::string& t, std::initializer_list<double> values, const char* sep) {
  char b[32];
  bool first = true;
  for (const double v : values) {
    if (!first)
      t += sep;
    first = false;
    // to_chars: the shortest-path printer, several times faster than printf's %.9g.
    const auto r = std::to_chars(b, b + sizeof b, v, std::chars_format::general, 9);
    t.append(b, r.ptr);
  }
  t += '\n';
}

std::string number_text(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.9g", v);
  return b;
}

} // namespace fiberbridge::dic
