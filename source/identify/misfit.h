#pragma once
// identify's misfit (docs/design.md section 6, "identify"): a trial law and J_tip run forward on
// each prepared record, the model's load and crack length compared with the record's at its
// openings, as weighted residuals.
#include "prepared_record.h"

#include "fiberbridge/core/clock.h"

#include <array>
#include <chrono>
#include <string>
#include <vector>

namespace fiberbridge::identify::detail {

/// Physical parameters in the order of the report: d1, s1, d2, s2, dc [m, Pa], J_tip [J/m^2].
constexpr int n_parameters = 6;
using Parameters = std::array<double, n_parameters>;
extern const char* const parameter_names[n_parameters];
extern const double parameter_units[n_parameters];

inline law::TrilinearParameters trilinear_of(const Parameters& p) {
  return {p[0], p[1], p[2], p[3], p[4]};
}

/// The misfit of trial parameters over the prepared records, counting its forward runs. One
/// Misfit per job: the counts are the job's own (jobs.h sums them in the serial order).
class Misfit {
public:
  Misfit(const std::vector<PreparedRecord>& records, const IdentifySettings& settings,
         const ForwardModel& forward)
      : records_(records), settings_(settings), forward_(forward) {}

  /// Weighted residuals (load rows, then fresh crack readings, record after record); the model
  /// curves go to `fits` if given.
  std::vector<double> residuals(const Parameters& p, std::vector<RecordFit>* fits = nullptr);

  /// The sum of the squared residuals (the chi^2 the optimizer minimizes).
  double chi2(const Parameters& p);

  int forward_runs = 0;
  double forward_time_s = 0;
  std::string last_failure;

private:
  /// The forward model's P(opening) and a(opening) at the record's openings, mapped onto large
  /// displacements when asked (`min_F`: the smallest F over the run).
  void simulate(const PreparedRecord& pr, const Parameters& p, std::vector<double>& load,
                std::vector<double>& a, double& min_F);

  const std::vector<PreparedRecord>& records_;
  const IdentifySettings& settings_;
  const ForwardModel& forward_;
};

} // namespace fiberbridge::identify::detail
