// Our record columns in a machine export: the column map, header matching with or without the
// unit, and unit conversion (record_columns.h).
#include "record_columns.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/text_encoding.h"
#include "fiberbridge/core/unit_parse.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>

namespace fiberbridge::analysis {

namespace {

using units::Dimension;

struct OurColumn {
  const char* name;
  Dimension dimension;
  const char* unit; ///< the unit in our name
};

constexpr OurColumn time_s{"time_s", Dimension::time, "s"};
constexpr OurColumn opening_mm{"opening_mm", Dimension::length, "mm"};
constexpr OurColumn load_N{"load_N", Dimension::force, "N"};
constexpr OurColumn a_mm{"a_mm", Dimension::length, "mm"};
constexpr OurColumn delta_root_mm{"delta_root_mm", Dimension::length, "mm"};

std::string lower(std::string s) {
  for (auto& c : s)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// The headers as decoded, numbered for the '#N' form, and the encoding they were decoded from:
/// a map written in the right characters matches nothing when the file's code page was guessed
/// wrong, and the garbled names alone do not say why (issue 42).
std::string headers_found(const ExportedTable& t) {
  std::string have;
  constexpr std::size_t max_listed = 40; // a 68 kB one-line message helps no one
  std::size_t listed = 0;
  for (std::size_t i = 0; i < t.header().size(); ++i) {
    if (t.header()[i].empty())
      continue;
    if (++listed > max_listed) {
      have += ", ...";
      break;
    }
    have += (have.empty() ? "#" : ", #") + std::to_string(i + 1) + " '" +
            message_excerpt(t.header()[i], 40) + "'";
    if (!t.units()[i].empty())
      have += " (" + message_excerpt(t.units()[i], 20) + ")";
  }
  return (have.empty() ? std::string("none") : have) + "; text read as " + t.layout().encoding +
         " (" + t.layout().encoding_how + "), Test/Encoding or --encoding overrides";
}

/// 'N' for a map entry '#N' (a column by its 1-based position); 0 when `wanted` is no such
/// entry.
std::size_t column_position(const std::string& wanted) {
  if (wanted.size() < 2 || wanted[0] != '#' || wanted.size() > 8)
    return 0;
  std::size_t n = 0;
  for (std::size_t i = 1; i < wanted.size(); ++i) {
    if (!std::isdigit(static_cast<unsigned char>(wanted[i])))
      return 0;
    n = 10 * n + static_cast<std::size_t>(wanted[i] - '0');
  }
  return n;
}

/// The column whose header is `wanted`: the whole text first, then the name without the unit
/// on both sides, then the same ignoring case. Several matches at one step are an error; no
/// match is std::nullopt.
std::optional<std::size_t> match_header(const ExportedTable& t, const std::string& wanted,
                                        const std::string& ours) {
  const auto& h = t.header();
  if (const std::size_t n = column_position(wanted)) {
    if (n > h.size())
      throw InputError(t.source() + ":" + std::to_string(t.layout().header_line) + ": '" + wanted +
                       "' for " + ours + " asks for column " + std::to_string(n) +
                       " but the rows have " + std::to_string(h.size()) +
                       " (headers found: " + headers_found(t) + ")");
    return n - 1;
  }
  if (wanted == "#0")
    throw InputError(t.source() + ": '#0' for " + ours + ": columns count from #1");
  const std::string wanted_name = units::split_header_unit(wanted).name;
  const auto equal_name = [&](std::size_t i, bool fold) {
    const std::string name = units::split_header_unit(h[i]).name;
    return fold ? lower(name) == lower(wanted_name) : name == wanted_name;
  };
  for (int step = 0; step < 3; ++step) {
    std::vector<std::size_t> hits;
    for (std::size_t i = 0; i < h.size(); ++i)
      if (!h[i].empty() && (step == 0 ? h[i] == wanted : equal_name(i, step == 2)))
        hits.push_back(i);
    if (hits.size() == 1)
      return hits[0];
    if (hits.size() > 1) {
      std::string names;
      for (auto i : hits)
        names += (names.empty() ? "'" : ", '") + message_excerpt(h[i], 40) + "'";
      throw InputError(t.source() + ":" + std::to_string(t.layout().header_line) + ": '" + wanted +
                       "' for " + ours + " matches several headers (" + names +
                       "); give the whole header in the column map");
    }
  }
  return std::nullopt;
}

/// A column that names the specimen of each row ("Specimen", "Specimen #", "Sample", "Probe",
/// "Probe-Nr."), when exactly one header is such a name; nullopt otherwise.
std::optional<std::size_t> specimen_column(const ExportedTable& t) {
  std::optional<std::size_t> found;
  for (std::size_t i = 0; i < t.header().size(); ++i) {
    std::string name = lower(units::split_header_unit(t.header()[i]).name);
    while (!name.empty() && (name.back() == '#' || name.back() == '.' || name.back() == ' '))
      name.pop_back();
    for (const char* w : {"specimen", "specimen no", "specimen number", "sample", "sample no",
                          "probe", "probe-nr", "probe nr", "probennummer"})
      if (name == w) {
        if (found)
          return std::nullopt;
        found = i;
      }
  }
  return found;
}

struct Found {
  std::size_t index;
  double factor; ///< file unit -> SI
  std::string note;
};

/// Locates `c`; nullopt when it is optional, not mapped and absent. A mapped column that is
/// absent, or a required one, is an error listing the headers found.
std::optional<Found> locate(const ExportedTable& t, const RecordColumnMap& map, const OurColumn& c,
                            bool required) {
  const bool mapped = map.file_header.count(c.name) > 0;
  const std::string wanted = map.header_for(c.name);
  const std::string at = t.source() + ":" + std::to_string(t.layout().header_line);
  const auto index = match_header(t, wanted, c.name);
  if (!index) {
    if (!required && !mapped)
      return std::nullopt;
    throw InputError(at + ": no column '" + wanted + "' for " + c.name + " (headers found: " +
                     headers_found(t) + "); name the header that holds " + c.name +
                     ", with or without its unit, or its position, in the column map "
                     "(Test/Columns or --columns), e.g. '" +
                     c.name + ": <header>' or '" + c.name + ": #3'");
  }
  const std::string& header = t.header()[*index];
  const std::string header_unit = units::split_header_unit(header).unit;
  const std::string row_unit = t.units()[*index];
  const std::string map_unit =
      mapped && !column_position(wanted) ? units::split_header_unit(wanted).unit : "";
  if (!header_unit.empty() && !row_unit.empty() && header_unit != row_unit)
    throw InputError(at + ": column '" + header + "' says '" + header_unit +
                     "' but the units row on line " + std::to_string(t.layout().units_line) +
                     " says '" + row_unit + "'");
  const std::string file_unit = header_unit.empty() ? row_unit : header_unit;
  if (!map_unit.empty() && !file_unit.empty() && map_unit != file_unit)
    throw InputError(at + ": the column map gives " + c.name + " as '" + wanted +
                     "' but the file's column '" + header + "' is in '" + file_unit + "'");
  std::string unit = file_unit, origin = "from the file";
  if (unit.empty() && !map_unit.empty()) {
    unit = map_unit;
    origin = "from the column map";
  }
  if (unit.empty()) {
    unit = c.unit;
    origin = "no unit in the file: taken from our name";
  }
  const double factor =
      units::si_factor(unit, c.dimension, at + ": column '" + header + "' for " + c.name);
  std::string note;
  if (header != c.name || unit != c.unit)
    note = std::string(c.name) + " from '" + header + "' in " + unit + " (" + origin + ")";
  return Found{*index, factor, note};
}

std::vector<double> si(const ExportedTable& t, const Found& f, std::size_t& grouped) {
  std::size_t g = 0;
  auto v = t.numeric(f.index, &g);
  grouped += g;
  for (std::size_t r = 0; r < v.size(); ++r) {
    v[r] *= f.factor;
    if (std::isinf(v[r])) // 1e308 kN: a number, but none a machine measures
      throw InputError(t.source() + ":" + std::to_string(t.line_of_row(r)) + ": column '" +
                       message_excerpt(t.header()[f.index]) + "' holds a value out of range");
  }
  return v;
}

/// Clock times ("13:45:02.25", "45:02,25", "2024-05-01 13:45:02"), as data loggers write the
/// time, in seconds from the first row; a clock passing midnight goes on counting. nullopt when
/// a cell that is not missing is no clock time.
std::optional<std::vector<double>> clock_seconds(const std::vector<std::string>& cells,
                                                 char decimal) {
  std::vector<double> out(cells.size(), NAN);
  double first = NAN, day = 0, last = NAN;
  for (std::size_t r = 0; r < cells.size(); ++r) {
    if (is_missing_value(cells[r]))
      continue;
    std::string c = cells[r];
    const auto space = c.find_last_of(" T");
    if (space != std::string::npos)
      c = c.substr(space + 1); // the date before the time of day
    double parts[3];
    std::size_t n = 0, from = 0;
    while (true) {
      const auto colon = c.find(':', from);
      const std::string part = c.substr(from, colon == std::string::npos ? colon : colon - from);
      if (n == 3 || !parse_exported_number(part, decimal, parts[n]) || parts[n] < 0)
        return std::nullopt;
      ++n;
      if (colon == std::string::npos)
        break;
      from = colon + 1;
    }
    if (n < 2)
      return std::nullopt;
    double seconds = 0;
    for (std::size_t k = 0; k < n; ++k)
      seconds = 60 * seconds + parts[k];
    if (!std::isnan(last) && seconds + day < last - 43200)
      day += 86400; // past midnight
    last = seconds + day;
    if (std::isnan(first))
      first = last;
    out[r] = last - first;
  }
  return out;
}

} // namespace

RecordColumns read_record_columns(const ExportedTable& t, const RecordReadOptions& o) {
  RecordColumns r;
  const RecordColumnMap& map = o.columns;
  std::vector<std::string> used;
  const auto note = [&](const std::optional<Found>& f) {
    if (f && !f->note.empty())
      used.push_back(f->note);
  };
  const auto opening = locate(t, map, opening_mm, true);
  const auto load = locate(t, map, load_N, true);
  const auto time = locate(t, map, time_s, false);
  const auto root = locate(t, map, delta_root_mm, false);
  const auto crack = o.crack_length == CrackLengthSource::equivalent
                         ? std::nullopt
                         : locate(t, map, a_mm, o.crack_length == CrackLengthSource::measured);
  for (const auto* f : {&time, &opening, &load, &crack, &root})
    note(*f);
  std::size_t grouped = 0;
  r.opening = si(t, *opening, grouped);
  r.load = si(t, *load, grouped);
  if (time) {
    r.has_time = true;
    try {
      r.time = si(t, *time, grouped);
    } catch (const InputError&) {
      const auto clock = clock_seconds(t.text(time->index), t.layout().decimal);
      if (!clock)
        throw;
      r.time = *clock;
      used.push_back("time_s read as clock times (seconds from the first row)");
    }
  }
  if (root) {
    r.has_root = true;
    r.root = si(t, *root, grouped);
  }
  if (crack) {
    r.has_crack = true;
    r.crack = si(t, *crack, grouped);
    r.crack_factor = crack->factor;
  }
  const std::string record_header = map.header_for("record");
  if (const auto i = match_header(t, record_header, "record")) {
    r.labels = t.text(*i);
    r.labels_header = t.header()[*i];
  } else if (const auto s = map.file_header.count("record") ? std::nullopt : specimen_column(t)) {
    // A machine's specimen column (a stacked export with one column naming the specimen).
    r.labels = t.text(*s);
    r.labels_header = t.header()[*s];
    r.labels_from_specimen_column = true;
    used.push_back("records split by the specimen column '" + t.header()[*s] + "'");
  } else if (map.file_header.count("record")) {
    throw InputError(t.source() + ":" + std::to_string(t.layout().header_line) + ": no column '" +
                     record_header + "' that the column map gives for record (headers found: " +
                     headers_found(t) + ")");
  }

  if (t.layout().is_export())
    r.notes.push_back(t.layout().describe());
  if (!used.empty()) {
    std::string s = "Columns: ";
    for (std::size_t i = 0; i < used.size(); ++i)
      s += (i ? "; " : "") + used[i];
    r.notes.push_back(s + ".");
  }
  if (grouped)
    r.notes.push_back(std::to_string(grouped) +
                      " number(s) written with thousands separators read as such.");
  if (o.crack_length == CrackLengthSource::equivalent)
    r.notes.push_back("Crack readings not used (Crack length = equivalent): R against the "
                      "equivalent crack length from the compliance.");
  else if (!crack)
    r.notes.push_back("No crack-length column ('" + map.header_for("a_mm") +
                      "' not among the headers): the record has no crack readings.");
  return r;
}

} // namespace fiberbridge::analysis
