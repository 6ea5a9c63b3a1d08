// The registry of simulation models (app/scene/models.h): every built model runs through the same
// interface (declare through the scene's sections, check, run, report) on one small specimen, and
// the registry is the one list the scene's items come from.
#include "fiberbridge/app/items/campaign_simulation.h"
#include "fiberbridge/app/scene/models.h"
#include "fiberbridge/app/scene/scene_reader.h"
#include "fiberbridge/core/error.h"

#include <deal.II/base/parameter_handler.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

using namespace fiberbridge;

namespace {

std::string fresh_dir(const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() / ("fb_models_" + name);
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d.string();
}

/// A small DCB with a short linear-softening zone (J_tip 200 + J_c 100 J/m^2): every model's R
/// curve rises to J_tip + J_c within a few centimetres of growth.
std::string small_scene(const std::string& dir) {
  const std::string path = dir + "/scene.prm";
  std::ofstream(path) << "set Output directory = " << dir << "/out\n"
                      << "subsection Specimen\n  set Length = 120\n  set Height = 20\n"
                         "  set Width = 35\n  set Initial crack = 40\nend\n"
                         "subsection Cohesive law\n  set Type = linear\n  set Peak stress = 1000\n"
                         "  set Delta c = 0.2\n  set J tip = 200\nend\n";
  return path;
}

/// Settings that keep each model's run short; a model without an entry runs its defaults.
const std::map<std::string, std::vector<std::string>> quick = {
    {"fem", {"FEM/Element size=1"}},
    {"mpm", {"MPM/Cell size=2.5", "MPM/Threads=1", "MPM/Steady growth=30"}},
};

} // namespace

TEST(ModelRegistry, SceneItemsComeFromTheRegistryInCostOrder) {
  std::set<std::string> names;
  for (const auto& m : app::simulation_models()) {
    EXPECT_TRUE(names.insert(m.name).second) << m.name << " registered twice";
    EXPECT_EQ(app::find_model(m.name), &m);
    EXPECT_EQ(m.built, m.declare != nullptr && m.check != nullptr && m.run != nullptr) << m.name;
  }
  // The scene runs the built models cheapest first, after the analysis items and before compare.
  std::vector<std::string> sims;
  for (const auto& item : app::scene_items())
    if (app::built_model(item.name))
      sims.push_back(item.name);
  const auto built = app::built_models();
  ASSERT_EQ(sims.size(), built.size());
  for (std::size_t i = 0; i < built.size(); ++i) {
    EXPECT_EQ(sims[i], built[i]->name);
    if (i > 0) { // braces: EXPECT_LE is an if-else of its own (-Wdangling-else)
      EXPECT_LE(built[i - 1]->cost, built[i]->cost);
    }
  }
  // The studies run last: they run whole scenes of their own (the model study, then the chain
  // and programme studies over virtual tests).
  const auto& items = app::scene_items();
  ASSERT_GE(items.size(), 3u);
  EXPECT_EQ(items[items.size() - 3].name, "study");
  EXPECT_EQ(items[items.size() - 2].name, "chain study");
  EXPECT_EQ(items.back().name, "programme study");
}

// Each model's item file defines its entry by name (items/item_<model>.cc), compiled in every
// build: a model left out of FIBERBRIDGE_MODELS still has its card, so scenes and messages name
// it, and a built one has every function the scene, the campaign and the study call.
TEST(ModelRegistry, EveryModelHasItsCardAndEveryBuiltOneItsFunctions) {
  ASSERT_FALSE(app::simulation_models().empty());
  int identify_own = 0;
  for (const auto& m : app::simulation_models()) {
    ASSERT_NE(m.name, nullptr);
    ASSERT_NE(m.section, nullptr) << m.name;
    EXPECT_FALSE(std::string(m.name).empty());
    EXPECT_FALSE(std::string(m.section).empty()) << m.name;
    EXPECT_FALSE(std::string(m.ladder_doc).empty()) << m.name;
    EXPECT_FALSE(std::string(m.target_key).empty()) << m.name;
    EXPECT_GT(m.cost, 0) << m.name;
    identify_own += m.identify_builtin;
    if (m.built) {
      EXPECT_NE(m.parse, nullptr) << m.name;
      EXPECT_NE(m.simulate, nullptr) << m.name;
    } else {
      EXPECT_EQ(m.declare, nullptr) << m.name;
      EXPECT_EQ(m.simulate, nullptr) << m.name;
    }
  }
  // identify has one model of its own (the beam); the others offer identify_forward.
  EXPECT_EQ(identify_own, 1);
  // The campaign's Fig. 10 offers the finite-element models first, then the others cheapest first.
  const auto offered = app::campaign_simulation_models();
  bool past_fe = false;
  double last_cost = 0;
  for (const auto& name : offered) {
    const app::SimulationModel* m = app::built_model(name);
    ASSERT_NE(m, nullptr) << name;
    if (m->finite_elements) {
      EXPECT_FALSE(past_fe) << name << " after a model that is not finite elements";
      continue;
    }
    if (past_fe) { // braces: EXPECT_LE is an if-else of its own (-Wdangling-else)
      EXPECT_LE(last_cost, m->cost) << name;
    }
    past_fe = true;
    last_cost = m->cost;
  }
}

TEST(ModelRegistry, EveryBuiltModelRunsThroughTheSameInterface) {
  if (app::built_models().empty())
    GTEST_SKIP() << "no simulation model built (FIBERBRIDGE_MODELS)";
  for (const app::SimulationModel* m : app::built_models()) {
    SCOPED_TRACE(m->name);
    const std::string dir = fresh_dir(m->name);
    std::vector<std::string> sets = {std::string("Run=") + m->name};
    if (quick.count(m->name))
      for (const auto& s : quick.at(m->name))
        sets.push_back(s);
    app::SceneContext ctx;
    ctx.params = app::read_scene_parameters(small_scene(dir), sets);
    ASSERT_EQ(ctx.parameters().run, std::vector<std::string>{m->name});
    ctx.scene_file = dir + "/scene.prm";
    ctx.run_items = {m->name};
    ctx.output_dir = dir + "/out";
    std::filesystem::create_directories(ctx.output_dir);
    m->check(ctx);
    // The model's run returns what it made and leaves the context as it was (item_outcome.h).
    const app::ItemOutcome outcome = m->run(ctx);
    EXPECT_TRUE(ctx.results.empty());
    EXPECT_FALSE(outcome.hands_on_analysis());
    ASSERT_TRUE(outcome.simulation.has_value());
    const auto& r = *outcome.simulation;
    EXPECT_EQ(r.model, m->name);
    ASSERT_FALSE(r.rcurve.empty());
    EXPECT_TRUE(std::filesystem::exists(ctx.out(std::string("rcurve_") + m->name + ".csv")));
    const Json& blocks = outcome.report.blocks;
    ASSERT_TRUE(blocks.contains(m->name));
    EXPECT_EQ(blocks[m->name]["law_source"], "Cohesive law section");
    // Eq. 2 at steady state: G_ss = J_tip + J_c = 300 J/m^2 (the mean R_J after the notch root
    // moved when the run stops before its plateau rule is met: the MPM's 2.5 mm cells read 296
    // here). 5 % is the models' plateau tolerance (Beam/MPM/FEM Plateau tolerance, 0.05 or less)
    // and far below what a wrong law, J_tip or specimen in the interface would give (J_tip alone
    // is a third less).
    ASSERT_TRUE(std::isfinite(r.G_ss)) << blocks[m->name]["notes"];
    EXPECT_NEAR(r.G_ss, 300.0, 0.05 * 300.0) << blocks[m->name]["notes"];
  }
}
