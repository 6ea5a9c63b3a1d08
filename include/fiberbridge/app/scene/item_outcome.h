#pragma once
// What a scene item makes (docs/design.md section 4, "Items return what they made"): the typed
// values it hands on to later items, and its report, the summary blocks and plots it shows the
// reader. An item returns one ItemOutcome and changes nothing else; only the scene runner merges
// outcomes into the scene's state (merge_outcome, run/scene_runner.cc), and resume and the MPI
// task hand-out keep and send the outcome a simulation item returned (run/outcome_archive.h).
#include "fiberbridge/core/summary.h"
#include "fiberbridge/law/traction_law.h"
#include "fiberbridge/result/rcurve.h"
#include "fiberbridge/specimen/specimen.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fiberbridge::analysis {
struct TestRecord;        // analysis/test_record.h
struct RDeltaData;        // analysis/rdelta_data.h
struct ExtractionOutcome; // analysis/law_extraction.h
} // namespace fiberbridge::analysis
namespace fiberbridge::identify {
struct Identification; // identify/identify.h
}
namespace fiberbridge::app {

struct ReduceOutcome; // step_outcomes.h

/// Where the law a simulation uses comes from.
enum class LawSource { section, fit, identify };
/// The name summary.json gives a law source ("Cohesive law section", "fit", "identify").
const char* law_source_name(LawSource source);

/// A crack law with its crack-tip toughness and its source.
struct CrackLaw {
  law::TractionLawPtr law;
  double j_tip = 0; ///< [J/m^2]
  LawSource source = LawSource::section;
};

/// Where the specimen and material a simulation uses come from.
enum class SpecimenSource { section, identify };
/// "Specimen and Material sections" or "identify".
const char* specimen_source_name(SpecimenSource source);

/// The specimen and its material with their source.
struct SpecimenSetup {
  specimen::Specimen specimen;
  specimen::Material material;
  SpecimenSource source = SpecimenSource::section;
};

/// What an item shows the reader: its summary.json blocks by key, in the order it made them, and
/// the PNGs it drew (summary.json's "plots", in run order). Its files are in the output directory
/// and named in its blocks.
struct ItemReport {
  Json blocks = Json::object();
  std::vector<std::string> plots;
  /// The block `key` (made empty on first use), as summary["key"] was.
  Json& operator[](const std::string& key) { return blocks[key]; }
  /// Another report's blocks and plots after this one's (an item that runs another's work, fit
  /// running extract).
  void append(ItemReport other);
};

/// What an item makes. The hand-overs are empty unless the item made them; the scene runner sets
/// each one it finds in the scene's context (scene_context.h says who reads which).
struct ItemOutcome {
  std::shared_ptr<const std::vector<analysis::TestRecord>> records;
  std::shared_ptr<const ReduceOutcome> reduced;
  std::shared_ptr<const analysis::RDeltaData> rdelta_root;
  std::shared_ptr<const analysis::ExtractionOutcome> extraction;
  std::shared_ptr<const identify::Identification> identification;
  std::optional<CrackLaw> law;
  std::optional<SpecimenSetup> specimen;
  std::optional<std::vector<std::string>> records_from_dic;
  /// A simulation item's result (its model's name is simulation->model).
  std::optional<result::SimulationResult> simulation;
  ItemReport report;

  /// Does it hand on anything beyond a simulation result and its report? (What resume and the
  /// task hand-out keep of an outcome is only those two, run/outcome_archive.h.)
  bool hands_on_analysis() const;
};

/// The report's blocks and plots added to a summary.json being built (a command's, or the
/// scene's through merge_outcome): each block set under its key, the plots appended.
void add_report_to_summary(const ItemReport& report, Json& summary);

} // namespace fiberbridge::app
