#include "fiberbridge/app/scene_context.h"

#include "fiberbridge/app/scene.h"
#include "fiberbridge/app/section.h"
#include "fiberbridge/app/shared_sections.h"
#include "fiberbridge/law/law_spec.h"

namespace fiberbridge::app {

const law::TractionLaw* SceneContext::law_known_before_run() {
  if (fitted_law || run_items.count("fit") || run_items.count("identify"))
    return nullptr;
  return law().get();
}

law::TractionLawPtr SceneContext::law() {
  if (fitted_law)
    return fitted_law;
  if (!section_law_) {
    auto spec = parse_section<LawSection>(*prm, "Cohesive law");
    if (!spec.table_file.empty())
      spec.table_file = resolve_scene_path(spec.table_file, scene_file);
    section_law_ = law::make_law(spec);
    section_j_tip_ = spec.j_tip;
  }
  return section_law_;
}

double SceneContext::j_tip() {
  if (fitted_law)
    return fitted_j_tip;
  law();
  return section_j_tip_;
}

specimen::Specimen SceneContext::specimen() const {
  if (identified_specimen)
    return *identified_specimen;
  return parse_section<SpecimenSection>(*prm, "Specimen");
}

specimen::Material SceneContext::material() const {
  if (identified_material)
    return *identified_material;
  return parse_section<MaterialSection>(*prm, "Material");
}

} // namespace fiberbridge::app
