#pragma once
// DIC frames of a DCB from an analytic displacement field with a known cohesive tip, written in
// the layouts DIC software exports (tests of the dic library and its benchmark).
//
// The field, in crack coordinates (s from the notch root along the growth direction, n normal to
// the plane, up): the arms open by delta(s) = lambda A d^2, d = max(0, s_m - s), behind the model
// tip s_m (the front of the bridging zone: the opening closes smoothly there, as under a cohesive
// law with finite stress), each arm carrying half; an elastic strain lambda E0 exp(-|s - s_m|/L)
// normal to the plane; the arms' rotation in u:
//   v = sign(n) delta/2 + eps_el(s) n,   u = -n (1/2) d delta/ds.
// The points lie on a regular grid in the reference configuration (step h; the plane on a row or
// midway between two rows); the displacements get Gaussian noise (sd noise_v); the strain is what
// DIC software computes: the slope dv/dn of a least-squares plane through the noisy displacements
// of a window of (2k+1) x (2k+1) grid points centred on the point (truncated at the edges), so
// that the strain across the crack includes the opening (docs/dic_tip_rule.md).
#include "fiberbridge/dic/geometry.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace fiberbridge::test {

struct SyntheticDcb {
  double h = 0.5e-3;                    ///< [m] grid step
  double s_min = -10e-3, s_max = 60e-3; ///< [m] field of view along the plane
  double n_half = 8e-3;                 ///< [m] field of view either side of the plane
  bool plane_on_row = false;            ///< rows at n = j h, else at (j + 1/2) h
  int window = 2;                       ///< k: strain window of 2k+1 points
  double A = 1.2;                       ///< [1/m] opening curvature: delta = lambda A d^2
  double E0 = 0.002, L = 4e-3;          ///< elastic strain amplitude and decay [m]
  double noise_v = 0;                   ///< [m] displacement noise (sd)
  double fail_fraction = 0;             ///< random points flagged as failed

  double opening(double s, double s_m, double lambda) const {
    const double d = std::max(0.0, s_m - s);
    return lambda * A * d * d;
  }
  double elastic(double s, double s_m, double lambda) const {
    return lambda * E0 * std::exp(-std::abs(s - s_m) / L);
  }
  double v(double s, double n, double s_m, double lambda) const {
    return (n > 0   ? 0.5
            : n < 0 ? -0.5
                    : 0.0) *
               opening(s, s_m, lambda) +
           elastic(s, s_m, lambda) * n;
  }
  /// delta_root the extensometer should read: the material points at (0, +-g/2).
  double delta_root(double g, double s_m, double lambda) const {
    return v(0, 0.5 * g, s_m, lambda) - v(0, -0.5 * g, s_m, lambda);
  }

  std::vector<double> columns() const {
    std::vector<double> c;
    for (double s = s_min; s <= s_max + 1e-12; s += h)
      c.push_back(s);
    return c;
  }
  std::vector<double> rows() const {
    std::vector<double> r;
    const int J = static_cast<int>(std::round(n_half / h));
    for (int j = -J; j <= J; ++j) {
      const double n = plane_on_row ? j * h : (j + 0.5) * h;
      if (std::abs(n) <= n_half + 1e-12)
        r.push_back(n);
    }
    return r;
  }

  /// LS slope dv/dn over the window centred on (column ci, row rj) of a field given on the grid.
  static double window_slope(const std::vector<double>& cols, const std::vector<double>& rws,
                             const std::vector<double>& vgrid, int ci, int rj, int k) {
    const int nc = static_cast<int>(cols.size()), nr = static_cast<int>(rws.size());
    const int c0 = std::max(0, ci - k), c1 = std::min(nc - 1, ci + k);
    const int r0 = std::max(0, rj - k), r1 = std::min(nr - 1, rj + k);
    double nbar = 0;
    for (int r = r0; r <= r1; ++r)
      nbar += rws[r];
    nbar /= (r1 - r0 + 1);
    double num = 0, den = 0;
    for (int c = c0; c <= c1; ++c)
      for (int r = r0; r <= r1; ++r) {
        num += (rws[r] - nbar) * vgrid[static_cast<std::size_t>(c) * nr + r];
        den += (rws[r] - nbar) * (rws[r] - nbar);
      }
    return num / den;
  }

  /// One frame in crack coordinates: points in column-major order.
  dic::PlaneFrame frame(double s_m, double lambda, unsigned seed) const {
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0, 1);
    std::uniform_real_distribution<double> uni(0, 1);
    const auto cols = columns(), rws = rows();
    const std::size_t nc = cols.size(), nr = rws.size();
    std::vector<double> vg(nc * nr);
    dic::PlaneFrame f;
    for (std::size_t c = 0; c < nc; ++c)
      for (std::size_t r = 0; r < nr; ++r) {
        const double s = cols[c], n = rws[r];
        vg[c * nr + r] = v(s, n, s_m, lambda) + noise_v * noise(rng);
        const double ddelta =
            (opening(s + 1e-6, s_m, lambda) - opening(s - 1e-6, s_m, lambda)) / 2e-6;
        f.s.push_back(s);
        f.n.push_back(n);
        f.vn.push_back(vg[c * nr + r]);
        f.us.push_back(-n * 0.5 * ddelta + noise_v * noise(rng));
      }
    for (std::size_t c = 0; c < nc; ++c)
      for (std::size_t r = 0; r < nr; ++r) {
        f.eyy.push_back(
            window_slope(cols, rws, vg, static_cast<int>(c), static_cast<int>(r), window));
        const bool failed = fail_fraction > 0 && uni(rng) < fail_fraction;
        f.valid.push_back(failed ? 0 : 1);
        f.n_failed += failed;
      }
    return f;
  }

  /// The DIC strain on the plane at station s without noise (the LS slope of the exact field over
  /// the window, interpolated between the rows nearest the plane): what the rule should see.
  double plane_strain(double s, double s_m, double lambda) const {
    const auto rws = rows();
    const int nr = static_cast<int>(rws.size());
    std::vector<double> cols;
    for (int i = -window; i <= window; ++i)
      cols.push_back(s + i * h);
    std::vector<double> vg(cols.size() * rws.size());
    for (std::size_t c = 0; c < cols.size(); ++c)
      for (int r = 0; r < nr; ++r)
        vg[c * nr + r] = v(cols[c], rws[r], s_m, lambda);
    int above = 0;
    while (above < nr && rws[above] < 0)
      ++above;
    const double ea = window_slope(cols, rws, vg, window, above, window);
    if (plane_on_row)
      return ea;
    const double eb = window_slope(cols, rws, vg, window, above - 1, window);
    const double w = (0 - rws[above - 1]) / (rws[above] - rws[above - 1]);
    return eb + w * (ea - eb);
  }

  /// Where plane_strain crosses the threshold behind the model tip (bisection), >= 0.
  double expected_rule_tip(double thr, double s_m, double lambda) const {
    double lo = s_m - 30e-3, hi = s_m + 5 * h;
    if (plane_strain(0, s_m, lambda) < thr)
      return 0;
    lo = 0;
    if (plane_strain(hi, s_m, lambda) >= thr)
      return hi;
    for (int it = 0; it < 80; ++it) {
      const double mid = 0.5 * (lo + hi);
      (plane_strain(mid, s_m, lambda) >= thr ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }
};

enum class Out { vic, dice, dice_space, gom, plain };

/// Writes frame `f` (crack coordinates) as a file of layout `out`, mapped to the frames'
/// coordinates by `g` (pixels, y down, plane and root position, growth direction).
inline void write_frame(const std::string& path, const dic::PlaneFrame& f,
                        const dic::FrameGeometry& g, Out out, double time_s = NAN) {
  std::FILE* o = std::fopen(path.c_str(), "w");
  const double k = g.scale(), flip = g.y_down ? -1.0 : 1.0;
  double sx, sy, nx, ny;
  g.axes(sx, sy, nx, ny);
  const auto X = [&](std::size_t i) { return g.frame_x(f.s[i], f.n[i]); };
  const auto Y = [&](std::size_t i) { return g.frame_y(f.n[i], f.s[i]); };
  const auto U = [&](std::size_t i) { return (f.us[i] * sx + f.vn[i] * nx) / k; };
  const auto V = [&](std::size_t i) { return flip * (f.us[i] * sy + f.vn[i] * ny) / k; };
  const std::size_t n = f.s.size();
  switch (out) {
  case Out::vic: {
    // VIC: quoted header, ", " separators; two areas of interest (above / below the plane)
    // separated by a blank line; sigma -1 for a failed point.
    const char* names = g.pixels
                            ? "\"x\", \"y\", \"u\", \"v\", \"exx\", \"eyy\", \"exy\", \"sigma\""
                            : "\"X\", \"Y\", \"Z\", \"U\", \"V\", \"W\", \"exx\", \"eyy\", "
                              "\"exy\", \"sigma\"";
    std::fprintf(o, "%s\n", names);
    for (int aoi = 0; aoi < 2; ++aoi) {
      if (aoi == 1)
        std::fprintf(o, "\n");
      for (std::size_t i = 0; i < n; ++i) {
        if ((f.n[i] >= 0) != (aoi == 0))
          continue;
        const double sigma = f.valid[i] ? 0.012 : -1;
        if (g.pixels)
          std::fprintf(o, "%.6g, %.6g, %.8g, %.8g, %.6g, %.8g, %.6g, %.4g\n", X(i), Y(i), U(i),
                       V(i), 0.0, f.eyy[i], 0.0, sigma);
        else
          std::fprintf(o, "%.6g, %.6g, 0, %.8g, %.8g, 0, %.6g, %.8g, %.6g, %.4g\n", X(i), Y(i),
                       U(i), V(i), 0.0, f.eyy[i], 0.0, sigma);
      }
    }
    break;
  }
  case Out::dice:
  case Out::dice_space: {
    const char* d = out == Out::dice ? "," : " ";
    std::fprintf(o, "***\n*** Digital Image Correlation Engine (DICe), synthetic test frame\n"
                    "***\n*** Step size: x 10 y 10 (-1 implies not regular grid)\n"
                    "*** Coordinates given with (0,0) as upper left corner of image, x positive "
                    "right, y positive down\n***\n");
    std::fprintf(o,
                 "SUBSET_ID%sCOORDINATE_X%sCOORDINATE_Y%sDISPLACEMENT_X%sDISPLACEMENT_Y%sSIGMA%s"
                 "GAMMA%sBETA%sSTATUS_FLAG%sUNCERTAINTY%sVSG_STRAIN_XX%sVSG_STRAIN_YY%s"
                 "VSG_STRAIN_XY\n",
                 d, d, d, d, d, d, d, d, d, d, d, d);
    for (std::size_t i = 0; i < n; ++i)
      std::fprintf(o,
                   "%zu%s%.6E%s%.6E%s%.6E%s%.6E%s%.4E%s0.0000E+00%s0.0000E+00%s%d%s0.0000E+00"
                   "%s0.0000E+00%s%.6E%s0.0000E+00\n",
                   i, d, X(i), d, Y(i), d, U(i), d, V(i), d, f.valid[i] ? 0.01 : -1.0, d, d, d,
                   f.valid[i] ? 4 : 11, d, d, d, f.eyy[i], d);
    break;
  }
  case Out::gom: {
    // nodemap: '#' metadata, the header as the last '#' line, ';' delimited, strains in %.
    std::fprintf(o, "# Process data:\n# project_name                  : synthetic\n");
    if (std::isfinite(time_s))
      std::fprintf(o, "# current_stage_relative_date   : %g\n", time_s);
    std::fprintf(o, "%s\n", std::string(100, '#').c_str());
    std::fprintf(o, "#%10s; %20s; %20s; %20s; %20s; %20s; %20s; %20s; %20s; %20s; %20s\n", "ID",
                 "x_undef [mm]", "y_undef [mm]", "z_undef [mm]", "u [mm]", "v [mm]", "w [mm]",
                 "epsx [%]", "epsy [%]", "epsxy [1]", "epseqv [%]");
    for (std::size_t i = 0; i < n; ++i) {
      if (f.valid[i])
        std::fprintf(o,
                     "%10zu; %20.10f; %20.10f; %20.10f; %20.15f; %20.15f; %20.15f; %20.15f; "
                     "%20.15f; %20.15f; %20.15f\n",
                     i + 1, X(i), Y(i), 0.0, U(i), V(i), 0.0, 0.0, 100 * f.eyy[i], 0.0,
                     100 * std::abs(f.eyy[i]));
      else
        std::fprintf(o, "%10zu; %20.10f; %20.10f; %20.10f; nan; nan; nan; nan; nan; nan; nan\n",
                     i + 1, X(i), Y(i), 0.0);
    }
    break;
  }
  case Out::plain: {
    std::fprintf(o, "x,y,u,v,eyy,valid%s\n", std::isfinite(time_s) ? ",time_s" : "");
    for (std::size_t i = 0; i < n; ++i) {
      std::fprintf(o, "%.8g,%.8g,%.8g,%.8g,%.8g,%d", X(i), Y(i), U(i), V(i), f.eyy[i],
                   f.valid[i] ? 1 : -1);
      if (std::isfinite(time_s))
        std::fprintf(o, ",%.6f", time_s);
      std::fprintf(o, "\n");
    }
    break;
  }
  }
  std::fclose(o);
}

} // namespace fiberbridge::test
