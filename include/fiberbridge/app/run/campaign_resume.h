#pragma once
// The campaign's units of work for `--resume` (issue 33 item 6; docs/design.md section 1,
// "Resuming a campaign per group"): each group's bootstrap and each group's Fig. 10 simulation,
// kept as they finish in the output directory's resume/ folder (core/binary_archive.h: every
// double bit for bit), tied to the scene's parameters and to the group's specimens (the manifest
// rows and a hash of each file's bytes, or of a DIC set's files). A resumed campaign restores the
// kept groups and runs the others; its tables equal a straight run's byte for byte.
#include "fiberbridge/analysis/campaign_run.h"
#include "fiberbridge/app/run/resume_store.h"
#include "fiberbridge/app/scene/step_outcomes.h"

#include <string>
#include <vector>

namespace fiberbridge::app {

/// The scene's parameters, the manifest's path as resolved (the group's notes name it) and, per
/// member of the group, its manifest row (material, cycles,
/// specimen, the per-row values) and a hash of its file's bytes (a DIC set: of every file under
/// its folder, with their names).
Fingerprint campaign_group_inputs(const Fingerprint& scene, const analysis::CampaignGroup& group,
                                  const std::vector<analysis::CampaignSpecimen>& specimens);

/// The bootstrap part of a group (samples, failed samples, intervals, the law's band, notes)
/// as bytes and back (the point estimate is not in them: it is recomputed, deterministic).
std::string campaign_group_bytes(const analysis::CampaignGroup& group);
void campaign_group_from_bytes(const std::string& bytes, const std::string& source,
                               analysis::CampaignGroup& group);

/// resume/campaign_group_<material>_c<cycles>.bin
std::string campaign_group_record(const std::string& output_dir,
                                  const analysis::CampaignGroup& group);

/// With `resume` and a record of this group: its bootstrap part into `group` (true). Throws
/// InputError naming the record and the first input that differs, as find_finished_unit does.
bool restore_campaign_group(const std::string& output_dir, bool resume, const Fingerprint& inputs,
                            analysis::CampaignGroup& group);
/// Keeps a finished group (atomically; a rank writes it when it owns its files).
void keep_campaign_group(const std::string& output_dir, const Fingerprint& inputs,
                         const analysis::CampaignGroup& group);

/// A group's simulation as bytes and back (every field of GroupSimulation).
std::string campaign_simulation_bytes(const GroupSimulation& s);
void campaign_simulation_from_bytes(const std::string& bytes, const std::string& source,
                                    GroupSimulation& s);
/// The same for a group's Fig. 10 simulation: resume/campaign_fig10_<material>_c<cycles>.bin.
bool restore_campaign_simulation(const std::string& output_dir, bool resume,
                                 const Fingerprint& inputs, GroupSimulation& s);
void keep_campaign_simulation(const std::string& output_dir, const Fingerprint& inputs,
                              const GroupSimulation& s);

} // namespace fiberbridge::app
