#include "fiberbridge/app/run/task_distributor.h"

#include "fiberbridge/core/error.h"
#include "fiberbridge/core/output_guard.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <thread>
#include <time.h>

namespace fiberbridge::app {

namespace {

MPI_Comm current_simulation_comm = MPI_COMM_WORLD;

/// Sets simulation_communicator() for one task and restores it (also when the task throws).
class SimulationCommScope {
public:
  explicit SimulationCommScope(MPI_Comm c) : previous_(current_simulation_comm) {
    current_simulation_comm = c;
  }
  ~SimulationCommScope() { current_simulation_comm = previous_; }

private:
  MPI_Comm previous_;
};

enum Status : std::int32_t { ok = 0, input_error = 1, computation_error = 2, other_error = 3 };

struct Done {
  std::uint64_t index;
  std::int32_t status;
  double seconds, cpu_seconds;
  std::string text; ///< the result, or the error message
};

template <class T>
void put(std::string& buf, const T& v) {
  buf.append(reinterpret_cast<const char*>(&v), sizeof(T));
}
template <class T>
T take(const char*& p) {
  T v;
  std::memcpy(&v, p, sizeof(T));
  p += sizeof(T);
  return v;
}

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

Done run_one(std::size_t i, const std::function<std::string(std::size_t)>& task) {
  const auto t0 = std::chrono::steady_clock::now();
  const double c0 = process_cpu_seconds();
  Done d{i, ok, 0.0, 0.0, {}};
  try {
    SimulationCommScope scope(MPI_COMM_SELF);
    d.text = task(i);
  } catch (const InputError& e) {
    d = {i, input_error, 0.0, 0.0, e.what()};
  } catch (const ComputationError& e) {
    d = {i, computation_error, 0.0, 0.0, e.what()};
  } catch (const std::exception& e) {
    d = {i, other_error, 0.0, 0.0, e.what()};
  }
  d.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  d.cpu_seconds = process_cpu_seconds() - c0;
  return d;
}

/// The shared task counter: rank 0 holds one integer, every rank fetches-and-increments it.
/// MPI_Win_allocate (not MPI_Win_create) lets Open MPI use shared memory on one node.
class SharedCounter {
public:
  explicit SharedCounter(MPI_Comm comm) {
    int rank = 0;
    MPI_Comm_rank(comm, &rank);
    MPI_Win_allocate(rank == 0 ? sizeof(std::int64_t) : 0, sizeof(std::int64_t), MPI_INFO_NULL,
                     comm, &base_, &win_);
    if (rank == 0) {
      MPI_Win_lock(MPI_LOCK_EXCLUSIVE, 0, 0, win_);
      *base_ = 0;
      MPI_Win_unlock(0, win_);
    }
    MPI_Barrier(comm); // nobody fetches before the counter is zeroed
  }
  ~SharedCounter() { MPI_Win_free(&win_); }
  std::int64_t fetch_and_increment() {
    const std::int64_t one = 1;
    std::int64_t got = 0;
    MPI_Win_lock(MPI_LOCK_SHARED, 0, 0, win_);
    MPI_Fetch_and_op(&one, &got, MPI_INT64_T, 0, 0, MPI_SUM, win_);
    MPI_Win_unlock(0, win_);
    return got;
  }

private:
  std::int64_t* base_ = nullptr;
  MPI_Win win_;
};

/// Waits until every rank has arrived, sleeping instead of busy-polling: a rank that ran out of
/// tasks must not take a core from the ranks still computing (Open MPI's blocking collectives
/// spin; on a shared or oversubscribed node that halves the others' speed).
void wait_for_all_without_spinning(MPI_Comm comm) {
  MPI_Request request;
  MPI_Ibarrier(comm, &request);
  for (int arrived = 0;;) {
    MPI_Test(&request, &arrived, MPI_STATUS_IGNORE);
    if (arrived)
      return;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

/// Every rank's buffer to every rank (sizes first, then the bytes).
std::vector<std::string> all_gather_bytes(const std::string& mine, MPI_Comm comm) {
  int n_ranks = 1;
  MPI_Comm_size(comm, &n_ranks);
  const long long my_size = static_cast<long long>(mine.size());
  std::vector<long long> sizes(n_ranks);
  MPI_Allgather(&my_size, 1, MPI_LONG_LONG, sizes.data(), 1, MPI_LONG_LONG, comm);
  const long long total = std::accumulate(sizes.begin(), sizes.end(), 0LL);
  if (total > static_cast<long long>(std::numeric_limits<int>::max()))
    throw ComputationError("task results: " + std::to_string(total) +
                           " bytes to gather, more than one MPI message holds");
  std::vector<int> counts(n_ranks), offsets(n_ranks);
  for (int r = 0, off = 0; r < n_ranks; ++r) {
    counts[r] = static_cast<int>(sizes[r]);
    offsets[r] = off;
    off += counts[r];
  }
  std::string all(static_cast<std::size_t>(total), '\0');
  MPI_Allgatherv(mine.data(), static_cast<int>(my_size), MPI_CHAR, all.data(), counts.data(),
                 offsets.data(), MPI_CHAR, comm);
  std::vector<std::string> out(n_ranks);
  for (int r = 0; r < n_ranks; ++r)
    out[r] = all.substr(offsets[r], counts[r]);
  return out;
}

} // namespace

MPI_Comm simulation_communicator() {
  return current_simulation_comm;
}

TaskResults run_tasks_across_ranks(std::size_t n,
                                   const std::function<std::string(std::size_t)>& task,
                                   MPI_Comm comm, const std::vector<double>& cost) {
  if (!cost.empty() && cost.size() != n)
    throw std::logic_error("run_tasks_across_ranks: " + std::to_string(cost.size()) +
                           " cost estimates for " + std::to_string(n) + " tasks");
  // Hand-out order: decreasing cost, ties in task order (the same on every rank).
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  if (!cost.empty())
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return cost[a] > cost[b]; });

  int n_ranks = 1, rank = 0;
  MPI_Comm_size(comm, &n_ranks);
  MPI_Comm_rank(comm, &rank);
  std::vector<Done> done;
  if (n_ranks == 1) {
    for (const auto i : order) {
      done.push_back(run_one(i, task));
      if (done.back().status != ok)
        break;
    }
  } else {
    SharedCounter counter(comm);
    for (auto k = counter.fetch_and_increment(); k < static_cast<std::int64_t>(n);
         k = counter.fetch_and_increment()) {
      done.push_back(run_one(order[k], task));
      if (done.back().status != ok)
        break;
    }
    // Before the counter's MPI_Win_free, which is collective and would spin like the gather.
    wait_for_all_without_spinning(comm);
  }

  std::string mine;
  for (const auto& d : done) {
    put(mine, d.index);
    put(mine, d.status);
    put(mine, d.seconds);
    put(mine, d.cpu_seconds);
    put(mine, static_cast<std::uint64_t>(d.text.size()));
    mine += d.text;
  }
  const auto per_rank =
      n_ranks == 1 ? std::vector<std::string>{mine} : all_gather_bytes(mine, comm);

  TaskResults res;
  res.output.resize(n);
  res.rank.assign(n, -1);
  res.seconds.assign(n, 0.0);
  res.cpu_seconds.assign(n, 0.0);
  std::vector<std::int32_t> status(n, ok);
  for (int r = 0; r < n_ranks; ++r) {
    const char* p = per_rank[r].data();
    const char* end = p + per_rank[r].size();
    while (p < end) {
      const auto i = take<std::uint64_t>(p);
      status[i] = take<std::int32_t>(p);
      res.seconds[i] = take<double>(p);
      res.cpu_seconds[i] = take<double>(p);
      const auto len = take<std::uint64_t>(p);
      res.output[i].assign(p, len);
      p += len;
      res.rank[i] = r;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (status[i] == input_error)
      throw InputError(res.output[i]);
    if (status[i] == computation_error)
      throw ComputationError(res.output[i]);
    if (status[i] == other_error)
      throw std::runtime_error(res.output[i]);
  }
  for (std::size_t i = 0; i < n; ++i)
    if (res.rank[i] < 0) // only a failure stops a rank early, and failures threw above
      throw std::logic_error("run_tasks_across_ranks: task " + std::to_string(i) + " never ran");
  return res;
}

TaskOwnsItsFiles::TaskOwnsItsFiles() : previous_(output_enabled()) {
  set_output_enabled(true);
}
TaskOwnsItsFiles::~TaskOwnsItsFiles() {
  set_output_enabled(previous_);
}

} // namespace fiberbridge::app
