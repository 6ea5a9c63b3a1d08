#pragma once
// The sections every model shares: Cohesive law, Specimen, Material, each a step-44 section
// struct that declares, parses and validates itself (section.h). SceneContext reads them
// (scene_context.cc); the defaults are the seed's DCB of Douglas-fir and the PVA control law.
#include "fiberbridge/law/law_spec.h"
#include "fiberbridge/specimen/specimen.h"

#include <deal.II/base/parameter_handler.h>

namespace fiberbridge::app {

/// `Cohesive law`: the law's type and numbers. `table_file` is as written in the scene (the
/// context resolves it against the scene's folder); `points` are parsed only for the types that
/// use them, so the default PVA points do not make a linear law ambiguous.
struct LawSection : law::LawSpec {
  static void declare_parameters(dealii::ParameterHandler& prm);
  void parse_parameters(dealii::ParameterHandler& prm);
};

/// `Specimen`: length, width, both arms and the pre-crack, in mm in the scene.
struct SpecimenSection : specimen::Specimen {
  static void declare_parameters(dealii::ParameterHandler& prm);
  void parse_parameters(dealii::ParameterHandler& prm);
};

/// `Material`: the orthotropic arm material, MPa in the scene.
struct MaterialSection : specimen::Material {
  static void declare_parameters(dealii::ParameterHandler& prm);
  void parse_parameters(dealii::ParameterHandler& prm);
};

/// The three shared sections declared (the scene reader calls these once for every scene).
void declare_law_section(dealii::ParameterHandler& prm);
void declare_specimen_sections(dealii::ParameterHandler& prm);
class SceneParameters;
/// Cohesive law, Specimen and Material parsed into the scene's parameters (SceneParameters::law,
/// specimen, material).
void parse_shared_sections(dealii::ParameterHandler& prm, SceneParameters& out);

} // namespace fiberbridge::app
