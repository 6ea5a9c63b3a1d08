// The task distributor (include/fiberbridge/app/run/task_distributor.h) and a simulation result
// crossing ranks in the archive (core/binary_archive.h, result/result_archive.h). Run on one
// process (ctest discovers them) and under `mpirun -np 2` (AppTasks.TwoRanks): every test is
// collective, so every rank runs it and checks what it got.
#include "fiberbridge/app/run/task_distributor.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/result/result_archive.h"

#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <thread>

using namespace fiberbridge;

namespace {

int n_ranks() {
  int n = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}

int sum_over_ranks(int v) {
  int s = 0;
  MPI_Allreduce(&v, &s, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  return s;
}

} // namespace

TEST(TaskDistributor, EveryTaskRunsOnceAndEveryRankGetsEveryResultInTaskOrder) {
  const std::size_t n = 11;
  int ran_here = 0;
  const auto r = app::run_tasks_across_ranks(
      n,
      [&](std::size_t i) {
        ++ran_here;
        return "task " + std::to_string(i) + std::string(i * 1000, 'x'); // sizes differ
      },
      MPI_COMM_WORLD);
  EXPECT_EQ(sum_over_ranks(ran_here), int(n)); // once each, over all ranks together
  ASSERT_EQ(r.output.size(), n);
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_EQ(r.output[i], "task " + std::to_string(i) + std::string(i * 1000, 'x'));
    EXPECT_GE(r.rank[i], 0);
    EXPECT_LT(r.rank[i], n_ranks());
  }
}

TEST(TaskDistributor, TasksRunOnCommSelfAndTheCommunicatorIsRestored) {
  int ident = MPI_UNEQUAL;
  MPI_Comm_compare(app::simulation_communicator(), MPI_COMM_WORLD, &ident);
  EXPECT_EQ(ident, MPI_IDENT);
  const auto r = app::run_tasks_across_ranks(
      3,
      [](std::size_t) {
        int size = 0;
        MPI_Comm_size(app::simulation_communicator(), &size);
        return std::to_string(size);
      },
      MPI_COMM_WORLD);
  for (const auto& s : r.output)
    EXPECT_EQ(s, "1");
  MPI_Comm_compare(app::simulation_communicator(), MPI_COMM_WORLD, &ident);
  EXPECT_EQ(ident, MPI_IDENT);
}

TEST(TaskDistributor, MostExpensiveTaskStartsFirst) {
  // Each task reports how many tasks its rank had run before it: the costliest (index 4) is the
  // first one handed out, so it is the first task of whichever rank took it; on one rank the
  // whole hand-out order is the decreasing cost.
  const std::vector<double> cost = {1, 3, 2, 2, 9, 0.5};
  int before = 0;
  const auto r = app::run_tasks_across_ranks(
      cost.size(), [&](std::size_t) { return std::to_string(before++); }, MPI_COMM_WORLD, cost);
  EXPECT_EQ(r.output[4], "0");
  if (n_ranks() == 1) {
    EXPECT_EQ(r.output[1], "1");
    EXPECT_EQ(r.output[2], "2"); // ties keep task order
    EXPECT_EQ(r.output[3], "3");
    EXPECT_EQ(r.output[0], "4");
    EXPECT_EQ(r.output[5], "5");
  }
}

TEST(TaskDistributor, SlowTasksAreShared) {
  if (n_ranks() < 2)
    GTEST_SKIP() << "needs mpirun -np 2 (AppTasks.TwoRanks)";
  // Eight 100 ms tasks: a rank that is free takes the next, so no rank runs them all (one rank
  // alone would need 0.8 s while the other idles; the hand-out takes microseconds).
  const auto r = app::run_tasks_across_ranks(
      8,
      [](std::size_t) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        return std::string();
      },
      MPI_COMM_WORLD);
  std::vector<int> per_rank(n_ranks(), 0);
  for (const int k : r.rank)
    ++per_rank[k];
  for (int k = 0; k < n_ranks(); ++k)
    EXPECT_GT(per_rank[k], 0) << "rank " << k << " ran no task";
}

TEST(TaskDistributor, CpuSecondsOfEachTaskComeBack) {
  // Task 1 computes for at least 50 ms of process CPU time; the others return at once. Its
  // cpu_seconds must reach every rank (0 would mean the figure was lost on the way).
  const auto spin = [](std::size_t i) {
    if (i == 1) {
      const std::clock_t c0 = std::clock();
      volatile double x = 0;
      while (double(std::clock() - c0) / CLOCKS_PER_SEC < 0.05)
        x = x + 1;
    }
    return std::string();
  };
  const auto r = app::run_tasks_across_ranks(3, spin, MPI_COMM_WORLD);
  EXPECT_GE(r.cpu_seconds[1], 0.05);
  EXPECT_LT(r.cpu_seconds[0], 0.05);
}

TEST(TaskDistributor, FailureReachesEveryRankWithItsType) {
  const auto failing = [](int kind) {
    return [kind](std::size_t i) -> std::string {
      if (i == 2 && kind == 0)
        throw InputError("Study/FEM ladder: 'x' is not Key = v1");
      if (i == 2 && kind == 1)
        throw ComputationError("no convergence at level 2");
      if (i == 4)
        throw ComputationError("level 4 failed too");
      return "ok";
    };
  };
  try {
    app::run_tasks_across_ranks(6, failing(0), MPI_COMM_WORLD);
    ADD_FAILURE() << "no exception";
  } catch (const InputError& e) {
    // On several ranks task 4 may also have run and failed: the smallest index wins everywhere.
    EXPECT_STREQ(e.what(), "Study/FEM ladder: 'x' is not Key = v1");
  }
  EXPECT_THROW(app::run_tasks_across_ranks(6, failing(1), MPI_COMM_WORLD), ComputationError);
  // The distributor is usable again after a failure (the counter window was freed).
  EXPECT_EQ(app::run_tasks_across_ranks(
                2, [](std::size_t) { return std::string("again"); }, MPI_COMM_WORLD)
                .output[1],
            "again");
}

TEST(ResultArchive, ResultRunOnAnyRankComesBackBitForBit) {
  // Each task makes a result from its index alone; whatever rank ran it, every rank must read
  // back exactly the result it would have made itself (NaN columns included).
  auto make = [](std::size_t i) {
    result::SimulationResult r;
    r.model = "beam " + std::to_string(i);
    for (std::size_t k = 0; k < 3 + i; ++k) {
      result::RCurvePoint p;
      p.a = 0.1 + double(k) * 1e-3 / 3.0; // not representable in short decimals
      p.load = k == 1 ? result::not_available : 412.123456789012345 * (1 + double(i) * 1e-15);
      r.rcurve.push_back(p);
    }
    r.G_ss = 1082.4750557029999 + double(i);
    r.notes = {"task " + std::to_string(i)};
    return r;
  };
  const auto done = app::run_tasks_across_ranks(
      5, [&](std::size_t i) { return to_archive_bytes(make(i), "test result"); }, MPI_COMM_WORLD);
  for (std::size_t i = 0; i < 5; ++i) {
    const auto back = from_archive_bytes<result::SimulationResult>(done.output[i], "test result");
    const auto want = make(i);
    ASSERT_EQ(back.rcurve.size(), want.rcurve.size());
    EXPECT_EQ(std::memcmp(back.rcurve.data(), want.rcurve.data(),
                          want.rcurve.size() * sizeof(result::RCurvePoint)),
              0)
        << "task " << i << " (rank " << done.rank[i] << ")";
    EXPECT_EQ(back.model, want.model);
    EXPECT_EQ(back.G_ss, want.G_ss);
    EXPECT_EQ(back.notes, want.notes);
  }
}

int main(int argc, char** argv) {
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ::testing::InitGoogleTest(&argc, argv);
  // A launcher that starts the wrong number of processes must fail, not skip.
  if (const char* want = std::getenv("FIBERBRIDGE_REQUIRE_RANKS"))
    if (std::atoi(want) != n_ranks()) {
      std::fprintf(stderr, "expected %s ranks, got %d\n", want, n_ranks());
      return 1;
    }
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  return RUN_ALL_TESTS();
}
