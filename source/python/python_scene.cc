#include "python_scene.h"

#include "fiberbridge/app/scene/scene_reader.h"

#include <map>
#include <mutex>

namespace fiberbridge::python {

namespace {

/// Reading a scene declares and parses every section (about 4 ms, the most of a short call's
/// overhead: bench/python_overhead.py). The parameters depend only on the call and its settings
/// and are immutable, so a script's loop over specimens reads them once. A few dozen sets are
/// kept; the cache starts afresh when it is full.
std::shared_ptr<const app::SceneParameters> parameters_of(const std::vector<std::string>& key) {
  static std::mutex mutex;
  static std::map<std::vector<std::string>, std::shared_ptr<const app::SceneParameters>> kept;
  {
    const std::lock_guard<std::mutex> lock(mutex);
    if (const auto it = kept.find(key); it != kept.end())
      return it->second;
  }
  const std::vector<std::string> settings(key.begin() + 1, key.end());
  auto p = app::read_scene_parameters_from_settings(key.front(), settings);
  const std::lock_guard<std::mutex> lock(mutex);
  if (kept.size() >= 64)
    kept.clear();
  kept.emplace(key, p);
  return p;
}

} // namespace

app::SceneContext call_context(const std::string& where, const std::vector<std::string>& settings,
                               const std::string& run) {
  std::vector<std::string> key = {where, "Run=" + run};
  key.insert(key.end(), settings.begin(), settings.end());
  app::SceneContext ctx;
  ctx.params = parameters_of(key);
  ctx.scene_file = where;
  ctx.run_items = {run};
  return ctx;
}

} // namespace fiberbridge::python
