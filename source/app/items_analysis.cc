// Scene items of the analysis chain and the shared sections (Data, Fit, Rank, Bridging,
// Cohesive law, Specimen, Material): declarations in plain words with units, step-44 style.
#include "fiberbridge/analysis/bridging_model.h"
#include "fiberbridge/app/analysis_steps.h"
#include "fiberbridge/app/items.h"
#include "fiberbridge/app/scene.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/units.h"

#include <deal.II/base/patterns.h>

#include <cmath>
#include <filesystem>

namespace fiberbridge::app {

using dealii::Patterns::Bool;
using dealii::Patterns::Double;
using dealii::Patterns::Integer;
using dealii::Patterns::Selection;
using units::kPa;
using units::mm;

namespace {

/// "auto" or a positive number; returns 0 for auto.
double auto_or_positive(const std::string& v, const std::string& key, const std::string& section,
                        double unit) {
  if (v == "auto")
    return 0;
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (end == v.c_str() || *end != '\0' || !(x > 0) || !std::isfinite(x))
    throw InputError(section + "/" + key + ": expected 'auto' or a positive number, got '" + v +
                     "'");
  return x * unit;
}

} // namespace

void declare_data_section(dealii::ParameterHandler& prm) {
  prm.enter_subsection("Data");
  prm.declare_entry("File", "", dealii::Patterns::Anything(),
                    "CSV with columns delta_mm, R_J_m2 (R(delta) data); optional a_mm, time_s, "
                    "replicate (raw replicates, converted and averaged).");
  prm.declare_entry("Delta c", "auto", dealii::Patterns::Anything(),
                    "Steady-state onset delta_c in mm, or 'auto' (criterion in summary.json).");
  prm.declare_entry("J tip", "auto", dealii::Patterns::Anything(),
                    "Crack-tip toughness in J/m^2, or 'auto' (R on the initial flat part).");
  prm.declare_entry("Intervals", "100", Integer(4, 1000000),
                    "n of seed Eq. 6: the curve from 0 to delta_c is cut into n intervals.");
  prm.declare_entry("Smoothing half-width", "3", Integer(1, 100000),
                    "k of seed section 2.3: slopes S_i from a line fit over i-k..i+k.");
  prm.declare_entry("Averaging grid points", "401", Integer(16, 10000000),
                    "Points of the common delta grid on which replicates are averaged.");
  prm.leave_subsection();
}

void declare_fit_section(dealii::ParameterHandler& prm) {
  prm.enter_subsection("Fit");
  prm.declare_entry("Delta 1", "0.1", Double(0), "First breakpoint d1 in mm (seed: 0.1).");
  prm.declare_entry("Delta 2", "1.0", Double(0), "Second breakpoint d2 in mm (seed: 1.0).");
  prm.declare_entry("Free breakpoints", "false", Bool(),
                    "Fit d1 and d2 too (variable projection within the bounds below).");
  prm.declare_entry("Delta 1 minimum", "0.02", Double(0), "Lower bound of d1 in mm when free.");
  prm.declare_entry("Delta 1 maximum", "0.5", Double(0), "Upper bound of d1 in mm when free.");
  prm.declare_entry("Delta 2 maximum", "0", Double(0),
                    "Upper bound of d2 in mm when free; 0 means delta_c/2.");
  prm.leave_subsection();
}

void declare_rank_section(dealii::ParameterHandler& prm) {
  prm.enter_subsection("Rank");
  prm.declare_entry("Table file", "", dealii::Patterns::Anything(),
                    "Property table in the format of data/reference/seed_table1.csv.");
  prm.declare_entry("Delta 1", "0.1", Double(0), "d1 in mm used in the J1/J2 consistency check.");
  prm.declare_entry("Delta 2", "1.0", Double(0), "d2 in mm used in the J1/J2 consistency check.");
  prm.leave_subsection();
}

void declare_bridging_section(dealii::ParameterHandler& prm) {
  prm.enter_subsection("Bridging");
  prm.declare_entry("Zone length", "6.7", Double(0),
                    "Bridging zone length l_b at peak stress in mm (seed Table 1).");
  prm.declare_entry("Opening", "0.1", Double(0), "Opening in mm at which the stress is matched.");
  prm.declare_entry("Stress", "auto", dealii::Patterns::Anything(),
                    "Bridging stress in kPa at that opening, or 'auto': the scene's law (the "
                    "fitted trilinear law when fit runs, else the Cohesive law section).");
  prm.declare_entry("Fiber modulus", "40", Double(0), "E_f in GPa (tracheid: 40).");
  prm.declare_entry("Fiber radius", "20", Double(0), "r_f in micrometres (tracheid: 20).");
  prm.declare_entry("Fiber strength", "648", Double(0), "sigma_f in MPa (tracheid: 648).");
  prm.declare_entry("Peeling toughness", "200", Double(0), "G_c in J/m^2 (200 down to 50).");
  prm.leave_subsection();
}

void declare_law_section(dealii::ParameterHandler& prm) {
  prm.enter_subsection("Cohesive law");
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
  prm.leave_subsection();
}

void declare_specimen_sections(dealii::ParameterHandler& prm) {
  const specimen::Specimen s;
  prm.enter_subsection("Specimen");
  prm.declare_entry("Length", std::to_string(s.length / mm), Double(0),
                    "Beam length along the grain, mm (seed 2.2: 300).");
  prm.declare_entry("Width", std::to_string(s.width / mm), Double(0), "Width B in mm (35).");
  prm.declare_entry("Height", std::to_string(s.height / mm), Double(0),
                    "Both arms together, 2h, in mm (35).");
  prm.declare_entry("Initial crack", std::to_string(s.initial_crack / mm), Double(0),
                    "Sawn pre-crack from the load line, mm (100).");
  prm.leave_subsection();
  const specimen::Material m;
  prm.enter_subsection("Material");
  prm.declare_entry("E_L", std::to_string(m.E_L / units::MPa), Double(0),
                    "MPa; coast Douglas-fir 12 % MC, USDA Wood Handbook Ch. 5: 13400.");
  prm.declare_entry("E_T", std::to_string(m.E_T / units::MPa), Double(0),
                    "MPa; Wood Handbook ratio E_T/E_L = 0.050.");
  prm.declare_entry("G_LT", std::to_string(m.G_LT / units::MPa), Double(0),
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
  prm.leave_subsection();
}

namespace {

/// A data file named in the scene: resolved against the scene's folder; it must exist.
std::string existing_scene_file(const std::string& file, const std::string& key,
                                const SceneContext& ctx) {
  const std::string path = resolve_scene_path(file, ctx.scene_file);
  if (!std::filesystem::exists(path))
    throw InputError(ctx.scene_file + ": " + key + ": file '" + file + "' not found");
  return path;
}

/// The Data section. `file_may_come_later`: reduce runs first and may name the file itself.
ExtractionOptions parse_data_section(SceneContext& ctx, bool file_may_come_later) {
  auto& prm = *ctx.prm;
  ExtractionOptions o;
  prm.enter_subsection("Data");
  o.data_file = prm.get("File");
  o.intervals = prm.get_integer("Intervals");
  o.half_width = prm.get_integer("Smoothing half-width");
  o.grid_points = prm.get_integer("Averaging grid points");
  const std::string delta_c = prm.get("Delta c"), j_tip = prm.get("J tip");
  prm.leave_subsection();
  o.delta_c = auto_or_positive(delta_c, "Delta c", "Data", mm);
  o.j_tip = auto_or_positive(j_tip, "J tip", "Data", 1.0);
  if (!o.data_file.empty())
    o.data_file = existing_scene_file(o.data_file, "Data/File", ctx);
  else if (!file_may_come_later)
    throw InputError("Data/File: the scene runs 'extract' but names no data file");
  return o;
}

FitOptions parse_fit_section(dealii::ParameterHandler& prm) {
  FitOptions o;
  prm.enter_subsection("Fit");
  o.d1 = prm.get_double("Delta 1") * mm;
  o.d2 = prm.get_double("Delta 2") * mm;
  o.free_breakpoints = prm.get_bool("Free breakpoints");
  o.d1_min = prm.get_double("Delta 1 minimum") * mm;
  o.d1_max = prm.get_double("Delta 1 maximum") * mm;
  o.d2_max = prm.get_double("Delta 2 maximum") * mm;
  prm.leave_subsection();
  // What can be said before delta_c is known (run_trilinear_fit checks d2 < delta_c).
  if (!o.free_breakpoints && !(o.d1 > 0 && o.d1 < o.d2))
    throw InputError("Fit/Delta 1, Delta 2: need 0 < Delta 1 < Delta 2 (mm), got " +
                     fmt(o.d1 / mm) + " and " + fmt(o.d2 / mm));
  if (o.free_breakpoints && !(o.d1_min > 0 && o.d1_min < o.d1_max))
    throw InputError("Fit/Delta 1 minimum, Delta 1 maximum: need 0 < minimum < maximum (mm), "
                     "got " +
                     fmt(o.d1_min / mm) + " and " + fmt(o.d1_max / mm));
  return o;
}

RankOptions parse_rank_section(SceneContext& ctx) {
  auto& prm = *ctx.prm;
  prm.enter_subsection("Rank");
  RankOptions o;
  o.table_file = prm.get("Table file");
  o.d1_mm = prm.get_double("Delta 1");
  o.d2_mm = prm.get_double("Delta 2");
  prm.leave_subsection();
  if (o.table_file.empty())
    throw InputError("Rank/Table file: the scene runs 'rank' but names no table");
  o.table_file = existing_scene_file(o.table_file, "Rank/Table file", ctx);
  return o;
}

struct BridgingInput {
  analysis::BridgingFiber fiber;
  double zone_length = 0, opening = 0;
  double stress = 0; ///< 0: from the scene's law
};

BridgingInput parse_bridging_section(dealii::ParameterHandler& prm) {
  BridgingInput b;
  prm.enter_subsection("Bridging");
  b.fiber.E_f = prm.get_double("Fiber modulus") * units::GPa;
  b.fiber.r_f = prm.get_double("Fiber radius") * units::um;
  b.fiber.sigma_fb = prm.get_double("Fiber strength") * units::MPa;
  b.fiber.G_c = prm.get_double("Peeling toughness");
  b.zone_length = prm.get_double("Zone length") * mm;
  b.opening = prm.get_double("Opening") * mm;
  const std::string stress = prm.get("Stress");
  prm.leave_subsection();
  b.stress = auto_or_positive(stress, "Stress", "Bridging", kPa);
  const auto& f = b.fiber;
  if (!(b.zone_length > 0 && b.opening > 0 && f.E_f > 0 && f.r_f > 0 && f.sigma_fb > 0 &&
        f.G_c > 0))
    throw InputError("Bridging: zone length, opening and fiber properties must be positive");
  return b;
}

} // namespace

void check_extract_item(SceneContext& ctx) {
  parse_data_section(ctx, ctx.run_items.count("reduce") > 0);
}

void run_extract_item(SceneContext& ctx) {
  auto e = std::make_shared<ExtractionOutcome>(
      run_extraction(parse_data_section(ctx, false), ctx.output_dir, ctx.summary));
  ctx.extraction = e;
#ifdef FIBERBRIDGE_HAVE_IDENTIFY
  // identify ran before (scene order): its law beside Eq. 5/6 and dR/d delta on the same data.
  if (ctx.identification)
    report_law_routes(ctx);
#endif
}

void check_fit_item(SceneContext& ctx) {
  check_extract_item(ctx); // fit implies extract
  parse_fit_section(*ctx.prm);
}

void run_fit_item(SceneContext& ctx) {
  if (!ctx.extraction)
    run_extract_item(ctx); // fit works on the extracted law: it implies extract
  const FitOptions o = parse_fit_section(*ctx.prm);
  const auto fit = run_trilinear_fit(*ctx.extraction, o, ctx.output_dir, ctx.summary);
  // The extracted law is handed to the simulations without being retyped
  // (docs/design.md section 5).
  ctx.fitted_law = std::make_shared<law::PiecewiseLinearLaw>(law::make_trilinear(fit.law));
  ctx.fitted_j_tip = ctx.extraction->steady.j_tip;
  plot_extraction(*ctx.extraction, &fit, ctx.output_dir, ctx.summary);
}

void check_rank_item(SceneContext& ctx) {
  parse_rank_section(ctx);
}

void run_rank_item(SceneContext& ctx) {
  run_ranking(parse_rank_section(ctx), ctx.output_dir, ctx.summary);
}

void check_bridging_item(SceneContext& ctx) {
  if (parse_bridging_section(*ctx.prm).stress == 0)
    ctx.law_known_before_run();
}

void run_bridging_item(SceneContext& ctx) {
  const BridgingInput in = parse_bridging_section(*ctx.prm);
  const analysis::BridgingFiber& f = in.fiber;
  const double l_b = in.zone_length, delta = in.opening;
  double sigma = in.stress;
  std::string stress_source = "Bridging/Stress";
  if (sigma == 0) {
    sigma = ctx.law()->envelope(delta);
    stress_source = ctx.fitted_law ? "fitted trilinear law" : "Cohesive law section";
    if (!(sigma > 0))
      throw InputError("Bridging: the scene's law carries no traction at the opening " +
                       std::to_string(delta / mm) + " mm; set Bridging/Stress");
  }
  using analysis::BridgingMechanism;
  const double rho_peel =
      analysis::bridged_density(sigma, delta, l_b, f, BridgingMechanism::peeling, true);
  const double rho_break =
      analysis::bridged_density(sigma, delta, l_b, f, BridgingMechanism::breaking, true);
  const double rho_exact =
      analysis::bridged_density(sigma, delta, l_b, f, BridgingMechanism::governing, false);
  const double r_peel = analysis::r_b_peeling(delta / l_b, f);
  const double r_break = analysis::r_b_breaking(delta / l_b, f);
  ctx.summary["bridging"] = {{"sigma_kPa", sigma / kPa},
                             {"sigma_source", stress_source},
                             {"opening_mm", delta / mm},
                             {"zone_length_mm", l_b / mm},
                             {"rho_b_eq15_peeling_per_mm2", rho_peel * units::mm2},
                             {"rho_b_eq13_breaking_per_mm2", rho_break * units::mm2},
                             {"rho_b_exact_governing_per_mm2", rho_exact * units::mm2},
                             {"governing_mechanism", r_peel < r_break ? "peeling" : "breaking"},
                             {"fiber",
                              {{"E_f_GPa", f.E_f / units::GPa},
                               {"r_f_um", f.r_f / units::um},
                               {"sigma_f_MPa", f.sigma_fb / units::MPa},
                               {"G_c_J_m2", f.G_c}}}};
  // The model's law up to the peak region (its stated range of validity, seed section 3.4).
  CsvWriter w(ctx.out("bridging_model.csv"),
              {"delta_mm", "sigma_exact_kPa", "sigma_eq13_kPa", "sigma_eq15_kPa"},
              {"seed Eqs. 11-15 with rho_b from the exact governing form; valid only up to the "
               "peak stress"});
  w.row({0.0, 0.0, 0.0, 0.0});
  for (int i = 1; i <= 50; ++i) {
    const double d = 2 * delta * i / 50;
    w.row(
        {d / mm,
         analysis::bridging_stress_exact(d, l_b, rho_exact, f, BridgingMechanism::governing) / kPa,
         analysis::bridging_stress_eq13(d, l_b, rho_exact, f) / kPa,
         analysis::bridging_stress_eq15(d, l_b, rho_exact, f) / kPa});
  }
  w.close();
}

} // namespace fiberbridge::app
