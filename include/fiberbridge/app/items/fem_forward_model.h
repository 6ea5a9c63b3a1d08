#pragma once
// The FEM as identify's forward model (Identify/Forward model = fem; docs/design.md section 6,
// "Forward model of identify (issue 34 item 4)"): the app's adapter between the two libraries,
// which do not know each other (cmake/fiberbridge_layers.cmake).
#include "fiberbridge/fem/dcb_simulation.h"
#include "fiberbridge/identify/forward_model.h"

namespace fiberbridge::app {

/// The FEM with `parameters` (the scene's FEM section) as identify's forward model: each trial
/// law on the record's specimen set-up, on MPI_COMM_SELF (identify's jobs are already spread over
/// the ranks), writing nothing. One mesh for every trial law (FEM/Element size = auto takes its
/// law-free part, fem::arm_element_size); the steady-state window stretched so that the run
/// reaches the record's last crack length; a run whose steady_state_status is zone_unresolved or
/// ledger_open throws ComputationError (a failed trial, as a law the beam cannot follow).
identify::ForwardModel fem_forward_model(fem::FemParameters parameters);

} // namespace fiberbridge::app
