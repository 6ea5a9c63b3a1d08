#include "fiberbridge/mpm/crack.h"

#include "fiberbridge/core/binary_archive.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/mpm/shape_function.h"

#include <algorithm>
#include <cmath>

namespace fiberbridge::mpm {

Crack::Crack(double x_start, double x_tip, double spacing, const law::TractionLaw& law,
             double split_offset)
    : law_(law), law_bridges_(law.critical_opening() > 0), tolerance_(1e-6 * spacing),
      split_offset_(split_offset) {
  if (!(x_tip > x_start) || !(spacing > 0))
    throw InputError("MPM crack: the initial crack must have positive length and the crack "
                     "particle spacing must be positive");
  const int n = std::max(1, static_cast<int>(std::ceil((x_tip - x_start) / spacing)));
  for (int k = 0; k <= n; ++k) {
    CrackParticle c;
    c.X = x_tip - (n - k) * (x_tip - x_start) / n;
    particles_.push_back(c);
  }
  segments_.assign(n, CrackSegment{}); // the sawn notch: traction-free
}

void Crack::advance(double x_new, double ux, double uy) {
  if (!(x_new > tip()))
    throw ComputationError("MPM crack: a tip advance must move the tip forward");
  CrackParticle c;
  c.X = x_new;
  c.ux[below] = c.ux[above] = ux;
  c.uy[below] = c.uy[above] = uy;
  particles_.push_back(c);
  CrackSegment s;
  s.bridged = law_bridges_;
  segments_.push_back(s);
}

void Crack::update_tractions() {
  for (std::size_t k = 0; k < segments_.size(); ++k) {
    CrackSegment& s = segments_[k];
    const double opening = 0.5 * (particles_[k].opening() + particles_[k + 1].opening());
    // The traction of the last step acted while the opening moved from s.opening to opening.
    traction_work_ += s.traction * (opening - s.opening) * (particles_[k + 1].X - particles_[k].X);
    s.opening = opening;
    if (!s.bridged || s.failed) {
      s.traction = 0;
      continue;
    }
    const law::CohesiveResponse r = law_.respond(s.opening, s.delta_max, 0.0);
    s.traction = r.traction;
    s.delta_max = r.delta_max;
    s.failed = r.failed;
  }
}

namespace {
// Spreads a force on one side's field at (x, y): linear weights over the nodes where that field
// has mass, renormalized, so that the whole force reaches material of that side.
void spread(Grid& grid, int side, double x, double y, double fx, double fy) {
  const AxisWeights wx = linear_weights(x, grid.x_min(), grid.cell());
  const AxisWeights wy = linear_weights(y, grid.y_min(), grid.cell());
  double sum = 0;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const int i = wx.first + a, j = wy.first + b;
      if (i >= 0 && j >= 0 && i < grid.nx() && j < grid.ny() &&
          grid.field(grid.node(i, j), side).mass > 0)
        sum += wx.S[a] * wy.S[b];
    }
  if (sum <= 0)
    throw ComputationError("MPM crack: a bridging traction at x = " + std::to_string(x * 1e3) +
                           " mm has no material of its side to act on; the crack surfaces left "
                           "the particles (time step or loading rate too large)");
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      const int i = wx.first + a, j = wy.first + b;
      if (i < 0 || j < 0 || i >= grid.nx() || j >= grid.ny())
        continue;
      NodeField& f = grid.field(grid.node(i, j), side);
      if (f.mass <= 0)
        continue;
      const double w = wx.S[a] * wy.S[b] / sum;
      f.fx += w * fx;
      f.fy += w * fy;
    }
}
} // namespace

void Crack::add_traction_forces(Grid& grid, double thickness) const {
  for (std::size_t k = 0; k < segments_.size(); ++k) {
    const CrackSegment& s = segments_[k];
    if (s.traction == 0)
      continue;
    const double half_force =
        0.5 * s.traction * (particles_[k + 1].X - particles_[k].X) * thickness;
    for (std::size_t e = k; e <= k + 1; ++e) {
      const CrackParticle& c = particles_[e];
      spread(grid, above, c.X + c.ux[above], c.uy[above], 0.0, -half_force);
      spread(grid, below, c.X + c.ux[below], c.uy[below], 0.0, half_force);
    }
  }
}

void Crack::move_surfaces(const Grid& grid, double dt) {
  for (CrackParticle& c : particles_)
    for (int side : {below, above}) {
      double vx = 0, vy = 0;
      // A surface with no material of its side around it (the notch mouth outside the body)
      // stays where it is; it carries no traction.
      if (interpolate_field_velocity(grid, side, c.X + c.ux[side], c.uy[side], vx, vy)) {
        c.ux[side] += vx * dt;
        c.uy[side] += vy * dt;
      }
    }
}

int Crack::root_segment() const {
  for (std::size_t k = 0; k < segments_.size(); ++k)
    if (segments_[k].bridged && !segments_[k].failed)
      return static_cast<int>(k);
  return -1;
}

double Crack::zone_recoverable(double thickness) const {
  double e = 0;
  for (std::size_t k = 0; k < segments_.size(); ++k) {
    const CrackSegment& s = segments_[k];
    if (s.bridged && !s.failed && s.opening > 0 && s.traction > 0)
      e += 0.5 * s.traction * s.opening * (particles_[k + 1].X - particles_[k].X);
  }
  return e * thickness;
}

double Crack::zone_dissipated(double thickness) const {
  double e = 0;
  for (std::size_t k = 0; k < segments_.size(); ++k) {
    const CrackSegment& s = segments_[k];
    if (!s.bridged)
      continue;
    // Elastic-damage unloading to the origin: what is not stored as delta sigma/2 at delta_max
    // has been dissipated; a failed segment has dissipated the whole area.
    const double d = s.failed ? law_.area()
                              : law_.envelope_integral(s.delta_max) -
                                    0.5 * s.delta_max * law_.envelope(s.delta_max);
    e += d * (particles_[k + 1].X - particles_[k].X);
  }
  return e * thickness;
}

double Crack::max_plane_offset() const {
  double m = 0;
  for (const CrackParticle& c : particles_)
    m = std::max(m, std::fabs(0.5 * (c.uy[above] + c.uy[below])));
  return m;
}

void Crack::save_state(BinaryWriter& out) const {
  out.put(particles_);
  out.put(segments_);
  out.put(traction_work_);
}

void Crack::load_state(BinaryReader& in) {
  std::vector<CrackParticle> particles;
  std::vector<CrackSegment> segments;
  in.get(particles);
  in.get(segments);
  if (particles.empty() || segments.size() + 1 != particles.size())
    throw InputError(in.source() + ": the crack holds " + std::to_string(particles.size()) +
                     " crack particles and " + std::to_string(segments.size()) +
                     " segments (expected one segment fewer than particles)");
  particles_ = std::move(particles);
  segments_ = std::move(segments);
  in.get(traction_work_);
}

} // namespace fiberbridge::mpm
