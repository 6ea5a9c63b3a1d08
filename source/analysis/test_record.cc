// Reading raw DCB test records and cleaning what real machines write (test_record.h).
#include "fiberbridge/analysis/test_record.h"

#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <algorithm>
#include <sstream>

namespace fiberbridge::analysis {

namespace {

constexpr std::size_t min_rows = 8;
const char* const our_columns[] = {"time_s", "opening_mm",    "load_N",
                                   "a_mm",   "delta_root_mm", "record"};

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos)
    return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

std::string where(const std::string& source, std::size_t line) {
  return source + ":" + std::to_string(line);
}

std::string num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string stem(const std::string& path) {
  const auto slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const auto dot = name.find_last_of('.');
  return dot == std::string::npos || dot == 0 ? name : name.substr(0, dot);
}

/// The raw rows of one record (indices into the table), in file order.
struct RawRecord {
  std::string name;
  std::vector<std::size_t> rows;
};

/// Rows kept so far, as indices into the table, with the values that cleaning may change.
struct Rows {
  std::vector<std::size_t> row;
  std::vector<double> time, opening, load, a, root;
};

/// Keeps the rows where keep[i] is true.
void filter(Rows& r, const std::vector<bool>& keep) {
  Rows out;
  for (std::size_t i = 0; i < r.row.size(); ++i) {
    if (!keep[i])
      continue;
    out.row.push_back(r.row[i]);
    out.opening.push_back(r.opening[i]);
    out.load.push_back(r.load[i]);
    out.a.push_back(r.a[i]);
    if (!r.time.empty())
      out.time.push_back(r.time[i]);
    if (!r.root.empty())
      out.root.push_back(r.root[i]);
  }
  r = std::move(out);
}

class RecordCleaner {
public:
  RecordCleaner(const CsvTable& t, const RecordReadOptions& o) : t_(t), o_(o) {}

  TestRecord clean(const RawRecord& raw, const std::vector<double>* time,
                   const std::vector<double>& opening_mm, const std::vector<double>& load,
                   const std::vector<double>& a_mm, const std::vector<double>* root_mm) {
    name_ = raw.name;
    Rows r;
    for (std::size_t row : raw.rows) {
      r.row.push_back(row);
      r.opening.push_back(opening_mm[row] * units::mm);
      r.load.push_back(load[row]);
      r.a.push_back(a_mm[row] * units::mm);
      if (time)
        r.time.push_back((*time)[row]);
      if (root_mm)
        r.root.push_back((*root_mm)[row] * units::mm);
    }
    check_raw(r);
    cleaning_.clear();
    clamp_leading_negative_loads(r);
    drop_after_final_drop(r);
    drop_duplicated_times(r);
    drop_unload_reload(r);
    check_loads(r);
    smooth_crack_back_steps(r);
    check_growth(r);

    TestRecord out;
    out.name = raw.name;
    out.source = t_.source();
    out.time = r.time;
    out.opening = r.opening;
    out.load = r.load;
    out.crack_length = r.a;
    out.delta_root = r.root;
    for (std::size_t row : r.row)
      out.line.push_back(t_.line_of_row(row));
    count_repeated_readings(out);
    out.cleaning = cleaning_;
    return out;
  }

private:
  std::string at(const Rows& r, std::size_t i) const {
    return where(t_.source(), t_.line_of_row(r.row[i])) + ": ";
  }
  std::string line(const Rows& r, std::size_t i) const {
    return std::to_string(t_.line_of_row(r.row[i]));
  }
  std::string lines(const Rows& r, std::size_t first, std::size_t last) const {
    return first == last ? "line " + line(r, first)
                         : "lines " + line(r, first) + "-" + line(r, last);
  }
  std::string label() const { return "record '" + name_ + "'"; }

  /// What cannot be cleaned: decreasing time, negative openings or crack lengths.
  void check_raw(const Rows& r) const {
    for (std::size_t i = 0; i < r.row.size(); ++i) {
      if (!r.time.empty() && i > 0 && r.time[i] < r.time[i - 1])
        throw InputError(at(r, i) + "time_s = " + num(r.time[i]) + " is earlier than " +
                         num(r.time[i - 1]) + " on line " + line(r, i - 1) + " (" + label() +
                         "); a record must be in time order");
      if (r.opening[i] < 0)
        throw InputError(at(r, i) + "opening_mm = " + num(r.opening[i] / units::mm) +
                         " is negative; the load-line opening must be >= 0");
      if (!(r.a[i] > 0))
        throw InputError(at(r, i) + "a_mm = " + num(r.a[i] / units::mm) +
                         " is not positive; the crack length from the load line must be > 0");
      if (!r.root.empty() && r.root[i] < 0)
        throw InputError(at(r, i) + "delta_root_mm = " + num(r.root[i] / units::mm) +
                         " is negative; the notch-root opening must be >= 0");
    }
  }

  void clamp_leading_negative_loads(Rows& r) {
    std::size_t n = 0;
    double lowest = 0;
    for (std::size_t i = 0; i < r.load.size() && !(r.load[i] > 0); ++i)
      if (r.load[i] < 0) {
        lowest = std::min(lowest, r.load[i]);
        r.load[i] = 0;
        ++n;
      }
    if (n)
      cleaning_.push_back(std::to_string(n) + " leading row(s) with a negative load (lowest " +
                          num(lowest) + " N, load-cell offset before contact) set to 0 N.");
  }

  void drop_after_final_drop(Rows& r) {
    const double peak = *std::max_element(r.load.begin(), r.load.end());
    if (!(peak > 0))
      throw InputError(t_.source() + ": " + label() + " (" + lines(r, 0, r.row.size() - 1) +
                       ") never carries a positive load_N; nothing to reduce");
    std::size_t last = r.load.size() - 1;
    while (r.load[last] < o_.final_drop_fraction * peak)
      --last;
    if (last + 1 == r.load.size())
      return;
    cleaning_.push_back(std::to_string(r.load.size() - 1 - last) +
                        " row(s) after the final drop (" + lines(r, last + 1, r.load.size() - 1) +
                        ", load below " + num(o_.final_drop_fraction) + " of the peak " +
                        num(peak) + " N) dropped.");
    std::vector<bool> keep(r.load.size(), false);
    std::fill(keep.begin(), keep.begin() + last + 1, true);
    filter(r, keep);
  }

  void drop_duplicated_times(Rows& r) {
    if (r.time.empty())
      return;
    std::vector<bool> keep(r.time.size(), true);
    std::size_t n = 0, first = 0;
    for (std::size_t i = 1; i < r.time.size(); ++i)
      if (r.time[i] == r.time[i - 1]) {
        keep[i] = false;
        if (n++ == 0)
          first = i;
      }
    if (!n)
      return;
    cleaning_.push_back(std::to_string(n) +
                        " row(s) repeating the time of the row before dropped (first on line " +
                        line(r, first) + "; the first row of each time kept).");
    filter(r, keep);
  }

  void drop_unload_reload(Rows& r) {
    std::vector<bool> keep(r.opening.size(), true);
    double envelope = r.opening[0];
    std::size_t segments = 0, dropped = 0;
    std::string first_segment;
    bool tail = false;
    for (std::size_t i = 1; i < r.opening.size();) {
      if (r.opening[i] >= envelope) {
        envelope = r.opening[i++];
        continue;
      }
      const std::size_t begin = i;
      while (i < r.opening.size() && r.opening[i] <= envelope)
        keep[i++] = false;
      dropped += i - begin;
      if (i == r.opening.size())
        tail = true;
      else if (segments++ == 0)
        first_segment = lines(r, begin, i - 1);
    }
    if (segments)
      cleaning_.push_back(std::to_string(segments) +
                          " unload/reload segment(s) dropped (first: " + first_segment +
                          "): rows below the largest opening so far; the loading envelope is "
                          "kept.");
    if (tail) {
      std::size_t first = r.opening.size();
      while (first > 0 && !keep[first - 1])
        --first;
      cleaning_.push_back(std::to_string(r.opening.size() - first) +
                          " row(s) at the end where the opening never again exceeds its largest "
                          "value (" +
                          lines(r, first, r.opening.size() - 1) +
                          ": crosshead stopped or unloading) dropped.");
    }
    if (dropped)
      filter(r, keep);
  }

  void check_loads(const Rows& r) const {
    bool started = false;
    for (std::size_t i = 0; i < r.load.size(); ++i) {
      started = started || r.load[i] > 0;
      if (started && r.load[i] < 0)
        throw InputError(at(r, i) + "load_N = " + num(r.load[i]) +
                         " is negative after the "
                         "test started (" +
                         label() + "); a DCB is loaded in tension");
    }
  }

  void smooth_crack_back_steps(Rows& r) {
    std::size_t n = 0;
    double largest = 0, running = r.a[0];
    for (std::size_t i = 1; i < r.a.size(); ++i) {
      if (r.a[i] >= running) {
        running = r.a[i];
        continue;
      }
      const double back = running - r.a[i];
      if (back > o_.crack_back_tolerance)
        throw InputError(at(r, i) + "a_mm = " + num(r.a[i] / units::mm) + " is " +
                         num(back / units::mm) + " mm shorter than the longest reading before (" +
                         num(running / units::mm) + " mm); a crack length must not go back by " +
                         "more than the tracking tolerance of " +
                         num(o_.crack_back_tolerance / units::mm) + " mm");
      largest = std::max(largest, back);
      r.a[i] = running;
      ++n;
    }
    if (n)
      cleaning_.push_back(std::to_string(n) + " crack reading(s) stepping back (at most " +
                          num(largest / units::mm) + " mm, within the tracking tolerance of " +
                          num(o_.crack_back_tolerance / units::mm) +
                          " mm) replaced by the longest reading before: a crack does not heal.");
  }

  void check_growth(const Rows& r) const {
    if (r.row.size() < min_rows)
      throw InputError(t_.source() + ": " + label() + " has " + std::to_string(r.row.size()) +
                       " rows after cleaning (" + lines(r, 0, r.row.size() - 1) + "); at least " +
                       std::to_string(min_rows) + " are needed");
    if (!(r.a.back() > r.a.front()))
      throw InputError(at(r, r.row.size() - 1) + label() + ": the crack length stays at " +
                       num(r.a.front() / units::mm) + " mm from line " + line(r, 0) +
                       " to here; no crack growth, so no R curve");
  }

  void count_repeated_readings(const TestRecord& out) {
    const std::size_t readings = crack_reading_rows(out).size();
    const std::size_t repeated = out.crack_length.size() - readings;
    if (repeated)
      cleaning_.push_back(std::to_string(repeated) + " of " +
                          std::to_string(out.crack_length.size()) +
                          " rows repeat the crack reading of the row before (kept for load and "
                          "opening; the reductions use the " +
                          std::to_string(readings) + " rows with a new reading).");
  }

  const CsvTable& t_;
  const RecordReadOptions& o_;
  std::string name_;
  std::vector<std::string> cleaning_;
};

} // namespace

RecordColumnMap RecordColumnMap::parse(const std::string& text, const std::string& where_) {
  RecordColumnMap m;
  if (trim(text).empty())
    return m;
  std::istringstream in(text);
  std::string entry;
  while (std::getline(in, entry, ',')) {
    entry = trim(entry);
    if (entry.empty())
      continue;
    const auto colon = entry.find(':');
    if (colon == std::string::npos)
      throw InputError(where_ + ": column map entry '" + entry +
                       "' has no ':'; expected 'our_name: File header', e.g. 'load_N: Load (N)'");
    const std::string ours = trim(entry.substr(0, colon));
    const std::string theirs = trim(entry.substr(colon + 1));
    if (std::find(std::begin(our_columns), std::end(our_columns), ours) == std::end(our_columns))
      throw InputError(where_ + ": column map names '" + ours +
                       "'; expected one of time_s, opening_mm, load_N, a_mm, delta_root_mm, "
                       "record");
    if (theirs.empty())
      throw InputError(where_ + ": column map entry '" + ours + "' gives no file header");
    if (!m.file_header.emplace(ours, theirs).second)
      throw InputError(where_ + ": column map names '" + ours + "' twice");
  }
  return m;
}

std::string RecordColumnMap::header_for(const std::string& ours) const {
  const auto it = file_header.find(ours);
  return it == file_header.end() ? ours : it->second;
}

std::vector<TestRecord> read_test_records(const std::string& path,
                                          const RecordReadOptions& options) {
  const CsvTable t = CsvTable::read(path);
  const RecordColumnMap& map = options.columns;
  for (const char* required : {"opening_mm", "load_N", "a_mm"}) {
    const std::string h = map.header_for(required);
    if (!t.has_column(h)) {
      std::string have;
      for (const auto& c : t.header())
        have += (have.empty() ? "" : ", ") + c;
      throw InputError(path + ":1: missing column '" + h + "' for " + required +
                       " (columns present: " + have +
                       "; map the file's headers with Columns, e.g. '" + required + ": " +
                       (have.empty() ? std::string("Header") : t.header().front()) + "')");
    }
  }
  // numeric() rejects empty, non-numeric, NaN and infinite cells naming file:line.
  const auto opening = t.numeric(map.header_for("opening_mm"));
  const auto load = t.numeric(map.header_for("load_N"));
  const auto a = t.numeric(map.header_for("a_mm"));
  std::vector<double> time, root;
  const bool has_time = t.has_column(map.header_for("time_s"));
  const bool has_root = t.has_column(map.header_for("delta_root_mm"));
  for (const char* optional : {"time_s", "delta_root_mm", "record"})
    if (map.file_header.count(optional) && !t.has_column(map.header_for(optional)))
      throw InputError(path + ":1: missing column '" + map.header_for(optional) +
                       "' that the column map gives for " + optional);
  if (has_time)
    time = t.numeric(map.header_for("time_s"));
  if (has_root)
    root = t.numeric(map.header_for("delta_root_mm"));

  std::vector<RawRecord> raw;
  if (t.has_column(map.header_for("record"))) {
    const auto& labels = t.text(map.header_for("record"));
    std::map<std::string, std::size_t> index;
    for (std::size_t row = 0; row < t.n_rows(); ++row) {
      if (labels[row].empty())
        throw InputError(where(path, t.line_of_row(row)) +
                         ": column 'record' is empty; expected a record label");
      const auto it = index.emplace(labels[row], raw.size());
      if (it.second)
        raw.push_back({labels[row], {}});
      raw[it.first->second].rows.push_back(row);
    }
  } else {
    raw.push_back({stem(path), {}});
    for (std::size_t row = 0; row < t.n_rows(); ++row)
      raw[0].rows.push_back(row);
  }

  RecordCleaner cleaner(t, options);
  std::vector<TestRecord> records;
  for (const auto& r : raw)
    records.push_back(
        cleaner.clean(r, has_time ? &time : nullptr, opening, load, a, has_root ? &root : nullptr));
  return records;
}

std::vector<std::size_t> crack_reading_rows(const TestRecord& r) {
  std::vector<std::size_t> rows;
  for (std::size_t i = 0; i < r.crack_length.size(); ++i)
    if (i == 0 || r.crack_length[i] != r.crack_length[i - 1])
      rows.push_back(i);
  return rows;
}

void TestSpecimen::check(const std::string& where_) const {
  if (std::isnan(width))
    throw InputError(where_ + ": the specimen width is missing; give Specimen/Width (mm) or "
                              "--width MM");
  if (std::isnan(arm_thickness))
    throw InputError(where_ + ": the arm thickness is missing; give Specimen/Height (mm, both "
                              "arms) or --arm-thickness MM");
  const std::pair<const char*, double> values[] = {{"width", width},
                                                   {"arm thickness", arm_thickness},
                                                   {"length", length},
                                                   {"initial crack", initial_crack},
                                                   {"pin to arm mid-plane", pin_to_arm_midplane},
                                                   {"pin to block edge", pin_to_block_edge}};
  for (const auto& [name, v] : values)
    if (!std::isnan(v) && !(v > 0))
      throw InputError(where_ + ": the specimen " + name + " is " + num(v / units::mm) +
                       " mm; expected a positive length");
}

} // namespace fiberbridge::analysis
