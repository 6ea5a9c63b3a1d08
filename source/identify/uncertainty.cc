// The uncertainty of an identification from the Jacobian at the optimum (docs/design.md
// section 6, "identify"; identify/covariance.h).
#include "uncertainty.h"

#include "fiberbridge/core/format.h"
#include "fiberbridge/identify/covariance.h"
#include "fiberbridge/law/piecewise_linear_law.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace fiberbridge::identify::detail {

void estimate_uncertainty(const std::vector<PreparedRecord>& prepared,
                          const IdentifySettings& settings, const ForwardModel& forward,
                          const Parameters& best, const IdentifyJobRunner& run_jobs,
                          RunCounts& counts, Identification& out) {
  // Uncertainty: Jacobian of the weighted residuals by central differences (2 % steps: the
  // beam's discrete advances make the misfit piecewise smooth below about 1 %). Job 0 is the
  // optimum itself (with the model curves), jobs 2j+1 and 2j+2 parameter j up and down.
  const auto jacobian_runs =
      run_batch(run_jobs, "jacobian", 1 + 2 * n_parameters, [&](std::size_t k) {
        Misfit misfit(prepared, settings, forward);
        ByteWriter w;
        if (k == 0) {
          std::vector<RecordFit> fits;
          w.numbers(misfit.residuals(best, &fits));
          w.integer(static_cast<std::int64_t>(fits.size()));
          for (const auto& f : fits)
            write_fit(w, f);
        } else {
          const int j = static_cast<int>(k - 1) / 2;
          Parameters p = best;
          const double step = 0.02 * best[j];
          if ((k - 1) % 2 == 0)
            p[j] += step;
          else
            p[j] -= step;
          w.numbers(misfit.residuals(p));
        }
        RunCounts::write(w, misfit, 0);
        return w.bytes();
      });
  std::vector<std::vector<double>> residuals_of(jacobian_runs.size());
  for (std::size_t k = 0; k < jacobian_runs.size(); ++k) {
    ByteReader r(jacobian_runs[k]);
    residuals_of[k] = r.numbers();
    if (k == 0)
      for (auto n = r.integer(); n > 0; --n)
        out.records.push_back(read_fit(r));
    counts.add(r);
    r.expect_end();
  }
  const std::vector<double>& r0 = residuals_of[0];
  std::vector<std::vector<double>> jac(r0.size(), std::vector<double>(n_parameters));
  for (int j = 0; j < n_parameters; ++j) {
    const double step = 0.02 * best[j];
    const auto &rp = residuals_of[1 + 2 * j], &rm = residuals_of[2 + 2 * j];
    for (std::size_t i = 0; i < r0.size(); ++i)
      jac[i][j] = (rp[i] - rm[i]) / (2 * step);
  }
  out.chi2 = 0;
  for (double v : r0)
    out.chi2 += v * v;
  out.n_residuals = r0.size();
  const Covariance cov = covariance_from_jacobian(jac, out.chi2);
  out.law = trilinear_of(best);
  out.j_tip = best[5];
  out.g_ss = out.j_tip + out.law.area();
  for (int j = 0; j < n_parameters; ++j)
    out.parameters.push_back({parameter_names[j], best[j] / parameter_units[j],
                              std::sqrt(std::max(cov.matrix[j][j], 0.0)) / parameter_units[j]});
  out.correlation = cov.correlation;
  for (const auto& n : cov.notes)
    out.notes.push_back(n);
  for (int i = 0; i < n_parameters; ++i) {
    for (int j = i + 1; j < n_parameters; ++j)
      if (std::abs(cov.correlation[i][j]) > 0.95)
        out.notes.push_back(std::string(parameter_names[i]) + " and " + parameter_names[j] +
                            " are correlated at " + fmt(cov.correlation[i][j], 3) +
                            ": the records identify a combination of them, not each one");
    if (out.parameters[i].std_error > 0.5 * out.parameters[i].value)
      out.notes.push_back(std::string(parameter_names[i]) +
                          " is poorly identified (standard "
                          "error " +
                          fmt(100 * out.parameters[i].std_error / out.parameters[i].value, 3) +
                          " % of its value)");
  }
  // J_c and the law's band by linear propagation of the covariance (law parameters only).
  const auto& l = out.law;
  const double g_area[5] = {-0.5 * l.s2, 0.5 * l.d2, 0.5 * l.s1, 0.5 * (l.dc - l.d1), 0.5 * l.s2};
  double var_area = 0;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      var_area += g_area[i] * cov.matrix[i][j] * g_area[j];
  out.j_c_std_error = std::sqrt(std::max(var_area, 0.0));
  const auto law = law::make_trilinear(l);
  for (int k = 0; k <= 100; ++k) {
    const double d = 1.1 * l.dc * k / 100.0;
    double g[5];
    for (int j = 0; j < 5; ++j) {
      Parameters p = best;
      const double h = 1e-4 * best[j];
      p[j] += h;
      const double sp = law::make_trilinear(trilinear_of(p)).envelope(d);
      p[j] -= 2 * h;
      const double sm = law::make_trilinear(trilinear_of(p)).envelope(d);
      g[j] = (sp - sm) / (2 * h);
    }
    double var = 0;
    for (int i = 0; i < 5; ++i)
      for (int j = 0; j < 5; ++j)
        var += g[i] * cov.matrix[i][j] * g[j];
    const double sigma = law.envelope(d), sd = std::sqrt(std::max(var, 0.0));
    out.band_delta.push_back(d);
    out.band_sigma.push_back(sigma);
    out.band_lo.push_back(std::max(0.0, sigma - sd));
    out.band_hi.push_back(sigma + sd);
  }
}

} // namespace fiberbridge::identify::detail
