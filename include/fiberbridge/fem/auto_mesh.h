#pragma once
// FEM/Element size = auto (issue 34 item 1; docs/design.md section 2, "FEM", "The automatic
// mesh"): the element length along the crack plane chosen from the specimen (arm thickness, the
// crack-plane aspect bound, the notch and the ligament) and from the law (a closed-form estimate
// of the cohesive zone length), before the run. A given size is honoured as it is. No deal.II
// here: the choice is plain arithmetic, unit-tested alone.
#include "fiberbridge/fem/dcb_simulation.h"
#include "fiberbridge/law/traction_law.h"
#include "fiberbridge/specimen/specimen.h"

#include <string>

namespace fiberbridge::fem {

// The tunables are defined in source/fem/auto_mesh.cc (extern here, so that tuning them does
// not recompile the engine, which includes this header through distributed_dcb.h).

/// Never coarser than the old default, 2 mm: the mesh of the seed figures (docs/verification.md;
/// on the seed DCB with the PVA control law G_ss and R_J within 0.1 %), so a scene that ran on
/// the default keeps its mesh wherever its arm and its zone allow.
extern const double kAutoLargestElement;
/// The cost bound: auto refines for the zone only while the mesh stays within this many dofs
/// (estimated_dofs; auto_mesh.cc says why). A zone that needs finer elements is run at the
/// finest element within the bound and flagged by the zone rule (result::note_zone_resolution:
/// steady_state_status zone_unresolved).
extern const double kAutoMostDofs;
/// The element is the estimated zone length over this (auto_mesh.cc says why).
extern const double kAutoElementsPerZoneEstimate;

/// The mesh a run uses and why (summary.json fem.mesh).
struct MeshChoice {
  bool automatic = false;      ///< FEM/Element size = auto
  double element_size = 0;     ///< the size asked of the mesh [m] (snapped to a0 / round(a0 / it))
  double arm_limit = 0;        ///< largest element the arm, notch and ligament admit [m]
  double zone_estimate = 0;    ///< closed-form cohesive zone length [m]; 0: no zone (LEFM)
  unsigned layers_per_arm = 0; ///< element layers through each arm (0: a read mesh decides)
  std::string reason;          ///< one sentence: what bounded the size
};

/// The largest element the generated mesh admits on this specimen: kAutoLargestElement, at most
/// kMaxCrackPlaneAspect crack-plane layers (arm thickness / Minimum layers per arm) long, at most
/// a0 / max(5, Tip J domain half-width + 1) (the notch holds the far-field J domain) and at most
/// (Length - a0 - h) / Tip J domain half-width (the ligament holds the tip J domains) where that
/// is positive; snapped down to a0 / n (the mesh needs a line at a0), so that the snapped element
/// keeps these bounds. Needs no law: the scene's input check uses it.
double arm_element_size(const specimen::Specimen& specimen, const FemParameters& parameters);

/// The element size a mesh is built with: the given FEM/Element size, or arm_element_size for
/// auto (the law-free part of the choice; what a check made before the law is known can use).
double element_length(const specimen::Specimen& specimen, const FemParameters& parameters);

/// The effective modulus of a crack along L opening along T in the orthotropic plane (Sih, Paris
/// & Irwin 1965: G = K^2 / E'), with the reduced compliance of specimen::in_plane_compliance
/// (plane stress or strain): 1/E' = sqrt(s11 s22 / 2) sqrt(sqrt(s22/s11) + (2 s12 + s66)/(2 s11)).
double crack_modulus(const specimen::Material& material);

/// The law's own closed-form cohesive zone length on this specimen [m]: the smaller of the
/// infinite-body length E' G_c / sigma_max^2 (Hillerborg; Turon et al. 2007) and the slender-arm
/// length (E_L G_c / sigma_max^2)^(1/4) h^(3/4) (Yang & Cox 2005; docs/design.md section 3,
/// "Reference formulas"), with G_c the law's area and sigma_max its peak traction. 0 for a law
/// without a zone.
double bridging_zone_length(const specimen::Specimen& specimen, const specimen::Material& material,
                            const law::TractionLaw& law);

/// How far behind the tip the tip's own field opens the crack to `critical_opening` under
/// `j_tip` alone [m]: the smaller of the K-field length pi E' delta_c^2 / (32 J_tip) and the
/// slender-arm length sqrt(delta_c / kappa), kappa = sqrt(12 J_tip / (E_L h^3)). Infinite for
/// J_tip = 0.
double tip_opening_length(const specimen::Specimen& specimen, const specimen::Material& material,
                          double critical_opening, double j_tip);

/// Closed-form cohesive zone length of `law` behind a tip at `j_tip` [m]: the harmonic mean of
/// bridging_zone_length (the law's own energy and peak) and tip_opening_length (the tip's share),
/// so that a law weak against J_tip (the zone closes in the tip's field) gets the tip's short
/// length and a strong law its Hillerborg length. 0 for a law without a zone.
double estimated_zone_length(const specimen::Specimen& specimen, const specimen::Material& material,
                             const law::TractionLaw& law, double j_tip);

/// The degrees of freedom of the generated mesh (both arms, every displacement component) with
/// elements of `element_size` (a0 / n), with the degree FEM/Element degree resolves to and, in
/// 3D, the elements across the width. A read mesh is counted as the generated one it replaces.
double estimated_dofs(const specimen::Specimen& specimen, const specimen::Material& material,
                      const FemParameters& parameters, double element_size);

/// The mesh of a run: for a given size that size; for auto the smallest of arm_element_size and
/// the zone estimate over kAutoElementsPerZoneEstimate (snapped down to a0 / n), not finer than
/// the finest a0 / n within kAutoMostDofs; the layers through each arm follow from
/// the generated mesh lines (crack-plane layer min(element, h / Minimum layers per arm), graded by
/// FEM/Grading).
MeshChoice choose_mesh(const specimen::Specimen& specimen, const specimen::Material& material,
                       const law::TractionLaw& law, double j_tip, const FemParameters& parameters);

/// `parameters` with FEM/Element size set to the choice's size (what the engine runs).
FemParameters with_mesh(const FemParameters& parameters, const MeshChoice& choice);

} // namespace fiberbridge::fem
