// identify's jobs: the byte form of a record's fit and the runner of a batch of jobs (serial by
// default, over MPI ranks when the app supplies a runner).
#include "jobs.h"

namespace fiberbridge::identify {

namespace detail {

void write_fit(ByteWriter& w, const RecordFit& f) {
  w.text(f.name);
  for (double v : {f.initial_crack, f.initial_compliance, f.E_L, f.peak_load, f.load_rms_rel,
                   f.crack_rms, f.max_opening_over_a, f.min_F})
    w.number(v);
  for (const auto* v : {&f.opening, &f.load, &f.crack_length, &f.model_load, &f.model_crack_length})
    w.numbers(*v);
}

RecordFit read_fit(ByteReader& r) {
  RecordFit f;
  f.name = r.text();
  for (double* v : {&f.initial_crack, &f.initial_compliance, &f.E_L, &f.peak_load, &f.load_rms_rel,
                    &f.crack_rms, &f.max_opening_over_a, &f.min_F})
    *v = r.number();
  for (auto* v : {&f.opening, &f.load, &f.crack_length, &f.model_load, &f.model_crack_length})
    *v = r.numbers();
  return f;
}

std::vector<std::string> run_batch(const IdentifyJobRunner& run_jobs, const std::string& what,
                                   std::size_t n, const IdentifyJob& job) {
  auto out = run_jobs ? run_jobs(what, n, job) : serial_jobs(what, n, job);
  if (out.size() != n)
    throw std::logic_error("identify: the job runner returned " + std::to_string(out.size()) +
                           " results for " + std::to_string(n) + " " + what + " jobs");
  return out;
}

} // namespace detail

std::vector<std::string> serial_jobs(const std::string&, std::size_t n, const IdentifyJob& job) {
  std::vector<std::string> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    out.push_back(job(i));
  return out;
}

} // namespace fiberbridge::identify
