// Scene items of the analysis chain and their sections (Data, Fit, Rank, Bridging), each a
// step-44 section struct (section.h) whose declarations in plain words with units stand beside
// the parse that reads and validates them. The shared sections are in shared_sections.cc.
#include "fiberbridge/analysis/bridging_model.h"
#include "fiberbridge/app/items/analysis_steps.h"
#include "fiberbridge/app/items/item_identify.h"
#include "fiberbridge/app/items/items.h"
#include "fiberbridge/app/outputs/bridging_writers.h"
#include "fiberbridge/app/outputs/extraction_writers.h"
#include "fiberbridge/app/scene/scene_reader.h"
#include "fiberbridge/app/scene/section.h"
#ifdef FIBERBRIDGE_HAVE_IDENTIFY
#include "fiberbridge/app/items/fit_correction_step.h"
#include "outputs/fit_correction_writers.h"
#endif
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

/// Data: the R(delta) data and n, k of seed Eq. 6. `data_file` is as written; the item resolves
/// it against the scene's folder (existing_scene_file), since reduce may supply it later.
struct DataSection : ExtractionOptions {
  static void declare_parameters(dealii::ParameterHandler& prm) {
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
  }
  void parse_parameters(dealii::ParameterHandler& prm) {
    data_file = prm.get("File");
    intervals = prm.get_integer("Intervals");
    half_width = prm.get_integer("Smoothing half-width");
    grid_points = prm.get_integer("Averaging grid points");
    delta_c = auto_or_positive(prm.get("Delta c"), "Delta c", "Data", mm);
    j_tip = auto_or_positive(prm.get("J tip"), "J tip", "Data", 1.0);
  }
};

/// Fit: the trilinear breakpoints, fixed or free within bounds, and the correction of the chain's
/// bias by simulation (identify/chain_correction.h).
/// Its correction keys are read where they are used (items/fit_correction_step.h): the stored
/// section stays analysis::FitOptions, which the campaign and the Python module read too.
struct FitSection : FitOptions {

  static void declare_parameters(dealii::ParameterHandler& prm) {
    prm.declare_entry("Delta 1", "0.1", Double(0), "First breakpoint d1 in mm (seed: 0.1).");
    prm.declare_entry("Delta 2", "1.0", Double(0), "Second breakpoint d2 in mm (seed: 1.0).");
    prm.declare_entry("Free breakpoints", "false", Bool(),
                      "Fit d1 and d2 too (variable projection within the bounds below).");
    prm.declare_entry("Delta 1 minimum", "0.02", Double(0), "Lower bound of d1 in mm when free.");
    prm.declare_entry("Delta 1 maximum", "0.5", Double(0), "Upper bound of d1 in mm when free.");
    prm.declare_entry("Delta 2 maximum", "0", Double(0),
                      "Upper bound of d2 in mm when free; 0 means delta_c/2.");
    prm.declare_entry(
        "Model correction", "auto", dealii::Patterns::Selection("auto|none|beam|fem"),
        "Remove the measuring chain's bias by simulating the test: the fitted law is run in the "
        "beam at the records' openings, the same chain measures the simulated records, and the "
        "law is moved by the difference until the chain gives back what it gave on the records "
        "(seed Eq. 2's recoverable energy is not the dissipation a test measures while the zone "
        "develops). auto: where the fit's data are this scene's records through reduce; none: "
        "the seed's fit alone; beam: as auto, an error where it cannot run; fem: as beam with "
        "the FEM (FEM section) as the simulated test, about 0.2 s a run at 2 mm elements against "
        "the beam's 0.07 s: it holds the specimen's far end, which the beam does not (long zones "
        "on short specimens; its J_tip runs a few per cent low: docs/verification.md, \"The "
        "correction's forward model\").");
    prm.declare_entry("Correction iterations", "8", Integer(1, 100),
                      "Simulations at most before the correction gives up (with a note).");
    prm.declare_entry("Correction tolerance", "0.01", Double(1e-6, 0.5),
                      "Converged when the chain on the simulated records matches the records' "
                      "estimate within this fraction (J_tip of itself, stresses of the larger "
                      "stress, openings of delta_c).");
  }
  void parse_parameters(dealii::ParameterHandler& prm) {
    d1 = prm.get_double("Delta 1") * mm;
    d2 = prm.get_double("Delta 2") * mm;
    free_breakpoints = prm.get_bool("Free breakpoints");
    d1_min = prm.get_double("Delta 1 minimum") * mm;
    d1_max = prm.get_double("Delta 1 maximum") * mm;
    d2_max = prm.get_double("Delta 2 maximum") * mm;
    // What can be said before delta_c is known (run_trilinear_fit checks d2 < delta_c).
    if (!free_breakpoints && !(d1 > 0 && d1 < d2))
      throw InputError("Fit/Delta 1, Delta 2: need 0 < Delta 1 < Delta 2 (mm), got " +
                       fmt(d1 / mm) + " and " + fmt(d2 / mm));
    if (free_breakpoints && !(d1_min > 0 && d1_min < d1_max))
      throw InputError("Fit/Delta 1 minimum, Delta 1 maximum: need 0 < minimum < maximum (mm), "
                       "got " +
                       fmt(d1_min / mm) + " and " + fmt(d1_max / mm));
  }
};

/// Rank: the property table (as written; the item resolves it) and d1, d2 of the J1/J2 check.
struct RankSection : RankOptions {
  static void declare_parameters(dealii::ParameterHandler& prm) {
    prm.declare_entry("Table file", "", dealii::Patterns::Anything(),
                      "Property table in the format of data/reference/seed_table1.csv.");
    prm.declare_entry("Delta 1", "0.1", Double(0), "d1 in mm used in the J1/J2 consistency check.");
    prm.declare_entry("Delta 2", "1.0", Double(0), "d2 in mm used in the J1/J2 consistency check.");
  }
  void parse_parameters(dealii::ParameterHandler& prm) {
    table_file = prm.get("Table file");
    d1_mm = prm.get_double("Delta 1");
    d2_mm = prm.get_double("Delta 2");
    if (table_file.empty())
      throw InputError("Rank/Table file: the scene runs 'rank' but names no table");
  }
};

/// Bridging: the fiber-bridging model's inputs (seed Eqs. 9-15).
struct BridgingSection {
  analysis::BridgingFiber fiber;
  double zone_length = 0, opening = 0;
  double stress = 0; ///< 0: from the scene's law

  static void declare_parameters(dealii::ParameterHandler& prm) {
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
  }
  void parse_parameters(dealii::ParameterHandler& prm) {
    fiber.E_f = prm.get_double("Fiber modulus") * units::GPa;
    fiber.r_f = prm.get_double("Fiber radius") * units::um;
    fiber.sigma_fb = prm.get_double("Fiber strength") * units::MPa;
    fiber.G_c = prm.get_double("Peeling toughness");
    zone_length = prm.get_double("Zone length") * mm;
    opening = prm.get_double("Opening") * mm;
    stress = auto_or_positive(prm.get("Stress"), "Stress", "Bridging", kPa);
    const auto& f = fiber;
    if (!(zone_length > 0 && opening > 0 && f.E_f > 0 && f.r_f > 0 && f.sigma_fb > 0 && f.G_c > 0))
      throw InputError("Bridging: zone length, opening and fiber properties must be positive");
  }
};

/// A data file named in the scene: resolved against the scene's folder; it must exist.
std::string existing_scene_file(const std::string& file, const std::string& key,
                                const SceneContext& ctx) {
  const std::string path = resolve_scene_path(file, ctx.scene_file);
  if (!std::filesystem::exists(path))
    throw InputError(ctx.scene_file + ": " + key + ": file '" + file + "' not found");
  return path;
}

/// Rows a replicate needs for the slope fits (the reader's own minimum, rdelta_data.cc).
constexpr std::size_t min_rows_per_replicate = 8;

/// The Data section, its file resolved. `file_may_come_later`: reduce runs first and may hand on
/// R(delta_root) itself. With no Data/File, the data are reduce's R(delta_root) (in memory, named
/// by the rdelta_test.csv reduce also writes).
ExtractionOptions data_options(const SceneContext& ctx, bool file_may_come_later) {
  ExtractionOptions o = ctx.parameters().section<ExtractionOptions>("Data");
  if (!o.data_file.empty())
    o.data_file = existing_scene_file(o.data_file, "Data/File", ctx);
  else if (ctx.rdelta_root) {
    for (const auto& r : ctx.rdelta_root->replicates)
      if (r.delta.size() < min_rows_per_replicate)
        throw InputError("Data/File: none given, and record '" + r.label + "' gives " +
                         std::to_string(r.delta.size()) + " values of R(delta_root); at least " +
                         std::to_string(min_rows_per_replicate) +
                         " are needed to fit slopes: name a Data/File");
    o.data = ctx.rdelta_root;
    o.data_file = ctx.rdelta_root->source;
  } else if (ctx.reduced)
    throw InputError("Data/File: the scene runs 'extract' but names no data file, and reduce has "
                     "no R(delta_root) to hand on (not every record has delta_root_mm)");
  else if (!file_may_come_later)
    throw InputError("Data/File: the scene runs 'extract' but names no data file");
  return o;
}

RankOptions rank_options(const SceneContext& ctx) {
  RankOptions o = ctx.parameters().section<RankOptions>("Rank");
  o.table_file = existing_scene_file(o.table_file, "Rank/Table file", ctx);
  return o;
}

/// Is the extraction's R(delta_root) this scene's own records' (reduce's, no Data/File)? Only
/// then can the fit's correction simulate the records it came from.
[[maybe_unused]] bool extraction_of_own_records(const SceneContext& ctx) {
  return ctx.parameters().entry("Data/File").empty() && ctx.rdelta_root != nullptr;
}

/// Can the fit be corrected by simulation in this scene (checked before anything runs)?
bool correction_possible(const SceneContext& ctx) {
#ifdef FIBERBRIDGE_HAVE_IDENTIFY
  return ctx.run_items.count("reduce") > 0 && ctx.parameters().entry("Data/File").empty();
#else
  (void)ctx;
  return false;
#endif
}

} // namespace

void declare_data_section(dealii::ParameterHandler& prm) {
  declare_section<DataSection>(prm, "Data");
}

void declare_fit_section(dealii::ParameterHandler& prm) {
  declare_section<FitSection>(prm, "Fit");
}

void declare_rank_section(dealii::ParameterHandler& prm) {
  declare_section<RankSection>(prm, "Rank");
}

void declare_bridging_section(dealii::ParameterHandler& prm) {
  declare_section<BridgingSection>(prm, "Bridging");
}

void parse_data_section(dealii::ParameterHandler& prm, SceneParameters& out) {
  parse_into<DataSection, ExtractionOptions>(prm, "Data", out);
}

void parse_fit_section(dealii::ParameterHandler& prm, SceneParameters& out) {
  parse_into<FitSection, FitOptions>(prm, "Fit", out);
}

void parse_rank_section(dealii::ParameterHandler& prm, SceneParameters& out) {
  parse_into<RankSection, RankOptions>(prm, "Rank", out);
}

void parse_bridging_section(dealii::ParameterHandler& prm, SceneParameters& out) {
  parse_into<BridgingSection>(prm, "Bridging", out);
}

void check_extract_item(SceneContext& ctx) {
  data_options(ctx, ctx.run_items.count("reduce") > 0);
}

ItemOutcome run_extract_item(const SceneContext& ctx) {
  ItemOutcome out;
  auto e = std::make_shared<const ExtractionOutcome>(
      run_extraction(data_options(ctx, false), ctx.output_dir, out.report));
  out.extraction = e;
#ifdef FIBERBRIDGE_HAVE_IDENTIFY
  // identify ran before (scene order): its law beside Eq. 5/6 and dR/d delta on the same data.
  if (ctx.identification)
    report_law_routes(*e, *ctx.identification, ctx.output_dir, out.report);
#endif
  return out;
}

void check_fit_item(SceneContext& ctx) {
  check_extract_item(ctx); // fit implies extract
  ctx.parameters().section<FitOptions>("Fit");
  const std::string mode = ctx.parameters().entry("Fit/Model correction");
  if ((mode == "beam" || mode == "fem") && !correction_possible(ctx))
    throw InputError(ctx.scene_file + ": Fit/Model correction = " + mode +
                     " needs the fit's data to be this scene's records through reduce (no "
                     "Data/File) and a build with the beam and identify");
#ifdef FIBERBRIDGE_HAVE_IDENTIFY
  if (mode == "fem")
    correction_forward_model(ctx); // an error now, not after reduce and extract, without the FEM
#endif
}

ItemOutcome run_fit_item(const SceneContext& ctx) {
  // fit works on the extracted law: it implies extract, whose outcome it then hands on too.
  ItemOutcome out = ctx.extraction ? ItemOutcome{} : run_extract_item(ctx);
  const ExtractionOutcome& extraction = ctx.extraction ? *ctx.extraction : *out.extraction;
  const FitOptions& o = ctx.parameters().section<FitOptions>("Fit");
  const auto fit = run_trilinear_fit(extraction, o, ctx.output_dir, out.report);
  // The extracted law is handed to the simulations without being retyped
  // (docs/design.md section 5); corrected by simulation where the scene asks and can.
  law::TrilinearParameters handed = fit.law;
  double handed_j_tip = extraction.steady.j_tip;
  bool corrected = false;
#ifdef FIBERBRIDGE_HAVE_IDENTIFY
  if (ctx.parameters().entry("Fit/Model correction") != "none" && ctx.reduced &&
      extraction_of_own_records(ctx)) {
    const auto c = correct_fit_by_simulation(ctx, extraction, o, fit, fit_correction_settings(ctx));
    write_fit_correction(c, ctx.output_dir, out.report);
    if (c.converged) {
      corrected = true;
      handed = c.corrected.law;
      handed_j_tip = c.corrected.j_tip;
    }
  }
#endif
  out.law = CrackLaw{std::make_shared<law::PiecewiseLinearLaw>(law::make_trilinear(handed)),
                     handed_j_tip, LawSource::fit};
  plot_extraction(extraction, &fit, ctx.output_dir, out.report, corrected);
  return out;
}

void check_rank_item(SceneContext& ctx) {
  rank_options(ctx);
}

ItemOutcome run_rank_item(const SceneContext& ctx) {
  ItemOutcome out;
  run_ranking(rank_options(ctx), ctx.output_dir, out.report);
  return out;
}

void check_bridging_item(SceneContext& ctx) {
  if (ctx.parameters().section<BridgingSection>("Bridging").stress == 0)
    ctx.law_known_before_run();
}

ItemOutcome run_bridging_item(const SceneContext& ctx) {
  ItemOutcome out;
  const auto& in = ctx.parameters().section<BridgingSection>("Bridging");
  const analysis::BridgingFiber& f = in.fiber;
  const double l_b = in.zone_length, delta = in.opening;
  double sigma = in.stress;
  std::string stress_source = "Bridging/Stress";
  if (sigma == 0) {
    const CrackLaw& crack = ctx.crack_law();
    sigma = crack.law->envelope(delta);
    stress_source = crack.source == LawSource::fit        ? "fitted trilinear law"
                    : crack.source == LawSource::identify ? "identified trilinear law"
                                                          : "Cohesive law section";
    if (!(sigma > 0))
      throw InputError("Bridging: the scene's law carries no traction at the opening " +
                       std::to_string(delta / mm) + " mm; set Bridging/Stress");
  }
  write_bridging(analysis::estimate_bridging(sigma, delta, l_b, f), stress_source, ctx.output_dir,
                 out.report);
  return out;
}

} // namespace fiberbridge::app
