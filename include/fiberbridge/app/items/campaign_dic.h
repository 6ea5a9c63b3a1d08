#pragma once
// DIC sets in a campaign's manifest (issue 33 item 1; docs/design.md section 1, "DIC sets in the
// manifest"): a row whose file is a folder holds one specimen's DIC frames and its testing
// machine's record. The frames are the files DIC/Frames names inside that folder, the machine
// record the one Test/Files names there (read with Test/Columns); they go through the DIC step
// with the DIC section's settings (dic_step.h: tip rule, virtual extensometer, matched in time),
// a = the row's a0_mm (else Specimen/Initial crack) + the tip's shift, and the record it makes
// (dic_record.csv's columns) is read as `reduce` reads one after `dic`.
#include "fiberbridge/analysis/campaign.h"
#include "fiberbridge/app/items/dic_step.h"
#include "fiberbridge/app/scene/dic_section.h"
#include "fiberbridge/app/scene/test_section.h"

#include <string>

namespace fiberbridge::app {

struct CampaignDicSets {
  DicSection dic;
  TestSection test;
  /// The scene's one chain's read options (SceneContext::record_chain): the machine record is
  /// read with them, and the record the DIC step makes with them less the column map.
  analysis::RecordReadOptions read;
  double scene_initial_crack = 0; ///< [m] Specimen/Initial crack
};

/// The set's test record; `record_text` receives the dic_record.csv text it was read from (the
/// campaign writes it beside its tables). InputError naming the manifest line for a set without
/// DIC/Frames or Test/Files, or a missing frame or machine record.
analysis::TestRecord read_campaign_dic_set(const analysis::CampaignRow& row,
                                           const CampaignDicSets& sets, std::string& record_text);

} // namespace fiberbridge::app
