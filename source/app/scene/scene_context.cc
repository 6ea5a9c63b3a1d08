#include "fiberbridge/app/scene/scene_context.h"

#include "fiberbridge/app/scene/scene_reader.h"
#include "fiberbridge/app/scene/test_section.h"
#include "fiberbridge/law/law_spec.h"

#include <iostream>

namespace fiberbridge::app {

const char* law_source_name(LawSource source) {
  switch (source) {
  case LawSource::fit:
    return "fit";
  case LawSource::identify:
    return "identify";
  case LawSource::section:
    break;
  }
  return "Cohesive law section";
}

const char* specimen_source_name(SpecimenSource source) {
  return source == SpecimenSource::identify ? "identify" : "Specimen and Material sections";
}

const law::TractionLaw* SceneContext::law_known_before_run() const {
  if (handed_law || run_items.count("fit") || run_items.count("identify"))
    return nullptr;
  return law().get();
}

const CrackLaw& SceneContext::crack_law() const {
  if (handed_law)
    return *handed_law;
  if (!section_law_) {
    auto spec = parameters().law();
    if (!spec.table_file.empty())
      spec.table_file = resolve_scene_path(spec.table_file, scene_file);
    section_law_ = CrackLaw{law::make_law(spec), spec.j_tip, LawSource::section};
  }
  return *section_law_;
}

SpecimenSetup SceneContext::specimen_setup() const {
  if (handed_specimen)
    return *handed_specimen;
  return {parameters().specimen(), parameters().material(), SpecimenSource::section};
}

analysis::RecordChainOptions SceneContext::record_chain() const {
  return parameters().section<TestSection>("Test").chain_options(scene_file, specimen(),
                                                                 material());
}

void SceneContext::progress(const std::string& line) const {
  if (progress_sink)
    progress_sink(line);
  else
    std::cerr << line << '\n';
}

SceneContext SceneContext::derived(const std::string& dir, HandOn what,
                                   std::shared_ptr<const SceneParameters> parameters) const {
  SceneContext sub;
  if (parameters)
    sub.params = std::move(parameters);
  else {
    sub.params = params;
    sub.section_law_ = section_law_; // the same sections: the law built from them holds
  }
  sub.output_dir = dir;
  sub.scene_file = scene_file;
  sub.resume = resume;
  sub.progress_sink = progress_sink;
  sub.run_items = run_items;
  if (what == HandOn::everything) {
    sub.records = records;
    sub.reduced = reduced;
    sub.rdelta_root = rdelta_root;
    sub.extraction = extraction;
    sub.identification = identification;
    sub.handed_law = handed_law;
    sub.handed_specimen = handed_specimen;
  }
  return sub;
}

} // namespace fiberbridge::app
