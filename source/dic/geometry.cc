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

double FrameGeometry::frame_x(double s) const {
  return notch_root_x + growth_sign * s / scale();
}

double FrameGeometry::frame_y(double n) const {
  return crack_plane_y + (y_down ? -1 : 1) * n / scale();
}

PlaneFrame to_crack_coordinates(const RawFrame& raw, const FrameGeometry& g) {
  PlaneFrame f;
  f.source = raw.source;
  f.time = raw.time;
  const double k = g.scale(), sy = g.y_down ? -1.0 : 1.0, sx = g.growth_sign;
  const std::size_t n = raw.x.size();
  f.s.resize(n);
  f.n.resize(n);
  f.us.resize(n);
  f.vn.resize(n);
  f.eyy = raw.eyy;
  f.valid = raw.valid;
  for (std::size_t i = 0; i < n; ++i) {
    f.s[i] = sx * (raw.x[i] - g.notch_root_x) * k;
    f.n[i] = sy * (raw.y[i] - g.crack_plane_y) * k;
    f.us[i] = sx * raw.u[i] * k;
    f.vn[i] = sy * raw.v[i] * k;
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
