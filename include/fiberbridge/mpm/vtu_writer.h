#pragma once
// ParaView output written here (no VTK dependency): particles as VTK_VERTEX cells in ASCII
// .vtu files, and a .pvd collection that lists them with their times.
#include "fiberbridge/mpm/explicit_solver.h"

#include <string>
#include <utility>
#include <vector>

namespace fiberbridge::mpm {

class ParticleVtuWriter {
public:
  /// Files go to `directory` as <base>_NNNN.vtu and <base>.pvd.
  ParticleVtuWriter(std::string directory, std::string base);
  /// Writes the particles (current positions; displacement, velocity, stress, strain energy
  /// density) and rewrites the .pvd so that it is complete after every call.
  void write(const ExplicitSolver& solver);
  /// The files written so far with their times: a resumed run continues the .pvd with them.
  const std::vector<std::pair<double, std::string>>& written() const { return written_; }
  void set_written(std::vector<std::pair<double, std::string>> w) { written_ = std::move(w); }

private:
  std::string directory_, base_;
  std::vector<std::pair<double, std::string>> written_;
};

} // namespace fiberbridge::mpm
