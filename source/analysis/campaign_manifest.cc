// The campaign's manifest and its specimens as read (campaign.h).
#include "fiberbridge/analysis/campaign.h"
#include "fiberbridge/core/csv.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/format.h"
#include "fiberbridge/core/units.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <tuple>
#include <utility>

namespace fiberbridge::analysis {

namespace {

/// Beyond this, a cycle count is a slip (moisture cycles are counted in tens).
constexpr double max_cycles = 1e6;
/// File names hold "campaign_degradation_" + this + "_c<cycles>.csv": 255 bytes is the limit.
constexpr std::size_t max_material_file_part = 120;

/// An optional positive cell: NaN when empty.
double optional_positive(const CsvTable& t, const std::string& column, std::size_t row, double unit,
                         const std::string& where) {
  if (!t.has_column(column))
    return NAN;
  const std::string v = trim_blanks(t.text(column)[row]);
  if (v.empty())
    return NAN;
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (end == v.c_str() || *end != '\0' || !std::isfinite(x) || !(x > 0))
    throw InputError(where + ": column " + column +
                     ": expected a positive number or an empty "
                     "cell, got '" +
                     v + "'");
  return x * unit;
}

/// Two materials whose names become the same file-name part ("PF 1" and "PF_1", "X/Y" and
/// "X:Y") would overwrite each other's law and degradation files; a name too long for a file
/// name would fail only after every group ran (issue 42). Both refused before anything runs.
void refuse_colliding_materials(const CampaignManifest& m) {
  std::map<std::string, const CampaignRow*> by_part;
  for (const auto& r : m.rows) {
    const std::string part = campaign_file_part(r.material);
    if (part.size() > max_material_file_part)
      throw InputError(r.where() + ": material name of " + std::to_string(r.material.size()) +
                       " characters; expected at most " + std::to_string(max_material_file_part) +
                       " (it is part of file names)");
    const auto [it, fresh] = by_part.emplace(part, &r);
    if (!fresh && it->second->material != r.material)
      throw InputError(r.where() + ": material '" + r.material + "' and '" + it->second->material +
                       "' (" + it->second->where() + ") become the same file names ('" + part +
                       "'; letters, digits, '-' and '_' are kept, anything else is '_'): rename "
                       "one of them");
  }
}

} // namespace

CampaignManifest read_campaign_manifest(const std::string& path) {
  const CsvTable t = CsvTable::read(path);
  for (const char* c : {"file", "material", "cycles", "specimen"})
    if (!t.has_column(c))
      throw InputError(path +
                       ": manifest needs the columns file, material, cycles, specimen "
                       "(optional delta_c_mm, j_tip_J_m2, width_mm, arm_thickness_mm, a0_mm, "
                       "length_mm); "
                       "column '" +
                       std::string(c) + "' is missing");
  if (t.n_rows() == 0)
    throw InputError(path + ": the manifest lists no specimen");
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  CampaignManifest m;
  m.source = path;
  std::map<std::tuple<std::string, double, std::string>, std::size_t> seen;
  std::map<std::string, std::size_t> seen_file;
  for (std::size_t i = 0; i < t.n_rows(); ++i) {
    CampaignRow r;
    r.manifest = path;
    r.line = t.line_of_row(i);
    const std::string where = r.where();
    r.file_as_written = trim_blanks(t.text("file")[i]);
    r.material = trim_blanks(t.text("material")[i]);
    r.specimen = trim_blanks(t.text("specimen")[i]);
    if (r.file_as_written.empty() || r.material.empty() || r.specimen.empty())
      throw InputError(where + ": file, material and specimen must not be empty");
    const std::string c = trim_blanks(t.text("cycles")[i]);
    char* end = nullptr;
    r.cycles = std::strtod(c.c_str(), &end);
    // Moisture cycles are counted in tens; far beyond, the degradation fit's sums overflow
    // (1e300 gave a slope of 0 without a word, issue 42).
    if (c.empty() || *end != '\0' || !std::isfinite(r.cycles) || r.cycles < 0 ||
        r.cycles > max_cycles)
      throw InputError(where + ": cycles: expected a number of moisture cycles from 0 to " +
                       fmt(max_cycles) + ", got '" + c + "'");
    const std::filesystem::path f(r.file_as_written);
    r.file = (f.is_absolute() ? f : folder / f).lexically_normal().string();
    if (!std::filesystem::is_regular_file(r.file) && !std::filesystem::is_directory(r.file))
      throw InputError(where + ": file '" + r.file_as_written + "' not found (looked for " +
                       r.file + "; paths are relative to the manifest's folder)");
    r.delta_c = optional_positive(t, "delta_c_mm", i, units::mm, where);
    r.j_tip = optional_positive(t, "j_tip_J_m2", i, 1.0, where);
    r.width = optional_positive(t, "width_mm", i, units::mm, where);
    r.arm_thickness = optional_positive(t, "arm_thickness_mm", i, units::mm, where);
    r.initial_crack = optional_positive(t, "a0_mm", i, units::mm, where);
    r.length = optional_positive(t, "length_mm", i, units::mm, where);
    if (std::isfinite(r.initial_crack) && std::isfinite(r.length) && !(r.initial_crack < r.length))
      throw InputError(where + ": a0_mm must be shorter than length_mm");
    const auto key = std::make_tuple(r.material, r.cycles, r.specimen);
    if (const auto it = seen.find(key); it != seen.end())
      throw InputError(where + ": specimen '" + r.specimen + "' of " + r.material + " at " + c +
                       " cycles is listed twice (first at line " + std::to_string(it->second) +
                       ")");
    seen.emplace(key, r.line);
    const std::string canonical = std::filesystem::weakly_canonical(r.file).string();
    if (const auto it = seen_file.find(canonical); it != seen_file.end())
      throw InputError(where + ": file '" + r.file_as_written +
                       "' is listed twice (first at line " + std::to_string(it->second) +
                       "): one file is one specimen");
    seen_file.emplace(canonical, r.line);
    m.rows.push_back(r);
  }
  refuse_colliding_materials(m);
  return m;
}

std::string campaign_file_part(const std::string& material) {
  return file_name_part(material);
}

const char* to_string(SpecimenInput k) {
  return k == SpecimenInput::rdelta       ? "R(delta) table"
         : k == SpecimenInput::raw_record ? "raw test record"
                                          : "DIC set";
}

SpecimenInput classify_specimen_file(const std::string& path) {
  if (std::filesystem::is_directory(path))
    return SpecimenInput::dic_set;
  const CsvTable t = CsvTable::read(path);
  return t.has_column("delta_mm") && t.has_column("R_J_m2") ? SpecimenInput::rdelta
                                                            : SpecimenInput::raw_record;
}

const char* to_string(RaMethod m) {
  static const char* names[n_ra_methods] = {"energy", "MBT", "CC", "MCC", "CBBM"};
  return names[static_cast<std::size_t>(m)];
}

RaMethod parse_ra_method(const std::string& word, const std::string& where) {
  for (std::size_t k = 0; k < n_ra_methods; ++k)
    if (word == to_string(static_cast<RaMethod>(k)))
      return static_cast<RaMethod>(k);
  throw InputError(where + ": expected energy, MBT, CC, MCC or CBBM, got '" + word + "'");
}

namespace {

/// An R(a)-only specimen: every estimator's values, the chosen one's as its own, and a note when
/// the estimators' plateaus disagree beyond the direct-energy band of the plateau mean (the one
/// band the reduction has: the beam-theory estimators come with none).
void take_ra_estimates(CampaignSpecimen& s, const ReducedRecord& rr, RaMethod estimator,
                       double plateau_fraction) {
  s.methods = {rr.energy, rr.mbt, rr.cc, rr.mcc, rr.cbbm};
  const MethodSummary& chosen = s.methods[static_cast<std::size_t>(estimator)];
  s.initiation = chosen.initiation;
  s.plateau = chosen.plateau;
  s.notes.push_back(std::string("no delta_root in the record: R(a) only (initiation and plateau "
                                "by ") +
                    to_string(estimator) + "), no law");
  if (!std::isfinite(chosen.plateau))
    s.notes.push_back(std::string("the record gives no ") + to_string(estimator) + " plateau (" +
                      (rr.crack == "equivalent" ? "no measured crack readings"
                                                : "its fits failed; see the reduction notes") +
                      "): the specimen has no G_ss; name another Campaign/R(a) estimator");
  if (!rr.da.empty() && rr.R_energy_lo.size() == rr.da.size()) {
    const double from = (1 - plateau_fraction) * rr.da.back();
    double sum = 0;
    int n = 0;
    for (std::size_t i = 0; i < rr.da.size(); ++i)
      if (rr.da[i] >= from && std::isfinite(rr.R_energy_hi[i]) &&
          std::isfinite(rr.R_energy_lo[i])) {
        sum += (rr.R_energy_hi[i] - rr.R_energy_lo[i]) / 2;
        ++n;
      }
    // The band is pointwise; the plateau is a mean over its extent, whose slope errors are
    // independent only a window apart: the mean's band is the pointwise one over sqrt(extent /
    // window) (at least one window).
    const double extent = plateau_fraction * rr.da.back();
    const double independent =
        std::isfinite(rr.window) && rr.window > 0 ? std::max(1.0, extent / rr.window) : 1.0;
    if (n > 0)
      s.plateau_band = sum / n / std::sqrt(independent);
  }
  if (!std::isfinite(chosen.plateau) || !std::isfinite(s.plateau_band))
    return;
  std::string values;
  bool apart = false;
  for (std::size_t k = 0; k < n_ra_methods; ++k) {
    const double p = s.methods[k].plateau;
    if (!std::isfinite(p))
      continue;
    values += std::string(values.empty() ? "" : ", ") + to_string(static_cast<RaMethod>(k)) + " " +
              fmt(p);
    apart = apart || std::abs(p - chosen.plateau) > s.plateau_band;
  }
  if (apart)
    s.notes.push_back("the R(a) estimators' plateaus disagree beyond the direct-energy band of "
                      "the plateau (+-" +
                      fmt(s.plateau_band) + " J/m^2): " + values + " J/m^2; the group takes " +
                      to_string(estimator));
}

} // namespace

CampaignSpecimen load_campaign_specimen(const CampaignRow& row, const RawRecordOptions& raw) {
  CampaignSpecimen s;
  s.row = row;
  const std::string where = row.where();
  try {
    s.input = classify_specimen_file(row.file);
    if (s.input == SpecimenInput::rdelta) {
      const RDeltaData d = read_rdelta_csv(row.file);
      if (d.replicates.size() != 1)
        throw InputError(row.file + " holds " + std::to_string(d.replicates.size()) +
                         " replicates; a manifest row is one specimen (split the file or list "
                         "one row per replicate file)");
      s.curve = d.replicates.front();
      s.has_rdelta = true;
    } else {
      std::vector<TestRecord> records;
      if (s.input == SpecimenInput::dic_set) {
        if (!raw.dic_set)
          throw InputError("'" + row.file_as_written +
                           "' is a folder (a DIC set), which this reader cannot analyse");
        records.push_back(raw.dic_set(row));
      } else {
        records = read_test_records(row.file, raw.read);
      }
      if (records.size() != 1)
        throw InputError(row.file + " holds " + std::to_string(records.size()) +
                         " records; a manifest row is one specimen");
      const RecordChainOptions own =
          with_specimen_overrides(raw, row.width, row.arm_thickness, row.length, row.initial_crack);
      const ReducedRecord rr = reduce_record(records.front(), own.specimen, own.reduce);
      if (!rr.delta_root.empty()) {
        s.curve = to_rdelta({rr}, row.file).replicates.front();
        s.has_rdelta = true;
        s.record = std::make_shared<const TestRecord>(records.front());
        s.chain = own;
      } else {
        take_ra_estimates(s, rr, raw.estimator, own.reduce.plateau_fraction);
      }
    }
  } catch (const InputError& e) {
    throw InputError(where + ": " + e.what());
  } catch (const ComputationError& e) {
    throw ComputationError(where + ": " + e.what());
  }
  return s;
}

} // namespace fiberbridge::analysis
