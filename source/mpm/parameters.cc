#include "fiberbridge/mpm/parameters.h"

#include "fiberbridge/core/error.h"

#include <cmath>

namespace fiberbridge::mpm {

namespace {
void require(bool ok, const std::string& entry, const std::string& expected) {
  if (!ok)
    throw InputError("MPM/" + entry + ": " + expected);
}
} // namespace

void MpmParameters::validate() const {
  require(cell_size > 0 && std::isfinite(cell_size), "Cell size", "must be positive (mm)");
  require(particles_per_cell >= 1 && particles_per_cell <= 4, "Particles per cell",
          "must be 1 to 4 per axis");
  // Above 1 the explicit update is unstable for any material; 0.9 leaves room for the uGIMP
  // stiffness being a little above the linear-element estimate.
  require(cfl > 0 && cfl <= 0.9, "CFL factor", "must lie in (0, 0.9]");
  require(pic_fraction >= 0 && pic_fraction <= 1, "PIC fraction", "must lie in [0, 1]");
  require(loading_periods >= 1, "Loading periods",
          "must be >= 1 (faster loading is not quasi-static)");
  require(ramp_periods >= 0, "Ramp periods", "must be >= 0");
  require(growth_step_cells >= 1 && growth_step_cells <= 4, "Tip advance",
          "must round to 1 to 4 whole cells (the tip moves from node column to node column)");
  require(j_window_periods >= 0 && j_window_periods <= 1, "J window periods",
          "must lie in [0, 1] arm periods");
  require(tip_j_cells >= 1, "Tip J domain", "must be at least 1 cell");
  require(end_ligament >= 0, "Minimum ligament", "must be >= 0 (mm)");
  require(steady_growth >= 0, "Steady growth", "must be >= 0 (mm)");
  require(steady_state_window > 0 && std::isfinite(steady_state_window), "Steady state window",
          "must be positive (mm)");
  require(plateau_tolerance > 0 && plateau_tolerance < 1, "Plateau tolerance",
          "must lie in (0, 1)");
  require(max_steps > 0, "Maximum steps", "must be positive");
  require(threads >= 1 && threads <= 256, "Threads", "must lie in [1, 256]");
  require(vtu_every_advances >= 0, "VTU every advances", "must be >= 0");
  require(checkpoint_interval >= 0 && std::isfinite(checkpoint_interval), "Checkpoint interval",
          "must be >= 0 seconds (0 = no checkpoints)");
}

} // namespace fiberbridge::mpm
