#pragma once
// How identify's independent jobs (optimizer starts, polish rounds, Jacobian columns) hand their
// results back: each job's result as bytes, so that a runner may run it in another process
// (IdentifyJobRunner, app/task_distributor.h spreads them over MPI ranks), and the forward-run
// counts summed in the serial order whatever ran where.
#include "misfit.h"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace fiberbridge::identify::detail {

/// A job's result as bytes (IdentifyJobRunner): doubles and integers copied bit for bit, so a
/// result computed in another process is the one this process would have computed.
class ByteWriter {
public:
  void number(double v) { put(v); }
  void integer(std::int64_t v) { put(v); }
  void text(const std::string& v) {
    integer(static_cast<std::int64_t>(v.size()));
    bytes += v;
  }
  void numbers(const std::vector<double>& v) {
    integer(static_cast<std::int64_t>(v.size()));
    bytes.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(double));
  }
  std::string bytes;

private:
  template <class T>
  void put(const T& v) {
    bytes.append(reinterpret_cast<const char*>(&v), sizeof(T));
  }
};

class ByteReader {
public:
  explicit ByteReader(const std::string& b) : p_(b.data()), end_(b.data() + b.size()) {}
  double number() { return take<double>(); }
  std::int64_t integer() { return take<std::int64_t>(); }
  std::string text() {
    const auto n = static_cast<std::size_t>(integer());
    need(n);
    std::string v(p_, n);
    p_ += n;
    return v;
  }
  std::vector<double> numbers() {
    const auto n = static_cast<std::size_t>(integer());
    need(n * sizeof(double));
    std::vector<double> v(n);
    if (n)
      std::memcpy(v.data(), p_, n * sizeof(double));
    p_ += n * sizeof(double);
    return v;
  }

private:
  void need(std::size_t n) const {
    if (static_cast<std::size_t>(end_ - p_) < n)
      throw std::logic_error("identify: a job's result is shorter than its format");
  }
  template <class T>
  T take() {
    need(sizeof(T));
    T v;
    std::memcpy(&v, p_, sizeof(T));
    p_ += sizeof(T);
    return v;
  }
  const char* p_;
  const char* end_;
};

/// A record's fit as bytes and back (the Jacobian's job 0 carries the model curves).
void write_fit(ByteWriter& w, const RecordFit& f);
RecordFit read_fit(ByteReader& r);

/// The forward-run bookkeeping of one job (its own Misfit), summed over the jobs in job order:
/// the totals and the last failure are those of the serial run.
struct RunCounts {
  int evaluations = 0;
  int forward_runs = 0;
  double forward_time_s = 0;
  std::string last_failure;

  /// A job's part: its own Misfit's counts and `evals` optimizer evaluations.
  static void write(ByteWriter& w, const Misfit& m, int evals) {
    w.integer(evals);
    w.integer(m.forward_runs);
    w.number(m.forward_time_s);
    w.text(m.last_failure);
  }
  void add(ByteReader& r) {
    evaluations += static_cast<int>(r.integer());
    forward_runs += static_cast<int>(r.integer());
    forward_time_s += r.number();
    const std::string failure = r.text();
    if (!failure.empty())
      last_failure = failure;
  }
};

/// `run_jobs` (or serial_jobs when empty) on n jobs; throws std::logic_error unless it returns one
/// result per job.
std::vector<std::string> run_batch(const IdentifyJobRunner& run_jobs, const std::string& what,
                                   std::size_t n, const IdentifyJob& job);

} // namespace fiberbridge::identify::detail
