#pragma once
// The forward model of an identification (docs/design.md section 6, "Forward model of identify
// (issue 34 item 4)"): the simulation that turns a trial law and J_tip into the load and crack
// length at a record's openings. identify's own is the beam (beam_forward_model); the app hands
// it another one (the FEM, Identify/Forward model = fem) through this interface, so that this
// library depends on the beam alone.
#include "fiberbridge/beam/dcb_beam.h"
#include "fiberbridge/law/traction_law.h"
#include "fiberbridge/result/rcurve.h"
#include "fiberbridge/specimen/specimen.h"

#include <functional>
#include <string>

namespace fiberbridge::identify {

struct ForwardModel {
  /// "beam", "fem": for the summary and the notes.
  std::string name;
  /// One run of `law` and `j_tip` on a record's specimen set-up (a0 and E_L the record's), going
  /// on until the crack is at least `reach` long [m] where the ligament allows (the misfit
  /// compares the run with the whole record). A trial law the model cannot follow or resolve is
  /// an exception: the misfit scores it as a failed trial (the model carries no load). Called
  /// inside identify's jobs, which the app spreads over MPI ranks: a model that uses MPI runs on
  /// MPI_COMM_SELF. Every call with the same arguments must give the same result, bit for bit
  /// (the jobs may run anywhere, identify.h).
  std::function<result::SimulationResult(const specimen::Specimen& specimen,
                                         const specimen::Material& material,
                                         const law::TractionLaw& law, double j_tip, double reach)>
      run;
  /// The model's compliance of the specimen set-up before the crack grows [m/N]; empty: corrected
  /// beam theory's, which the beam reproduces. With Identify/Calibrate modulus, E_L is then
  /// corrected from the CBT calibration until the model's compliance is the record's (the FEM's
  /// 2D solid is a few per cent stiffer or softer than CBT: a modulus calibrated for the beam
  /// would leave the FEM that systematic load error).
  std::function<double(const specimen::Specimen& specimen, const specimen::Material& material)>
      initial_compliance;
  /// Small-rotation kinematics: the misfit maps the run onto arms that rotate far
  /// (IdentifySettings::large_displacement, with_large_displacements) only then.
  bool geometrically_linear = true;
};

/// identify's own forward model: the beam with `parameters` (IdentifySettings::beam), run five
/// tip advances past `reach` (the model may lag the readings), within the ligament.
ForwardModel beam_forward_model(const beam::BeamParameters& parameters);

} // namespace fiberbridge::identify
