// The command line's commands (docs/design.md section 5, "Command line"), in the app library so
// that tests link them; main.cc only starts MPI and hands over. Every command returns 0 on
// success and non-zero with a one-line reason on stderr otherwise.
#include "fiberbridge/app/cli/commands.h"

#include "fiberbridge/analysis/synthetic_data.h"
#include "fiberbridge/app/items/analysis_steps.h"
#include "fiberbridge/app/items/dic_step.h"
#include "fiberbridge/app/items/reduce_step.h"
#include "fiberbridge/app/outputs/extraction_writers.h"
#include "fiberbridge/app/outputs/run_directory.h"
#include "fiberbridge/app/run/scene_runner.h"
#include "fiberbridge/app/scene/dic_section.h"
#include "fiberbridge/app/scene/scene_reader.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/output_guard.h"
#include "fiberbridge/core/units.h"
#include "fiberbridge/dic/layouts.h"
#include "fiberbridge/law/law_spec.h"

#include <boost/program_options.hpp>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace po = boost::program_options;
using namespace fiberbridge;

namespace {

const char* usage = R"(fiberbridge: fiber-bridging cohesive laws from R curves, and DCB simulations.

Usage:
  fiberbridge run SCENE.prm [--set "Section/Key=value"]... [--resume]   run a .prm scene
                                        (--resume: continue a killed run into the same directory)
  fiberbridge extract DATA.csv [--delta-c MM|auto] [--j-tip J_M2|auto] [--out DIR]
                                        R(delta) -> Eq. 6 law, R' law, trilinear fit
  fiberbridge rank TABLE.csv [--out DIR]  degradation statistics and durability ranking
  fiberbridge forward --type T [--points "d:s,..."] [--peak-stress KPA] --delta-c MM
                      [--j-tip J_M2] [--out DIR]   the R(delta) a law implies (Eq. 2)
  fiberbridge synth --out FILE [law options] [--replicates N] [--noise J_M2] [--seed S]
                                        synthetic replicate data from a law (labelled as such)
  fiberbridge reduce RECORD.csv... --width MM --arm-thickness MM [--columns MAP] [--encoding E] [--out DIR]
                                        raw DCB records -> R(a) by direct energy, MBT, CC, MCC,
                                        CBBM (equivalent crack, also without crack readings)
  fiberbridge dic FRAMES... --record MACHINE.csv [--columns MAP] [--format F] [--coordinates mm|px]
                  [--pixel-size MM] [--y-axis up|down] [--crack-plane-y Y] [--notch-root-x X]
                  [--growth-direction +x|-x] [--frame-rate HZ] [--first-frame-time S]
                  [--threshold E] [--gauge-length MM] [--initial-crack MM] [--out DIR]
                                        DIC frames -> crack length (1 % strain rule) and
                                        delta_root (virtual extensometer): dic_record.csv
  fiberbridge parameters                print every scene parameter with its documentation
  fiberbridge COMMAND --help            options of one command
)";

double auto_or_value(const std::string& v, const std::string& option, double unit) {
  if (v == "auto")
    return 0;
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (end == v.c_str() || *end != '\0' || !(x > 0))
    throw InputError(option + ": expected 'auto' or a positive number, got '" + v + "'");
  return x * unit;
}

/// Parses the options after the command; returns false when --help was printed.
bool parse(const std::vector<std::string>& args, po::options_description& desc,
           po::positional_options_description& pos, po::variables_map& vm) {
  desc.add_options()("help,h", "this help");
  po::store(po::command_line_parser(args).options(desc).positional(pos).run(), vm);
  if (vm.count("help")) {
    std::cout << desc << "\n";
    return false;
  }
  po::notify(vm);
  // boost reads "nan" and "inf" as doubles: no option of ours means either (issue 42).
  for (const auto& [name, v] : vm)
    if (const double* x = boost::any_cast<double>(&v.value()); x && !std::isfinite(*x))
      throw InputError("--" + name + ": '" + fmt(*x) + "' is not a finite number");
  return true;
}

/// The value of a numeric option within [lo, hi] (`what` says the unit and meaning); NAN when it
/// was not given. The bounds keep a unit slip (um for mm, 1e-300) from reaching the formulas,
/// where it would give R of 1e304 without a word.
double option_in(const po::variables_map& vm, const char* key, double lo, double hi,
                 const std::string& what) {
  if (!vm.count(key))
    return NAN;
  const double x = vm[key].as<double>();
  if (!(x >= lo && x <= hi))
    throw InputError(std::string("--") + key + ": " + fmt(x) + " is out of range; expected " +
                     what + " from " + fmt(lo) + " to " + fmt(hi));
  return x;
}

/// The same, with one positional option `name` taking `count` arguments (-1: all the rest).
bool parse(const std::vector<std::string>& args, po::options_description& desc, const char* name,
           int count, po::variables_map& vm) {
  po::positional_options_description pos;
  pos.add(name, count);
  return parse(args, desc, pos, vm);
}

void add_law_options(po::options_description& d) {
  d.add_options()("type", po::value<std::string>()->default_value("trilinear"),
                  "none|linear|bilinear|trilinear|exponential")(
      "points", po::value<std::string>()->default_value("0.1:661, 1.0:187"),
      "interior points delta_mm:sigma_kPa (default: PVA control, seed Table 1)")(
      "peak-stress", po::value<double>()->default_value(0),
      "kPa (linear, exponential)")("delta-c", po::value<double>()->default_value(6.0),
                                   "mm")("j-tip", po::value<double>()->default_value(200), "J/m^2");
}

law::LawSpec law_from_options(const po::variables_map& vm) {
  law::LawSpec s;
  s.type = vm["type"].as<std::string>();
  if (s.type == "bilinear" || s.type == "trilinear" || s.type == "table")
    s.points = law::parse_points_mm_kPa(vm["points"].as<std::string>(), "--points");
  s.peak_stress = vm["peak-stress"].as<double>() * units::kPa;
  s.delta_c = vm["delta-c"].as<double>() * units::mm;
  s.j_tip = vm["j-tip"].as<double>();
  s.context = "command line law";
  return s;
}

/// Commands whose options are all named (forward, synth).
po::positional_options_description no_positional;

/// A command's output directory made ready: created, a stale summary removed (so a failed run
/// never leaves an old one looking current), and the summary begun with the command's name.
Json begin_command_output(const std::string& out, const std::string& command) {
  app::ensure_directory(out);
  app::remove_stale_summary(out);
  Json summary;
  summary["command"] = command;
  summary["plots"] = Json::array();
  return summary;
}

int cmd_run(const std::vector<std::string>& args) {
  po::options_description d("fiberbridge run SCENE.prm [options]");
  d.add_options()("scene", po::value<std::string>()->required(),
                  "scene file (.prm)")("set", po::value<std::vector<std::string>>()->composing(),
                                       "override \"Section/Key=value\" (repeatable)")(
      "resume", po::bool_switch(),
      "continue a run that was killed: restore the work it finished (simulations, study runs, "
      "identify fits; kept in OUTPUT/resume/) and continue the MPM from its checkpoint");
  po::variables_map vm;
  if (!parse(args, d, "scene", 1, vm))
    return 0;
  std::vector<std::string> sets;
  if (vm.count("set"))
    sets = vm["set"].as<std::vector<std::string>>();
  const auto out = app::run_scene(vm["scene"].as<std::string>(), sets, vm["resume"].as<bool>());
  if (output_enabled())
    std::cout << "results in " << out << " (summary.json)\n";
  return 0;
}

int cmd_extract(const std::vector<std::string>& args) {
  po::options_description d("fiberbridge extract DATA.csv [options]");
  d.add_options()("data", po::value<std::string>()->required(), "R(delta) CSV")(
      "delta-c", po::value<std::string>()->default_value("auto"),
      "mm or auto")("j-tip", po::value<std::string>()->default_value("auto"), "J/m^2 or auto")(
      "intervals", po::value<int>()->default_value(100), "n of Eq. 6")(
      "smoothing", po::value<int>()->default_value(3), "half-width k of the slope fits")(
      "delta1", po::value<double>()->default_value(0.1), "trilinear d1 in mm")(
      "delta2", po::value<double>()->default_value(1.0),
      "trilinear d2 in mm")("free-breakpoints", po::bool_switch(), "fit d1, d2 too")(
      "out", po::value<std::string>()->default_value("output/extract"), "output directory");
  po::variables_map vm;
  if (!parse(args, d, "data", 1, vm))
    return 0;
  app::ExtractionOptions o;
  o.data_file = vm["data"].as<std::string>();
  o.delta_c = auto_or_value(vm["delta-c"].as<std::string>(), "--delta-c", units::mm);
  o.j_tip = auto_or_value(vm["j-tip"].as<std::string>(), "--j-tip", 1.0);
  o.intervals = vm["intervals"].as<int>();
  o.half_width = vm["smoothing"].as<int>();
  const std::string out = vm["out"].as<std::string>();
  Json summary = begin_command_output(out, "extract");
  app::ItemReport report;
  const auto e = app::run_extraction(o, out, report);
  app::FitOptions f;
  f.d1 = vm["delta1"].as<double>() * units::mm;
  f.d2 = vm["delta2"].as<double>() * units::mm;
  f.free_breakpoints = vm["free-breakpoints"].as<bool>();
  const auto fit = app::run_trilinear_fit(e, f, out, report);
  app::plot_extraction(e, &fit, out, report);
  app::add_report_to_summary(report, summary);
  app::write_run_summary(out, summary);
  std::cout << "J_tip " << e.steady.j_tip << " J/m^2, G_ss " << e.steady.G_ss << " J/m^2, delta_c "
            << e.steady.delta_c / units::mm << " mm; trilinear sigma1 " << fit.law.s1 / units::kPa
            << " kPa, sigma2 " << fit.law.s2 / units::kPa << " kPa; results in " << out << "\n";
  return 0;
}

int cmd_rank(const std::vector<std::string>& args) {
  po::options_description d("fiberbridge rank TABLE.csv [options]");
  d.add_options()("table", po::value<std::string>()->required(), "property table CSV")(
      "out", po::value<std::string>()->default_value("output/rank"), "output directory");
  po::variables_map vm;
  if (!parse(args, d, "table", 1, vm))
    return 0;
  const std::string out = vm["out"].as<std::string>();
  Json summary = begin_command_output(out, "rank");
  app::ItemReport report;
  app::RankOptions o;
  o.table_file = vm["table"].as<std::string>();
  app::run_ranking(o, out, report);
  app::add_report_to_summary(report, summary);
  app::write_run_summary(out, summary);
  std::cout << "ranking (most durable first):";
  for (const auto& m : summary["ranking"])
    std::cout << " " << m.get<std::string>();
  std::cout << "; results in " << out << "\n";
  return 0;
}

int cmd_forward(const std::vector<std::string>& args) {
  po::options_description d("fiberbridge forward [options]");
  add_law_options(d);
  d.add_options()("out", po::value<std::string>()->default_value("output/forward"), "directory")(
      "points-out", po::value<int>()->default_value(400), "rows of the R(delta) table");
  po::variables_map vm;
  if (!parse(args, d, no_positional, vm))
    return 0;
  const auto spec = law_from_options(vm);
  const auto law = law::make_law(spec);
  const std::string out = vm["out"].as<std::string>();
  app::ensure_directory(out);
  const int n = vm["points-out"].as<int>();
  const double dmax = 1.25 * std::max(law->critical_opening(), 1e-4);
  CsvWriter w(out + "/rdelta_forward.csv", {"delta_mm", "sigma_kPa", "R_J_m2", "J_ff_J_m2"},
              {"forward R curve of seed Eq. 2 and far-field J of Eq. 1 for the " + law->name() +
               " law with J_tip = " + std::to_string(spec.j_tip) + " J/m^2"});
  for (int i = 0; i <= n; ++i) {
    const double dl = dmax * i / n;
    w.row({dl / units::mm, law->envelope(dl) / units::kPa, law::r_curve_eq2(*law, spec.j_tip, dl),
           law::j_far_field_eq1(*law, spec.j_tip, dl)});
  }
  w.close();
  std::cout << "G_ss = " << spec.j_tip + law->area()
            << " J/m^2 at delta_c = " << law->critical_opening() / units::mm << " mm; " << out
            << "/rdelta_forward.csv\n";
  return 0;
}

int cmd_synth(const std::vector<std::string>& args) {
  po::options_description d("fiberbridge synth --out FILE [options]");
  add_law_options(d);
  d.add_options()("out", po::value<std::string>()->required(), "CSV file to write")(
      "replicates", po::value<int>()->default_value(6),
      "number of replicates")("rows", po::value<int>()->default_value(150), "rows per replicate")(
      "noise", po::value<double>()->default_value(15), "std. dev. of R noise, J/m^2")(
      "delta-max", po::value<double>()->default_value(0), "largest opening in mm (0: 1.6 dc)")(
      "seed", po::value<unsigned>()->default_value(1), "random seed");
  po::variables_map vm;
  if (!parse(args, d, no_positional, vm))
    return 0;
  const auto spec = law_from_options(vm);
  const auto law = law::make_law(spec);
  double dmax = vm["delta-max"].as<double>() * units::mm;
  if (dmax <= 0)
    dmax = 1.6 * law->critical_opening();
  const auto data = analysis::make_synthetic_rdelta(*law, spec.j_tip, vm["replicates"].as<int>(),
                                                    vm["rows"].as<int>(), vm["noise"].as<double>(),
                                                    dmax, vm["seed"].as<unsigned>());
  std::string cmdline = "fiberbridge synth";
  for (const auto& a : args)
    cmdline += " " + (a.find(' ') != std::string::npos ? "\"" + a + "\"" : a);
  analysis::write_rdelta_csv(
      vm["out"].as<std::string>(), data,
      {"SYNTHETIC DATA, not measurements: generated by fiberbridge's forward model (seed Eq. 2)",
       "law: " + law->name() + ", J_tip " + std::to_string(spec.j_tip) + " J/m^2, G_ss " +
           std::to_string(spec.j_tip + law->area()) + " J/m^2",
       "regenerate with: " + cmdline});
  std::cout << "wrote " << vm["out"].as<std::string>() << "\n";
  return 0;
}

int cmd_reduce(const std::vector<std::string>& args) {
  po::options_description d("fiberbridge reduce RECORD.csv... --width MM --arm-thickness MM");
  d.add_options()("records", po::value<std::vector<std::string>>()->required(),
                  "raw DCB records (replicates)")("width", po::value<double>(),
                                                  "specimen width B in mm (required)")(
      "arm-thickness", po::value<double>(), "thickness h of one arm in mm (required)")(
      "columns", po::value<std::string>()->default_value(""),
      "'time_s: Time (s), opening_mm: ..., load_N: ..., a_mm: ...' (or by position: '#3')")(
      "encoding", po::value<std::string>()->default_value("auto"),
      "text encoding of the records: auto, or CP1250, CP932, GB18030, EUC-KR, UTF-16LE, ...")(
      "smoothing-window", po::value<double>()->default_value(0), "mm; 0 = automatic")(
      "out", po::value<std::string>()->default_value("output/reduce"), "output directory");
  // R without crack readings (CBBM equivalent crack; docs/design.md section 6).
  d.add_options()("crack-length", po::value<std::string>()->default_value("auto"),
                  "auto (measured where the records have a_mm), measured or equivalent")(
      "initial-crack", po::value<double>(), "a0 in mm (needed without crack readings)")(
      "shear-modulus", po::value<double>(), "G13 of the arms in MPa (CBBM's shear term)")(
      "transverse-modulus", po::value<double>(),
      "E22 in MPa (with G13: |Delta| = chi h without crack readings)")(
      "root-rotation", po::value<double>(), "|Delta| of CBBM in mm (overrides the above)")(
      "energy-crack", po::value<std::string>()->default_value("readings"),
      "direct energy against: readings (as read) or monotone (smooth a(t))");
  po::variables_map vm;
  if (!parse(args, d, "records", -1, vm))
    return 0;
  const std::string out = vm["out"].as<std::string>();
  Json summary = begin_command_output(out, "reduce");
  app::ItemReport report;
  app::ReduceStepOptions o;
  o.where = "fiberbridge reduce";
  o.files = vm["records"].as<std::vector<std::string>>();
  o.specimen.width = option_in(vm, "width", 0.01, 1e4, "a width in mm") * units::mm;
  o.specimen.height = // both arms
      2 * option_in(vm, "arm-thickness", 0.01, 1e4, "an arm thickness in mm") * units::mm;
  o.read.columns = analysis::RecordColumnMap::parse(vm["columns"].as<std::string>(), "--columns");
  if (const std::string e = vm["encoding"].as<std::string>(); e != "auto")
    o.read.encoding = e;
  const double w = option_in(vm, "smoothing-window", 0, 1e4, "a window in mm (0 = automatic)");
  o.reduce.smoothing_window = w > 0 ? w * units::mm : NAN;
  // One word for every door (analysis/record_chain.h): `measured` makes a missing a_mm column an
  // error; `equivalent` reduces against the compliance's equivalent crack, the readings (when the
  // file has them) giving a0 and shown beside.
  analysis::set_crack_length(o, vm["crack-length"].as<std::string>(), "--crack-length");
  auto opt = [&](const char* key, double unit) {
    return vm.count(key) ? vm[key].as<double>() * unit : NAN;
  };
  option_in(vm, "initial-crack", 0.01, 1e5, "a crack length a0 in mm");
  option_in(vm, "shear-modulus", 1e-3, 1e7, "G13 in MPa");
  option_in(vm, "transverse-modulus", 1e-3, 1e7, "E22 in MPa");
  option_in(vm, "root-rotation", 0, 1e4, "|Delta| in mm");
  o.specimen.initial_crack = opt("initial-crack", units::mm);
  o.reduce.shear_modulus = opt("shear-modulus", 1e6);
  o.reduce.transverse_modulus = opt("transverse-modulus", 1e6);
  o.reduce.root_rotation = opt("root-rotation", units::mm);
  o.reduce.energy_crack = vm["energy-crack"].as<std::string>();
  const auto r = app::run_reduce(o, out, report);
  app::add_report_to_summary(report, summary);
  app::write_run_summary(out, summary);
  for (const auto& x : r.reduced) // what makes a value uncertain is said where it is read
    if (!x.initiation.vis.note.empty())
      std::cout << "note: " << x.name << ": " << x.initiation.vis.note << "\n";
  std::cout << r.reduced.size() << " record(s); mean plateau R: energy " << r.mean.energy.plateau
            << ", MBT " << r.mean.mbt.plateau << ", CC " << r.mean.cc.plateau << ", MCC "
            << r.mean.mcc.plateau << ", CBBM " << r.mean.cbbm.plateau << " J/m^2; results in "
            << out << "\n";
  return 0;
}

/// fiberbridge dic: the scene item's DIC section as options (dic_step.h), its frames as arguments.
int cmd_dic(const std::vector<std::string>& args) {
  po::options_description d("fiberbridge dic FRAMES... --record MACHINE.csv [options]");
  d.add_options()("frames", po::value<std::vector<std::string>>()->required(),
                  "DIC frame files (ordered by the image number in their names)")(
      "record", po::value<std::string>()->required(), "the machine record (time, opening, load)")(
      "columns", po::value<std::string>()->default_value(""),
      "machine record columns: 'time_s: Time, opening_mm: Extension, load_N: Load'")(
      "encoding", po::value<std::string>()->default_value("auto"),
      "text encoding of the machine record: auto, or CP1250, CP932, GB18030, UTF-16LE, ...")(
      "frame-columns", po::value<std::string>()->default_value(""),
      "frame columns: 'eyy: ..., valid: ...' (x, y, u, v, eyy, valid, time_s)")(
      "format", po::value<std::string>()->default_value("auto"),
      ("auto|" + dic::layout_names("|")).c_str())(
      "coordinates", po::value<std::string>()->default_value("mm"),
      "mm|px")("pixel-size", po::value<double>()->default_value(0), "mm per pixel (with px)")(
      "y-axis", po::value<std::string>()->default_value("up"), "up|down")(
      "crack-plane-y", po::value<double>()->default_value(0), "in the frames' coordinates")(
      "notch-root-x", po::value<double>()->default_value(0), "in the frames' coordinates")(
      "growth-direction", po::value<std::string>()->default_value("+x"), "+x|-x")(
      "crack-plane-points", po::value<std::string>()->default_value(""),
      "'x0, y0, x1, y1': notch root and a point ahead on the plane (replaces the three above)")(
      "frame-rate", po::value<double>()->default_value(1),
      "Hz")("first-frame-time", po::value<double>()->default_value(0), "s on the machine's clock")(
      "frame-time-source", po::value<std::string>()->default_value("auto"),
      "auto|column|name|index")("threshold", po::value<double>()->default_value(0.01),
                                "crack-normal strain at the tip")(
      "gauge-length", po::value<double>()->default_value(2), "extensometer, mm")(
      "initial-crack", po::value<double>()->required(), "a at the notch root, mm")(
      "out", po::value<std::string>()->default_value("output/dic"), "output directory");
  po::variables_map vm;
  if (!parse(args, d, "frames", -1, vm))
    return 0;
  const auto choice = [&](const char* key, std::initializer_list<const char*> allowed) {
    const std::string v = vm[key].as<std::string>();
    for (const char* a : allowed)
      if (v == a)
        return v;
    throw InputError(std::string("--") + key + ": '" + v + "' is not allowed");
  };
  app::DicSection s;
  s.format = vm["format"].as<std::string>();
  s.columns = vm["frame-columns"].as<std::string>();
  s.pixels = choice("coordinates", {"mm", "px"}) == "px";
  s.pixel_size = option_in(vm, "pixel-size", 0, 1e3, "mm per pixel (0: none)") * units::mm;
  s.y_down = choice("y-axis", {"up", "down"}) == "down";
  s.crack_plane_y = vm["crack-plane-y"].as<double>();
  s.notch_root_x = vm["notch-root-x"].as<double>();
  s.growth_sign = choice("growth-direction", {"+x", "-x"}) == "-x" ? -1 : 1;
  s.crack_plane_points = vm["crack-plane-points"].as<std::string>();
  s.frame_rate = option_in(vm, "frame-rate", 1e-9, 1e9, "images per second (Hz)");
  s.first_frame_time = vm["first-frame-time"].as<double>();
  s.frame_time_source = vm["frame-time-source"].as<std::string>();
  s.threshold = option_in(vm, "threshold", 1e-9, 1, "a strain (fraction)");
  s.gauge_length = option_in(vm, "gauge-length", 1e-3, 1e4, "a gauge length in mm") * units::mm;
  if (s.pixels && !(s.pixel_size > 0))
    throw InputError("--pixel-size: --coordinates px needs a positive pixel size (mm)");
  app::DicStepOptions o;
  o.where = "fiberbridge dic";
  o.dic = s.options();
  o.frames = vm["frames"].as<std::vector<std::string>>();
  o.machine_record = vm["record"].as<std::string>();
  // Read as `reduce` reads a record (dic_step.h): the same column map, layouts and units.
  o.machine_read.columns =
      analysis::RecordColumnMap::parse(vm["columns"].as<std::string>(), "--columns");
  if (const std::string e = vm["encoding"].as<std::string>(); e != "auto")
    o.machine_read.encoding = e;
  o.initial_crack =
      option_in(vm, "initial-crack", 0.01, 1e5, "a crack length a0 in mm") * units::mm;
  const std::string out = vm["out"].as<std::string>();
  Json summary = begin_command_output(out, "dic");
  app::ItemReport report;
  const auto r = app::run_dic(o, out, report);
  app::add_report_to_summary(report, summary);
  app::write_run_summary(out, summary);
  std::cout << r.analysis.frames.size() << " frame(s), " << r.analysis.frames_used << " used, "
            << r.rows.size() << " row(s) in " << r.record_path << "\n";
  return 0;
}

/// A message that already names the command ("fiberbridge reduce: ...", the steps' `where`)
/// without it: the line starts with the command once.
std::string unprefixed(const std::string& what, const std::string& cmd) {
  const std::string prefix = "fiberbridge " + cmd + ": ";
  return what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what;
}

} // namespace

int app::run_command_line(std::vector<std::string> args, unsigned rank) {
  const std::string on_rank = rank == 0 ? "" : " [MPI rank " + std::to_string(rank) + "]";
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::cout << usage;
    return args.empty() ? 1 : 0;
  }
  const std::string cmd = args[0];
  args.erase(args.begin());
  try {
    if (cmd == "run")
      return cmd_run(args);
    if (cmd == "extract")
      return cmd_extract(args);
    if (cmd == "rank")
      return cmd_rank(args);
    if (cmd == "forward")
      return cmd_forward(args);
    if (cmd == "synth")
      return cmd_synth(args);
    if (cmd == "reduce")
      return cmd_reduce(args);
    if (cmd == "dic")
      return cmd_dic(args);
    if (cmd == "parameters") {
      app::print_scene_parameters(std::cout);
      return 0;
    }
    std::cerr << "fiberbridge: unknown command '" << cmd << "' (see fiberbridge --help)\n";
    return 2;
  } catch (const po::error& e) {
    if (rank == 0)
      std::cerr << "fiberbridge " << cmd << ": " << e.what() << " (see fiberbridge " << cmd
                << " --help)\n";
  } catch (const InputError& e) {
    if (rank == 0)
      std::cerr << "fiberbridge " << cmd << ": input error: " << unprefixed(e.what(), cmd) << "\n";
  } catch (const ComputationError& e) {
    std::cerr << "fiberbridge " << cmd << on_rank
              << ": cannot compute: " << unprefixed(e.what(), cmd) << "\n";
  } catch (const std::exception& e) {
    std::cerr << "fiberbridge " << cmd << on_rank << ": error: " << unprefixed(e.what(), cmd)
              << "\n";
  }
  return 1;
}
