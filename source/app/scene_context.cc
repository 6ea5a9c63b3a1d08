#include "fiberbridge/app/scene_context.h"

#include "fiberbridge/app/scene.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/law/law_spec.h"

namespace fiberbridge::app {

using units::kPa;
using units::mm;
using units::MPa;

namespace {

law::LawSpec read_law_section(dealii::ParameterHandler& prm, const std::string& scene_file) {
  law::LawSpec s;
  prm.enter_subsection("Cohesive law");
  s.type = prm.get("Type");
  s.peak_stress = prm.get_double("Peak stress") * kPa;
  s.delta_c = prm.get_double("Delta c") * mm;
  s.j_tip = prm.get_double("J tip");
  const std::string points = prm.get("Points");
  s.table_file = prm.get("Table file");
  prm.leave_subsection();
  if (!s.table_file.empty())
    s.table_file = resolve_scene_path(s.table_file, scene_file);
  // Points matter only for the types that use them (the default PVA points must not make a
  // linear law ambiguous).
  if (s.type == "bilinear" || s.type == "trilinear" || (s.type == "table" && s.table_file.empty()))
    s.points = law::parse_points_mm_kPa(points, "Cohesive law/Points");
  s.context = "Cohesive law";
  return s;
}

} // namespace

const law::TractionLaw* SceneContext::law_known_before_run() {
  if (fitted_law || run_items.count("fit") || run_items.count("identify"))
    return nullptr;
  return law().get();
}

law::TractionLawPtr SceneContext::law() {
  if (fitted_law)
    return fitted_law;
  if (!section_law_) {
    const auto spec = read_law_section(*prm, scene_file);
    section_law_ = law::make_law(spec);
    section_j_tip_ = spec.j_tip;
  }
  return section_law_;
}

double SceneContext::j_tip() {
  if (fitted_law)
    return fitted_j_tip;
  law();
  return section_j_tip_;
}

specimen::Specimen SceneContext::specimen() const {
  if (identified_specimen)
    return *identified_specimen;
  specimen::Specimen s;
  prm->enter_subsection("Specimen");
  s.length = prm->get_double("Length") * mm;
  s.width = prm->get_double("Width") * mm;
  s.height = prm->get_double("Height") * mm;
  s.initial_crack = prm->get_double("Initial crack") * mm;
  prm->leave_subsection();
  s.validate("Specimen");
  return s;
}

specimen::Material SceneContext::material() const {
  if (identified_material)
    return *identified_material;
  specimen::Material m;
  prm->enter_subsection("Material");
  m.E_L = prm->get_double("E_L") * MPa;
  m.E_T = prm->get_double("E_T") * MPa;
  m.G_LT = prm->get_double("G_LT") * MPa;
  m.nu_LT = prm->get_double("nu_LT");
  m.plane_stress = prm->get("Plane") == "stress";
  m.density = prm->get_double("Density");
  m.E_R_over_E_L = prm->get_double("E_R over E_L");
  m.nu_LR = prm->get_double("nu_LR");
  m.nu_RT = prm->get_double("nu_RT");
  prm->leave_subsection();
  m.validate("Material");
  return m;
}

} // namespace fiberbridge::app
