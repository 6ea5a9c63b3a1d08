#pragma once
// A scene without a file for the Python module's calls: the defaults of every section with the
// call's settings ("Section/Key=value", the scene file's and --set's own syntax) on top, read and
// checked by the scene reader (app/scene/scene_reader.h). So `fb.reduce(...)` reads its Test,
// Specimen and Material keys exactly as a scene's `reduce` does, and messages name the call.
#include "fiberbridge/app/scene/scene_context.h"

#include <string>
#include <vector>

namespace fiberbridge::python {

/// The context of a call `where` ("fiberbridge.reduce") with `settings` on the defaults, and
/// `run` as its Run item (the sections that item reads are then the ones checked). Relative paths
/// in the settings are the caller's (the working directory). Throws InputError naming `where`.
app::SceneContext call_context(const std::string& where, const std::vector<std::string>& settings,
                               const std::string& run);

} // namespace fiberbridge::python
