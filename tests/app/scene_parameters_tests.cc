// The scene's parameters parsed once (app/scene/scene_parameters.h): every section read into its
// struct when the scene is read, a section's error kept and thrown where an item reads it (naming
// section and key), and a study's copy with its own settings parsed anew, the scene's own
// untouched. Structurally, the items cannot reach the ParameterHandler: SceneContext holds only the
// parsed parameters, and the handler is a local of the scene reader (scene/scene_reader.cc), gone
// before any check.
#include "fiberbridge/app/scene/scene_parameters.h"
#include "fiberbridge/app/scene/scene_reader.h"
#include "fiberbridge/core/error.h"
#include "fiberbridge/core/units.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace fiberbridge;

namespace {

std::string scene_file(const std::string& name, const std::string& body) {
  const auto d = std::filesystem::temp_directory_path() / ("fb_scene_parameters_" + name);
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  const std::string path = (d / "scene.prm").string();
  std::ofstream(path) << "set Output directory = " << d.string() << "/out\nset Run = beam\n"
                      << body;
  return path;
}

} // namespace

TEST(SceneParameters, EverySectionIsParsedOnceIntoItsStruct) {
  const auto p = app::read_scene_parameters(
      scene_file("parsed", "subsection Specimen\n  set Length = 120\nend\n"),
      {"Specimen/Width=20"});
  EXPECT_EQ(p->run, std::vector<std::string>{"beam"});
  EXPECT_NE(p->output_directory.find("fb_scene_parameters_parsed/out"), std::string::npos);
  // mm in the scene, m in the struct; the --set is in.
  EXPECT_DOUBLE_EQ(p->specimen().length, 120 * units::mm);
  EXPECT_DOUBLE_EQ(p->specimen().width, 20 * units::mm);
  EXPECT_EQ(p->entry("Specimen/Length"), "120");
  EXPECT_EQ(p->entry("Specimen/Width"), "20");
  // The listing parameters_used.prm gets holds the values as set.
  EXPECT_NE(p->listing.find("set Length"), std::string::npos);
  EXPECT_THROW(p->entry("Specimen/No such key"), std::out_of_range);
}

TEST(SceneParameters, ASectionErrorIsThrownWhereTheSectionIsReadNamingSectionAndKey) {
  // Reading the scene succeeds: no item of the run needs to read this law section (a scene with
  // fit or identify never does), as when each item parsed its sections itself.
  const auto p = app::read_scene_parameters(
      scene_file("deferred", "subsection Cohesive law\n  set Type = trilinear\n"
                             "  set Points = 0.1:oops\nend\n"),
      {});
  EXPECT_DOUBLE_EQ(p->specimen().length, specimen::Specimen{}.length);
  for (int twice = 0; twice < 2; ++twice) {
    try {
      p->law();
      FAIL() << "a bad Cohesive law/Points was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("Cohesive law/Points"), std::string::npos) << e.what();
    }
  }
}

TEST(SceneParameters, ACopyWithSettingsIsParsedAnewAndLeavesTheSceneAlone) {
  const auto p = app::read_scene_parameters(
      scene_file("copy", "subsection Specimen\n  set Length = 120\nend\n"), {"Specimen/Width=20"});
  const auto q = app::scene_parameters_with(*p, {"Specimen/Length=200"}, "Study/Beam ladder");
  EXPECT_DOUBLE_EQ(q->specimen().length, 200 * units::mm);
  EXPECT_DOUBLE_EQ(q->specimen().width, 20 * units::mm); // the scene's --set holds in the copy
  EXPECT_DOUBLE_EQ(p->specimen().length, 120 * units::mm);
  EXPECT_EQ(q->entry("Specimen/Length"), "200");
  try {
    app::scene_parameters_with(*p, {"Specimen/Lenght=200"}, "Study/Beam ladder");
    FAIL() << "a misspelt key was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("Study/Beam ladder 'Specimen/Lenght=200'", 0), 0u)
        << e.what();
  }
}
