#pragma once
// The crack-plane interface of the DCB model without any deal.II type, so that the cohesive
// mechanics can be tested on their own (docs/design.md section 3: a single interface element under
// load/unload cycles dissipates exactly the law's area).
//
// The crack plane is a row of integration points with an opening each (the FE model
// interpolates it from the nodal openings of the point's segment). Segments (the crack-plane
// faces) are integrated with a composite Gauss-Lobatto rule: Lobatto points include the segment
// ends, the usual cure for the traction oscillations that Gauss-integrated interface elements
// show next to stiff ties (Schellekens & de Borst 1993), and sub-intervals resolve a law that
// changes strongly within one element (next to the tip).
//
// A segment starts intact (the two sides are tied by constraints, owned by the FE model), and is
// opened once: as a traction-free crack face (the sawn notch) or as a fresh cohesive segment
// (dynamic insertion at the crack tip). Points of an opened segment carry the traction law with
// its damage history delta_max; every opened segment also carries frictionless contact.
#include "fiberbridge/law/traction_law.h"

#include <vector>

namespace fiberbridge::fem {

enum class SegmentState { intact, traction_free, cohesive };

/// Nodal response of one interface point at a given opening with the committed history.
struct InterfacePointResponse {
  double force = 0;     ///< traction integrated over the point's weight [N/m out of plane]
  double stiffness = 0; ///< d force / d opening [N/m^2]
  double traction = 0;  ///< traction of the cohesive segments (contact if closing) [Pa]
  bool failed = false;  ///< cohesive and delta_max >= delta_c
};

class CohesiveInterface {
public:
  /// `law` must outlive this object. `contact_stiffness` [Pa/m] is the frictionless penalty for
  /// negative opening on every opened segment.
  CohesiveInterface(const law::TractionLaw& law, double contact_stiffness);

  /// Adds a point at position x [m]; points must be added in non-decreasing x (adjacent segments
  /// each have their own point at a shared node). Returns its index.
  unsigned add_point(double x);
  /// Adds a segment over the given points (increasing x) with Lobatto weights times the segment
  /// length [m]. Returns its index. The segment starts intact.
  unsigned add_segment(const std::vector<unsigned>& points, const std::vector<double>& weights);

  /// Opens an intact segment: traction-free crack face or fresh cohesive segment. Throws
  /// ComputationError if a cohesive segment would inherit damage (insertion must be fresh).
  void open_segment(unsigned segment, SegmentState new_state);

  /// Response of point p at `opening` [m] with the committed history.
  InterfacePointResponse respond(unsigned p, double opening) const;
  /// Traction [Pa] that segment s applies at its local point j at `opening` (0 for intact).
  double segment_traction(unsigned s, unsigned j, double opening) const;
  /// Commits the history at the given openings (one per point): delta_max = max(delta_max,
  /// opening).
  void commit(const std::vector<double>& openings);

  /// Recoverable (elastic) energy of the interface at these openings: sum of force*opening/2,
  /// unloading to the origin [J per m out of plane]. Includes contact.
  double recoverable_energy(const std::vector<double>& openings) const;
  /// Energy dissipated by damage so far, exact from the history:
  /// sum of weight * (int_0^dmax sigma - dmax sigma(dmax)/2) [J per m out of plane].
  double dissipated_energy() const;

  unsigned n_points() const { return static_cast<unsigned>(x_.size()); }
  unsigned n_segments() const { return static_cast<unsigned>(segments_.size()); }
  double x(unsigned p) const { return x_[p]; }
  double delta_max(unsigned p) const { return delta_max_[p]; }
  /// Sum of the weights of the cohesive segments containing p [m].
  double cohesive_weight(unsigned p) const { return cohesive_weight_[p]; }
  /// Sum of the weights of all opened segments containing p [m].
  double open_weight(unsigned p) const { return open_weight_[p]; }
  bool is_cohesive(unsigned p) const { return cohesive_weight_[p] > 0; }
  bool has_failed(unsigned p) const;
  SegmentState state(unsigned s) const { return segments_[s].state; }
  const std::vector<unsigned>& segment_points(unsigned s) const { return segments_[s].points; }
  const std::vector<double>& segment_weights(unsigned s) const { return segments_[s].weights; }
  const law::TractionLaw& law() const { return law_; }
  double contact_stiffness() const { return contact_stiffness_; }

private:
  struct Segment {
    std::vector<unsigned> points;
    std::vector<double> weights;
    SegmentState state = SegmentState::intact;
  };
  const law::TractionLaw& law_;
  double contact_stiffness_;
  std::vector<double> x_, delta_max_, cohesive_weight_, open_weight_;
  std::vector<Segment> segments_;
};

} // namespace fiberbridge::fem
