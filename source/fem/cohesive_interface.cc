#include "fiberbridge/fem/cohesive_interface.h"

#include "fiberbridge/core/error.h"

#include <algorithm>
#include <sstream>

namespace fiberbridge::fem {

CohesiveInterface::CohesiveInterface(const law::TractionLaw& law, double contact_stiffness)
    : law_(law), contact_stiffness_(contact_stiffness) {
  if (!(contact_stiffness > 0))
    throw InputError("FEM/Contact stiffness factor: the contact penalty must be positive");
}

unsigned CohesiveInterface::add_point(double x) {
  if (!x_.empty() && x < x_.back())
    throw ComputationError("interface points must be added in non-decreasing x");
  x_.push_back(x);
  delta_max_.push_back(0);
  cohesive_weight_.push_back(0);
  open_weight_.push_back(0);
  return n_points() - 1;
}

unsigned CohesiveInterface::add_segment(const std::vector<unsigned>& points,
                                        const std::vector<double>& weights) {
  if (points.size() < 2 || points.size() != weights.size())
    throw ComputationError("an interface segment needs >= 2 points and one weight per point");
  for (const unsigned p : points)
    if (p >= n_points())
      throw ComputationError("interface segment refers to an unknown point");
  segments_.push_back({points, weights, SegmentState::intact});
  return n_segments() - 1;
}

void CohesiveInterface::open_segment(unsigned s, SegmentState new_state) {
  Segment& seg = segments_.at(s);
  if (seg.state != SegmentState::intact || new_state == SegmentState::intact)
    throw ComputationError("an interface segment is opened once, from intact");
  for (std::size_t j = 0; j < seg.points.size(); ++j) {
    const unsigned p = seg.points[j];
    if (new_state == SegmentState::cohesive) {
      // Dynamic insertion: the new cohesive segment must start undamaged. Its points were tied
      // (zero opening) or are shared with a cohesive neighbour whose history at this point is
      // still zero because the point was tied until now.
      if (delta_max_[p] != 0) {
        std::ostringstream m;
        m << "cohesive segment inserted at x = " << x_[p] * 1e3
          << " mm would inherit damage delta_max = " << delta_max_[p] * 1e3 << " mm";
        throw ComputationError(m.str());
      }
      cohesive_weight_[p] += seg.weights[j];
    }
    open_weight_[p] += seg.weights[j];
  }
  seg.state = new_state;
}

bool CohesiveInterface::has_failed(unsigned p) const {
  return cohesive_weight_[p] > 0 && delta_max_[p] >= law_.critical_opening();
}

InterfacePointResponse CohesiveInterface::respond(unsigned p, double opening) const {
  InterfacePointResponse r;
  if (opening < 0) {
    // Frictionless contact on every opened face; elastic, no damage.
    r.traction = contact_stiffness_ * opening;
    r.force = open_weight_[p] * r.traction;
    r.stiffness = open_weight_[p] * contact_stiffness_;
    r.failed = has_failed(p);
    return r;
  }
  if (cohesive_weight_[p] > 0) {
    const auto c = law_.respond(opening, delta_max_[p], contact_stiffness_);
    r.traction = c.traction;
    r.force = cohesive_weight_[p] * c.traction;
    r.stiffness = cohesive_weight_[p] * c.tangent;
    r.failed = c.failed;
  }
  return r;
}

double CohesiveInterface::segment_traction(unsigned s, unsigned j, double opening) const {
  const Segment& seg = segments_.at(s);
  if (seg.state == SegmentState::intact)
    return 0;
  if (opening < 0)
    return contact_stiffness_ * opening;
  if (seg.state == SegmentState::traction_free)
    return 0;
  return law_.respond(opening, delta_max_[seg.points[j]], contact_stiffness_).traction;
}

void CohesiveInterface::commit(const std::vector<double>& openings) {
  if (openings.size() != x_.size())
    throw ComputationError("CohesiveInterface::commit: one opening per point expected");
  for (unsigned p = 0; p < n_points(); ++p)
    if (cohesive_weight_[p] > 0)
      delta_max_[p] = std::max(delta_max_[p], openings[p]);
}

double CohesiveInterface::recoverable_energy(const std::vector<double>& openings) const {
  double e = 0;
  for (unsigned p = 0; p < n_points(); ++p)
    e += 0.5 * openings[p] * respond(p, openings[p]).force;
  return e;
}

double CohesiveInterface::dissipated_energy() const {
  double d = 0;
  for (unsigned p = 0; p < n_points(); ++p) {
    if (cohesive_weight_[p] == 0 || delta_max_[p] <= 0)
      continue;
    const double dm = delta_max_[p];
    d += cohesive_weight_[p] * (law_.envelope_integral(dm) - 0.5 * dm * law_.envelope(dm));
  }
  return d;
}

} // namespace fiberbridge::fem
