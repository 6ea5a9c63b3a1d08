#pragma once
// The crack plane of the FEM (docs/design.md section 2, "Crack plane" and "What MPI changes"):
// the crack-plane and load-line dofs gathered on every rank, the ties ahead of the tip, the
// release of the tip, the replicated CohesiveInterface with its integration points, and the
// notch-root bookkeeping. Every rank holds all of it, so every rank takes the same decisions.
#include "fiberbridge/fem/cohesive_interface.h"
#include "fiberbridge/fem/dcb_common.h"
#include "mpi_algebra.h"

#include <deal.II/base/index_set.h>
#include <deal.II/base/point.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <map>
#include <memory>
#include <utility>
#include <vector>

namespace fiberbridge::fem {

template <int dim>
class CrackPlane {
public:
  using dof_index = dealii::types::global_dof_index;

  /// `tolerance`: distance below which two support points coincide [m].
  explicit CrackPlane(double tolerance) : tol_(tolerance) {}

  // Setup, in this order.
  /// Notes one support point of a locally owned cell (component c, arm top or bottom) when it
  /// lies on the crack plane or on the load line.
  void note_support_point(dof_index dof, unsigned c, const dealii::Point<dim>& p, bool top);
  /// Gathers the noted dofs of all ranks into the node grid, the load lines and the supports.
  void gather(MPI_Comm comm);
  /// FEM/Kinematics = finite: each load line holds the weighted mean of its vertical
  /// displacements instead of each of them, so that the loaded end section rotates freely at any
  /// angle (a uniform vertical displacement of a rotated section is a moment at second order).
  /// `local_weights`: this rank's integrals of the load-line dofs' shape functions over the end
  /// face (a uniform shear traction's consistent loads), summed over the ranks here.
  void hold_mean_load_line(const std::map<dof_index, double>& local_weights, MPI_Comm comm);
  /// The crack-plane and load-line dofs: every rank keeps them as ghosts.
  std::vector<dof_index> dofs() const;
  /// The replicated interface: composite Gauss-Lobatto points per crack-plane face row
  /// (`subintervals` per element; nodal Lobatto across the width in 3D), the notch opened.
  void make_interface(const law::TractionLaw& law, double contact_stiffness, unsigned degree,
                      unsigned subintervals, const std::vector<double>& x_lines,
                      const std::vector<double>& z_lines, const dealii::IndexSet& owned,
                      double initial_crack);

  /// Ties ahead of the tip, the load lines at +-opening/2, the supports.
  void make_constraints(double opening, const dealii::IndexSet& relevant,
                        dealii::AffineConstraints<double>& c) const;
  /// The face row ahead of the tip becomes a fresh cohesive segment (the constraints change).
  void release_tip();

  // Assembly (the segments this rank assembles).
  /// Adds the interface forces at u (ghosted) to r_full.
  void add_forces(const Vec& u_ghost, Vec& r_full) const;
  /// Adds the interface tangents to the condensed Jacobian.
  void add_jacobian(const std::vector<double>& tangents,
                    const dealii::AffineConstraints<double>& constraints,
                    dealii::TrilinosWrappers::SparseMatrix& jacobian) const;
  void add_pattern(const dealii::AffineConstraints<double>& constraints,
                   dealii::DynamicSparsityPattern& dsp) const;
  /// Adds to c (laid out on `owned`, zero) the operator with c . u = the opening of point p,
  /// not condensed.
  void opening_operator(unsigned p, const dealii::IndexSet& owned, Vec& c) const;
  /// Adds to c (laid out on `owned`, zero) the operator with c . u = station_opening(ix, ...):
  /// the controlled opening of the crack-tip opening control (docs/design.md section 2).
  void station_opening_operator(unsigned ix, double width, const dealii::IndexSet& owned,
                                Vec& c) const;

  /// (top, bottom) dofs of every crack-plane node and component: the pairs the ties hold
  /// together (the condensed solver's jump variables, condensed_solver.h).
  std::vector<std::pair<dof_index, dof_index>> node_pairs() const;
  /// The nodes of interface point p: (top dof of the opening component, Lagrange weight); the
  /// opening is the sum of weight * (top - bottom).
  std::vector<std::pair<dof_index, double>> point_weights(unsigned p) const;

  // Measurements (u ghosted, identical on every rank).
  std::vector<double> node_openings(const Vec& u_ghost) const;
  std::vector<double> openings(const Vec& u_ghost) const;
  /// Width average of the nodal openings at x-station ix (2D: the opening).
  double station_opening(unsigned ix, const std::vector<double>& nodal, double width) const;
  /// int sigma_coh d(delta)/dx q dA over the opened faces (q = 1 without a ramp), per width B
  /// times B: divide by the width.
  double crack_face_integral(const Ramp* ramp, const Vec& u_ghost) const;
  /// The notch root and its opening: the sawn-notch tip until the first point fails (width
  /// average in 3D past delta_c), then where the opening crosses delta_c.
  std::pair<double, double> notch_root(const std::vector<double>& o,
                                       const std::vector<double>& nodal, double delta_c,
                                       double width) const;
  /// "; N crack-face points in contact between x = ... mm" for a failed solve's diagnosis.
  std::string contact_summary(const std::vector<double>& o) const;

  CohesiveInterface& interface() { return *interface_; }
  const CohesiveInterface& interface() const { return *interface_; }
  unsigned n_points() const { return point_map_.size(); }
  unsigned n_z() const { return n_z_; }
  double x_tip() const { return x_st_[tip_]; }
  /// x-station index of the tip (station_opening's ix).
  unsigned tip_station() const { return tip_; }
  /// The initial notch root's station (the sawn notch's tip, x = a0).
  unsigned notch_station() const { return notch_; }
  const std::vector<double>& point_z() const { return point_z_; }
  const std::vector<dof_index>& load_top() const { return load_top_; }
  const std::vector<dof_index>& load_bottom() const { return load_bottom_; }

private:
  /// One pair of coincident crack-plane support points (a "node"), at station (ix, iz).
  struct Node {
    double x = 0, z = 0;
    dof_index top[dim], bottom[dim];
  };
  struct PointMap {
    std::vector<unsigned> nodes; ///< global node indices
    std::vector<unsigned> local; ///< their positions in the segment's node list
    std::vector<double> N, dN;   ///< Lagrange weights and their x-derivatives
  };
  /// Interface points at one x inside one segment (all z in 3D), with their z weights.
  struct Station {
    std::vector<unsigned> points;
    std::vector<double> wz;
  };
  unsigned node_index(unsigned ix, unsigned iz) const { return ix * n_z_ + iz; }
  /// The opening dofs of segment s: the top ones, then the bottom ones.
  std::vector<dof_index> segment_dofs(unsigned s) const;
  bool assembles(unsigned s) const {
    return segment_mine_[s] && interface_->state(s) != SegmentState::intact;
  }

  const double tol_;
  std::vector<double> noted_; ///< (kind 0 crack / 1 load, x, z, component, top?, dof)
  std::vector<Node> nodes_;   ///< sorted by x, then z
  std::vector<double> x_st_, z_st_;
  unsigned n_z_ = 1;
  std::vector<double> node_zw_; ///< width weight of each z station (sum = width)
  std::vector<dof_index> load_top_, load_bottom_, support_;
  std::map<dof_index, double> load_weight_; ///< empty: each load-line dof is prescribed

  std::unique_ptr<CohesiveInterface> interface_;
  std::vector<PointMap> point_map_;
  std::vector<double> point_z_;
  std::vector<Station> stations_;
  std::vector<std::vector<unsigned>> segment_stations_; ///< x-station indices of a segment
  std::vector<std::vector<unsigned>> segment_nodes_;    ///< node indices of a segment
  std::vector<std::vector<unsigned>> segment_points_;
  std::vector<bool> segment_mine_; ///< this rank assembles the segment
  std::vector<unsigned> segment_of_left_station_;
  unsigned tip_ = 0, notch_ = 0; ///< x-station indices
};

} // namespace fiberbridge::fem
