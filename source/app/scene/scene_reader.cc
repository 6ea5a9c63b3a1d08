// Reading a .prm scene (docs/design.md section 5): every section declared from the item registry,
// the file parsed (unknown entries are errors), --set applied, the Run list checked, then each
// section parsed once into SceneParameters.
#include "fiberbridge/app/scene/scene_reader.h"

#include "fiberbridge/app/scene/models.h"
#include "fiberbridge/app/scene/scene_context.h"
#include "fiberbridge/app/scene/scene_parameters.h"
#include "fiberbridge/app/scene/shared_sections.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

namespace fiberbridge::app {

namespace {

/// Every item a scene may list, built or not.
const std::string all_item_names =
    "dic, reduce, identify, extract, fit, rank, bridging, campaign, " + model_names() +
    ", compare, study, chain study, programme study";

void declare_everything(dealii::ParameterHandler& prm) {
  prm.declare_entry("Output directory", "output", dealii::Patterns::Anything(),
                    "Where results go (created if missing).");
  prm.declare_entry("Run", "", dealii::Patterns::Anything(),
                    "Comma-separated items to run, from: " + all_item_names +
                        ". Only these are built and run.");
  declare_law_section(prm);
  declare_specimen_sections(prm);
  for (const auto& item : scene_items())
    if (item.declare)
      item.declare(prm);
}

} // namespace

namespace {

/// deal.II's exception text is many lines (where in deal.II, the violated condition, then the
/// "Additional information" that says what was wrong in the user's file); keep the last part.
std::string condense(const std::string& what) {
  std::stringstream in(what);
  std::string line, best;
  bool in_info = false, have_info = what.find("Additional information") != std::string::npos;
  while (std::getline(in, line)) {
    const auto b = line.find_first_not_of(" \t");
    if (b == std::string::npos)
      continue;
    line = line.substr(b);
    if (line.rfind("Additional information", 0) == 0) {
      in_info = true;
      continue;
    }
    if (line.rfind("---", 0) == 0 || line.rfind("Stacktrace", 0) == 0) {
      in_info = false;
      continue;
    }
    if (have_info
            ? !in_info
            : (line.rfind("An error occurred", 0) == 0 || line.rfind("The violated", 0) == 0 ||
               line.rfind("#", 0) == 0 || line.find("in function") != std::string::npos))
      continue;
    best += (best.empty() ? "" : " ") + line;
    if (best.size() > 300)
      break;
  }
  return best.empty() ? what : best;
}

} // namespace

void apply_setting(dealii::ParameterHandler& prm, const std::string& setting,
                   const std::string& where) {
  const auto eq = setting.find('=');
  if (eq == std::string::npos)
    throw InputError(where + " '" + setting + "': expected \"Section/Key=value\"");
  // Blanks around the names and the value are the user's layout, not part of them.
  const std::string path = setting.substr(0, eq);
  const auto parts = split_list(path, '/');
  const auto last = path.find_last_not_of(" \t");
  if (parts.empty() || path[last] == '/')
    throw InputError(where + " '" + setting + "': no key before '='");
  std::string value = setting.substr(eq + 1);
  value.erase(0, value.find_first_not_of(" \t"));
  value.erase(value.find_last_not_of(" \t") + 1);
  for (std::size_t i = 0; i + 1 < parts.size(); ++i)
    prm.enter_subsection(parts[i]);
  try {
    prm.set(parts.back(), value);
  } catch (const std::exception& e) {
    for (std::size_t i = 0; i + 1 < parts.size(); ++i)
      prm.leave_subsection();
    // deal.II's reason says which: no such entry, or the value against the entry's pattern.
    throw InputError(where + " '" + setting + "': " + condense(e.what()));
  }
  for (std::size_t i = 0; i + 1 < parts.size(); ++i)
    prm.leave_subsection();
}

namespace {

/// "Section/Key" -> value of every entry, in the order of deal.II's ShortPRM listing
/// ("subsection S", "set Key = value", "end"): the one complete listing ParameterHandler offers.
std::vector<std::pair<std::string, std::string>> listed_entries(const std::string& listing) {
  std::vector<std::pair<std::string, std::string>> out;
  std::vector<std::string> path;
  std::istringstream in(listing);
  for (std::string line; std::getline(in, line);) {
    line = trim_blanks(line);
    if (line.rfind("subsection ", 0) == 0)
      path.push_back(trim_blanks(line.substr(11)));
    else if (line == "end" && !path.empty())
      path.pop_back();
    else if (line.rfind("set ", 0) == 0) {
      const auto eq = line.find('=');
      if (eq == std::string::npos)
        continue;
      std::string key;
      for (const auto& p : path)
        key += p + "/";
      key += trim_blanks(line.substr(4, eq - 4));
      out.emplace_back(key, trim_blanks(line.substr(eq + 1)));
    }
  }
  return out;
}

/// A number too small or too large for a double (1e-320 is subnormal, 1e400 overflows) passes
/// deal.II's Double pattern but not get_double, whose failure is an internal assertion with a
/// stack trace (issue 42): refused here, before any section reads it, naming key and value.
void refuse_unreadable_numbers(const std::vector<std::pair<std::string, std::string>>& entries,
                               const std::string& prm_file) {
  for (const auto& [key, value] : entries) {
    if (value.empty())
      continue;
    char* end = nullptr;
    errno = 0;
    const double x = std::strtod(value.c_str(), &end);
    if (end == value.c_str() || *end != '\0')
      continue; // not a number: the entry's pattern and parse judge it
    if (errno == ERANGE || (x != 0 && !std::isnormal(x)))
      throw InputError(prm_file + ": " + key + " = " + value +
                       ": not a normal double (subnormal or out of range); expected 0 or a "
                       "magnitude between 2.3e-308 and 1.7e308");
  }
}

/// Every section of the scene read in `prm` parsed once into its struct (each item's parse, the
/// shared sections); the handler is not used after this.
std::shared_ptr<const SceneParameters> parse_scene(dealii::ParameterHandler& prm,
                                                   const std::string& prm_file,
                                                   const std::vector<std::string>& overrides,
                                                   std::vector<std::string> run) {
  auto p = std::make_shared<SceneParameters>();
  p->scene_file = prm_file;
  p->overrides = overrides;
  p->run = std::move(run);
  p->output_directory = prm.get("Output directory");
  std::ostringstream listing;
  prm.print_parameters(listing, dealii::ParameterHandler::ShortPRM);
  p->listing = listing.str();
  p->entries = listed_entries(p->listing);
  refuse_unreadable_numbers(p->entries, prm_file);
  parse_shared_sections(prm, *p);
  for (const auto& item : scene_items())
    if (item.parse)
      item.parse(prm, *p);
  return p;
}

} // namespace

std::shared_ptr<const SceneParameters>
read_scene_parameters(const std::string& prm_file, const std::vector<std::string>& overrides) {
  dealii::ParameterHandler prm;
  auto run = read_scene(prm, prm_file, overrides);
  return parse_scene(prm, prm_file, overrides, std::move(run));
}

std::shared_ptr<const SceneParameters>
read_scene_parameters_from_settings(const std::string& where,
                                    const std::vector<std::string>& settings) {
  dealii::ParameterHandler prm;
  declare_everything(prm);
  auto run = apply_settings_and_check_run(prm, where, settings);
  auto p = parse_scene(prm, where, settings, std::move(run));
  std::const_pointer_cast<SceneParameters>(p)->from_file = false;
  return p;
}

std::shared_ptr<const SceneParameters>
scene_parameters_with(const SceneParameters& scene, const std::vector<std::string>& settings,
                      const std::string& where) {
  // ParameterHandler cannot be copied, and its JSON and XML listings do not read back in deal.II
  // 9.4 (mangled entry names): the copy reads the scene as the runner did, the file and then
  // --set, then the settings. Nothing wrote into the scene's parameters after that
  // (docs/design.md section 4), so the copy holds the same values but for the settings.
  dealii::ParameterHandler prm;
  std::vector<std::string> run;
  if (scene.from_file)
    run = read_scene(prm, scene.scene_file, scene.overrides);
  else {
    declare_everything(prm);
    run = apply_settings_and_check_run(prm, scene.scene_file, scene.overrides);
  }
  for (const auto& s : settings)
    apply_setting(prm, s, where);
  auto p = parse_scene(prm, scene.scene_file, scene.overrides, std::move(run));
  std::const_pointer_cast<SceneParameters>(p)->from_file = scene.from_file;
  return p;
}

std::string resolve_scene_path(const std::string& path, const std::string& scene_file) {
  namespace fs = std::filesystem;
  if (path.empty() || fs::path(path).is_absolute() || fs::exists(path))
    return path;
  const fs::path alt = fs::path(scene_file).parent_path() / path;
  return fs::exists(alt) ? alt.string() : path;
}

void print_scene_parameters(std::ostream& out) {
  dealii::ParameterHandler prm;
  declare_everything(prm);
  prm.print_parameters(out, dealii::ParameterHandler::PRM);
}

std::vector<std::string> read_scene(dealii::ParameterHandler& prm, const std::string& prm_file,
                                    const std::vector<std::string>& overrides) {
  declare_everything(prm);
  if (!std::filesystem::exists(prm_file))
    throw InputError(prm_file + ": scene file not found");
  try {
    // Unknown entries and values that do not match their pattern are errors (a typo in a scene
    // must not silently fall back to a default).
    prm.parse_input(prm_file, "", false, true);
  } catch (const std::exception& e) {
    throw InputError(prm_file + ": " + condense(e.what()));
  }
  return apply_settings_and_check_run(prm, prm_file, overrides, "--set");
}

std::vector<std::string> apply_settings_and_check_run(dealii::ParameterHandler& prm,
                                                      const std::string& prm_file,
                                                      const std::vector<std::string>& overrides,
                                                      const std::string& where) {
  // --set "Section/Sub/Key=value": set() validates against the entry's pattern.
  for (const auto& o : overrides)
    apply_setting(prm, o, where.empty() ? prm_file : where);

  const auto wanted = split_list(prm.get("Run"), ',');
  if (wanted.empty())
    throw InputError(prm_file + ": 'Run' lists no items; choose from " +
                     std::string(all_item_names));
  for (const auto& w : wanted) {
    bool known = false;
    for (const auto& item : scene_items())
      known = known || item.name == w;
    if (!known) {
      const std::string all = all_item_names;
      // A whole name of the list (a model left out of this build), not any substring of it.
      const auto names = split_list(all, ',');
      if (std::find(names.begin(), names.end(), w) != names.end())
        throw InputError(prm_file + ": Run item '" + w +
                         "' is not available in this build (its module is not built yet)");
      throw InputError(prm_file + ": unknown Run item '" + w + "', expected one of " + all);
    }
  }
  return wanted;
}

} // namespace fiberbridge::app
