#pragma once
// A small team of helper threads for the particle loops of one explicit step, built for 2 cores
// shared with other processes. Work is cut into chunks that whichever thread is running claims:
// when a helper is descheduled, the calling thread does its chunks instead of waiting for it
// (OpenMP's join waits for every thread of the team). Idle helpers spin only briefly, then
// sleep: libgomp reads its wait policy from the environment once, at load time, and its default
// spin made 2 threads 4x slower than 1 on busy cores (measured, docs/verification.md).
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace fiberbridge::mpm {

class WorkTeam {
public:
  /// `threads` counts the calling thread: threads - 1 helpers are started (none for 1).
  explicit WorkTeam(int threads);
  ~WorkTeam();
  WorkTeam(const WorkTeam&) = delete;
  WorkTeam& operator=(const WorkTeam&) = delete;

  int threads() const { return static_cast<int>(helpers_.size()) + 1; }
  /// With false, run() does every chunk on the calling thread (the helpers sleep): the same
  /// chunks in the same order, so the same results.
  void set_parallel(bool on) { parallel_ = on; }
  bool parallel() const { return parallel_ && !helpers_.empty(); }
  /// Runs body(chunk) for every chunk in [0, n_chunks) and returns when all have finished. The
  /// caller takes part. Which thread runs a chunk varies from run to run, so a body must write
  /// only what its chunk owns (results then do not depend on the threads). The body must not
  /// throw.
  void run(int n_chunks, const std::function<void(int)>& body);

private:
  void helper_loop();
  /// Claims and runs chunks of job `generation` until none is left.
  void work_on(std::uint64_t generation);

  // Claim ticket: job generation (bits 40-63), number of chunks (20-39) and next unclaimed chunk
  // (0-19) in one word, so that a claim succeeds only while its job is current; the claimer
  // reads the body after the claim, when the job cannot have ended.
  std::atomic<std::uint64_t> ticket_{0};
  std::atomic<const std::function<void(int)>*> body_{nullptr};
  std::atomic<int> done_{0};
  std::atomic<int> sleepers_{0};
  std::atomic<bool> stop_{false};
  std::mutex mutex_;
  std::condition_variable wake_;
  std::vector<std::thread> helpers_;
  bool parallel_ = true;
};

} // namespace fiberbridge::mpm
