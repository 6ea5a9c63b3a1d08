// The forward simulation of a trial law on each record and the weighted residuals against the
// record (docs/design.md section 6, "identify"). ISO 15024's F and N (with_large_displacements)
// map the geometrically linear beam onto arms that rotate far.
#include "misfit.h"

#include "fiberbridge/core/units.h"
#include "fiberbridge/law/piecewise_linear_law.h"
#include "fiberbridge/specimen/large_displacement.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>

namespace fiberbridge::identify {

using units::kPa;
using units::mm;

namespace detail {

const char* const parameter_names[n_parameters] = {"d1_mm",      "sigma1_kPa", "d2_mm",
                                                   "sigma2_kPa", "delta_c_mm", "J_tip_J_m2"};
const double parameter_units[n_parameters] = {mm, kPa, mm, kPa, mm, 1.0};

std::vector<double> Misfit::residuals(const Parameters& p, std::vector<RecordFit>* fits) {
  std::vector<double> r;
  for (const auto& pr : records_) {
    const auto& rec = *pr.record;
    std::vector<double> model_load, model_a;
    double min_F = 1;
    simulate(pr, p, model_load, model_a, min_F);
    for (std::size_t i = 0; i < rec.opening.size(); ++i)
      r.push_back((model_load[i] - rec.load[i]) / (settings_.load_scatter * pr.peak_load));
    for (std::size_t i : pr.crack_rows)
      r.push_back((model_a[i] - rec.crack_length[i]) / settings_.crack_scatter);
    if (fits) {
      RecordFit f;
      f.name = rec.name;
      f.initial_crack = pr.specimen.initial_crack;
      f.initial_compliance = pr.compliance;
      f.E_L = pr.material.E_L;
      f.peak_load = pr.peak_load;
      f.opening = rec.opening;
      f.load = rec.load;
      // NaN on every row without readings, so that writers can index it as the other columns.
      f.crack_length = rec.crack_length.empty() ? std::vector<double>(rec.opening.size(), NAN)
                                                : rec.crack_length;
      f.model_load = model_load;
      f.model_crack_length = model_a;
      f.min_F = min_F;
      double sp = 0, sa = 0;
      for (std::size_t i = 0; i < rec.opening.size(); ++i) {
        sp += std::pow(model_load[i] - rec.load[i], 2);
        f.max_opening_over_a =
            std::max(f.max_opening_over_a, rec.opening[i] / pr.crack_estimate[i]);
      }
      for (std::size_t i : pr.crack_rows)
        sa += std::pow(model_a[i] - rec.crack_length[i], 2);
      f.load_rms_rel = std::sqrt(sp / rec.opening.size()) / pr.peak_load;
      f.crack_rms = pr.crack_rows.empty() ? 0 : std::sqrt(sa / pr.crack_rows.size());
      fits->push_back(std::move(f));
    }
  }
  return r;
}

double Misfit::chi2(const Parameters& p) {
  double s = 0;
  for (double v : residuals(p))
    s += v * v;
  return s;
}

void Misfit::simulate(const PreparedRecord& pr, const Parameters& p, std::vector<double>& load,
                      std::vector<double>& a, double& min_F) {
  const auto& rec = *pr.record;
  const auto t = std::chrono::steady_clock::now();
  ++forward_runs;
  try {
    const auto law = law::make_trilinear(trilinear_of(p));
    auto run = forward_.run(pr.specimen, pr.material, law, p[5], pr.crack_estimate.back());
    if (settings_.large_displacement && forward_.geometrically_linear)
      min_F = with_large_displacements(run, pr.specimen.arm_thickness());
    model_at_openings(run, rec.opening, load, a);
  } catch (const std::exception& e) {
    // A law the model cannot follow from initiation (or, the FEM, resolve): the model carries no
    // load, a large but finite misfit that keeps the optimizer's quadratic model usable.
    last_failure = e.what();
    load.assign(rec.opening.size(), 0.0);
    a.assign(rec.opening.size(), pr.specimen.initial_crack);
  }
  forward_time_s += seconds_since(t);
}

} // namespace detail

void model_at_openings(const result::SimulationResult& run, const std::vector<double>& opening,
                       std::vector<double>& load, std::vector<double>& crack_length) {
  const auto& rc = run.rcurve;
  std::vector<const result::RCurvePoint*> path;
  for (const auto& p : rc)
    if (path.empty() || p.load_point_opening > path.back()->load_point_opening)
      path.push_back(&p);
  load.resize(opening.size());
  crack_length.resize(opening.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < opening.size(); ++i) {
    const double d = opening[i];
    const auto& first = *path.front();
    if (d <= first.load_point_opening) {
      load[i] = first.load * d / first.load_point_opening;
      crack_length[i] = first.a;
      continue;
    }
    while (k + 1 < path.size() && path[k + 1]->load_point_opening < d)
      ++k;
    if (k + 1 >= path.size()) {
      load[i] = path.back()->load;
      crack_length[i] = path.back()->a;
      continue;
    }
    const auto &p = *path[k], &q = *path[k + 1];
    const double w = (d - p.load_point_opening) / (q.load_point_opening - p.load_point_opening);
    load[i] = p.load + w * (q.load - p.load);
    crack_length[i] = p.a + w * (q.a - p.a);
  }
}

double with_large_displacements(result::SimulationResult& run, double arm_thickness) {
  const double l1 = 0.5 * arm_thickness; // hinges on the arms' surfaces, no end blocks (l2 = 0)
  double min_F = 1;
  for (auto& p : run.rcurve) {
    const double a = p.a, d_small = p.load_point_opening;
    if (!(a > 0) || !(d_small > 0))
      continue;
    // F and N at the large-displacement opening, which depends on them: two fixed-point passes
    // from the small one (the change is O((delta/a)^2), the second pass leaves O((delta/a)^4)).
    double d = d_small, F = 1;
    for (int pass = 0; pass < 2; ++pass) {
      F = specimen::large_displacement_F(d, a, l1);
      const double N = specimen::end_block_N(d, a, l1, 0.0);
      d = d_small * N / std::sqrt(F);
    }
    p.load_point_opening = d;
    p.load /= std::sqrt(F);
    min_F = std::min(min_F, F);
  }
  return min_F;
}

} // namespace fiberbridge::identify
