#pragma once
// Reading a .prm scene (docs/design.md section 5): declare every section, parse the file (unknown
// entries are errors), apply --set overrides and check the Run list (run/scene_runner.h runs it).
#include "fiberbridge/core/format.h" // split_list, the lists of a scene

#include <memory>
#include <string>
#include <vector>

namespace dealii {
class ParameterHandler;
}

namespace fiberbridge::app {

/// Declares every section in `prm`, parses `prm_file` (unknown entries are errors), applies the
/// --set overrides and checks the Run list; returns the items to run. Throws InputError. (The
/// handler-level step of read_scene_parameters, for tests that look at the handler itself.)
std::vector<std::string> read_scene(dealii::ParameterHandler& prm, const std::string& prm_file,
                                    const std::vector<std::string>& overrides);

/// The settings ("Section/Key=value", --set's syntax) applied to `prm`, whose sections are
/// declared, then the Run list checked; returns the items to run. Messages start with `where`
/// ("--set"), or with `prm_file` when `where` is empty.
std::vector<std::string> apply_settings_and_check_run(dealii::ParameterHandler& prm,
                                                      const std::string& prm_file,
                                                      const std::vector<std::string>& overrides,
                                                      const std::string& where = "");

class SceneParameters;
/// The scene read as read_scene does, then every section parsed once into its typed struct
/// (scene_parameters.h); the handler ends here. Throws InputError for the file, --set and Run;
/// a section's own error is kept and thrown where an item reads it.
std::shared_ptr<const SceneParameters>
read_scene_parameters(const std::string& prm_file, const std::vector<std::string>& overrides);

/// A scene without a file: every section's defaults with `settings` on top (which must set Run),
/// parsed as read_scene_parameters parses a file's; `where` ("fiberbridge.reduce", the Python
/// call) stands for the file in messages and as SceneParameters::scene_file (relative paths are
/// then the working directory's). Throws InputError as read_scene_parameters.
std::shared_ptr<const SceneParameters>
read_scene_parameters_from_settings(const std::string& where,
                                    const std::vector<std::string>& settings);

/// One setting "Section/Sub/Key=value" applied to `prm` (the scene's --set, a study's
/// overrides); set() validates the value against the entry's pattern. Throws InputError that
/// starts with `where` ("--set", "Study/Beam ladder") and quotes the setting.
void apply_setting(dealii::ParameterHandler& prm, const std::string& setting,
                   const std::string& where);

/// The scene's parameters with `settings` ("Section/Key=value", apply_setting with `where`) on
/// top, parsed anew: the scene file read again with its --set settings, then these (deal.II 9.4
/// cannot copy a ParameterHandler). For runs that apply their own overrides without touching the
/// scene's (a study's ladder levels and stability cases).
std::shared_ptr<const SceneParameters>
scene_parameters_with(const SceneParameters& scene, const std::vector<std::string>& settings,
                      const std::string& where);

/// Writes the full documented parameter set (every section, defaults) to `out`.
void print_scene_parameters(std::ostream& out);

/// Resolves a data path from a scene: as given when it exists relative to the working directory,
/// else relative to the scene file's directory.
std::string resolve_scene_path(const std::string& path, const std::string& scene_file);

} // namespace fiberbridge::app
