// Frame coordinates to crack coordinates (geometry.h).
#include "fiberbridge/dic/geometry.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fiberbridge::dic {

double FrameGeometry::scale() const {
  return pixels ? pixel_size : units::mm;
}

void FrameGeometry::axes(double& sx, double& sy, double& nx, double& ny) const {
  // n = growth_sign x (s turned a quarter counter-clockwise): (0, 1) for both growth directions
  // of a level plane (a mirror for -x, which leaves normal strains and openings unchanged).
  sx = growth_sign * std::cos(tilt);
  sy = std::sin(tilt);
  nx = -growth_sign * sy;
  ny = growth_sign * sx;
}

void FrameGeometry::set_from_points(double x0, double y0, double x1, double y1,
                                    const std::string& where) {
  const double dx = x1 - x0, dy = (y_down ? -1 : 1) * (y1 - y0);
  if (!(std::hypot(dx, dy) > 0))
    throw InputError(where + ": the two points coincide");
  growth_sign = dx >= 0 ? +1 : -1;
  tilt = std::atan2(dy, std::abs(dx));
  if (std::abs(tilt) > 10 * M_PI / 180)
    throw InputError(where + ": the crack plane is tilted " + std::to_string(tilt * 180 / M_PI) +
                     " degrees from the frames' x axis; over 10 degrees the frames' eyy is not the "
                     "crack-normal strain: rotate the export");
  notch_root_x = x0;
  crack_plane_y = y0;
}

double FrameGeometry::frame_x(double s, double n) const {
  double sx, sy, nx, ny;
  axes(sx, sy, nx, ny);
  return notch_root_x + (s * sx + n * nx) / scale();
}

double FrameGeometry::frame_y(double n, double s) const {
  double sx, sy, nx, ny;
  axes(sx, sy, nx, ny);
  return crack_plane_y + (y_down ? -1 : 1) * (s * sy + n * ny) / scale();
}

PlaneFrame to_crack_coordinates(const RawFrame& raw, const FrameGeometry& g) {
  PlaneFrame f;
  f.source = raw.source;
  f.time = raw.time;
  const double k = g.scale(), flip = g.y_down ? -1.0 : 1.0;
  double sx, sy, nx, ny;
  g.axes(sx, sy, nx, ny);
  const std::size_t n = raw.x.size();
  f.s.resize(n);
  f.n.resize(n);
  f.us.resize(n);
  f.vn.resize(n);
  f.eyy = raw.eyy;
  f.valid = raw.valid;
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = raw.x[i] - g.notch_root_x, dy = flip * (raw.y[i] - g.crack_plane_y);
    const double u = raw.u[i], v = flip * raw.v[i];
    f.s[i] = (dx * sx + dy * sy) * k;
    f.n[i] = (dx * nx + dy * ny) * k;
    f.us[i] = (u * sx + v * sy) * k;
    f.vn[i] = (u * nx + v * ny) * k;
    if (!std::isfinite(f.s[i]) || !std::isfinite(f.n[i]))
      f.valid[i] = 0;
  }
  f.n_failed = static_cast<std::size_t>(std::count(f.valid.begin(), f.valid.end(), 0));
  return f;
}

double point_spacing(const PlaneFrame& f) {
  std::vector<std::size_t> placed;
  for (std::size_t i = 0; i < f.s.size(); ++i)
    if (std::isfinite(f.s[i]) && std::isfinite(f.n[i]))
      placed.push_back(i);
  if (placed.size() < 2)
    throw ComputationError(f.source + ": fewer than 2 points with coordinates; no point spacing");
  const std::size_t samples = std::min<std::size_t>(400, placed.size());
  std::vector<double> nearest;
  for (std::size_t k = 0; k < samples; ++k) {
    const std::size_t i = placed[k * placed.size() / samples];
    double best = std::numeric_limits<double>::infinity();
    for (const std::size_t j : placed) {
      const double d2 =
          (f.s[i] - f.s[j]) * (f.s[i] - f.s[j]) + (f.n[i] - f.n[j]) * (f.n[i] - f.n[j]);
      if (j != i && d2 > 0 && d2 < best)
        best = d2;
    }
    if (std::isfinite(best))
      nearest.push_back(std::sqrt(best));
  }
  if (nearest.empty())
    throw ComputationError(f.source + ": all points coincide; no point spacing");
  std::nth_element(nearest.begin(), nearest.begin() + nearest.size() / 2, nearest.end());
  return nearest[nearest.size() / 2];
}

} // namespace fiberbridge::dic
