// Reading measured R curves and averaging replicates
// (docs/design.md section 1, "Data preparation").
#include "fiberbridge/analysis/rdelta_data.h"

#include "fiberbridge/analysis/line_fit.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <sstream>

namespace fiberbridge::analysis {

namespace {

constexpr std::size_t min_rows_per_replicate = 8;

std::string where(const std::string& source, std::size_t line) {
  return source + ":" + std::to_string(line);
}

/// Where a row came from: the file and its line, or (arrays in memory) the source and the row's
/// 1-based index.
struct RowPlaces {
  std::string source;
  std::function<std::size_t(std::size_t)> line_of; ///< line (or index) of a row
  const char* word = "line";                       ///< "line" or "row"
  /// "file:12" or "source, row 12".
  std::string at(std::size_t line) const {
    return std::string(word) == "line" ? where(source, line)
                                       : source + ", row " + std::to_string(line);
  }
};

/// Rows of one replicate in time order (file order without a time column), checked.
Replicate build_replicate(const RowPlaces& t, const std::string& label,
                          const std::vector<std::size_t>& rows, const std::vector<double>& delta_mm,
                          const std::vector<double>& R, const std::vector<double>* a_mm,
                          const std::vector<double>* time_s) {
  std::vector<std::size_t> order = rows;
  if (time_s)
    // R(delta) is assembled through the shared reference parameter (seed section 3.1: time);
    // stable so that equal times keep the file order.
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t p, std::size_t q) { return (*time_s)[p] < (*time_s)[q]; });

  const std::string& src = t.source;
  Replicate r;
  r.label = label;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t row = order[k];
    const std::size_t line = t.line_of(row);
    if (delta_mm[row] < 0)
      throw InputError(t.at(line) + ": delta_mm = " + std::to_string(delta_mm[row]) +
                       " is negative; the notch-root opening must be >= 0");
    if (R[row] < 0)
      throw InputError(t.at(line) + ": R_J_m2 = " + std::to_string(R[row]) +
                       " is negative; a toughness must be >= 0");
    if (a_mm && (*a_mm)[row] < 0)
      throw InputError(t.at(line) + ": a_mm = " + std::to_string((*a_mm)[row]) +
                       " is negative; the crack position must be >= 0");
    if (k > 0 && delta_mm[row] < delta_mm[order[k - 1]])
      throw InputError(
          t.at(line) + ": delta_mm = " + std::to_string(delta_mm[row]) + " is smaller than " +
          std::to_string(delta_mm[order[k - 1]]) + " on " + t.word + " " +
          std::to_string(t.line_of(order[k - 1])) + (time_s ? " earlier in time" : " above") +
          " (replicate '" + label +
          "'); the notch-root opening is the reference parameter and must not decrease");
    r.delta.push_back(delta_mm[row] * units::mm);
    r.R.push_back(R[row]);
    if (a_mm)
      r.a.push_back((*a_mm)[row] * units::mm);
    if (time_s)
      r.time_s.push_back((*time_s)[row]);
    r.line.push_back(line);
  }
  if (r.delta.size() < min_rows_per_replicate)
    throw InputError(src + ": replicate '" + label + "' has " + std::to_string(r.delta.size()) +
                     " rows (last on " + t.word + " " + std::to_string(t.line_of(rows.back())) +
                     "); at least " + std::to_string(min_rows_per_replicate) +
                     " are needed to fit slopes");
  return r;
}

/// (delta, R) of a replicate with repeated openings merged into their mean R, so the polyline
/// through it is a function of delta.
void merge_equal_openings(const Replicate& r, std::vector<double>& x, std::vector<double>& y) {
  x.clear();
  y.clear();
  std::size_t i = 0;
  while (i < r.delta.size()) {
    std::size_t j = i;
    double sum = 0;
    while (j < r.delta.size() && r.delta[j] == r.delta[i])
      sum += r.R[j++];
    x.push_back(r.delta[i]);
    y.push_back(sum / static_cast<double>(j - i));
    i = j;
  }
}

} // namespace

RDeltaData read_rdelta_csv(const std::string& path) {
  const CsvTable t = CsvTable::read(path);
  for (const char* required : {"delta_mm", "R_J_m2"})
    if (!t.has_column(required)) {
      std::string have;
      for (const auto& h : t.header())
        have += (have.empty() ? "" : ", ") + h;
      throw InputError(path + ": missing required column '" + required +
                       "' (expected delta_mm and R_J_m2, optionally a_mm, time_s, replicate; "
                       "found: " +
                       have + ")");
    }
  // numeric() rejects empty, non-numeric and non-finite cells naming file and line.
  const std::vector<double> delta_mm = t.numeric("delta_mm");
  const std::vector<double> R = t.numeric("R_J_m2");
  std::vector<double> a_mm, time_s;
  if (t.has_column("a_mm"))
    a_mm = t.numeric("a_mm");
  if (t.has_column("time_s"))
    time_s = t.numeric("time_s");

  // Split on the replicate column, keeping replicates in order of first appearance.
  std::vector<std::string> labels;
  std::vector<std::vector<std::size_t>> rows;
  if (t.has_column("replicate")) {
    const auto& text = t.text("replicate");
    std::map<std::string, std::size_t> index;
    for (std::size_t row = 0; row < t.n_rows(); ++row) {
      if (text[row].empty())
        throw InputError(where(path, t.line_of_row(row)) +
                         ": column 'replicate' is empty; expected a replicate label");
      const auto it = index.find(text[row]);
      if (it == index.end()) {
        index.emplace(text[row], labels.size());
        labels.push_back(text[row]);
        rows.push_back({row});
      } else
        rows[it->second].push_back(row);
    }
  } else {
    labels.push_back("1");
    rows.emplace_back(t.n_rows());
    std::iota(rows[0].begin(), rows[0].end(), std::size_t{0});
  }

  RDeltaData data;
  data.source = path;
  const RowPlaces places{path, [&t](std::size_t row) { return t.line_of_row(row); }};
  for (std::size_t r = 0; r < labels.size(); ++r)
    data.replicates.push_back(build_replicate(places, labels[r], rows[r], delta_mm, R,
                                              a_mm.empty() ? nullptr : &a_mm,
                                              time_s.empty() ? nullptr : &time_s));
  return data;
}

RDeltaData rdelta_from_columns(const std::string& source, const RDeltaColumns& c) {
  const std::size_t n = c.delta_mm.size();
  auto check_column = [&](const std::vector<double>& v, const char* name, bool optional) {
    if (optional && v.empty())
      return;
    if (v.size() != n)
      throw InputError(source + ": " + name + " has " + std::to_string(v.size()) +
                       " values, delta_mm has " + std::to_string(n));
    for (std::size_t i = 0; i < n; ++i)
      if (!std::isfinite(v[i]))
        throw InputError(source + ", row " + std::to_string(i + 1) + ": " + name +
                         " is not a finite number");
  };
  check_column(c.delta_mm, "delta_mm", false);
  check_column(c.R_J_m2, "R_J_m2", false);
  check_column(c.a_mm, "a_mm", true);
  check_column(c.time_s, "time_s", true);
  if (!c.replicate.empty() && c.replicate.size() != n)
    throw InputError(source + ": replicate has " + std::to_string(c.replicate.size()) +
                     " labels, delta_mm has " + std::to_string(n) + " values");
  // Replicates in order of first appearance, as the file reader splits them.
  std::vector<std::string> labels;
  std::vector<std::vector<std::size_t>> rows;
  std::map<std::string, std::size_t> index;
  for (std::size_t row = 0; row < n; ++row) {
    const std::string label = c.replicate.empty() ? "1" : c.replicate[row];
    if (label.empty())
      throw InputError(source + ", row " + std::to_string(row + 1) +
                       ": the replicate label is empty");
    const auto it = index.find(label);
    if (it == index.end()) {
      index.emplace(label, labels.size());
      labels.push_back(label);
      rows.push_back({row});
    } else
      rows[it->second].push_back(row);
  }
  if (labels.empty())
    throw InputError(source + ": no rows");
  RDeltaData data;
  data.source = source;
  const RowPlaces places{source, [](std::size_t row) { return row + 1; }, "row"};
  for (std::size_t r = 0; r < labels.size(); ++r)
    data.replicates.push_back(build_replicate(places, labels[r], rows[r], c.delta_mm, c.R_J_m2,
                                              c.a_mm.empty() ? nullptr : &c.a_mm,
                                              c.time_s.empty() ? nullptr : &c.time_s));
  return data;
}

RDeltaCurve average_replicates(const RDeltaData& data, int n_grid) {
  if (data.replicates.empty())
    throw InputError(data.source + ": no replicates to average");
  if (n_grid < 2)
    throw InputError(data.source + ": the averaging grid needs at least 2 points, got " +
                     std::to_string(n_grid));
  double delta_end = INFINITY;
  std::string shortest;
  for (const auto& r : data.replicates) {
    if (r.delta.empty() || r.delta.size() != r.R.size())
      throw InputError(data.source + ": replicate '" + r.label +
                       "' has no rows or mismatched delta/R columns");
    if (r.delta.back() < delta_end) {
      delta_end = r.delta.back();
      shortest = r.label;
    }
  }
  if (!(delta_end > 0))
    throw InputError(data.source + ": replicate '" + shortest +
                     "' never opens (largest delta_mm is 0); no R(delta) curve to average");

  RDeltaCurve c;
  c.n_replicates = static_cast<int>(data.replicates.size());
  c.delta.resize(n_grid);
  for (int i = 0; i < n_grid; ++i)
    c.delta[i] = delta_end * i / (n_grid - 1);

  // Interpolate every replicate on the common grid; the polyline is held at its first R below
  // the first measured opening (the flat J_tip part of seed Eq. 2).
  std::vector<double> x, y;
  std::vector<std::vector<double>> values;
  for (const auto& r : data.replicates) {
    merge_equal_openings(r, x, y);
    values.push_back(resample_linear(x, y, c.delta));
  }
  c.R.assign(n_grid, 0.0);
  c.R_std.assign(n_grid, 0.0);
  const double m = static_cast<double>(values.size());
  for (int i = 0; i < n_grid; ++i) {
    double mean = 0;
    for (const auto& v : values)
      mean += v[i];
    mean /= m;
    double ss = 0;
    for (const auto& v : values)
      ss += (v[i] - mean) * (v[i] - mean);
    c.R[i] = mean;
    // Sample standard deviation (n - 1): the scatter between specimens, not of the mean.
    c.R_std[i] = values.size() > 1 ? std::sqrt(ss / (m - 1)) : 0.0;
  }

  std::ostringstream rep;
  rep << values.size() << " replicate(s) from " << data.source
      << " linearly interpolated on a uniform grid of " << n_grid << " points over [0, "
      << delta_end / units::mm << "] mm (the smallest largest delta, replicate '" << shortest
      << "'); below each replicate's first delta R is held at its first value";
  c.report = rep.str();
  return c;
}

} // namespace fiberbridge::analysis
