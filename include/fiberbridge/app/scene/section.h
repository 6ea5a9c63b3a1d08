#pragma once
// One convention for the sections of a scene (deal.II step-44's AllParameters style): a struct
// per section with `static void declare_parameters(prm)` and `void parse_parameters(prm)` side by
// side, where parse_parameters also validates (InputError naming "Section/Key"). Both are called
// inside the section; these helpers enter and leave it. The models' parameter structs stay free
// of deal.II (beam, mpm): their sections derive from them in the app (item_beam.cc, item_mpm.cc);
// the FEM's fem::FemParameters follows the convention itself. Every section of a scene is one:
// the analysis sections in items_analysis.cc (Data, Fit, Rank, Bridging), the shared ones in
// shared_sections.h (Cohesive law, Specimen, Material), Test in test_section.h, Identify,
// Compare and Study beside their items. A check that needs the scene's folder (a file must
// exist) is the item's, after parsing. Every section is parsed once, when the scene is read
// (parse_into, into SceneParameters); the items read the parsed structs, never the handler.
#include "fiberbridge/app/scene/scene_parameters.h"

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace fiberbridge::app {

template <class Section>
void declare_section(dealii::ParameterHandler& prm, const std::string& name) {
  prm.enter_subsection(name);
  Section::declare_parameters(prm);
  prm.leave_subsection();
}

/// The section `name` read and validated; the handler is back at the top level afterwards, also
/// when parsing throws.
template <class Section>
Section parse_section(dealii::ParameterHandler& prm, const std::string& name) {
  Section s;
  prm.enter_subsection(name);
  try {
    s.parse_parameters(prm);
  } catch (...) {
    prm.leave_subsection();
    throw;
  }
  prm.leave_subsection();
  return s;
}

/// The section `name` parsed into `out` once, when the scene is read, as a `Stored` (the
/// section's struct, or the public struct it derives from when the items read only that): an
/// error its parse throws is kept and thrown where an item reads the section
/// (SceneParameters::section).
template <class Section, class Stored = Section>
void parse_into(dealii::ParameterHandler& prm, const std::string& name, SceneParameters& out) {
  try {
    out.store(name, Stored(parse_section<Section>(prm, name)));
  } catch (...) {
    out.store_error(name, std::current_exception());
  }
}

} // namespace fiberbridge::app
