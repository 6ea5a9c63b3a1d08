#pragma once
// The files, plots and summary blocks of `identify` (item_identify.cc), apart from its computing
// (docs/design.md section 4, "Parse once and writers apart"): run_identify_item fits, then hands
// the identifications to these; check_identified_against_simulations compares, then writes here.
#include "fiberbridge/app/scene/scene_context.h"
#include "fiberbridge/identify/identify.h"

#include <string>
#include <vector>

namespace fiberbridge::app {

/// A record name as a gnuplot title (enhanced text would turn '_' into a subscript).
std::string title_of(std::string name);

/// One identification as its summary block (law, J_tip, misfits, standard errors, records).
Json identification_json(const identify::Identification& id);

/// summary["identify"]: the joint fit (fits[0]) with the modulus used, and per_record with the
/// fits of each record alone (fits[1..], one per record) when there are any.
Json identify_summary(const std::vector<identify::Identification>& fits,
                      const identify::IdentifySettings& settings, const specimen::Material& quoted,
                      const std::vector<analysis::TestRecord>& records);

/// identify_fit.csv, identify_law.csv, identify_fit_<k>.csv and the three PNGs.
void write_identification(const SceneContext& ctx, const identify::Identification& id,
                          ItemReport& report);

/// A simulation with the identified law at the record's openings.
struct SimulationAgainstRecord {
  std::string model;
  std::vector<double> load, a; ///< [N], [m] at every opening of the record
  std::size_t compared = 0;    ///< the first rows, those the simulation reached
  double load_rms_rel = 0;     ///< RMS load misfit over those rows / the record's peak load
  double final_a = 0;          ///< [m] the simulation's last crack length
};

/// identify_check_<model>.csv, summary["identify_check"], identify_check_load.png and, when
/// reduce wrote rcurve_test.csv, identify_check_R_a.png.
void write_identified_against_simulations(const SceneContext& ctx, const identify::RecordFit& rec,
                                          const std::vector<SimulationAgainstRecord>& checks,
                                          ItemReport& report);

} // namespace fiberbridge::app
