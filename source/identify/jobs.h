#pragma once
// How identify's independent jobs (optimizer starts, polish rounds, Jacobian columns) hand their
// results back: each job's result as bytes, so that a runner may run it in another process
// (IdentifyJobRunner, app/run/task_distributor.h spreads them over MPI ranks), and the forward-run
// counts summed in the serial order whatever ran where.
#include "misfit.h"

#include "fiberbridge/core/binary_archive.h"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace fiberbridge::identify::detail {

/// A job's result as bytes (IdentifyJobRunner), on core/binary_archive.h (the one byte codec of
/// the project, as the resume store's): doubles and integers copied bit for bit, so a result
/// computed in another process is the one this process would have computed. The header and the
/// checksum make a result of another layout or a damaged one an error, never a wrong answer.
inline constexpr const char* kJobMagic = "fiberbridge identify job";
inline constexpr std::uint32_t kJobVersion = 1;

class ByteWriter {
public:
  void number(double v) { w_.put(v); }
  void integer(std::int64_t v) { w_.put(v); }
  void text(const std::string& v) { w_.put(v); }
  void numbers(const std::vector<double>& v) { w_.put(v); }
  /// The finished bytes (header, values, checksum).
  std::string bytes() const { return w_.finish(); }

private:
  BinaryWriter w_{kJobMagic, kJobVersion};
};

class ByteReader {
public:
  explicit ByteReader(const std::string& b)
      : r_(b, kJobMagic, kJobVersion, "identify job result") {}
  double number() { return r_.get<double>(); }
  std::int64_t integer() { return r_.get<std::int64_t>(); }
  std::string text() { return r_.get<std::string>(); }
  std::vector<double> numbers() { return r_.get<std::vector<double>>(); }
  /// Throws unless every byte was read.
  void expect_end() const { r_.expect_end(); }

private:
  BinaryReader r_;
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
