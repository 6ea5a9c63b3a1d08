#include "fiberbridge/app/run/resume_store.h"

#include "fiberbridge/app/run/outcome_archive.h"

#include "fiberbridge/app/scene/models.h"
#include "fiberbridge/app/scene/scene_reader.h"
#include "fiberbridge/core/binary_archive.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/json_archive.h"
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
// 1: a CBOR document (<unit>.cbor); 2: the archive of core/binary_archive.h (<unit>.rec).
constexpr std::uint32_t record_version = 2;

/// Entries that steer the run but not its results.
const std::set<std::string> run_control = {"Output directory", "Run", "MPM/Threads",
                                           "MPM/Checkpoint interval"};

/// resume/<unit><extension>, the unit's name made a file name.
std::string record_path(const std::string& output_dir, std::string unit,
                        const char* extension = ".rec") {
  for (auto& c : unit)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.'))
      c = '_';
  return resume_directory(output_dir) + "/" + unit + extension;
}

} // namespace

Fingerprint scene_fingerprint(const SceneParameters& parameters) {
  Fingerprint fp;
  for (const auto& [key, value] : parameters.entries)
    if (!run_control.count(key))
      fp.emplace_back(key, value);
  return fp;
}

Fingerprint simulation_fingerprint(const SceneContext& ctx) {
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

void check_same_inputs(const std::string& path, const Fingerprint& saved,
                       const Fingerprint& inputs) {
  const std::string afresh = "; run without --resume to start afresh";
  std::map<std::string, std::string> kept(saved.begin(), saved.end());
  for (const auto& [key, value] : inputs) {
    const auto it = kept.find(key);
    if (it == kept.end())
      throw InputError(path + ": the scene changed since this work was done: " + key + " is new" +
                       afresh);
    if (it->second != value)
      throw InputError(path + ": the scene changed since this work was done: " + key + " was '" +
                       it->second + "', now '" + value + "'" + afresh);
    kept.erase(it);
  }
  if (!kept.empty())
    throw InputError(path + ": the scene changed since this work was done: " + kept.begin()->first +
                     " is gone" + afresh);
}

std::optional<BinaryReader> open_finished_unit(const std::string& output_dir, bool resume,
                                               const std::string& unit, const Fingerprint& inputs) {
  if (!resume)
    return std::nullopt;
  const std::string path = record_path(output_dir, unit);
  const std::string afresh = "; run without --resume to start afresh";
  if (!std::filesystem::exists(path)) {
    // The same rule as a record of another format version: the user decides to start afresh.
    const std::string before = record_path(output_dir, unit, ".cbor");
    if (std::filesystem::exists(before))
      throw InputError(before +
                       ": a record written by an earlier version of fiberbridge (CBOR, before "
                       "the one archive of issue 30); it cannot be restored" +
                       afresh);
    return std::nullopt;
  }
  std::optional<BinaryReader> in;
  try {
    in.emplace(read_file_bytes(path), record_format, record_version, path);
  } catch (const InputError& e) {
    throw InputError(e.what() + afresh);
  }
  if (const auto saved_unit = in->get<std::string>(); saved_unit != unit)
    throw InputError(path + ": a record of '" + saved_unit + "', not of '" + unit + "'" + afresh);
  check_same_inputs(path, in->get<Fingerprint>(), inputs);
  return in;
}

void report_restored(const std::string& unit, const std::string& path) {
  if (output_enabled())
    std::cerr << "fiberbridge: resume: " << unit << " restored from " << path << "\n";
}

BinaryWriter finished_unit_record(const std::string& unit, const Fingerprint& inputs) {
  BinaryWriter out(record_format, record_version);
  out.put(unit);
  out.put(inputs);
  return out;
}

void store_finished_unit(const std::string& output_dir, const std::string& unit,
                         const BinaryWriter& record) {
  if (!output_enabled())
    return;
  const std::string dir = resume_directory(output_dir);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec)
    throw InputError(dir + ": cannot create (" + ec.message() + ")");
  write_file_atomically(record_path(output_dir, unit), record.finish());
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
  if (auto kept = find_finished_unit<std::string>(output_dir, resume, unit, inputs))
    return std::move(*kept);
  const std::string bytes = run();
  keep_finished_unit(output_dir, unit, inputs, bytes);
  clear_resume_state(unit_dir);
  return bytes;
}

bool is_simulation_item(const std::string& item) {
  return built_model(item) != nullptr;
}

ItemOutcome run_or_restore_simulation_item(const SceneContext& ctx, const SceneItem& item) {
  const std::string unit = "item_" + item.name;
  const Fingerprint inputs = simulation_fingerprint(ctx);
  if (auto kept = find_finished_unit<ItemOutcome>(ctx.output_dir, ctx.resume, unit, inputs))
    return std::move(*kept);
  ItemOutcome outcome = item.run(ctx);
  keep_finished_unit(ctx.output_dir, unit, inputs, outcome);
  if (output_enabled()) {
    std::error_code ec;
    std::filesystem::remove(resume_directory(ctx.output_dir) + "/" + item.name + "_state.bin", ec);
  }
  return outcome;
}

} // namespace fiberbridge::app
