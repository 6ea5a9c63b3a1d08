// The campaign's units of work for --resume (campaign_resume.h): bytes by core/binary_archive.h,
// records in <output>/resume next to the other units' (resume_store.h).
#include "fiberbridge/app/run/campaign_resume.h"

#include "fiberbridge/analysis/campaign.h"
#include "fiberbridge/core/binary_archive.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/output_guard.h"
#include "fiberbridge/law/law_fingerprint.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <utility>

namespace fiberbridge::app {

namespace {

namespace fs = std::filesystem;

const char* group_magic = "fiberbridge campaign group";
const char* simulation_magic = "fiberbridge campaign simulation";
// Raise when the bytes of a group or a simulation change.
constexpr std::uint32_t group_version = 2;
constexpr std::uint32_t simulation_version = 1;

std::string hex(std::uint64_t h) {
  char b[24];
  std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(h));
  return b;
}

/// The bytes of a file, or of every regular file under a folder (a DIC set) with its relative
/// name, in name order: one hash.
std::string content_hash(const std::string& path) {
  if (!fs::is_directory(path)) {
    const std::string b = read_file_bytes(path);
    return std::to_string(b.size()) + " bytes, hash " + hex(checksum64(b.data(), b.size()));
  }
  std::vector<std::string> names;
  for (const auto& e : fs::recursive_directory_iterator(path))
    if (e.is_regular_file())
      names.push_back(fs::relative(e.path(), path).generic_string());
  std::sort(names.begin(), names.end());
  std::uint64_t h = 0;
  std::size_t bytes = 0;
  for (const auto& n : names) {
    const std::string b = read_file_bytes((fs::path(path) / n).string());
    bytes += b.size();
    h = (h * 1099511628211ULL) ^ checksum64(n.data(), n.size()) ^ checksum64(b.data(), b.size());
  }
  return std::to_string(names.size()) + " files, " + std::to_string(bytes) + " bytes, hash " +
         hex(h);
}

std::string record_path(const std::string& output_dir, const std::string& kind,
                        const std::string& material, double cycles) {
  return resume_directory(output_dir) + "/campaign_" + kind + "_" +
         analysis::group_file_stem(material, cycles) + ".bin";
}

/// Reads a record: its inputs compared with `inputs` (the first difference named, as
/// find_finished_unit does), then its payload bytes.
std::string read_record(const std::string& path, const char* magic, std::uint32_t version,
                        const Fingerprint& inputs) {
  BinaryReader in(read_file_bytes(path), magic, version, path);
  Fingerprint saved;
  in.get(saved);
  std::string payload;
  in.get(payload);
  in.expect_end();
  check_same_inputs(path, saved, inputs);
  return payload;
}

void write_record(const std::string& path, const char* magic, std::uint32_t version,
                  const Fingerprint& inputs, const std::string& payload) {
  if (!output_enabled())
    return;
  std::error_code ec;
  fs::create_directories(fs::path(path).parent_path(), ec);
  if (ec)
    throw InputError(fs::path(path).parent_path().string() + ": cannot create (" + ec.message() +
                     ")");
  BinaryWriter out(magic, version);
  out.put(inputs);
  out.put(payload);
  write_file_atomically(path, out.finish());
}

} // namespace

Fingerprint campaign_group_inputs(const Fingerprint& scene, const analysis::CampaignGroup& group,
                                  const std::vector<analysis::CampaignSpecimen>& specimens) {
  Fingerprint fp = scene;
  using law::exact_number;
  auto opt = [](double v) { return std::isfinite(v) ? exact_number(v) : std::string("-"); };
  // The manifest as resolved: the notes a group keeps name it (manifest:line).
  if (!group.members.empty())
    fp.emplace_back("campaign manifest", specimens[group.members.front()].row.manifest);
  for (std::size_t k = 0; k < group.members.size(); ++k) {
    const auto& r = specimens[group.members[k]].row;
    const std::string key = "campaign member " + std::to_string(k + 1);
    fp.emplace_back(key, r.file_as_written + " | " + r.material + " | " + exact_number(r.cycles) +
                             " | " + r.specimen + " | delta_c " + opt(r.delta_c) + " | J_tip " +
                             opt(r.j_tip) + " | B " + opt(r.width) + " | h " +
                             opt(r.arm_thickness) + " | a0 " + opt(r.initial_crack) + " | L " +
                             opt(r.length));
    fp.emplace_back(key + " content", content_hash(r.file));
  }
  return fp;
}

std::string campaign_group_bytes(const analysis::CampaignGroup& g) {
  BinaryWriter w(group_magic, group_version);
  w.put(g.samples);
  w.put(g.failed_samples);
  w.put(g.ci);
  w.put(g.law_delta);
  w.put(g.law_lo);
  w.put(g.law_hi);
  w.put(g.notes);
  const auto& c = g.correction;
  w.put(static_cast<std::uint8_t>(c.applied ? 1 : 0));
  for (double v : {c.d1, c.s1, c.d2, c.s2, c.dc, c.j_tip})
    w.put(v);
  return w.finish();
}

void campaign_group_from_bytes(const std::string& bytes, const std::string& source,
                               analysis::CampaignGroup& g) {
  BinaryReader r(bytes, group_magic, group_version, source);
  r.get(g.samples);
  r.get(g.failed_samples);
  r.get(g.ci);
  r.get(g.law_delta);
  r.get(g.law_lo);
  r.get(g.law_hi);
  r.get(g.notes);
  auto& c = g.correction;
  c.applied = r.get<std::uint8_t>() != 0;
  for (double* v : {&c.d1, &c.s1, &c.d2, &c.s2, &c.dc, &c.j_tip})
    r.get(*v);
  r.expect_end();
}

std::string campaign_group_record(const std::string& output_dir,
                                  const analysis::CampaignGroup& group) {
  return record_path(output_dir, "group", group.material, group.cycles);
}

bool restore_campaign_group(const std::string& output_dir, bool resume, const Fingerprint& inputs,
                            analysis::CampaignGroup& group) {
  const std::string path = campaign_group_record(output_dir, group);
  if (!resume || !fs::exists(path))
    return false;
  campaign_group_from_bytes(read_record(path, group_magic, group_version, inputs), path, group);
  return true;
}

void keep_campaign_group(const std::string& output_dir, const Fingerprint& inputs,
                         const analysis::CampaignGroup& group) {
  write_record(campaign_group_record(output_dir, group), group_magic, group_version, inputs,
               campaign_group_bytes(group));
}

std::string campaign_simulation_bytes(const GroupSimulation& s) {
  BinaryWriter w(simulation_magic, simulation_version);
  w.put(s.material);
  w.put(s.model);
  w.put(s.cycles);
  w.put(static_cast<std::uint8_t>(s.ran ? 1 : 0));
  w.put(s.failure);
  w.put(s.delta_root);
  w.put(s.R);
  for (double v : {s.G_ss, s.misfit_rel, s.within_scatter, s.wall_time_s, s.specimen.length,
                   s.specimen.width, s.specimen.height, s.specimen.initial_crack, s.a_start})
    w.put(v);
  w.put(s.geometry_note);
  return w.finish();
}

void campaign_simulation_from_bytes(const std::string& bytes, const std::string& source,
                                    GroupSimulation& s) {
  BinaryReader r(bytes, simulation_magic, simulation_version, source);
  r.get(s.material);
  r.get(s.model);
  r.get(s.cycles);
  s.ran = r.get<std::uint8_t>() != 0;
  r.get(s.failure);
  r.get(s.delta_root);
  r.get(s.R);
  for (double* v : {&s.G_ss, &s.misfit_rel, &s.within_scatter, &s.wall_time_s, &s.specimen.length,
                    &s.specimen.width, &s.specimen.height, &s.specimen.initial_crack, &s.a_start})
    r.get(*v);
  r.get(s.geometry_note);
  r.expect_end();
}

bool restore_campaign_simulation(const std::string& output_dir, bool resume,
                                 const Fingerprint& inputs, GroupSimulation& s) {
  const std::string path = record_path(output_dir, "fig10", s.material, s.cycles);
  if (!resume || !fs::exists(path))
    return false;
  campaign_simulation_from_bytes(read_record(path, simulation_magic, simulation_version, inputs),
                                 path, s);
  return true;
}

void keep_campaign_simulation(const std::string& output_dir, const Fingerprint& inputs,
                              const GroupSimulation& s) {
  write_record(record_path(output_dir, "fig10", s.material, s.cycles), simulation_magic,
               simulation_version, inputs, campaign_simulation_bytes(s));
}

} // namespace fiberbridge::app
