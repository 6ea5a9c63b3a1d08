// The sections every model shares (shared_sections.h): declarations in plain words with units,
// each beside the parse that reads it back, step-44 style.
#include "fiberbridge/app/scene/shared_sections.h"

#include "fiberbridge/app/scene/section.h"
#include "fiberbridge/core/units.h"

#include <deal.II/base/patterns.h>

#include <string>

namespace fiberbridge::app {

using dealii::Patterns::Double;
using dealii::Patterns::Selection;
using units::kPa;
using units::mm;
using units::MPa;

void LawSection::declare_parameters(dealii::ParameterHandler& prm) {
  prm.declare_entry("Type", "trilinear",
                    Selection("none|linear|bilinear|trilinear|exponential|table"),
                    "Bridging law; none = no bridging (the LEFM limit).");
  prm.declare_entry("Peak stress", "0", Double(0), "sigma_c in kPa (linear, exponential).");
  prm.declare_entry("Points", "0.1:661, 1.0:187", dealii::Patterns::Anything(),
                    "delta_mm:sigma_kPa pairs: 1 for bilinear, 2 for trilinear, the whole "
                    "polyline from 0 to delta_c for table. Default: PVA control, seed Table 1.");
  prm.declare_entry("Delta c", "6", Double(0), "Critical opening delta_c in mm.");
  prm.declare_entry("J tip", "200", Double(0), "Crack-tip toughness J_tip in J/m^2.");
  prm.declare_entry("Table file", "", dealii::Patterns::Anything(),
                    "For Type = table without Points: CSV with delta_mm, sigma_kPa.");
}

void LawSection::parse_parameters(dealii::ParameterHandler& prm) {
  type = prm.get("Type");
  peak_stress = prm.get_double("Peak stress") * kPa;
  delta_c = prm.get_double("Delta c") * mm;
  j_tip = prm.get_double("J tip");
  table_file = prm.get("Table file");
  if (type == "bilinear" || type == "trilinear" || (type == "table" && table_file.empty()))
    points = law::parse_points_mm_kPa(prm.get("Points"), "Cohesive law/Points");
}

void SpecimenSection::declare_parameters(dealii::ParameterHandler& prm) {
  const specimen::Specimen s;
  prm.declare_entry("Length", std::to_string(s.length / mm), Double(0),
                    "Beam length along the grain, mm (seed 2.2: 300).");
  prm.declare_entry("Width", std::to_string(s.width / mm), Double(0), "Width B in mm (35).");
  prm.declare_entry("Height", std::to_string(s.height / mm), Double(0),
                    "Both arms together, 2h, in mm (35).");
  prm.declare_entry("Initial crack", std::to_string(s.initial_crack / mm), Double(0),
                    "Sawn pre-crack from the load line, mm (100).");
}

void SpecimenSection::parse_parameters(dealii::ParameterHandler& prm) {
  length = prm.get_double("Length") * mm;
  width = prm.get_double("Width") * mm;
  height = prm.get_double("Height") * mm;
  initial_crack = prm.get_double("Initial crack") * mm;
  validate("Specimen");
}

void MaterialSection::declare_parameters(dealii::ParameterHandler& prm) {
  const specimen::Material m;
  prm.declare_entry("E_L", std::to_string(m.E_L / MPa), Double(0),
                    "MPa; coast Douglas-fir 12 % MC, USDA Wood Handbook Ch. 5: 13400.");
  prm.declare_entry("E_T", std::to_string(m.E_T / MPa), Double(0),
                    "MPa; Wood Handbook ratio E_T/E_L = 0.050.");
  prm.declare_entry("G_LT", std::to_string(m.G_LT / MPa), Double(0),
                    "MPa; Wood Handbook ratio G_LT/E_L = 0.078.");
  prm.declare_entry("nu_LT", std::to_string(m.nu_LT), Double(0, 0.999),
                    "Major Poisson ratio (Wood Handbook 0.449); nu_TL = nu_LT E_T/E_L.");
  prm.declare_entry("Plane", "stress", Selection("stress|strain"), "2D assumption.");
  prm.declare_entry("Density", std::to_string(m.density), Double(0),
                    "kg/m^3 (dynamic models only).");
  prm.declare_entry("E_R over E_L", std::to_string(m.E_R_over_E_L), Double(0),
                    "Radial (out-of-plane, z) modulus ratio; plane strain and 3D only (Wood "
                    "Handbook, Douglas-fir: 0.068).");
  prm.declare_entry("nu_LR", std::to_string(m.nu_LR), Double(0, 0.5),
                    "Plane strain and 3D only (Wood Handbook: 0.292).");
  prm.declare_entry("nu_RT", std::to_string(m.nu_RT), Double(0, 1),
                    "Plane strain and 3D only (Wood Handbook: 0.390).");
}

void MaterialSection::parse_parameters(dealii::ParameterHandler& prm) {
  E_L = prm.get_double("E_L") * MPa;
  E_T = prm.get_double("E_T") * MPa;
  G_LT = prm.get_double("G_LT") * MPa;
  nu_LT = prm.get_double("nu_LT");
  plane_stress = prm.get("Plane") == "stress";
  density = prm.get_double("Density");
  E_R_over_E_L = prm.get_double("E_R over E_L");
  nu_LR = prm.get_double("nu_LR");
  nu_RT = prm.get_double("nu_RT");
  validate("Material");
}

void declare_law_section(dealii::ParameterHandler& prm) {
  declare_section<LawSection>(prm, "Cohesive law");
}

void declare_specimen_sections(dealii::ParameterHandler& prm) {
  declare_section<SpecimenSection>(prm, "Specimen");
  declare_section<MaterialSection>(prm, "Material");
}

void parse_shared_sections(dealii::ParameterHandler& prm, SceneParameters& out) {
  parse_into<LawSection, law::LawSpec>(prm, "Cohesive law", out);
  parse_into<SpecimenSection, specimen::Specimen>(prm, "Specimen", out);
  parse_into<MaterialSection, specimen::Material>(prm, "Material", out);
}

} // namespace fiberbridge::app
