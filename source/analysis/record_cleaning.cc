// Cleaning what real machines write, one record at a time (record_cleaning.h). Each step that
// changes something says so in one sentence with row counts and lines; what would give a wrong
// result is refused naming file:line (docs/design.md section 6).
#include "record_cleaning.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/median.h"
#include "fiberbridge/core/units.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fiberbridge::analysis {

namespace {

using units::mm;

constexpr std::size_t min_rows = 8;
/// The test has started once the load exceeds this fraction of its peak.
constexpr double start_fraction = 0.05;
/// A single-row spike departs from both neighbours by more than this fraction of the channel's
/// largest value (and 20 times the noise of its second differences) while they agree.
constexpr double spike_fraction = 0.02;
/// A channel "at zero" is below this fraction of its largest value so far; it must have been
/// above `zero_from_fraction` the row before for a fall to zero to count as a dropout/re-zero.
constexpr double zero_fraction = 0.02, zero_from_fraction = 0.2;
/// A fall to zero this many rows long or shorter, after which the channel is back near where it
/// was, is a dropout of the reading.
constexpr std::size_t max_dropout_rows = 10;
/// The initial linear part of load against opening: loads between these fractions of the peak,
/// before the peak and the first crack growth. A zero offset is removed when it exceeds
/// `offset_fraction` of the opening at the top of that part (smaller ones are seating of the
/// pins and hinges, which a shift would turn into a false compliance; the shared records show
/// 0.04-0.07 mm at openings of 2 mm there).
constexpr double linear_low = 0.1, linear_high = 0.5, offset_fraction = 0.05;

bool same(double a, double b) {
  return a == b || (std::isnan(a) && std::isnan(b));
}

/// A dropout code in the file's own unit: 999, -999, 9999, 99999.9 ...
bool is_dropout_code(double v) {
  const double m = std::abs(v);
  if (!(m >= 999 && m < 1e12))
    return false;
  const std::string s = std::to_string(static_cast<long long>(m));
  return s.find_first_not_of('9') == std::string::npos;
}

struct Rows {
  std::vector<std::size_t> row;
  std::vector<double> time, opening, load, a, root;
};

void filter(Rows& r, const std::vector<bool>& keep) {
  Rows out;
  for (std::size_t i = 0; i < r.row.size(); ++i) {
    if (!keep[i])
      continue;
    out.row.push_back(r.row[i]);
    out.opening.push_back(r.opening[i]);
    out.load.push_back(r.load[i]);
    if (!r.a.empty())
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
  RecordCleaner(const RowOrigin& origin, const RecordColumns& c, const RecordReadOptions& o)
      : origin_(origin), c_(c), o_(o) {}

  TestRecord clean(const std::string& name, const std::vector<std::size_t>& rows) {
    name_ = name;
    cleaning_ = c_.notes;
    Rows r;
    for (std::size_t row : rows) {
      r.row.push_back(row);
      r.opening.push_back(c_.opening[row]);
      r.load.push_back(c_.load[row]);
      if (c_.has_crack)
        r.a.push_back(c_.crack[row]);
      if (c_.has_time)
        r.time.push_back(c_.time[row]);
      if (c_.has_root)
        r.root.push_back(c_.root[row]);
    }
    drop_rows_without_values(r);
    flip_negative_channels(r);
    check_time_order(r);
    drop_repeated_times(r);
    drop_pauses(r);
    mark_missing_crack_readings(r);
    clamp_leading_negative_loads(r);
    fix_spikes(r, r.load, "load_N", 1.0, "N");
    fix_spikes(r, r.opening, "opening_mm", mm, "mm");
    zero_falls(r, true);
    zero_falls(r, false);
    remove_opening_zero_offset(r);
    drop_after_final_drop(r);
    drop_unload_reload(r);
    clamp_or_refuse_negative_loads(r);
    clamp_or_refuse_negative_root(r);
    if (!r.a.empty()) {
      drop_crack_spikes(r);
      smooth_crack_back_steps(r);
    }
    check_rows_and_growth(r);

    TestRecord out;
    out.name = name;
    out.source = origin_.source;
    out.time = r.time;
    out.opening = r.opening;
    out.load = r.load;
    out.crack_length = r.a;
    out.delta_root = r.root;
    for (std::size_t row : r.row)
      out.line.push_back(origin_.line_of_row(row));
    if (!out.crack_length.empty()) {
      count_repeated_readings(out);
      name_trailing_block(r);
    }
    out.cleaning = cleaning_;
    return out;
  }

private:
  std::string line(const Rows& r, std::size_t i) const {
    return std::to_string(origin_.line_of_row(r.row[i]));
  }
  std::string at(const Rows& r, std::size_t i) const {
    return origin_.source + ":" + line(r, i) + ": ";
  }
  std::string lines(const Rows& r, std::size_t first, std::size_t last) const {
    return first == last ? "line " + line(r, first)
                         : "lines " + line(r, first) + "-" + line(r, last);
  }
  std::string label() const { return "record '" + name_ + "'"; }
  void say(const std::string& s) { cleaning_.push_back(s); }

  double peak(const Rows& r) const { return *std::max_element(r.load.begin(), r.load.end()); }

  /// The row where the test has started: the load first exceeds start_fraction of the peak.
  std::size_t start_row(const Rows& r) const {
    const double p = peak(r);
    std::size_t i = 0;
    while (i < r.load.size() && !(r.load[i] > start_fraction * p))
      ++i;
    return i;
  }

  /// A row whose time, load or opening (or measured root opening) is missing has nothing to
  /// give: the energy integral needs both, and the row order needs the time.
  void drop_rows_without_values(Rows& r) {
    std::vector<bool> keep(r.row.size(), true);
    std::size_t n = 0, first = 0;
    for (std::size_t i = 0; i < r.row.size(); ++i) {
      const bool missing = std::isnan(r.opening[i]) || std::isnan(r.load[i]) ||
                           (!r.time.empty() && std::isnan(r.time[i])) ||
                           (!r.root.empty() && std::isnan(r.root[i]));
      if (missing && n++ == 0)
        first = i;
      keep[i] = !missing;
    }
    if (n) {
      say(std::to_string(n) + " row(s) with an empty or NaN time, load or opening cell (first on " +
          "line " + line(r, first) + ") dropped: nothing was measured there.");
      filter(r, keep);
    }
    if (r.row.empty())
      throw InputError(origin_.source + ": " + label() +
                       " has no row with both a load and an opening value");
  }

  /// Machines set up for compression, or with the extension counted downwards, write the load or
  /// the opening negative. A channel whose most negative value is more than ten times its largest
  /// positive one is turned over (the work P d(opening) is the same); a few noise-level negatives
  /// in a positive record are left to the noise steps.
  void flip_negative_channels(Rows& r) {
    const auto flip = [&](std::vector<double>& v, const char* column, double unit,
                          const char* unit_name) {
      const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
      if (!(*lo < 0 && -*lo > 10 * std::max(*hi, 0.0)))
        return;
      const double lowest = *lo;
      for (double& x : v)
        x = -x;
      say(std::string(column) + " is negative throughout (down to " + num(lowest / unit) + " " +
          unit_name + "): the machine counts it the other way; its sign turned over.");
    };
    flip(r.load, "load_N", 1.0, "N");
    flip(r.opening, "opening_mm", mm, "mm");
    if (!(peak(r) > 0))
      throw InputError(origin_.source + ": " + label() + " (" + lines(r, 0, r.row.size() - 1) +
                       ") never carries a positive load_N; nothing to reduce");
  }

  void check_time_order(const Rows& r) const {
    for (std::size_t i = 1; i < r.time.size(); ++i)
      if (r.time[i] < r.time[i - 1]) {
        const bool restart = std::abs(r.time[i]) < 0.02 * std::abs(r.time[i - 1]);
        throw InputError(at(r, i) + "time_s = " + num(r.time[i]) + " is earlier than " +
                         num(r.time[i - 1]) + " on line " + line(r, i - 1) + " (" + label() +
                         "); a record must be in time order" +
                         (restart ? " (the clock restarts here: a second test appended to the "
                                    "file, or a re-zeroed clock? split the file there)"
                                  : ""));
      }
  }

  void drop_repeated_times(Rows& r) {
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
    say(std::to_string(n) + " row(s) repeating the time of the row before dropped (first on line " +
        line(r, first) + "; the first row of each time kept).");
    filter(r, keep);
  }

  /// A pause (the crosshead held, or the logger writing the last values again) repeats every
  /// channel while the time advances: those rows add nothing and are dropped.
  void drop_pauses(Rows& r) {
    std::vector<bool> keep(r.row.size(), true);
    std::size_t n = 0, first = 0, last_kept = 0;
    for (std::size_t i = 1; i < r.row.size(); ++i) {
      const std::size_t k = last_kept;
      const bool repeat = r.opening[i] == r.opening[k] && r.load[i] == r.load[k] &&
                          (r.a.empty() || same(r.a[i], r.a[k])) &&
                          (r.root.empty() || r.root[i] == r.root[k]);
      if (repeat) {
        keep[i] = false;
        if (n++ == 0)
          first = i;
      } else {
        last_kept = i;
      }
    }
    if (!n)
      return;
    say(std::to_string(n) + " row(s) repeating every channel of the row before while the time " +
        "advanced (a pause: the machine held or the logger repeated itself; first on line " +
        line(r, first) + ") dropped.");
    filter(r, keep);
  }

  /// Empty or NaN cells, crack lengths <= 0 (a crack is measured from the load line, so 0 is a
  /// tracker that lost the tip) and dropout codes (-999, 9999...) are rows without a reading.
  void mark_missing_crack_readings(Rows& r) {
    if (r.a.empty())
      return;
    std::size_t empty = 0, codes = 0, first_code = 0;
    double example = 0;
    bool positive_seen = false;
    for (std::size_t i = 0; i < r.a.size(); ++i) {
      if (std::isnan(r.a[i])) {
        ++empty;
        continue;
      }
      const bool code = is_dropout_code(r.a[i] / c_.crack_factor);
      // A zero or negative length before any positive reading is not a dropout: the column is
      // likely the crack extension (0 at the start), which read as a length would be wrong.
      if (r.a[i] <= 0 && !code && !positive_seen)
        throw InputError(at(r, i) + "a_mm = " + num(r.a[i] / mm) +
                         " before any positive crack reading; a crack length is measured from "
                         "the load line and is > 0 (a column of crack extension needs a0 added; "
                         "an empty cell or a dropout code such as -999 reads as no reading)");
      positive_seen = positive_seen || (r.a[i] > 0 && !code);
      if (r.a[i] <= 0 || code) {
        if (codes++ == 0) {
          first_code = i;
          example = r.a[i] / c_.crack_factor;
        }
        r.a[i] = NAN;
      }
    }
    if (empty + codes == 0)
      return;
    std::string s = std::to_string(empty + codes) + " row(s) without a crack reading (";
    if (empty)
      s += std::to_string(empty) + " empty or NaN cell(s)";
    if (codes)
      s += std::string(empty ? "; " : "") + std::to_string(codes) +
           " dropout value(s) <= 0 or 999..., first " + num(example) + " on line " +
           line(r, first_code);
    say(s + "): the crack length there is unknown (NaN); their load and opening are kept.");
    if (std::none_of(r.a.begin(), r.a.end(), [](double a) { return !std::isnan(a); })) {
      if (o_.crack_length == CrackLengthSource::measured)
        throw InputError(origin_.source + ": " + label() + " (" + lines(r, 0, r.row.size() - 1) +
                         ") has no crack reading in any row, and Crack length = measured");
      say("No row has a crack reading: the record is read as one without crack readings.");
      r.a.clear();
    }
  }

  void clamp_leading_negative_loads(Rows& r) {
    std::size_t n = 0;
    double lowest = 0;
    const std::size_t start = start_row(r);
    for (std::size_t i = 0; i < start; ++i)
      if (r.load[i] < 0) {
        lowest = std::min(lowest, r.load[i]);
        r.load[i] = 0;
        ++n;
      }
    if (n)
      say(std::to_string(n) + " row(s) with a negative load before the load first reached " +
          num(start_fraction) + " of its peak (lowest " + num(lowest) +
          " N: load-cell offset and noise before contact) set to 0 N.");
  }

  /// Single-row spikes: a value far from both neighbours, which agree with each other, is a
  /// glitch of the channel (electrical noise, a dropped bit), not mechanics: no specimen jumps
  /// and comes back within one sample at a constant crosshead rate. Replaced by the neighbours'
  /// mean (a load drop at crack growth stays down on the next row and is not touched).
  void fix_spikes(Rows& r, std::vector<double>& v, const char* column, double unit,
                  const char* unit_name) {
    const std::size_t n = v.size();
    if (n < 5)
      return;
    // The channel's own scales: its noise (median second difference) and its step per row
    // (median first difference; a coarsely sampled record moves a lot per row).
    std::vector<double> step(n - 1), second(n - 2);
    for (std::size_t i = 0; i + 1 < n; ++i)
      step[i] = std::abs(v[i + 1] - v[i]);
    for (std::size_t i = 1; i + 1 < n; ++i)
      second[i - 1] = std::abs(v[i + 1] - 2 * v[i] + v[i - 1]);
    double largest = 0;
    for (double x : v)
      largest = std::max(largest, std::abs(x));
    const double threshold =
        std::max({20 * median_upper(second), 5 * median_upper(step), spike_fraction * largest});
    std::size_t count = 0, first = 0;
    double worst = 0;
    for (std::size_t i = 1; i + 1 < n; ++i) {
      const double d1 = v[i] - v[i - 1], d2 = v[i] - v[i + 1];
      const double jump = std::min(std::abs(d1), std::abs(d2));
      if (d1 * d2 > 0 && jump > threshold && std::abs(v[i + 1] - v[i - 1]) < 0.25 * jump) {
        if (count++ == 0)
          first = i;
        worst = std::max(worst, jump);
        v[i] = 0.5 * (v[i - 1] + v[i + 1]);
      }
    }
    if (count)
      say(std::to_string(count) + " single-row spike(s) in " + column + " (first on line " +
          line(r, first) + ", largest " + num(worst / unit) + " " + unit_name +
          " off both neighbours) replaced by the mean of the two neighbours.");
  }

  /// A channel falling to ~0 in one row from well above it: a short dropout (it comes back near
  /// where it was) is dropped; an opening that restarts from ~0 while the load carries on was
  /// re-zeroed and is continued from before (safe: the shift is the last row's value plus one
  /// increment); a load that restarts from ~0 while the opening carries on was tared mid-test,
  /// which no continuity argument can undo safely (a fracture looks the same): refused.
  void zero_falls(Rows& r, bool load) {
    std::vector<double>& v = load ? r.load : r.opening;
    const std::vector<double>& w = load ? r.opening : r.load;
    const std::size_t n = v.size();
    std::vector<bool> keep(n, true);
    // Against the channel's largest value over the record: noise around zero at the start is
    // never a "fall".
    double largest = 0, w_largest = 0;
    for (std::size_t i = 0; i < n; ++i) {
      largest = std::max(largest, std::abs(v[i]));
      w_largest = std::max(w_largest, std::abs(w[i]));
    }
    std::size_t dropouts = 0, dropout_rows = 0, rezeros = 0;
    std::string first_dropout, rezero_text;
    for (std::size_t i = 1; i < n;) {
      if (!(largest > 0 && v[i - 1] > zero_from_fraction * largest &&
            std::abs(v[i]) < zero_fraction * largest)) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j < n && std::abs(v[j]) < zero_fraction * largest)
        ++j;
      if (j == n)
        break; // to zero for good: the final drop or the last unloading
      if (j - i <= max_dropout_rows && v[j] >= 0.5 * v[i - 1]) {
        std::fill(keep.begin() + static_cast<std::ptrdiff_t>(i),
                  keep.begin() + static_cast<std::ptrdiff_t>(j), false);
        if (dropouts++ == 0)
          first_dropout = lines(r, i, j - 1);
        dropout_rows += j - i;
        i = j;
        continue;
      }
      const bool other_carries_on =
          load ? w[i] >= w[i - 1] - 0.01 * w_largest : w[i] >= 0.8 * w[i - 1];
      if (!other_carries_on) {
        i = j; // both fell: an unloading, left to the unload/reload step
        continue;
      }
      if (load) {
        // After a fracture the load stays low (bridging decays); after a tare it rises again
        // from zero on the rising branch, or goes negative on the falling one.
        const bool rises_again =
            std::any_of(v.begin() + static_cast<std::ptrdiff_t>(j), v.end(), [&](double x) {
              return x > 5 * zero_fraction * largest || x < -zero_fraction * largest;
            });
        if (!rises_again) {
          i = j; // a fracture with some bridging load left: the final drop's business
          continue;
        }
        throw InputError(at(r, i) + "load_N falls from " + num(v[i - 1]) + " N on line " +
                         line(r, i - 1) + " to " + num(v[i]) +
                         " N here while the opening carries on, then rises again from there: the "
                         "load cell was re-zeroed (tared) mid-test (" +
                         label() +
                         "). The load after this line cannot be trusted; cut the record at line " +
                         line(r, i - 1) + " or export it without the tare");
      }
      const double step = i >= 2 ? std::max(0.0, v[i - 1] - v[i - 2]) : 0.0;
      const double shift = v[i - 1] + step - v[i];
      for (std::size_t k = i; k < n; ++k)
        v[k] += shift;
      if (rezeros++ == 0)
        rezero_text = "on line " + line(r, i) + ", from " + num(v[i - 1] / mm) + " mm to " +
                      num((v[i] - shift) / mm) + " mm while the load stayed at " + num(w[i]) +
                      " N; the " + std::to_string(n - i) + " rows from there shifted by " +
                      num(shift / mm) + " mm";
      i = j;
    }
    const char* column = load ? "load_N" : "opening_mm";
    if (dropouts) {
      say(std::to_string(dropouts) + " dropout(s) of " + column + " to ~0 for at most " +
          std::to_string(max_dropout_rows) + " rows (" + std::to_string(dropout_rows) +
          " rows, first " + first_dropout + ") dropped: the channel came back to where it was.");
      filter(r, keep);
    }
    if (rezeros)
      say(std::to_string(rezeros) + " re-zeroed opening_mm channel(s) continued from before (" +
          rezero_text + ": the last opening plus one row's increment).");
  }

  /// The zero offset of the load-line opening: the initial linear part of load against opening
  /// extrapolated to zero load (ASTM D5528's compliance starts there). Removed when it matters
  /// (see offset_fraction) or when negative openings beyond noise need it; the openings left
  /// below zero are then either noise or the toe before the linear part, both set to 0.
  void remove_opening_zero_offset(Rows& r) {
    const std::size_t n = r.row.size();
    const double p = peak(r);
    std::size_t end =
        static_cast<std::size_t>(std::max_element(r.load.begin(), r.load.end()) - r.load.begin());
    if (!r.a.empty()) {
      double first = NAN;
      for (std::size_t i = 0; i < end; ++i) {
        if (std::isnan(r.a[i]))
          continue;
        if (std::isnan(first))
          first = r.a[i];
        else if (r.a[i] != first) {
          end = i;
          break;
        }
      }
    }
    double sx = 0, sy = 0, sxx = 0, sxy = 0, top = 0;
    std::size_t m = 0, first_fit = n, last_fit = 0;
    for (std::size_t i = 0; i < end; ++i)
      if (r.load[i] >= linear_low * p && r.load[i] <= linear_high * p) {
        const double x = r.opening[i], y = r.load[i];
        sx += x, sy += y, sxx += x * x, sxy += x * y, ++m;
        top = std::max(top, x);
        first_fit = std::min(first_fit, i);
        last_fit = i;
      }
    double largest = 0, lowest = 0;
    for (double x : r.opening) {
      largest = std::max(largest, x);
      lowest = std::min(lowest, x);
    }
    double noise = o_.noise_fraction * largest;
    double x0 = NAN;
    if (m >= 5) {
      const double slope = (m * sxy - sx * sy) / (m * sxx - sx * sx);
      if (slope > 0 && std::isfinite(slope))
        x0 = (sx * slope - sy) / (m * slope); // opening at zero load: mean x - mean y / slope
    }
    // A small offset is removed only when it explains the negative openings: all of them,
    // beyond the toe, come back within noise (a negative block mid-test is no zero offset).
    // The band is a fraction of the largest opening measured from the zero: after a shift, of
    // the shifted openings (an absolute crosshead column at 112 mm would otherwise widen it
    // tenfold and pass real negatives as noise; issue 42).
    const double shifted_noise = std::isfinite(x0) ? o_.noise_fraction * (largest - x0) : noise;
    bool explains = lowest < -noise && std::isfinite(x0);
    for (std::size_t i = first_fit; explains && i < n; ++i)
      explains = r.opening[i] - x0 >= -shifted_noise;
    const bool shift = std::isfinite(x0) && (std::abs(x0) > offset_fraction * top || explains);
    if (shift) {
      for (double& x : r.opening)
        x -= x0;
      largest -= x0;
      noise = shifted_noise;
      say("Opening zero offset " + num(x0 / mm) +
          " mm found by extrapolating the initial linear part of the load against the opening (" +
          std::to_string(m) + " rows between " + num(linear_low) + " and " + num(linear_high) +
          " of the peak load, " + lines(r, first_fit, last_fit) +
          ") to zero load: removed from every opening.");
    }
    std::size_t clamped = 0, first = 0;
    double low = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (!(r.opening[i] < 0))
        continue;
      const bool toe = shift && i < first_fit;
      if (r.opening[i] < -noise && !toe)
        throw InputError(at(r, i) + "opening_mm = " + num(r.opening[i] / mm) +
                         " is negative beyond reading noise (" + num(o_.noise_fraction) +
                         " of the largest opening " + num(largest / mm) + " mm) " +
                         (shift ? "after removing the zero offset " + num(x0 / mm) + " mm"
                                : std::string("and the initial linear part of load against "
                                              "opening gives no zero offset that explains it")) +
                         "; the load-line opening must be >= 0");
      if (clamped++ == 0)
        first = i;
      low = std::min(low, r.opening[i]);
      r.opening[i] = 0;
    }
    if (clamped)
      say(std::to_string(clamped) + " negative opening(s) (first on line " + line(r, first) +
          ", lowest " + num(low / mm) + " mm" +
          (shift ? ": the toe before the linear part, or noise" : "") + "; within " +
          num(o_.noise_fraction) + " of the largest opening " + num(largest / mm) +
          " mm, noise around zero) set to 0.");
  }

  void drop_after_final_drop(Rows& r) {
    const double p = peak(r);
    std::size_t last = r.load.size() - 1;
    while (r.load[last] < o_.final_drop_fraction * p)
      --last;
    if (last + 1 == r.load.size())
      return;
    say(std::to_string(r.load.size() - 1 - last) + " row(s) after the final drop (" +
        lines(r, last + 1, r.load.size() - 1) + ", load below " + num(o_.final_drop_fraction) +
        " of the peak " + num(p) + " N) dropped.");
    std::vector<bool> keep(r.load.size(), false);
    std::fill(keep.begin(), keep.begin() + static_cast<std::ptrdiff_t>(last + 1), true);
    filter(r, keep);
  }

  void drop_unload_reload(Rows& r) {
    std::vector<bool> keep(r.opening.size(), true);
    double envelope = r.opening[0];
    std::size_t segments = 0, dropped = 0, jitter = 0;
    std::string first_segment;
    bool tail = false;
    for (std::size_t i = 1; i < r.opening.size();) {
      if (r.opening[i] >= envelope) {
        envelope = r.opening[i++];
        continue;
      }
      // Below the envelope until the opening exceeds it again: an unload/reload segment if it
      // falls back by more than the threshold, else reading noise of a slow crosshead.
      const std::size_t begin = i;
      double lowest = envelope;
      while (i < r.opening.size() && r.opening[i] <= envelope)
        lowest = std::min(lowest, r.opening[i++]);
      if (lowest >= envelope - o_.unload_fraction * envelope) {
        jitter += i - begin;
        continue;
      }
      std::fill(keep.begin() + static_cast<std::ptrdiff_t>(begin),
                keep.begin() + static_cast<std::ptrdiff_t>(i), false);
      dropped += i - begin;
      if (i == r.opening.size())
        tail = true;
      else if (segments++ == 0)
        first_segment = lines(r, begin, i - 1);
    }
    if (jitter)
      say(std::to_string(jitter) + " row(s) where the opening fell back by less than " +
          num(o_.unload_fraction) + " of its largest value so far (crosshead reading noise) kept.");
    if (segments)
      say(std::to_string(segments) + " unload/reload segment(s) dropped (first: " + first_segment +
          "): rows below the largest opening so far; the loading envelope is kept.");
    if (tail) {
      std::size_t first = r.opening.size();
      while (first > 0 && !keep[first - 1])
        --first;
      say(std::to_string(r.opening.size() - first) +
          " row(s) at the end where the opening never again exceeds its largest value (" +
          lines(r, first, r.opening.size() - 1) + ": crosshead stopped or unloading) dropped.");
    }
    if (dropped)
      filter(r, keep);
  }

  /// After the start a DCB carries a tensile load: a negative one within noise of the peak is
  /// set to 0, a larger one is refused.
  void clamp_or_refuse_negative_loads(Rows& r) {
    const double p = peak(r), noise = o_.noise_fraction * p;
    std::size_t n = 0, first = 0;
    for (std::size_t i = start_row(r); i < r.load.size(); ++i) {
      if (!(r.load[i] < 0))
        continue;
      if (r.load[i] < -noise)
        throw InputError(at(r, i) + "load_N = " + num(r.load[i]) +
                         " is negative after the test started (" + label() +
                         "), beyond reading noise (" + num(o_.noise_fraction) + " of the peak " +
                         num(p) + " N); a DCB is loaded in tension");
      if (n++ == 0)
        first = i;
      r.load[i] = 0;
    }
    if (n)
      say(std::to_string(n) + " negative load(s) after the start within " + num(o_.noise_fraction) +
          " of the peak (first on line " + line(r, first) + ": noise around zero) set to 0 N.");
  }

  void clamp_or_refuse_negative_root(Rows& r) {
    if (r.root.empty())
      return;
    double largest = 0;
    for (double x : r.root)
      largest = std::max(largest, x);
    std::size_t n = 0;
    for (std::size_t i = 0; i < r.root.size(); ++i) {
      if (!(r.root[i] < 0))
        continue;
      if (r.root[i] < -o_.noise_fraction * largest)
        throw InputError(at(r, i) + "delta_root_mm = " + num(r.root[i] / mm) +
                         " is negative beyond reading noise; the notch-root opening must be >= 0");
      r.root[i] = 0;
      ++n;
    }
    if (n)
      say(std::to_string(n) + " noise-level negative notch-root opening(s) set to 0.");
  }

  /// The rows of each reading: a reading is a run of equal non-NaN values (NaN rows between
  /// readings of the same value do not split it).
  std::vector<std::size_t> reading_starts(const Rows& r) const {
    std::vector<std::size_t> starts;
    double last = NAN;
    for (std::size_t i = 0; i < r.a.size(); ++i)
      if (!std::isnan(r.a[i]) && r.a[i] != last) {
        starts.push_back(i);
        last = r.a[i];
      }
    return starts;
  }

  /// A crack reading far (more than the tracking tolerance) from both neighbouring readings,
  /// which agree with each other within it, is a tracking spike: no reading.
  void drop_crack_spikes(Rows& r) {
    const auto s = reading_starts(r);
    const double tol = o_.crack_back_tolerance;
    std::size_t n = 0, first = 0;
    for (std::size_t k = 1; k + 1 < s.size(); ++k) {
      const double prev = r.a[s[k - 1]], here = r.a[s[k]], next = r.a[s[k + 1]];
      const double d1 = here - prev, d2 = here - next;
      if (!(d1 * d2 > 0 && std::abs(d1) > tol && std::abs(d2) > tol &&
            std::abs(next - prev) <= tol))
        continue;
      for (std::size_t i = s[k]; i < s[k + 1]; ++i)
        if (r.a[i] == here)
          r.a[i] = NAN;
      if (n++ == 0)
        first = s[k];
    }
    if (n)
      say(std::to_string(n) + " crack reading spike(s) (first on line " + line(r, first) +
          ": a reading more than " + num(tol / mm) +
          " mm off both neighbouring readings, which agree) made rows without a reading.");
  }

  void smooth_crack_back_steps(Rows& r) {
    std::size_t n = 0;
    double largest = 0, running = NAN;
    for (std::size_t i = 0; i < r.a.size(); ++i) {
      if (std::isnan(r.a[i]))
        continue;
      if (std::isnan(running) || r.a[i] >= running) {
        running = r.a[i];
        continue;
      }
      const double back = running - r.a[i];
      if (back > o_.crack_back_tolerance)
        throw InputError(at(r, i) + "a_mm = " + num(r.a[i] / mm) + " is " + num(back / mm) +
                         " mm shorter than the longest reading before (" + num(running / mm) +
                         " mm); a crack length must not go back by more than the tracking "
                         "tolerance of " +
                         num(o_.crack_back_tolerance / mm) + " mm");
      largest = std::max(largest, back);
      r.a[i] = running;
      ++n;
    }
    if (n)
      say(std::to_string(n) + " crack reading(s) stepping back (at most " + num(largest / mm) +
          " mm, within the tracking tolerance of " + num(o_.crack_back_tolerance / mm) +
          " mm) replaced by the longest reading before: a crack does not heal.");
  }

  void check_rows_and_growth(const Rows& r) const {
    if (r.row.size() < min_rows)
      throw InputError(origin_.source + ": " + label() + " has " + std::to_string(r.row.size()) +
                       " rows after cleaning (" + lines(r, 0, r.row.size() - 1) + "); at least " +
                       std::to_string(min_rows) + " are needed");
    if (r.a.empty())
      return;
    const auto s = reading_starts(r);
    if (s.size() < 2)
      throw InputError(at(r, r.row.size() - 1) + label() + ": the crack length stays at " +
                       num(r.a[s.at(0)] / mm) + " mm from line " + line(r, s[0]) +
                       " to here; no crack growth, so no R curve");
  }

  void count_repeated_readings(const TestRecord& out) {
    const std::size_t readings = crack_reading_rows(out).size();
    std::size_t with_reading = 0;
    for (double a : out.crack_length)
      with_reading += !std::isnan(a);
    const std::size_t repeated = with_reading - readings;
    if (repeated)
      say(std::to_string(repeated) + " of " + std::to_string(out.crack_length.size()) +
          " rows repeat the crack reading of the row before (kept for load and opening; the "
          "reductions use the " +
          std::to_string(readings) + " rows with a new reading).");
  }

  /// Crack tracking often stops before the test does (the tip hides in the fibres, or the
  /// camera's field ends): the rows after the last reading still carry load and opening.
  void name_trailing_block(const Rows& r) {
    std::size_t last = r.a.size();
    while (last > 0 && std::isnan(r.a[last - 1]))
      --last;
    if (last == r.a.size() || last == 0)
      return;
    const double p = peak(r);
    double highest = 0;
    for (std::size_t i = last; i < r.load.size(); ++i)
      highest = std::max(highest, r.load[i]);
    say("The last " + std::to_string(r.a.size() - last) + " row(s) (" +
        lines(r, last, r.a.size() - 1) + ") have no crack reading while the load is still up to " +
        num(std::round(100 * highest / p)) +
        " % of its peak: kept, their load and opening count for the energy.");
  }

  const RowOrigin& origin_;
  const RecordColumns& c_;
  const RecordReadOptions& o_;
  std::string name_;
  std::vector<std::string> cleaning_;
};

} // namespace

TestRecord clean_record(const RowOrigin& origin, const RecordColumns& c, const std::string& name,
                        const std::vector<std::size_t>& rows, const RecordReadOptions& o) {
  return RecordCleaner(origin, c, o).clean(name, rows);
}

} // namespace fiberbridge::analysis
