#include "fiberbridge/mpm/work_team.h"

#include <stdexcept>

namespace fiberbridge::mpm {

namespace {

void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#else
  std::this_thread::yield();
#endif
}

/// Idle polls of a helper before it sleeps: a pause took 25 ns on the 2-vCPU EPYC machine of
/// docs/verification.md, so this is some 30 us, longer than the serial pieces between two runs
/// of a step (the grid clear and update run on the team for that reason: serial, they outlasted
/// the spin, and the helper slept and was woken every step), and short enough to leave a busy
/// core to others (5000 spins: the same speed idle, 0.77-1.04 of it at a load of 1.4-2.2).
constexpr int idle_spins = 1200;

constexpr std::uint64_t chunk_mask = (1u << 20) - 1;
std::uint64_t generation_of(std::uint64_t t) {
  return t >> 40;
}
int chunks_of(std::uint64_t t) {
  return static_cast<int>((t >> 20) & chunk_mask);
}
int next_of(std::uint64_t t) {
  return static_cast<int>(t & chunk_mask);
}

} // namespace

WorkTeam::WorkTeam(int threads) {
  for (int t = 1; t < threads; ++t)
    helpers_.emplace_back([this] { helper_loop(); });
}

WorkTeam::~WorkTeam() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : helpers_)
    t.join();
}

void WorkTeam::work_on(std::uint64_t generation) {
  std::uint64_t t = ticket_.load();
  while (generation_of(t) == generation && next_of(t) < chunks_of(t)) {
    if (ticket_.compare_exchange_weak(t, t + 1)) {
      // The claimed chunk is not done, so the job is still current and body_ is its body.
      (*body_.load())(next_of(t));
      done_.fetch_add(1);
      t = ticket_.load();
    }
  }
}

void WorkTeam::run(int n_chunks, const std::function<void(int)>& body) {
  if (n_chunks <= 0)
    return;
  if (static_cast<std::uint64_t>(n_chunks) > chunk_mask)
    throw std::length_error("WorkTeam: more than 2^20 - 1 chunks in one run");
  if (!parallel()) {
    for (int c = 0; c < n_chunks; ++c)
      body(c);
    return;
  }
  // Publish the job: body first, then the ticket of the new generation (seq_cst throughout).
  const std::uint64_t generation = (generation_of(ticket_.load()) + 1) & 0xffffff;
  body_.store(&body);
  done_.store(0);
  ticket_.store(generation << 40 | static_cast<std::uint64_t>(n_chunks) << 20);
  if (sleepers_.load() > 0) {
    std::lock_guard<std::mutex> lock(mutex_);
    wake_.notify_all();
  }
  work_on(generation);
  // Every chunk is claimed; wait for those a helper is still running (each is one chunk long).
  // A helper that takes long was descheduled: yield the core, it may be waiting for it.
  for (int i = 0; done_.load() < n_chunks; ++i) {
    if (i < idle_spins)
      cpu_relax();
    else
      std::this_thread::yield();
  }
}

void WorkTeam::helper_loop() {
  std::uint64_t seen = 0;
  while (true) {
    std::uint64_t generation = generation_of(ticket_.load());
    for (int i = 0; i < idle_spins && generation == seen && !stop_.load(); ++i) {
      cpu_relax();
      generation = generation_of(ticket_.load());
    }
    if (generation == seen && !stop_.load()) {
      std::unique_lock<std::mutex> lock(mutex_);
      sleepers_.fetch_add(1);
      wake_.wait(lock, [&] { return stop_.load() || generation_of(ticket_.load()) != seen; });
      sleepers_.fetch_sub(1);
      generation = generation_of(ticket_.load());
    }
    if (stop_.load())
      return;
    seen = generation;
    work_on(generation);
  }
}

} // namespace fiberbridge::mpm
