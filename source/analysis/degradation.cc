// Degradation statistics, durability ranking and Table-1 row consistency (seed section 3.3,
// Table 1; docs/design.md section 1 "Degradation and ranking").
#include "fiberbridge/analysis/degradation.h"

#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>

namespace fiberbridge::analysis {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

std::string where(const std::string& source, std::size_t line) {
  return source + ":" + std::to_string(line) + ": ";
}

/// A whole-string finite number, or false.
bool parse_number(const std::string& s, double& value) {
  if (s.empty())
    return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && errno != ERANGE && std::isfinite(value);
}

/// Half a unit of the last printed digit: "661" -> 0.5, "6.7" -> 0.05, "1.5e2" -> 5.
double half_unit_of(const std::string& s) {
  const auto e = s.find_first_of("eE");
  const std::string mantissa = s.substr(0, e);
  const int exponent = e == std::string::npos ? 0 : std::atoi(s.c_str() + e + 1);
  const auto dot = mantissa.find('.');
  const int decimals = dot == std::string::npos ? 0 : static_cast<int>(mantissa.size() - dot - 1);
  return 0.5 * std::pow(10.0, exponent - decimals);
}

/// "40-111" -> (40, 111). The '-' that separates must follow a digit or '.', so "-1.0" is a
/// number and "-3--1" a range of negatives.
bool parse_range(const std::string& s, double& low, double& high) {
  for (std::size_t p = 1; p + 1 < s.size(); ++p) {
    if (s[p] != '-')
      continue;
    const char before = s[p - 1];
    if (!(std::isdigit(static_cast<unsigned char>(before)) || before == '.'))
      continue;
    if (parse_number(s.substr(0, p), low) && parse_number(s.substr(p + 1), high))
      return low <= high;
  }
  return false;
}

/// The interval of values that print as `p` with half unit `h`, rounded or truncated toward
/// zero: rounding gives [p - h, p + h], truncation [p, p + 2h) for p > 0 (mirrored for p < 0).
std::pair<double, double> printed_interval(double p, double h) {
  if (p > 0)
    return {p - h, p + 2 * h};
  if (p < 0)
    return {p - 2 * h, p + h};
  return {-2 * h, 2 * h};
}

} // namespace

LinearRegression linear_regression(const std::vector<double>& x, const std::vector<double>& y) {
  if (x.size() != y.size())
    throw InputError("linear_regression: " + std::to_string(x.size()) + " x values but " +
                     std::to_string(y.size()) + " y values; expected equal counts");
  const std::size_t n = x.size();
  if (n < 2)
    throw InputError("linear_regression: " + std::to_string(n) +
                     " points; a straight line needs at least 2");
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(x[i]) || !std::isfinite(y[i]))
      throw InputError("linear_regression: point " + std::to_string(i) +
                       " is not finite; expected finite x and y");
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < n; ++i) {
    mx += x[i];
    my += y[i];
  }
  mx /= n;
  my /= n;
  // Centred sums: the raw-moment formulas cancel badly when the mean is large vs. the spread.
  double sxx = 0, sxy = 0, syy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
    syy += (y[i] - my) * (y[i] - my);
  }
  if (!(sxx > 0))
    throw InputError("linear_regression: all x values are equal (" + fmt(mx, 5) +
                     "); a slope needs at least two distinct x");
  LinearRegression fit;
  fit.n = static_cast<int>(n);
  fit.slope = sxy / sxx;
  fit.intercept = my - fit.slope * mx;
  // A constant y has nothing to explain: R^2 is 0/0; report 0 (the slope is exactly 0, so the
  // property can never count as degrading).
  fit.r2 = syy > 0 ? sxy * sxy / (sxx * syy) : 0.0;
  if (n > 2) {
    double ssr = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double res = y[i] - fit.intercept - fit.slope * x[i];
      ssr += res * res;
    }
    fit.slope_std_error = std::sqrt(ssr / (n - 2) / sxx);
  } else {
    fit.slope_std_error = nan; // two points fit exactly: no residual to estimate scatter from
  }
  return fit;
}

const PropertyRow* PropertyTable::find(const std::string& material,
                                       const std::string& property) const {
  for (const auto& r : rows)
    if (r.material == material && r.property == property)
      return &r;
  return nullptr;
}

PropertyTable read_property_table(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw InputError(path + ": cannot open property table for reading");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parse_property_table(buffer.str(), path);
}

PropertyTable parse_property_table(const std::string& text, const std::string& source_name) {
  const CsvTable csv = CsvTable::parse(text, source_name);
  const std::string expected = "expected columns material,property,c<N>...,slope,r2 "
                               "(c<N> = value after N cycles)";
  PropertyTable table;
  table.source = source_name;
  std::vector<std::string> cycle_columns;
  bool has_slope = false, has_r2 = false;
  for (const auto& name : csv.header()) {
    double cycle = 0;
    if (name == "material" || name == "property")
      continue;
    if (name == "slope")
      has_slope = true;
    else if (name == "r2")
      has_r2 = true;
    else if (name.size() > 1 && name[0] == 'c' && parse_number(name.substr(1), cycle)) {
      if (cycle < 0)
        throw InputError(source_name + ": header: column '" + name +
                         "' names a negative number of cycles; " + expected);
      for (std::size_t i = 0; i < table.cycles.size(); ++i)
        if (table.cycles[i] == cycle)
          throw InputError(source_name + ": header: columns '" + cycle_columns[i] + "' and '" +
                           name + "' name the same cycle count " + fmt(cycle, 5));
      table.cycles.push_back(cycle);
      cycle_columns.push_back(name);
    } else {
      throw InputError(source_name + ": header: unknown column '" + name + "'; " + expected);
    }
  }
  for (const char* required : {"material", "property"})
    if (!csv.has_column(required))
      throw InputError(source_name + ": header: missing column '" + required + "'; " + expected);
  if (table.cycles.size() < 3)
    throw InputError(source_name + ": header: " + std::to_string(table.cycles.size()) +
                     " cycle columns (c<N>); a degradation trend needs at least 3; " + expected);
  if (has_slope != has_r2)
    throw InputError(source_name + ": header: column '" + (has_slope ? "slope" : "r2") +
                     "' without '" + (has_slope ? "r2" : "slope") +
                     "'; printed statistics come as the pair slope,r2");

  const auto& materials = csv.text("material");
  const auto& properties = csv.text("property");
  for (std::size_t r = 0; r < csv.n_rows(); ++r) {
    const std::size_t line = csv.line_of_row(r);
    const std::string at = where(source_name, line);
    PropertyRow row;
    row.material = materials[r];
    row.property = properties[r];
    row.line = line;
    if (row.material.empty() || row.property.empty())
      throw InputError(at + "empty " + (row.material.empty() ? "material" : "property") +
                       " name; every row needs a material and a property");
    if (const PropertyRow* first = table.find(row.material, row.property))
      throw InputError(at + "second row for " + row.material + " " + row.property +
                       " (first on line " + std::to_string(first->line) + ")");

    bool any_range = false, any_number = false;
    for (const auto& column : cycle_columns) {
      const std::string& cell = csv.text(column)[r];
      row.cells.push_back(cell);
      double v = 0, low = 0, high = 0;
      if (cell.empty()) {
        row.values.push_back(nan);
        row.half_units.push_back(nan);
        row.ranges.emplace_back(nan, nan);
      } else if (parse_number(cell, v)) {
        any_number = true;
        row.values.push_back(v);
        row.half_units.push_back(half_unit_of(cell));
        row.ranges.emplace_back(nan, nan);
      } else if (parse_range(cell, low, high)) {
        any_range = true;
        row.values.push_back(nan);
        row.half_units.push_back(nan);
        row.ranges.emplace_back(low, high);
      } else {
        throw InputError(at + "column '" + column + "' holds '" + cell +
                         "'; expected a number, a range low-high with low <= high, or empty");
      }
    }
    if (any_range && any_number)
      throw InputError(at + row.material + " " + row.property +
                       " mixes numbers and low-high ranges; a row holds one kind");
    if (any_range) {
      for (std::size_t i = 0; i < row.cells.size(); ++i)
        row.range_text += (i ? "," : "") + row.cells[i];
    } else {
      row.ranges.clear();
    }

    if (has_slope) {
      const std::string& s = csv.text("slope")[r];
      const std::string& q = csv.text("r2")[r];
      if (s.empty() != q.empty())
        throw InputError(at + "printed slope '" + s + "' and r2 '" + q + "': give both or neither");
      if (!s.empty()) {
        if (!parse_number(s, row.printed_slope))
          throw InputError(at + "column 'slope' holds '" + s + "', expected a finite number");
        if (!parse_number(q, row.printed_r2) || row.printed_r2 < 0 || row.printed_r2 > 1)
          throw InputError(at + "column 'r2' holds '" + q + "', expected a number in [0, 1]");
        row.has_printed = true;
        row.printed_slope_half_unit = half_unit_of(s);
        row.printed_r2_half_unit = half_unit_of(q);
      }
    }
    table.rows.push_back(std::move(row));
  }
  return table;
}

std::vector<DegradationRow> analyse_degradation(const PropertyTable& table) {
  std::vector<DegradationRow> out;
  for (const auto& row : table.rows) {
    if (!row.range_text.empty())
      continue;
    std::vector<double> x, y, h;
    for (std::size_t i = 0; i < row.values.size(); ++i)
      if (std::isfinite(row.values[i])) {
        x.push_back(table.cycles[i]);
        y.push_back(row.values[i]);
        h.push_back(row.half_units[i]);
      }
    if (x.size() < 2)
      throw InputError(where(table.source, row.line) + row.material + " " + row.property + " has " +
                       std::to_string(x.size()) +
                       " values; a degradation slope needs at least 2 cycle counts");
    DegradationRow d;
    d.material = row.material;
    d.property = row.property;
    d.source = table.source;
    d.line = row.line;
    d.fit = linear_regression(x, y);
    d.normalized_rate = d.fit.intercept > 0 ? d.fit.slope / d.fit.intercept : nan;
    // Paper's bold: negative slope with R^2 >= 0.8. Two points give R^2 = 1 whatever the data.
    d.significant = d.fit.n >= 3 && d.fit.slope < 0 && d.fit.r2 >= 0.8;
    d.has_printed = row.has_printed;
    d.printed_slope = row.printed_slope;
    d.printed_r2 = row.printed_r2;
    if (row.has_printed) {
      // First-order propagation of the +-h_i rounding of each printed input into slope and R^2:
      // d(slope)/dy_i = (x_i - xm)/Sxx, dR^2/dy_i = 2 Sxy/(Sxx Syy) ((x_i - xm) - Sxy/Syy (y_i -
      // ym)). The paper regressed its unrounded values, so this much difference is expected.
      const std::size_t n = x.size();
      double mx = 0, my = 0;
      for (std::size_t i = 0; i < n; ++i) {
        mx += x[i] / n;
        my += y[i] / n;
      }
      double sxx = 0, sxy = 0, syy = 0;
      for (std::size_t i = 0; i < n; ++i) {
        sxx += (x[i] - mx) * (x[i] - mx);
        sxy += (x[i] - mx) * (y[i] - my);
        syy += (y[i] - my) * (y[i] - my);
      }
      double slope_input = 0, r2_input = 0;
      for (std::size_t i = 0; i < n; ++i) {
        slope_input += std::abs(x[i] - mx) / sxx * h[i];
        if (syy > 0)
          r2_input +=
              std::abs(2 * sxy / (sxx * syy) * ((x[i] - mx) - sxy / syy * (y[i] - my))) * h[i];
      }
      // Round-off allowance only (the sums above are exact to ~1e-15 relative); without it a
      // value exactly on a band edge (PVA J1: -8.600 vs. -8.7) would depend on the last bit.
      const double roundoff = 1e-12;
      const auto [s_lo, s_hi] = printed_interval(row.printed_slope, row.printed_slope_half_unit);
      const auto [q_lo, q_hi] = printed_interval(row.printed_r2, row.printed_r2_half_unit);
      const bool slope_ok = d.fit.slope >= s_lo - slope_input - roundoff * (1 + std::abs(s_lo)) &&
                            d.fit.slope <= s_hi + slope_input + roundoff * (1 + std::abs(s_hi));
      const bool r2_ok =
          d.fit.r2 >= q_lo - r2_input - roundoff && d.fit.r2 <= q_hi + r2_input + roundoff;
      d.matches_printed = slope_ok && r2_ok;
      d.slope_tolerance = 0.5 * (s_hi - s_lo) + slope_input;
      d.r2_tolerance = 0.5 * (q_hi - q_lo) + r2_input;
    }
    out.push_back(std::move(d));
  }
  return out;
}

bool is_traction_law_property(const std::string& property) {
  return property == "sigma1" || property == "sigma2" || property == "J1" || property == "J2";
}

std::vector<MaterialRank> rank_materials(const std::vector<DegradationRow>& rows) {
  std::vector<MaterialRank> ranks;
  std::map<std::string, std::size_t> index;
  for (const auto& r : rows) {
    auto it = index.find(r.material);
    if (it == index.end()) {
      it = index.emplace(r.material, ranks.size()).first;
      ranks.push_back(MaterialRank{r.material, 0.0, 0, {}});
    }
    if (!r.significant || !is_traction_law_property(r.property))
      continue;
    if (!std::isfinite(r.normalized_rate))
      throw InputError(where(r.source, r.line) + r.material + " " + r.property +
                       " degrades significantly but its fitted value at 0 cycles is " +
                       fmt(r.fit.intercept, 5) +
                       "; a normalized rate (slope/intercept) needs a positive intercept");
    MaterialRank& m = ranks[it->second];
    m.degradation_score += r.normalized_rate;
    m.significant_properties.push_back(r.property);
  }
  // Least (negative) degradation first; stable so equal scores keep their table order.
  std::stable_sort(ranks.begin(), ranks.end(), [](const MaterialRank& a, const MaterialRank& b) {
    return a.degradation_score > b.degradation_score;
  });
  for (std::size_t i = 0; i < ranks.size(); ++i) {
    // Equal up to summation round-off (the scores are sums of a few doubles): same rank.
    const bool tie =
        i > 0 && std::abs(ranks[i].degradation_score - ranks[i - 1].degradation_score) <=
                     1e-12 * std::max(std::abs(ranks[i].degradation_score),
                                      std::abs(ranks[i - 1].degradation_score));
    ranks[i].rank = tie ? ranks[i - 1].rank : static_cast<int>(i + 1);
  }
  return ranks;
}

std::vector<ConsistencyIssue> check_row_consistency(const PropertyTable& table, double d1_mm,
                                                    double d2_mm,
                                                    double (*dc_mm_of)(const std::string&)) {
  return check_row_consistency(table, d1_mm, d2_mm, dc_mm_of, ConsistencyTolerance{});
}

std::vector<ConsistencyIssue> check_row_consistency(const PropertyTable& table, double d1_mm,
                                                    double d2_mm,
                                                    double (*dc_mm_of)(const std::string&),
                                                    const ConsistencyTolerance& tolerance) {
  if (!(d1_mm > 0 && d2_mm > d1_mm))
    throw InputError("check_row_consistency: openings d1 = " + fmt(d1_mm, 5) +
                     " mm, d2 = " + fmt(d2_mm, 5) + " mm; expected 0 < d1 < d2");
  if (!(tolerance.j1_relative >= 0 && tolerance.j2_relative >= 0))
    throw InputError("check_row_consistency: relative tolerances must be >= 0");
  std::vector<ConsistencyIssue> issues;
  std::vector<std::string> materials;
  for (const auto& r : table.rows)
    if (std::find(materials.begin(), materials.end(), r.material) == materials.end())
      materials.push_back(r.material);
  for (const auto& m : materials) {
    const PropertyRow* s1 = table.find(m, "sigma1");
    const PropertyRow* s2 = table.find(m, "sigma2");
    const PropertyRow* j1 = table.find(m, "J1");
    const PropertyRow* j2 = table.find(m, "J2");
    if (!s1 || !s2 || !j1 || !j2)
      continue;
    const double dc = dc_mm_of(m);
    if (!(dc > 0))
      throw InputError("check_row_consistency: delta_c of " + m + " is " + fmt(dc, 5) +
                       " mm; expected > 0");
    for (std::size_t i = 0; i < table.cycles.size(); ++i) {
      const double a = s1->values[i], b = s2->values[i], p1 = j1->values[i], p2 = j2->values[i];
      if (!(std::isfinite(a) && std::isfinite(b) && std::isfinite(p1) && std::isfinite(p2)))
        continue;
      // kPa * mm = J/m^2. Trilinear split (docs/design.md section 1; Table 1 uses '-' in J1).
      const double e1 = 0.5 * (a * d2_mm - b * d1_mm);
      const double e2 = 0.5 * b * dc;
      // Rounding of the printed digits: J itself, plus the stresses propagated through the
      // (linear) formulas. Anything beyond that is not explained by printing.
      const double round1 =
          j1->half_units[i] + 0.5 * (d2_mm * s1->half_units[i] + d1_mm * s2->half_units[i]);
      const double round2 = j2->half_units[i] + 0.5 * dc * s2->half_units[i];
      const double tol1 = round1 + tolerance.j1_relative * std::abs(e1);
      const double tol2 = round2 + tolerance.j2_relative * std::abs(e2);
      const double roundoff = 1e-9 * (1 + std::abs(e1) + std::abs(e2));
      ConsistencyIssue issue;
      issue.material = m;
      issue.cycles = table.cycles[i];
      issue.j1_printed = p1;
      issue.j1_expected = e1;
      issue.j2_printed = p2;
      issue.j2_expected = e2;
      issue.j1_consistent = std::abs(p1 - e1) <= tol1 + roundoff;
      issue.j2_consistent = std::abs(p2 - e2) <= tol2 + roundoff;
      if (issue.j1_consistent && issue.j2_consistent)
        continue;
      std::string msg;
      if (!issue.j1_consistent)
        msg += "J1 printed " + j1->cells[i] + ", expected " + fmt(e1, 5) + " = (sigma1 " +
               s1->cells[i] + " * " + fmt(d2_mm, 5) + " - sigma2 " + s2->cells[i] + " * " +
               fmt(d1_mm, 5) + ")/2 (tolerance " + fmt(tol1, 5) + ")";
      if (!issue.j2_consistent) {
        msg += std::string(msg.empty() ? "" : "; ") + "J2 printed " + j2->cells[i] + ", expected " +
               fmt(e2, 5) + " = sigma2 " + s2->cells[i] + " * " + fmt(dc, 5) + "/2 (tolerance " +
               fmt(tol2, 5) + "); the printed J2 implies sigma2 = " + fmt(2 * p2 / dc, 5) + " kPa";
      }
      const bool swapped = !issue.j1_consistent && !issue.j2_consistent &&
                           std::abs(p1 - e2) <= tol2 + roundoff &&
                           std::abs(p2 - e1) <= tol1 + roundoff;
      if (swapped)
        msg += "; J1 and J2 look swapped";
      issue.message = msg;
      issues.push_back(std::move(issue));
    }
  }
  return issues;
}

double seed_delta_c_mm(const std::string& material) {
  // Seed section 3.1: "We approximated delta_c for PVA LVL as 6 mm and for other materials as
  // 3.5 mm" (solid wood included, as a reference point).
  return material == "PVA" ? 6.0 : 3.5;
}

} // namespace fiberbridge::analysis
