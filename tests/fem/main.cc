// GoogleTest main of fem_tests (and tests/app's section_tests): initializes MPI (one process, one
// thread), as the fiberbridge program does, because the default linear solver (Trilinos Amesos
// KLU on Epetra) needs it.
#include <deal.II/base/mpi.h>

#include <gtest/gtest.h>

int main(int argc, char** argv) {
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
