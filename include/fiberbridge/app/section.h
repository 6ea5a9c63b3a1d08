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
// exist) is the item's, after parsing.
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

} // namespace fiberbridge::app
