#include "fiberbridge/mpm/j_integral.h"

#include <algorithm>
#include <cmath>

namespace fiberbridge::mpm {

namespace {

// Energy-momentum integrand of particle p for the X-direction: components (J=1, J=2) of
// P_iJ u_i,1 - W delta_1J, per reference volume.
void integrand(const ExplicitSolver& s, int p, double& e1, double& e2) {
  const Particles& P = s.particles();
  const auto& F = P.F[p];
  const auto& sig = P.stress[p];
  // First Piola stress P = det(F) sigma F^-T = sigma [[F22, -F21], [-F12, F11]].
  const double P11 = sig[0] * F[3] - sig[2] * F[1];
  const double P12 = -sig[0] * F[2] + sig[2] * F[0];
  const double P21 = sig[2] * F[3] - sig[1] * F[1];
  const double P22 = -sig[2] * F[2] + sig[1] * F[0];
  const double u11 = F[0] - 1, u21 = F[2];
  e1 = P11 * u11 + P21 * u21 - s.energy_density(p);
  e2 = P12 * u11 + P22 * u21;
}

// Lattice columns whose reference centres lie in [lo, hi).
std::pair<int, int> columns(const Particles& P, double lo, double hi) {
  const int first = std::max(0, static_cast<int>(std::ceil((lo - P.x0) / P.spacing_x - 0.5)));
  const int last =
      std::min(P.lattice_nx, static_cast<int>(std::ceil((hi - P.x0) / P.spacing_x - 0.5)));
  return {first, last};
}

} // namespace

double tip_j_integral(const ExplicitSolver& s, const Crack& crack, double r_in, double r_out) {
  const Particles& P = s.particles();
  const double xt = crack.tip();
  const double ramp = r_out - r_in;
  // Plateau q = 1 within r_in of the tip, linear to 0 at r_out: the gradient of q, which weights
  // the integrand, stays away from the tip where a crack smeared over a cell has the least
  // accurate fields (a pyramid weighting the tip itself reads 20-40 % low; see the tests).
  auto trapezoid = [&](double d) { return std::min(1.0, (r_out - std::fabs(d)) / ramp); };
  // The gradient of q is spread evenly over the particle columns (rows) whose centres fall in
  // each ramp, so that the particle quadrature of int dq/dX dX is exactly -1 wherever the tip
  // sits on the lattice. (With the continuous slope, a tip on a particle column left one of the
  // two ramp columns on a breakpoint and J came out at half its value.)
  auto ramp_count = [&](double centre, double spacing, double origin, int n, int sign) {
    int count = 0;
    for (int i = 0; i < n; ++i) {
      const double d = sign * (origin + (i + 0.5) * spacing - centre);
      if (d > r_in && d < r_out)
        ++count;
    }
    return count;
  };
  const int nx_right = ramp_count(xt, P.spacing_x, P.x0, P.lattice_nx, 1);
  const int nx_left = ramp_count(xt, P.spacing_x, P.x0, P.lattice_nx, -1);
  const int ny_up = ramp_count(0.0, P.spacing_y, P.y0, P.lattice_ny, 1);
  const int ny_down = ramp_count(0.0, P.spacing_y, P.y0, P.lattice_ny, -1);
  auto slope = [&](double d, int n_pos, int n_neg, double spacing) {
    if (std::fabs(d) <= r_in || std::fabs(d) >= r_out)
      return 0.0;
    return d > 0 ? (n_pos > 0 ? -1.0 / (n_pos * spacing) : 0.0)
                 : (n_neg > 0 ? 1.0 / (n_neg * spacing) : 0.0);
  };
  const auto [c0, c1] = columns(P, xt - r_out, xt + r_out);
  double J = 0;
  for (int ix = c0; ix < c1; ++ix)
    for (int iy = 0; iy < P.lattice_ny; ++iy) {
      const int p = P.index(ix, iy);
      const double dx = P.X[p] - xt, dy = P.Y[p];
      if (std::fabs(dx) >= r_out || std::fabs(dy) >= r_out)
        continue;
      const double dq1 = slope(dx, nx_right, nx_left, P.spacing_x) * trapezoid(dy);
      const double dq2 = trapezoid(dx) * slope(dy, ny_up, ny_down, P.spacing_y);
      if (dq1 == 0 && dq2 == 0)
        continue;
      double e1, e2;
      integrand(s, p, e1, e2);
      J += (e1 * dq1 + e2 * dq2) * P.volume[p];
    }
  J /= s.thickness();
  // The crack-face tractions inside the domain do work sigma d(delta) that the domain integral
  // counts; remove it to leave the tip's own energy release rate.
  const auto& cp = crack.particles();
  const auto& seg = crack.segments();
  for (std::size_t k = 0; k < seg.size(); ++k) {
    if (seg[k].traction == 0)
      continue;
    const double xm = 0.5 * (cp[k].X + cp[k + 1].X);
    if (std::fabs(xm - xt) < r_out)
      J -= seg[k].traction * (cp[k].opening() - cp[k + 1].opening()) * trapezoid(xm - xt);
  }
  // The opening jumps from delta_tip at the tip particle to zero in the continuum ahead: the
  // tip cell is only partly split (Crack::splits), and the tip particle reads an opening (mostly
  // the elastic stretch between the node rows, 8 % of delta_c in the linear-softening
  // verification run). Translating that profile with the tip opens material from 0 to
  // delta_tip at the jump, and the law does its work over [0, delta_tip] there: the crack-face
  // term of the domain integral across the jump. It is zone work, not tip energy; left in,
  // it made the tip grow early and G_ss 11 % low (6 % with it subtracted).
  if (!seg.empty() && seg.back().bridged && !seg.back().failed) {
    const double d_tip = cp.back().opening();
    if (d_tip > 0)
      J -= crack.law().envelope_integral(std::min(d_tip, crack.law().critical_opening()));
  }
  return J;
}

double far_field_j_integral(const ExplicitSolver& s, double x_left, double x_right, double w) {
  const Particles& P = s.particles();
  double J = 0;
  for (int strip = 0; strip < 2; ++strip) {
    const double xc = strip == 0 ? x_left : x_right;
    const auto [c0, c1] = columns(P, xc - 0.5 * w, xc + 0.5 * w);
    if (c1 <= c0)
      continue;
    // q rises from 0 to 1 across the left strip and falls across the right one; using the
    // width of the particle columns actually taken keeps the ramp exact on the lattice.
    const double dq = (strip == 0 ? 1.0 : -1.0) / ((c1 - c0) * P.spacing_x);
    for (int ix = c0; ix < c1; ++ix)
      for (int iy = 0; iy < P.lattice_ny; ++iy) {
        const int p = P.index(ix, iy);
        double e1, e2;
        integrand(s, p, e1, e2);
        J += e1 * dq * P.volume[p];
      }
  }
  return J / s.thickness();
}

} // namespace fiberbridge::mpm
