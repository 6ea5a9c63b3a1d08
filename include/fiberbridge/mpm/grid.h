#pragma once
// Regular background grid with two velocity fields per node (CRAMP, Nairn 2003): field `below`
// collects particles below the crack plane, field `above` those above it. A node away from the
// crack, or ahead of the tip, collects all its particles in the field of its own side; a node on
// the crack (its column at or behind the tip) also gets the particles of the other side, in their
// own field (Crack::splits).
#include <vector>

namespace fiberbridge::mpm {

enum Side : int { below = 0, above = 1 };

/// What one velocity field of one node accumulates during a step. The members come in x, y pairs
/// on 16-byte boundaries (mass with an unused partner), so that the scatter and the gather of
/// the explicit solver move a pair with one two-lane operation (the same arithmetic per lane:
/// the same sums to the bit).
struct alignas(16) NodeField {
  double mass = 0;
  double unused = 0;             ///< mass's partner in its pair (the scatter adds zeros to it)
  double px = 0, py = 0;         ///< momentum
  double mux = 0, muy = 0;       ///< mass-weighted displacement (for the contact test)
  double fx = 0, fy = 0;         ///< internal + external + crack-traction force
  double vx = 0, vy = 0;         ///< velocity at the start of the step
  double vx_new = 0, vy_new = 0; ///< velocity after the step (after contact and constraints)
};

class Grid {
public:
  /// Nodes at (x_min + i cell, y_min + j cell), i < nx, j < ny. The crack plane is y = 0.
  Grid(double x_min, double y_min, double cell, int nx, int ny);

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  double cell() const { return cell_; }
  double x_min() const { return x_min_; }
  double y_min() const { return y_min_; }
  double x(int i) const { return x_min_ + i * cell_; }
  double y(int j) const { return y_min_ + j * cell_; }
  int node(int i, int j) const { return i * ny_ + j; }
  int n_nodes() const { return nx_ * ny_; }
  /// The side of the crack plane a node lies on; y = 0 counts as above, but grids used with a
  /// crack are built with the plane in mid-cell so that no node lies on it.
  Side side_of(int j) const { return y(j) >= 0 ? above : below; }

  NodeField& field(int node, int side) { return fields_[2 * node + side]; }
  const NodeField& field(int node, int side) const { return fields_[2 * node + side]; }
  std::vector<NodeField>& fields() { return fields_; }
  void reset();

private:
  double x_min_, y_min_, cell_;
  int nx_, ny_;
  std::vector<NodeField> fields_;
};

/// Velocity of one side's field at (x, y) after the step, with linear weights over the nodes where
/// that field has mass, renormalized (a crack surface sees only its own side). False when no node
/// around the point carries that field.
bool interpolate_field_velocity(const Grid& grid, int side, double x, double y, double& vx,
                                double& vy);

} // namespace fiberbridge::mpm
