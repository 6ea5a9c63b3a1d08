// identify_law (include/fiberbridge/identify/identify.h) as its steps: the records prepared
// (prepared_record.cc), the optimizer's starts and polish (optimizer.cc) on the misfit
// (misfit.cc), the uncertainty at the optimum (uncertainty.cc), each batch of independent forward
// runs handed to the job runner (jobs.cc). docs/design.md section 6, "identify".
#include "fiberbridge/identify/identify.h"

#include "fiberbridge/core/error.h"
#include "optimizer.h"
#include "uncertainty.h"

#include <chrono>
#include <cmath>

namespace fiberbridge::identify {

void IdentifySettings::validate(const std::string& c) const {
  if (!(delta_c_min > 0 && delta_c_max > delta_c_min))
    throw InputError(c + "/Delta c range: need 0 < min < max (mm)");
  if (!(stress_max > 0))
    throw InputError(c + "/Stress max: must be positive (kPa)");
  if (!(j_tip_min > 0 && j_tip_max > j_tip_min))
    throw InputError(c + "/J tip range: need 0 < min < max (J/m^2)");
  if (!(load_scatter > 0))
    throw InputError(c + "/Load scatter: must be positive (fraction of the peak load)");
  if (!(crack_scatter > 0))
    throw InputError(c + "/Crack scatter: must be positive (mm)");
  if (!(compliance_low >= 0 && compliance_high > compliance_low && compliance_high <= 1))
    throw InputError(c + "/Compliance window: need 0 <= low < high <= 1 (fractions of the peak)");
  if (algorithm != "bobyqa" && algorithm != "sbplx")
    throw InputError(c + "/Algorithm: expected bobyqa or sbplx, got '" + algorithm + "'");
  if (max_evaluations < 10)
    throw InputError(c + "/Max evaluations: need at least 10");
  if (starts < 1)
    throw InputError(c + "/Starts: need at least 1");
  if (!(relative_tolerance > 0 && relative_tolerance < 1))
    throw InputError(c + "/Tolerance: must be in (0, 1)");
  if (start_j_tip > 0) {
    const auto& l = start_law;
    if (!(0 < l.d1 && l.d1 < l.d2 && l.d2 < l.dc && l.s1 > 0 && l.s2 > 0))
      throw InputError(c + ": the start law needs 0 < d1 < d2 < delta_c and positive stresses");
  }
  beam.validate(c);
}

Identification identify_law(const std::vector<analysis::TestRecord>& records,
                            const specimen::Specimen& specimen, const specimen::Material& quoted,
                            const IdentifySettings& settings,
                            const std::function<void(const std::string&)>& progress,
                            const IdentifyJobRunner& run_jobs, const ForwardModel& forward) {
  const auto t0 = std::chrono::steady_clock::now();
  settings.validate();
  if (records.empty())
    throw InputError("Identify: no records to identify from");
  // The beam unless the caller hands another model (forward_model.h).
  const ForwardModel model = forward.run ? forward : beam_forward_model(settings.beam);
  const auto prepared =
      detail::prepare_records(records, specimen, quoted, settings, model, progress);
  Identification out;
  detail::RunCounts counts; // over every job, in the serial order
  const detail::Parameters best =
      detail::optimize(prepared, settings, model, progress, run_jobs, counts, out.notes);
  out.evaluations = counts.evaluations;
  detail::estimate_uncertainty(prepared, settings, model, best, run_jobs, counts, out);
  // The misfit over all rows of all records, each record's RMS weighted by its rows.
  double sp = 0, sa = 0;
  std::size_t np = 0, na = 0;
  for (const auto& f : out.records) {
    sp += std::pow(f.load_rms_rel, 2) * f.opening.size();
    np += f.opening.size();
    const std::size_t readings = analysis::crack_reading_rows(records[&f - &out.records[0]]).size();
    const std::size_t n = readings > 0 ? readings - 1 : 0;
    sa += std::pow(f.crack_rms, 2) * n;
    na += n;
  }
  out.load_rms_rel = std::sqrt(sp / np);
  out.crack_rms = na ? std::sqrt(sa / na) : 0;
  if (!counts.last_failure.empty())
    out.notes.push_back("some trial laws could not be simulated (last: " + counts.last_failure +
                        "); they were scored as carrying no load");
  out.forward_runs = counts.forward_runs;
  out.forward_time_s = counts.forward_time_s;
  out.wall_time_s = seconds_since(t0);
  return out;
}

} // namespace fiberbridge::identify
