// GoogleTest main of fem_mpi_tests: MPI initialized (the distributed engine needs it); under
// mpirun only rank 0 prints GoogleTest's report, so two ranks do not interleave it, but every
// rank runs every test (they are collective) and a failure on any rank fails the process.
#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>

int main(int argc, char** argv) {
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ::testing::InitGoogleTest(&argc, argv);
  if (dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  return RUN_ALL_TESTS();
}
