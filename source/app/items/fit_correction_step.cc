// The fit corrected by simulation as a step of the scene's `fit` (fit_correction_step.h).
#include "fiberbridge/app/items/fit_correction_step.h"

#include "fiberbridge/analysis/record_reduction.h"
#include "fiberbridge/app/scene/models.h"
#include "fiberbridge/app/scene/step_outcomes.h"
#include "fiberbridge/beam/dcb_beam.h"
#include "fiberbridge/identify/forward_model.h"

#include "fiberbridge/core/error.h"

#include <cmath>
#include <memory>
#include <string>

namespace fiberbridge::app {

identify::ForwardModel correction_forward_model(const SceneContext& ctx, bool end_effect) {
  const std::string mode = fit_correction_mode(ctx);
  const SimulationModel* fem = built_model("fem");
  const bool fem_built = fem && fem->identify_forward;
  // auto: the beam (cheaper, and its corrected J_tip is the less biased on the virtual tests of
  // the Table 1 laws), but the FEM where the record's R falls at its end: that is the specimen's
  // far end, which the beam does not hold and the FEM does (docs/verification.md, "The
  // specimen's far end in the chain").
  const bool use_fem = mode == "fem" || (mode == "auto" && end_effect && fem_built);
  if (!use_fem)
    return identify::beam_forward_model(ctx.parameters().section<beam::BeamParameters>("Beam"));
  // The FEM through the model registry (the app's adapter, items/fem_forward_model.cc): the
  // scene's FEM section, each run on MPI_COMM_SELF, writing nothing.
  if (!fem_built)
    throw InputError(ctx.scene_file + ": Fit/Model correction = fem needs a build with the FEM "
                                      "(FIBERBRIDGE_MODELS); use beam");
  return fem->identify_forward(ctx);
}

namespace {

/// The reduce options of each measured record for its simulated twin: the chain's own, with the
/// direct-energy windows the record chose (analysis::reduce_with_windows_of). The chain must be
/// one statistic on the records and on their simulations; its data-chosen windows are wider on
/// a noisy record than on a clean simulation, and that alone moved the corrected delta_c 4 %
/// on a virtual test (docs/verification.md, "The correction's records reduced with the
/// measured windows").
std::vector<analysis::ReduceOptions>
reduce_options_of(const std::vector<analysis::ReducedRecord>& measured,
                  const analysis::RecordChainOptions& chain) {
  std::vector<analysis::ReduceOptions> out;
  for (const auto& r : measured) {
    analysis::ReduceOptions o = chain.reduce;
    analysis::reduce_with_windows_of(r, o);
    out.push_back(std::move(o));
  }
  return out;
}

} // namespace

identify::ChainCorrection correct_fit_by_simulation(const SceneContext& ctx,
                                                    const analysis::ExtractionOutcome& extraction,
                                                    const analysis::FitOptions& fit_options,
                                                    const analysis::TrilinearFit& fit,
                                                    const identify::ChainCorrectionSettings& s) {
  const analysis::RecordChainOptions chain_options = ctx.record_chain();
  // The Data section as extract read it; only its data are replaced by the simulated records'.
  const auto& data = ctx.parameters().section<analysis::ExtractionOptions>("Data");
  const auto& records = ctx.reduced->records;
  // The windows reduce chose on the records (ctx.reduced->reduced, one per record, same order).
  const std::vector<analysis::ReduceOptions> reduce =
      reduce_options_of(ctx.reduced->reduced, chain_options);
  const identify::MeasuringChain chain = [&](const std::vector<analysis::TestRecord>& sims) {
    std::vector<analysis::ReducedRecord> reduced;
    for (std::size_t i = 0; i < sims.size(); ++i)
      reduced.push_back(analysis::reduce_record(sims[i], chain_options.specimen, reduce[i]));
    analysis::ExtractionOptions o = data;
    o.data_file = "the records simulated by the fit's correction";
    o.data =
        std::make_shared<const analysis::RDeltaData>(analysis::to_rdelta(reduced, o.data_file));
    const analysis::ExtractionOutcome e = analysis::extract_law(o);
    return identify::ChainEstimate{analysis::fit_extracted_law(e, fit_options).law, e.steady.j_tip};
  };
  const SpecimenSetup setup = ctx.specimen_setup();
  const identify::ForwardModel model = correction_forward_model(ctx, extraction.steady.end_effect);
  return identify::correct_chain(
      records, std::vector<specimen::Specimen>(records.size(), setup.specimen), setup.material,
      {fit.law, extraction.steady.j_tip}, chain, model, s);
}

std::string fit_correction_mode(const SceneContext& ctx) {
  return ctx.parameters().entry("Fit/Model correction");
}

identify::ChainCorrectionSettings fit_correction_settings(const SceneContext& ctx) {
  // Validated by the Fit section's patterns when the scene was read.
  identify::ChainCorrectionSettings s;
  s.max_iterations = std::stoi(ctx.parameters().entry("Fit/Correction iterations"));
  s.tolerance = std::stod(ctx.parameters().entry("Fit/Correction tolerance"));
  return s;
}

std::function<analysis::LawCorrection(const std::vector<const analysis::CampaignSpecimen*>&,
                                      const law::TrilinearParameters&, double)>
group_law_correction(const SceneContext& ctx, const analysis::CampaignOptions& options) {
  if (fit_correction_mode(ctx) == "none")
    return {};
  const identify::ChainCorrectionSettings settings = fit_correction_settings(ctx);
  const specimen::Material material = ctx.material();
  const identify::ForwardModel model = correction_forward_model(ctx);
  analysis::CampaignOptions plain = options;
  plain.correct_law = {};
  return [settings, material, model,
          plain](const std::vector<const analysis::CampaignSpecimen*>& members,
                 const law::TrilinearParameters& law, double j_tip) {
    std::vector<analysis::TestRecord> records;
    std::vector<specimen::Specimen> specimens;
    std::vector<analysis::ReduceOptions> reduce;
    for (const auto* m : members) {
      records.push_back(*m->record);
      // A campaign specimen keeps its curve, not its reduction: reduced once more, per group.
      reduce.push_back(
          reduce_options_of(
              {analysis::reduce_record(*m->record, m->chain.specimen, m->chain.reduce)}, m->chain)
              .front());
      // a0: the record's first crack reading (correct_chain), else the row's or the scene's a0
      // for records without readings, as the reduction took it.
      specimen::Specimen sp = m->chain.specimen;
      if (!std::isfinite(sp.initial_crack))
        sp.initial_crack = m->chain.reduce.initial_crack_without_readings;
      specimens.push_back(sp);
    }
    // The group's chain on simulated records: each reduced as its row's record was, then the
    // group's own average, steady state, Eq. 6 and fit (analysis::estimate_group).
    const identify::MeasuringChain chain = [&](const std::vector<analysis::TestRecord>& sims) {
      std::vector<analysis::CampaignSpecimen> simulated;
      std::vector<std::size_t> all;
      for (std::size_t i = 0; i < sims.size(); ++i) {
        analysis::CampaignSpecimen c = *members[i];
        const analysis::ReducedRecord rr =
            analysis::reduce_record(sims[i], c.chain.specimen, reduce[i]);
        c.curve = analysis::to_rdelta({rr}, c.row.file).replicates.front();
        simulated.push_back(std::move(c));
        all.push_back(i);
      }
      const analysis::GroupEstimate e = analysis::estimate_group(simulated, all, plain, false);
      if (!e.ok || !e.has_law)
        throw ComputationError("the group's chain: " + e.failure);
      return identify::ChainEstimate{e.tri, e.j_tip};
    };
    const identify::ChainCorrection c =
        identify::correct_chain(records, specimens, material, {law, j_tip}, chain, model, settings);
    analysis::LawCorrection out;
    out.converged = c.converged;
    out.law = c.corrected.law;
    out.j_tip = c.corrected.j_tip;
    out.simulations = static_cast<int>(c.steps.size());
    out.notes = c.notes;
    return out;
  };
}

} // namespace fiberbridge::app
