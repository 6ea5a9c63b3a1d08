// Frames to tip and delta_root readings (dic_analysis.h).
#include "fiberbridge/dic/dic_analysis.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <exception>
#include <thread>
#include <unordered_map>
#include <utility>
#include <vector>

namespace fiberbridge::dic {

namespace {

/// The first frame's point positions bucketed by spacing, to tell whether a frame's points are the
/// same material points. Matched point by point, not by means: GOM/ZEISS exports leave failed
/// facets out, so a frame may hold fewer points than the first and its means move with them.
class ReferenceGrid {
public:
  void build(const PlaneFrame& f, double h) {
    h_ = h;
    for (std::size_t i = 0; i < f.s.size(); ++i)
      if (std::isfinite(f.s[i]) && std::isfinite(f.n[i]))
        cells_[key(cell(f.s[i]), cell(f.n[i]))].push_back({f.s[i], f.n[i]});
  }
  /// Whether a reference point lies within `tol` (< h) of (s, n) in both coordinates.
  bool has(double s, double n, double tol) const {
    const long cs = cell(s), cn = cell(n);
    for (long ds = -1; ds <= 1; ++ds)
      for (long dn = -1; dn <= 1; ++dn) {
        const auto it = cells_.find(key(cs + ds, cn + dn));
        if (it != cells_.end())
          for (const auto& p : it->second)
            if (std::abs(p.first - s) <= tol && std::abs(p.second - n) <= tol)
              return true;
      }
    return false;
  }

private:
  long cell(double x) const { return std::lround(std::floor(x / h_)); }
  static std::uint64_t key(long a, long b) {
    return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
  }
  double h_ = 1;
  std::unordered_map<std::uint64_t, std::vector<std::pair<double, double>>> cells_;
};

/// What every frame is checked against: the first frame's points near the crack plane.
struct Reference {
  double spacing = NAN;
  double band_mean_abs_n = NAN; ///< [m] mean |n| of the points within 1.5 spacings of the plane
  ReferenceGrid grid;           ///< every point placed (failed or not)
};

double band_mean_abs_n(const PlaneFrame& f, double h, std::size_t& count, double& nearest) {
  double sum = 0;
  count = 0;
  nearest = INFINITY;
  for (std::size_t i = 0; i < f.n.size(); ++i) {
    if (!std::isfinite(f.n[i]))
      continue;
    nearest = std::min(nearest, std::abs(f.n[i]));
    if (std::abs(f.n[i]) <= 1.5 * h + 1e-3 * h) { // as crack_plane_profile's band
      sum += std::abs(f.n[i]);
      ++count;
    }
  }
  return count ? sum / static_cast<double>(count) : NAN;
}

FrameResult analyse_one(const PlaneFrame& f, const Reference& ref, const DicOptions& o) {
  FrameResult r;
  r.n_points = f.s.size();
  r.n_failed = f.n_failed;
  const double h = ref.spacing;
  std::size_t count = 0;
  double nearest = NAN;
  const double mean_n = band_mean_abs_n(f, h, count, nearest);
  if (count == 0) {
    r.notes.push_back("points moved off the crack plane: none within 1.5 point spacings of it "
                      "(nearest " +
                      fmt(nearest * 1e3) + " mm away); frame left out");
    return r;
  }
  if (std::abs(mean_n - ref.band_mean_abs_n) > 0.5 * h) {
    r.notes.push_back("points moved off the crack plane: the points near it sit at mean |n| " +
                      fmt(mean_n * 1e3) + " mm, in the first frame " +
                      fmt(ref.band_mean_abs_n * 1e3) +
                      " mm (frames must give reference coordinates); frame left out");
    return r;
  }
  // The points are material points: a frame must give the same reference coordinates as the
  // first (an export in the deformed configuration, another area of interest or a moved image
  // origin shifts them).
  std::size_t placed = 0, matched = 0;
  for (std::size_t i = 0; i < f.s.size(); ++i)
    if (std::isfinite(f.s[i]) && std::isfinite(f.n[i])) {
      ++placed;
      matched += ref.grid.has(f.s[i], f.n[i], 0.25 * h) ? 1 : 0;
    }
  // 95 %: a frame may add a few points of its own (an area of interest grown at its edge).
  if (double(matched) < 0.95 * double(placed)) {
    r.notes.push_back("points moved off the crack plane: " + std::to_string(placed - matched) +
                      " of " + std::to_string(placed) +
                      " points are not within a quarter spacing of a point of the first frame "
                      "(frames must give reference coordinates); frame left out");
    return r;
  }
  r.profile = crack_plane_profile(f, h);
  r.tip = locate_tip(r.profile, o.tip, h);
  if (!r.tip.found || r.tip.beyond_view) {
    r.notes.push_back(r.tip.note + "; frame left out");
    return r;
  }
  r.extensometer = read_extensometer(f, o.gauge_length, h, o.points_per_fit);
  if (!r.extensometer.ok) {
    r.notes.push_back(r.extensometer.note + "; frame left out");
    return r;
  }
  r.used = true;
  return r;
}

/// The coordinates' unit the frames state (DICe's header) wins over the option's default: pixels
/// read as mm put the points 1/pixel-size too far apart, which surfaced as a gauge length "below
/// the point spacing" (issue 42). Pixels need the pixel size to become lengths.
FrameGeometry stated_geometry(const RawFrame& raw, FrameGeometry g) {
  if (raw.stated_coordinates.empty() || (raw.stated_coordinates == "px") == g.pixels)
    return g;
  if (raw.stated_coordinates == "mm") {
    g.pixels = false;
    return g;
  }
  if (!(g.pixel_size > 0))
    throw InputError(raw.source + ":" + std::to_string(raw.stated_line) +
                     ": the frame states its coordinates in px; give the pixel size "
                     "(DIC/Pixel size, --pixel-size MM) to turn them into lengths");
  g.pixels = true;
  return g;
}

} // namespace

DicAnalysis analyse_frames(const std::vector<FrameFile>& files, const DicOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  if (files.empty())
    throw InputError("DIC/Frames: no frame files");
  if (o.geometry.pixels && !(o.geometry.pixel_size > 0))
    throw InputError("DIC/Pixel size must be positive when Coordinates = px");
  if (!(o.gauge_length > 0))
    throw InputError("DIC/Extensometer gauge length must be positive");
  if (!(o.tip.threshold > 0))
    throw InputError("DIC/Strain threshold must be positive");

  DicAnalysis a;
  const RawFrame first_raw = read_frame(files.front().path, o.read);
  const FrameGeometry geometry = stated_geometry(first_raw, o.geometry);
  const PlaneFrame first = to_crack_coordinates(first_raw, geometry);
  Reference ref;
  ref.spacing = point_spacing(first);
  std::size_t count = 0;
  double nearest = NAN;
  ref.band_mean_abs_n = band_mean_abs_n(first, ref.spacing, count, nearest);
  ref.grid.build(first, ref.spacing);
  if (count == 0)
    throw InputError(files.front().path + ": no point within 1.5 point spacings (" +
                     fmt(1.5 * ref.spacing * 1e3) + " mm) of the crack plane (nearest " +
                     fmt(nearest * 1e3) +
                     " mm away): check DIC/Crack plane y, Y axis and Coordinates");
  if (0.5 * o.gauge_length < 0.5 * ref.spacing)
    throw InputError("DIC/Extensometer gauge length " + fmt(o.gauge_length * 1e3) +
                     " mm is below the point spacing " + fmt(ref.spacing * 1e3) +
                     " mm: its points would sit among the subsets that straddle the crack");
  a.spacing = ref.spacing;
  a.layout = first_raw.layout;
  a.columns_used = first_raw.used;
  a.strain_factor = first_raw.strain_factor;

  const std::size_t n = files.size();
  a.frames.resize(n);
  std::vector<double> column_times(n, NAN);
  std::vector<std::exception_ptr> errors(n);
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    for (std::size_t i; (i = next++) < n;) {
      try {
        const RawFrame raw = i == 0 ? first_raw : read_frame(files[i].path, o.read);
        column_times[i] = raw.time;
        const PlaneFrame f = i == 0 ? first : to_crack_coordinates(raw, geometry);
        a.frames[i] = analyse_one(f, ref, o);
        a.frames[i].file = files[i];
      } catch (...) {
        errors[i] = std::current_exception();
      }
    }
  };
  unsigned threads = o.threads ? o.threads : std::max(1u, std::thread::hardware_concurrency());
  threads = static_cast<unsigned>(std::min<std::size_t>(threads, n));
  std::vector<std::thread> team;
  for (unsigned t = 1; t < threads; ++t)
    team.emplace_back(work);
  work();
  for (auto& t : team)
    t.join();
  for (const auto& e : errors)
    if (e)
      std::rethrow_exception(e);

  const auto times = frame_times(files, column_times, o.clock, a.time_source);
  // Track the tip in image order: it never goes back (a crack does not heal); a fall-back beyond
  // the reading's uncertainty is said, as is a jump of many spacings between used frames.
  double s_prev = 0, sd_prev = 0;
  bool have_prev = false;
  for (std::size_t i = 0; i < n; ++i) {
    FrameResult& r = a.frames[i];
    r.time = times[i];
    a.points_failed += r.n_failed;
    a.points_used += r.n_points - r.n_failed;
    if (!r.used)
      continue;
    const TipReading& t = r.tip;
    if (!have_prev || t.s >= s_prev) {
      if (have_prev && t.s - s_prev > 20 * a.spacing)
        r.notes.push_back("the tip advanced " + fmt((t.s - s_prev) * 1e3) +
                          " mm since the last used frame (over 20 point spacings)");
      r.s_tip = t.s;
      r.s_tip_sd = t.sd;
    } else {
      r.s_tip = s_prev;
      r.s_tip_sd = sd_prev;
      if (s_prev - t.s > 3 * std::max(t.sd, 0.1 * a.spacing) + a.spacing)
        r.notes.push_back("the threshold point fell back by " + fmt((s_prev - t.s) * 1e3) +
                          " mm (unloading or noise); the tip is held at s = " + fmt(s_prev * 1e3) +
                          " mm (a crack does not heal)");
    }
    s_prev = r.s_tip;
    sd_prev = r.s_tip_sd;
    have_prev = true;
    ++a.frames_used;
  }
  a.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return a;
}

std::vector<DicRecordRow> match_to_machine(const DicAnalysis& a, const MachineRecord& m, double a0,
                                           std::vector<std::string>& notes) {
  std::vector<DicRecordRow> rows;
  std::size_t outside = 0, floored = 0;
  for (std::size_t i = 0; i < a.frames.size(); ++i) {
    const FrameResult& f = a.frames[i];
    if (!f.used)
      continue;
    if (f.time < m.time.front() || f.time > m.time.back()) {
      ++outside;
      continue;
    }
    DicRecordRow r;
    r.frame = i;
    r.time = f.time;
    machine_at(m, f.time, r.opening, r.load);
    r.a = a0 + f.s_tip;
    r.a_sd = f.s_tip_sd;
    r.delta_root = f.extensometer.opening;
    r.delta_root_sd = f.extensometer.sd;
    // The arms cannot overlap: an opening below zero by no more than its noise (3 sd, before the
    // load opens the root) is a zero opening; the record reader refuses a negative one. A larger
    // negative reading is kept, for the reader to refuse (a wrong Y axis or crack plane).
    if (r.delta_root < 0 && r.delta_root >= -3 * r.delta_root_sd) {
      r.delta_root = 0;
      ++floored;
    }
    rows.push_back(r);
  }
  if (floored)
    notes.push_back(std::to_string(floored) +
                    " frame(s) with delta_root below zero within 3 standard deviations (noise "
                    "before the root opens) written as 0");
  if (outside)
    notes.push_back(std::to_string(outside) +
                    " used frame(s) outside the machine record's time "
                    "span [" +
                    fmt(m.time.front()) + ", " + fmt(m.time.back()) +
                    "] s left out (check DIC/First frame time and Frame rate)");
  if (rows.empty())
    throw InputError(m.source +
                     ": no used DIC frame falls inside the machine record's time span "
                     "[" +
                     fmt(m.time.front()) + ", " + fmt(m.time.back()) +
                     "] s; check DIC/First frame time and Frame rate");
  return rows;
}

} // namespace fiberbridge::dic
