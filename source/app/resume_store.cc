#include "fiberbridge/app/resume_store.h"

#include "fiberbridge/app/models.h"
#include "fiberbridge/app/result_codec.h"
#include "fiberbridge/app/scene.h"
#include "fiberbridge/core/binary_archive.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/output_guard.h"
#include "fiberbridge/law/law_fingerprint.h"

#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

namespace fiberbridge::app {

namespace {

const char* record_format = "fiberbridge finished unit";
constexpr int record_version = 1;

/// Entries that steer the run but not its results.
const std::set<std::string> run_control = {"Output directory", "Run", "MPM/Threads",
                                           "MPM/Checkpoint interval"};

std::string record_path(const std::string& output_dir, std::string unit) {
  for (auto& c : unit)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.'))
      c = '_';
  return resume_directory(output_dir) + "/" + unit + ".cbor";
}

} // namespace

Fingerprint scene_fingerprint(const SceneParameters& parameters) {
  Fingerprint fp;
  for (const auto& [key, value] : parameters.entries)
    if (!run_control.count(key))
      fp.emplace_back(key, value);
  return fp;
}

Fingerprint simulation_fingerprint(SceneContext& ctx) {
  Fingerprint fp = scene_fingerprint(ctx.parameters());
  // What earlier items hand on. A scene whose own law or specimen is unusable may still run a
  // study of cases that override them: the fingerprint then records the reason.
  auto add = [&](const std::string& key, const std::function<std::string()>& value) {
    try {
      fp.emplace_back(key, value());
    } catch (const std::exception& e) {
      fp.emplace_back(key, std::string("unusable: ") + e.what());
    }
  };
  using law::exact_number;
  add("law in effect", [&] { return law::law_fingerprint(*ctx.law()); });
  add("J_tip in effect", [&] { return exact_number(ctx.j_tip(), "J/m^2"); });
  add("specimen in effect", [&] {
    const auto s = ctx.specimen();
    return exact_number(s.length) + " " + exact_number(s.width) + " " + exact_number(s.height) +
           " " + exact_number(s.initial_crack) + " m";
  });
  add("material in effect", [&] {
    const auto m = ctx.material();
    std::string v;
    for (double x : {m.E_L, m.E_T, m.G_LT, m.nu_LT, m.density, m.E_R_over_E_L, m.nu_LR, m.nu_RT})
      v += exact_number(x) + " ";
    return v + (m.plane_stress ? "plane stress" : "plane strain");
  });
  // A specimen mesh is named by its path: its content must match too, or a resumed FEM record
  // would be one of another specimen.
  std::string file;
  for (const auto& [key, value] : fp)
    if (key == "FEM/Mesh file")
      file = value;
  add("FEM/Mesh file content", [&] {
    if (file.empty())
      return std::string("none");
    std::ifstream in(resolve_scene_path(file, ctx.scene_file), std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return std::to_string(bytes.str().size()) + " bytes, hash " +
           std::to_string(std::hash<std::string>{}(bytes.str()));
  });
  return fp;
}

std::string resume_directory(const std::string& output_dir) {
  return output_dir + "/resume";
}

std::optional<Json> find_finished_unit(const std::string& output_dir, bool resume,
                                       const std::string& unit, const Fingerprint& inputs) {
  const std::string path = record_path(output_dir, unit);
  if (!resume || !std::filesystem::exists(path))
    return std::nullopt;
  Json r;
  try {
    r = json_from_bytes(read_file_bytes(path));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(path + ": not a record of finished work (" + e.what() +
                     "); remove it, or run without --resume");
  }
  if (!r.is_object() || r.value("format", "") != record_format || !r.contains("payload") ||
      !r.contains("inputs"))
    throw InputError(path + ": not a record of finished work; remove it, or run without --resume");
  if (r.value("version", 0) != record_version)
    throw InputError(path + ": written by another version of fiberbridge; run without --resume");
  std::map<std::string, std::string> saved;
  for (const auto& kv : r["inputs"])
    saved[kv.at(0).get<std::string>()] = kv.at(1).get<std::string>();
  const std::string afresh = "; run without --resume to start afresh";
  for (const auto& [key, value] : inputs) {
    const auto it = saved.find(key);
    if (it == saved.end())
      throw InputError(path + ": the scene changed since this work was done: " + key + " is new" +
                       afresh);
    if (it->second != value)
      throw InputError(path + ": the scene changed since this work was done: " + key + " was '" +
                       it->second + "', now '" + value + "'" + afresh);
    saved.erase(it);
  }
  if (!saved.empty())
    throw InputError(path + ": the scene changed since this work was done: " +
                     saved.begin()->first + " is gone" + afresh);
  if (output_enabled())
    std::cerr << "fiberbridge: resume: " << unit << " restored from " << path << "\n";
  return r["payload"];
}

void keep_finished_unit(const std::string& output_dir, const std::string& unit,
                        const Fingerprint& inputs, const Json& payload) {
  if (!output_enabled())
    return;
  const std::string dir = resume_directory(output_dir);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec)
    throw InputError(dir + ": cannot create (" + ec.message() + ")");
  Json in = Json::array();
  for (const auto& [k, v] : inputs)
    in.push_back({k, v});
  write_file_atomically(record_path(output_dir, unit), json_to_bytes({{"format", record_format},
                                                                      {"version", record_version},
                                                                      {"unit", unit},
                                                                      {"inputs", std::move(in)},
                                                                      {"payload", payload}}));
}

void clear_resume_state(const std::string& output_dir) {
  if (!output_enabled())
    return;
  std::error_code ec;
  std::filesystem::remove_all(resume_directory(output_dir), ec);
}

std::string run_or_restore(const std::string& output_dir, bool resume, const std::string& unit,
                           const Fingerprint& inputs, const std::string& unit_dir,
                           const std::function<std::string()>& run) {
  if (const auto kept = find_finished_unit(output_dir, resume, unit, inputs)) {
    const auto& b = kept->get_binary();
    return std::string(b.begin(), b.end());
  }
  const std::string bytes = run();
  keep_finished_unit(output_dir, unit, inputs,
                     Json::binary(std::vector<std::uint8_t>(bytes.begin(), bytes.end())));
  clear_resume_state(unit_dir);
  return bytes;
}

bool is_simulation_item(const std::string& item) {
  return built_model(item) != nullptr;
}

void run_or_restore_simulation_item(SceneContext& ctx, const SceneItem& item) {
  const std::string unit = "item_" + item.name;
  const Fingerprint inputs = simulation_fingerprint(ctx);
  if (auto kept = find_finished_unit(ctx.output_dir, ctx.resume, unit, inputs)) {
    for (const auto& [key, block] : (*kept)["summary"].items())
      ctx.summary[key] = block;
    for (const auto& p : (*kept)["plots"])
      ctx.summary["plots"].push_back(p);
    ctx.results[item.name] = result_from_json((*kept)["result"]);
    return;
  }
  const Json before = ctx.summary;
  item.run(ctx);
  // What the item left in the summary: its blocks, and the plots it added.
  Json blocks = Json::object();
  for (const auto& [key, block] : ctx.summary.items())
    if (key != "plots" && (!before.contains(key) || before[key] != block))
      blocks[key] = block;
  Json plots = Json::array();
  const std::size_t n_before = before.contains("plots") ? before["plots"].size() : 0;
  for (std::size_t i = n_before; i < ctx.summary["plots"].size(); ++i)
    plots.push_back(ctx.summary["plots"][i]);
  keep_finished_unit(ctx.output_dir, unit, inputs,
                     {{"summary", std::move(blocks)},
                      {"plots", std::move(plots)},
                      {"result", result_to_json(ctx.results.at(item.name))}});
  if (output_enabled()) {
    std::error_code ec;
    std::filesystem::remove(resume_directory(ctx.output_dir) + "/" + item.name + "_state.bin", ec);
  }
}

} // namespace fiberbridge::app
