// The crack plane of the FEM (crack_plane.h; docs/design.md section 2).
#include "crack_plane.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>

namespace fiberbridge::fem {

using namespace dealii;

template <int dim>
void CrackPlane<dim>::note_support_point(dof_index dof, unsigned c, const Point<dim>& p, bool top) {
  // As doubles for one all_gather (dofs < 2^53).
  const double z = dim == 3 ? p[dim - 1] : 0.0;
  if (std::abs(p[1]) < tol_)
    noted_.insert(noted_.end(), {0, p[0], z, double(c), top ? 1.0 : 0.0, double(dof)});
  if (std::abs(p[0]) < tol_ && c == 1)
    noted_.insert(noted_.end(), {1, p[0], z, double(c), top ? 1.0 : 0.0, double(dof)});
}

template <int dim>
void CrackPlane<dim>::gather(MPI_Comm comm) {
  const auto all = Utilities::MPI::all_gather(comm, noted_);
  noted_.clear();
  auto key = [&](double v) { return std::llround(v / tol_); };
  std::map<std::pair<long long, long long>, Node> by_xz;
  std::map<std::pair<long long, long long>, std::array<int, 2 * dim>> filled;
  std::set<dof_index> load_top, load_bottom;
  for (const auto& block : all)
    for (std::size_t r = 0; r + 6 <= block.size(); r += 6) {
      const auto dof = dof_index(std::llround(block[r + 5]));
      const bool top = block[r + 4] > 0.5;
      if (block[r] > 0.5) {
        (top ? load_top : load_bottom).insert(dof);
        continue;
      }
      const auto k = std::make_pair(key(block[r + 1]), key(block[r + 2]));
      const unsigned c = unsigned(block[r + 3]);
      auto& n = by_xz[k];
      n.x = block[r + 1];
      n.z = block[r + 2];
      (top ? n.top : n.bottom)[c] = dof;
      filled[k][(top ? 0 : dim) + c] = 1;
    }
  for (const auto& [k, f] : filled)
    if (std::count(f.begin(), f.end(), 1) != 2 * dim)
      throw ComputationError("FEM mesh: a crack-plane support point has no partner on the "
                             "other arm (mesh generation error)");
  nodes_.clear();
  std::set<long long> xs, zs;
  for (const auto& [k, n] : by_xz) {
    nodes_.push_back(n);
    xs.insert(k.first);
    zs.insert(k.second);
  }
  n_z_ = zs.size();
  x_st_.clear();
  z_st_.clear();
  for (unsigned a = 0; a < nodes_.size(); a += n_z_)
    x_st_.push_back(nodes_[a].x);
  for (unsigned b = 0; b < n_z_; ++b)
    z_st_.push_back(nodes_[b].z);
  if (nodes_.size() != xs.size() * zs.size())
    throw ComputationError("FEM mesh: the crack-plane nodes do not form a grid in x and z");
  load_top_.assign(load_top.begin(), load_top.end());
  load_bottom_.assign(load_bottom.begin(), load_bottom.end());
  // Rigid-body modes: the crack-plane line at x = L is held in x and y (in 2D the crack-plane
  // point); in 3D its z = 0 end also in z. The load line fixes the rotations about x and z, the
  // line the rotation about y. It carries no load under symmetric opening.
  support_.clear();
  for (unsigned iz = 0; iz < n_z_; ++iz) {
    const auto& n = nodes_[node_index(x_st_.size() - 1, iz)];
    support_.push_back(n.bottom[0]);
    support_.push_back(n.bottom[1]);
    if (dim == 3 && iz == 0)
      support_.push_back(n.bottom[dim - 1]);
  }
}

template <int dim>
void CrackPlane<dim>::hold_mean_load_line(const std::map<dof_index, double>& local_weights,
                                          MPI_Comm comm) {
  std::vector<double> flat; // (dof, weight) pairs as doubles for one all_gather (dofs < 2^53)
  for (const auto& [d, w] : local_weights)
    flat.insert(flat.end(), {double(d), w});
  load_weight_.clear();
  for (const auto& block : Utilities::MPI::all_gather(comm, flat))
    for (std::size_t r = 0; r + 2 <= block.size(); r += 2)
      load_weight_[dof_index(std::llround(block[r]))] += block[r + 1];
  // Lagrange shape functions of degree 1 and 2 have positive face integrals.
  for (const auto* line : {&load_top_, &load_bottom_})
    for (const auto d : *line)
      if (!(load_weight_[d] > 0))
        throw ComputationError("FEM mesh: a load-line dof has no end-face weight (mesh "
                               "generation error)");
}

template <int dim>
std::vector<types::global_dof_index> CrackPlane<dim>::dofs() const {
  std::vector<dof_index> special;
  for (const auto& n : nodes_)
    for (unsigned d = 0; d < dim; ++d) {
      special.push_back(n.top[d]);
      special.push_back(n.bottom[d]);
    }
  special.insert(special.end(), load_top_.begin(), load_top_.end());
  special.insert(special.end(), load_bottom_.begin(), load_bottom_.end());
  std::sort(special.begin(), special.end());
  special.erase(std::unique(special.begin(), special.end()), special.end());
  return special;
}

namespace {

/// Lagrange basis over the node positions `pos` at v, and its derivative.
void lagrange(const std::vector<double>& pos, double v, std::vector<double>& N,
              std::vector<double>& dN) {
  N.assign(pos.size(), 1.0);
  dN.assign(pos.size(), 0.0);
  for (unsigned a = 0; a < pos.size(); ++a)
    for (unsigned b = 0; b < pos.size(); ++b) {
      if (b == a)
        continue;
      double term = 1 / (pos[a] - pos[b]);
      for (unsigned c = 0; c < pos.size(); ++c)
        if (c != a && c != b)
          term *= (v - pos[c]) / (pos[a] - pos[c]);
      dN[a] += term;
      N[a] *= (v - pos[b]) / (pos[a] - pos[b]);
    }
}

} // namespace

template <int dim>
void CrackPlane<dim>::make_interface(const law::TractionLaw& law, double contact_stiffness,
                                     unsigned degree, unsigned subintervals,
                                     const std::vector<double>& x_lines,
                                     const std::vector<double>& z_lines, const IndexSet& owned,
                                     double initial_crack) {
  interface_ = std::make_unique<CohesiveInterface>(law, contact_stiffness);
  auto station_at = [&](const std::vector<double>& st, double v, const char* what) {
    const auto it = std::lower_bound(st.begin(), st.end(), v - tol_);
    if (it == st.end() || std::abs(*it - v) > tol_)
      throw ComputationError(std::string("FEM mesh: no crack-plane node at ") + what + " = " +
                             fmt(v));
    return unsigned(it - st.begin());
  };
  const QGaussLobatto<1> lobatto(degree + 1);
  // z rule: per face across the width the nodal Lobatto rule (2D: one point of weight 1).
  struct ZPoint {
    double z, w;
    std::vector<unsigned> iz;
    std::vector<double> N;
  };
  std::vector<ZPoint> zpoints;
  node_zw_.assign(n_z_, 0.0);
  if (dim == 2) {
    zpoints.push_back({0.0, 1.0, {0}, {1.0}});
    node_zw_[0] = 1;
  } else
    for (unsigned k = 0; k + 1 < z_lines.size(); ++k) {
      const double len = z_lines[k + 1] - z_lines[k];
      std::vector<unsigned> iz;
      std::vector<double> pos;
      for (unsigned q = 0; q < lobatto.size(); ++q) {
        iz.push_back(station_at(z_st_, z_lines[k] + lobatto.point(q)[0] * len, "z"));
        pos.push_back(z_st_[iz.back()]);
      }
      for (unsigned q = 0; q < lobatto.size(); ++q) {
        ZPoint zp;
        zp.z = z_lines[k] + lobatto.point(q)[0] * len;
        zp.w = lobatto.weight(q) * len;
        zp.iz = iz;
        std::vector<double> dN;
        lagrange(pos, zp.z, zp.N, dN);
        node_zw_[iz[q]] += zp.w;
        zpoints.push_back(zp);
      }
    }

  const unsigned m = subintervals;
  segment_of_left_station_.assign(x_st_.size(), ~0u);
  for (unsigned f = 0; f + 1 < x_lines.size(); ++f) {
    const double xl = x_lines[f], len = x_lines[f + 1] - xl;
    std::vector<unsigned> seg_st;
    std::vector<double> pos;
    for (unsigned q = 0; q < lobatto.size(); ++q) {
      seg_st.push_back(station_at(x_st_, xl + lobatto.point(q)[0] * len, "x"));
      pos.push_back(x_st_[seg_st.back()]);
    }
    std::vector<unsigned> seg_nodes;
    for (const unsigned ix : seg_st)
      for (unsigned iz = 0; iz < n_z_; ++iz)
        seg_nodes.push_back(node_index(ix, iz));
    // Composite Lobatto in x (joints of sub-intervals merged).
    std::vector<double> xs, ws;
    for (unsigned i = 0; i < m; ++i)
      for (unsigned q = 0; q < lobatto.size(); ++q) {
        const double x = xl + (i + lobatto.point(q)[0]) / m * len;
        const double w = lobatto.weight(q) * len / m;
        if (!xs.empty() && std::abs(x - xs.back()) < tol_)
          ws.back() += w;
        else {
          xs.push_back(x);
          ws.push_back(w);
        }
      }
    std::vector<unsigned> pts;
    std::vector<double> weights;
    std::vector<double> Nx, dNx;
    for (unsigned i = 0; i < xs.size(); ++i) {
      lagrange(pos, xs[i], Nx, dNx);
      Station station;
      for (const auto& zp : zpoints) {
        PointMap map;
        for (unsigned a = 0; a < seg_st.size(); ++a)
          for (unsigned c = 0; c < zp.iz.size(); ++c) {
            const unsigned node = node_index(seg_st[a], zp.iz[c]);
            map.nodes.push_back(node);
            map.local.push_back(
                unsigned(std::find(seg_nodes.begin(), seg_nodes.end(), node) - seg_nodes.begin()));
            map.N.push_back(Nx[a] * zp.N[c]);
            map.dN.push_back(dNx[a] * zp.N[c]);
          }
        point_map_.push_back(std::move(map));
        point_z_.push_back(zp.z);
        const unsigned p = interface_->add_point(xs[i]);
        pts.push_back(p);
        weights.push_back(ws[i] * zp.w);
        station.points.push_back(p);
        station.wz.push_back(zp.w);
      }
      stations_.push_back(std::move(station));
    }
    const unsigned s = interface_->add_segment(pts, weights);
    segment_stations_.push_back(seg_st);
    segment_nodes_.push_back(seg_nodes);
    segment_points_.push_back(pts);
    segment_mine_.push_back(owned.is_element(nodes_[seg_nodes.front()].top[1]));
    segment_of_left_station_[seg_st.front()] = s;
  }
  notch_ = station_at(x_st_, initial_crack, "x");
  tip_ = notch_;
  for (unsigned s = 0; s < interface_->n_segments(); ++s)
    if (segment_stations_[s].back() <= notch_)
      interface_->open_segment(s, SegmentState::traction_free);
}

template <int dim>
void CrackPlane<dim>::make_constraints(double opening, const IndexSet& relevant,
                                       AffineConstraints<double>& c) const {
  c.clear();
  c.reinit(relevant);
  for (unsigned ix = tip_; ix < x_st_.size(); ++ix)
    for (unsigned iz = 0; iz < n_z_; ++iz)
      for (unsigned d = 0; d < dim; ++d) {
        const auto& n = nodes_[node_index(ix, iz)];
        c.add_line(n.top[d]);
        c.add_entry(n.top[d], n.bottom[d], 1.0);
      }
  for (const auto& [line, value] :
       {std::make_pair(&load_top_, 0.5 * opening), std::make_pair(&load_bottom_, -0.5 * opening)}) {
    if (load_weight_.empty()) {
      for (const auto d : *line) {
        c.add_line(d);
        c.set_inhomogeneity(d, value);
      }
      continue;
    }
    // sum_i w_i u_i = value sum_i w_i, solved for the dof of largest weight.
    dof_index k = line->front();
    double total = 0;
    for (const auto d : *line) {
      total += load_weight_.at(d);
      if (load_weight_.at(d) > load_weight_.at(k))
        k = d;
    }
    const double wk = load_weight_.at(k);
    c.add_line(k);
    for (const auto d : *line)
      if (d != k)
        c.add_entry(k, d, -load_weight_.at(d) / wk);
    c.set_inhomogeneity(k, value * total / wk);
  }
  for (const auto d : support_)
    c.add_line(d);
  c.close();
}

template <int dim>
void CrackPlane<dim>::release_tip() {
  // The row of faces ahead of the tip (the whole width) becomes a fresh cohesive segment.
  const unsigned s = segment_of_left_station_[tip_];
  if (s == ~0u)
    throw ComputationError("FEM: the crack reached the end of the crack plane");
  interface_->open_segment(s, SegmentState::cohesive);
  tip_ = segment_stations_[s].back();
}

template <int dim>
std::vector<types::global_dof_index> CrackPlane<dim>::segment_dofs(unsigned s) const {
  const auto& sn = segment_nodes_[s];
  std::vector<dof_index> sd(2 * sn.size());
  for (unsigned a = 0; a < sn.size(); ++a) {
    sd[a] = nodes_[sn[a]].top[1];
    sd[sn.size() + a] = nodes_[sn[a]].bottom[1];
  }
  return sd;
}

template <int dim>
void CrackPlane<dim>::add_forces(const Vec& u_ghost, Vec& r_full) const {
  for (unsigned s = 0; s < interface_->n_segments(); ++s) {
    if (!assembles(s))
      continue;
    const unsigned ns = segment_nodes_[s].size();
    const auto sd = segment_dofs(s);
    Vector<double> fl(sd.size());
    bool any = false;
    for (const unsigned p : segment_points_[s]) {
      const auto& map = point_map_[p];
      double o = 0;
      for (unsigned a = 0; a < map.nodes.size(); ++a)
        o += map.N[a] *
             (u_ghost[nodes_[map.nodes[a]].top[1]] - u_ghost[nodes_[map.nodes[a]].bottom[1]]);
      const double force = interface_->respond(p, o).force;
      if (force == 0)
        continue;
      any = true;
      for (unsigned a = 0; a < map.nodes.size(); ++a) {
        fl[map.local[a]] += map.N[a] * force;
        fl[ns + map.local[a]] -= map.N[a] * force;
      }
    }
    if (any)
      r_full.add(sd, fl);
  }
}

template <int dim>
void CrackPlane<dim>::add_jacobian(const std::vector<double>& tangents,
                                   const AffineConstraints<double>& constraints,
                                   TrilinosWrappers::SparseMatrix& jacobian) const {
  for (unsigned s = 0; s < interface_->n_segments(); ++s) {
    if (!assembles(s))
      continue;
    const unsigned ns = segment_nodes_[s].size();
    const auto sd = segment_dofs(s);
    FullMatrix<double> kl(2 * ns, 2 * ns);
    bool any = false;
    for (const unsigned p : segment_points_[s]) {
      if (tangents[p] == 0)
        continue;
      any = true;
      const auto& map = point_map_[p];
      for (unsigned a = 0; a < map.nodes.size(); ++a)
        for (unsigned b = 0; b < map.nodes.size(); ++b) {
          const double k = tangents[p] * map.N[a] * map.N[b];
          const unsigned la = map.local[a], lb = map.local[b];
          kl(la, lb) += k;
          kl(la, ns + lb) -= k;
          kl(ns + la, lb) -= k;
          kl(ns + la, ns + lb) += k;
        }
    }
    if (any)
      constraints.distribute_local_to_global(kl, sd, jacobian);
  }
}

template <int dim>
void CrackPlane<dim>::add_pattern(const AffineConstraints<double>& constraints,
                                  DynamicSparsityPattern& dsp) const {
  for (unsigned s = 0; s < interface_->n_segments(); ++s)
    if (assembles(s))
      constraints.add_entries_local_to_global(segment_dofs(s), dsp, false);
}

template <int dim>
void CrackPlane<dim>::opening_operator(unsigned p, const IndexSet& owned, Vec& c) const {
  const auto& map = point_map_[p];
  std::vector<dof_index> idx;
  std::vector<double> val;
  for (unsigned a = 0; a < map.nodes.size(); ++a) {
    const auto& n = nodes_[map.nodes[a]];
    if (owned.is_element(n.top[1])) {
      idx.push_back(n.top[1]);
      val.push_back(map.N[a]);
    }
    if (owned.is_element(n.bottom[1])) {
      idx.push_back(n.bottom[1]);
      val.push_back(-map.N[a]);
    }
  }
  c.add(idx, val);
  c.compress(VectorOperation::add);
}

template <int dim>
void CrackPlane<dim>::station_opening_operator(unsigned ix, double width, const IndexSet& owned,
                                               Vec& c) const {
  std::vector<dof_index> idx;
  std::vector<double> val;
  for (unsigned iz = 0; iz < n_z_; ++iz) {
    const auto& n = nodes_[node_index(ix, iz)];
    const double w = node_zw_[iz] / width;
    if (owned.is_element(n.top[1])) {
      idx.push_back(n.top[1]);
      val.push_back(w);
    }
    if (owned.is_element(n.bottom[1])) {
      idx.push_back(n.bottom[1]);
      val.push_back(-w);
    }
  }
  c.add(idx, val);
  c.compress(VectorOperation::add);
}

template <int dim>
std::vector<std::pair<types::global_dof_index, types::global_dof_index>>
CrackPlane<dim>::node_pairs() const {
  std::vector<std::pair<dof_index, dof_index>> pairs;
  for (const auto& n : nodes_)
    for (unsigned d = 0; d < dim; ++d)
      pairs.emplace_back(n.top[d], n.bottom[d]);
  return pairs;
}

template <int dim>
std::vector<std::pair<types::global_dof_index, double>>
CrackPlane<dim>::point_weights(unsigned p) const {
  std::vector<std::pair<dof_index, double>> w;
  const auto& map = point_map_[p];
  for (unsigned a = 0; a < map.nodes.size(); ++a)
    w.emplace_back(nodes_[map.nodes[a]].top[1], map.N[a]);
  return w;
}

template <int dim>
std::vector<double> CrackPlane<dim>::node_openings(const Vec& u_ghost) const {
  std::vector<double> o(nodes_.size());
  for (unsigned a = 0; a < nodes_.size(); ++a)
    o[a] = u_ghost[nodes_[a].top[1]] - u_ghost[nodes_[a].bottom[1]];
  return o;
}

template <int dim>
std::vector<double> CrackPlane<dim>::openings(const Vec& u_ghost) const {
  const auto nodal = node_openings(u_ghost);
  std::vector<double> o(point_map_.size(), 0.0);
  for (unsigned p = 0; p < point_map_.size(); ++p)
    for (unsigned a = 0; a < point_map_[p].nodes.size(); ++a)
      o[p] += point_map_[p].N[a] * nodal[point_map_[p].nodes[a]];
  return o;
}

template <int dim>
double CrackPlane<dim>::station_opening(unsigned ix, const std::vector<double>& nodal,
                                        double width) const {
  double s = 0;
  for (unsigned iz = 0; iz < n_z_; ++iz)
    s += node_zw_[iz] * nodal[node_index(ix, iz)];
  return s / width;
}

template <int dim>
double CrackPlane<dim>::crack_face_integral(const Ramp* ramp, const Vec& u_ghost) const {
  double J = 0;
  const auto o = openings(u_ghost);
  const auto nodal = node_openings(u_ghost);
  for (unsigned s = 0; s < interface_->n_segments(); ++s) {
    if (interface_->state(s) == SegmentState::intact)
      continue;
    const auto& pts = interface_->segment_points(s);
    const auto& w = interface_->segment_weights(s);
    if (ramp && (interface_->x(pts.back()) <= ramp->x0 || interface_->x(pts.front()) >= ramp->x3))
      continue;
    for (unsigned j = 0; j < pts.size(); ++j) {
      const auto& map = point_map_[pts[j]];
      double slope = 0;
      for (unsigned a = 0; a < map.nodes.size(); ++a)
        slope += map.dN[a] * nodal[map.nodes[a]];
      const double xj = interface_->x(pts[j]);
      J += w[j] * interface_->segment_traction(s, j, o[pts[j]]) * slope *
           (ramp ? ramp->value(xj) : 1.0);
    }
  }
  return J;
}

template <int dim>
std::pair<double, double> CrackPlane<dim>::notch_root(const std::vector<double>& o,
                                                      const std::vector<double>& nodal, double dc,
                                                      double width) const {
  // On stations (x positions of the interface points; in 3D their width averages: opening, and
  // failed when the width-averaged delta_max passed delta_c). In 2D a station is one point.
  const unsigned ns = stations_.size();
  std::vector<double> sx(ns), so(ns);
  int last_failed = -1;
  for (unsigned k = 0; k < ns; ++k) {
    const auto& st = stations_[k];
    double wsum = 0, osum = 0, dsum = 0;
    for (unsigned j = 0; j < st.points.size(); ++j) {
      wsum += st.wz[j];
      osum += st.wz[j] * o[st.points[j]];
      dsum += st.wz[j] * interface_->delta_max(st.points[j]);
    }
    sx[k] = interface_->x(st.points[0]);
    so[k] = osum / wsum;
    if (interface_->is_cohesive(st.points[0]) && dsum / wsum >= dc)
      last_failed = int(k);
  }
  if (last_failed < 0)
    return {x_st_[notch_], station_opening(notch_, nodal, width)};
  const unsigned f = unsigned(last_failed);
  unsigned n = f + 1;
  while (n + 1 < ns && !(sx[n] > sx[f]))
    ++n;
  const double df = so[f], dn = so[n];
  const double root =
      (df > dn && dn < dc && df >= dc) ? sx[f] + (df - dc) / (df - dn) * (sx[n] - sx[f]) : sx[n];
  return {root, dc};
}

template <int dim>
std::string CrackPlane<dim>::contact_summary(const std::vector<double>& o) const {
  unsigned n = 0;
  double lo = 0, hi = 0;
  for (unsigned p = 0; p < o.size(); ++p)
    if (o[p] < 0 && interface_->open_weight(p) > 0) {
      const double x = interface_->x(p);
      lo = n == 0 ? x : std::min(lo, x);
      hi = n == 0 ? x : std::max(hi, x);
      ++n;
    }
  if (n == 0)
    return "; no crack-face point in contact";
  return "; " + std::to_string(n) +
         " crack-face points in contact between x = " + fmt(lo / units::mm) + " and " +
         fmt(hi / units::mm) + " mm";
}

template class CrackPlane<2>;
template class CrackPlane<3>;

} // namespace fiberbridge::fem
