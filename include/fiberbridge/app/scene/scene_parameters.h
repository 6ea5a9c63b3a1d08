#pragma once
// A scene's parameters, parsed once (docs/design.md section 4, "Parse once and writers apart"):
// the scene reader (scene.cc) declares every section in a dealii::ParameterHandler, parses the
// file and the --set settings, and then parses every section into its typed struct (the step-44
// section structs of section.h) held here. The handler ends with the reading: the items' checks
// and runs see only this immutable value (SceneContext::parameters()), so no item can read a key
// the parse did not validate, nor write one back.
//
// The sections are held by name, each as the struct its parse made: the shared ones (Cohesive
// law, Specimen, Material) have their accessors here, an item's own section struct stays
// private to the item's file (it parses and reads it there, section<T>(name)). A section whose
// parse threw keeps the error and throws it again where an item reads the section, so a scene
// fails with the same InputError (naming section and key) at the same check as when each item
// parsed its section itself: a bad section no item of the run reads stays harmless.
#include "fiberbridge/law/law_spec.h"
#include "fiberbridge/specimen/specimen.h"

#include <any>
#include <exception>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace fiberbridge::app {

class SceneParameters {
public:
  /// The scene file and the run's --set settings, in order: what a copy with overrides reads
  /// again (with_settings, scene.h).
  std::string scene_file;
  std::vector<std::string> overrides;
  /// false: no file, the defaults with `overrides` (read_scene_parameters_from_settings); then
  /// scene_file names the caller.
  bool from_file = true;
  std::string output_directory; ///< "Output directory"
  std::vector<std::string> run; ///< the items of "Run", in the scene's order
  /// Every entry as deal.II prints it (ShortPRM): parameters_used.prm.
  std::string listing;
  /// Every entry as "Section/Key" and its value as set, in the listing's order (the resume
  /// fingerprint; a raw value an item reads without the section's validation, entry()).
  std::vector<std::pair<std::string, std::string>> entries;

  /// The value of "Section/Sub/Key" as set (InputError-free: std::out_of_range when no such key,
  /// a programming error).
  const std::string& entry(const std::string& path) const {
    for (const auto& [key, value] : entries)
      if (key == path)
        return value;
    throw std::out_of_range("SceneParameters: no entry " + path);
  }

  /// The section `name` as parsed into `Section`; throws again the error its parse threw.
  template <class Section>
  const Section& section(const std::string& name) const {
    const auto it = sections_.find(name);
    if (it == sections_.end())
      throw std::logic_error("SceneParameters: section '" + name + "' was not parsed");
    if (it->second.error)
      std::rethrow_exception(it->second.error);
    return std::any_cast<const Section&>(it->second.value);
  }

  const law::LawSpec& law() const { return section<law::LawSpec>("Cohesive law"); }
  const specimen::Specimen& specimen() const { return section<specimen::Specimen>("Specimen"); }
  const specimen::Material& material() const { return section<specimen::Material>("Material"); }

  /// For the parse (parse_into, section.h): a section's struct, or the error its parse threw.
  void store(const std::string& name, std::any value) { sections_[name] = {std::move(value), {}}; }
  void store_error(const std::string& name, std::exception_ptr error) {
    sections_[name] = {{}, std::move(error)};
  }

private:
  struct Parsed {
    std::any value;
    std::exception_ptr error;
  };
  std::map<std::string, Parsed> sections_;
};

} // namespace fiberbridge::app
