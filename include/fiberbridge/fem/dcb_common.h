#pragma once
// Pieces of the DCB finite-element model (source/fem/dcb_model.h) that need no mesh: the
// orthotropic stiffness, the insertable law (extrinsic for rigid laws), the mesh
// lines, the steady-state rule's parameters, the J-integral weight, the stress output and number
// formatting.
#include "fiberbridge/core/format.h"
#include "fiberbridge/fem/dcb_simulation.h"
#include "fiberbridge/fem/finite_strain.h"
#include "fiberbridge/law/traction_law.h"
#include "fiberbridge/result/steady_state.h"
#include "fiberbridge/specimen/specimen.h"

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/numerics/data_postprocessor.h>

#include "fiberbridge/core/clock.h"

#include <chrono>
#include <memory>
#include <string>
#include <vector>

namespace fiberbridge::fem {

using Clock = std::chrono::steady_clock;

/// Stiffness of the orthotropic wood with 1 = L along x, 2 = T along y (normal to the crack
/// plane), 3 = R along z (out of plane in 2D, across the width in 3D).
/// dim = 2: plane stress, or plane strain through the reduced compliance S_ij - S_i3 S_j3 / S_33.
/// dim = 3: the full orthotropic solid (E_R, nu_LR, nu_RT from specimen::Material, G_LR, G_RT from
/// FemParameters; the Material section gives E_L, E_T, G_LT, nu_LT). Throws InputError if not
/// positive definite.
template <int dim>
dealii::SymmetricTensor<4, dim> orthotropic_stiffness(const specimen::Material& m,
                                                      const FemParameters& p);

/// Weight q(x) of the domain J integral: 0 outside [x0, x3], 1 on [x1, x2], linear between.
/// q depends on x only, so the strip spans both arms (and the whole width in 3D) and the top,
/// bottom and side faces (n_x = 0, traction-free) add nothing; its kinks sit on mesh lines, so
/// Gauss quadrature is exact. Free faces with n_x != 0 (a read mesh: a tapered arm) add
/// int W n_x q ds (j_integrals.cc).
struct Ramp {
  double x0, x1, x2, x3;
  double value(double x) const {
    if (x <= x0 || x >= x3)
      return 0;
    if (x < x1)
      return (x - x0) / (x1 - x0);
    if (x <= x2)
      return 1;
    return (x3 - x) / (x3 - x2);
  }
  double slope(double x) const {
    if (x <= x0 || x >= x3)
      return 0;
    if (x < x1)
      return 1 / (x1 - x0);
    if (x <= x2)
      return 0;
    return -1 / (x3 - x2);
  }
};

/// Mesh lines of one arm: uniform along x with a line at a0 (every tip advance is one element of
/// size dx); heights from the crack plane y = 0 to the arm thickness h with a first layer
/// y1 = min(dx, h / min_layers) (so at least min_layers layers through every arm), graded towards
/// the face and capped at h / min_layers. Throws InputError if the notch spans too few elements
/// for the far-field J domain, or if the crack-plane elements would be more than
/// kMaxCrackPlaneAspect times longer than high (an element length not tied to a thin arm).
struct DcbMeshLines {
  double dx = 0;
  double first_layer = 0; ///< height of the crack-plane layer [m]
  std::vector<double> x, y;
};
/// Bound on dx / y1 at the crack plane: 4 admits the default 2 mm elements down to 2 mm arms
/// with 4 layers (docs/design.md section 2, "FEM", "Mesh that follows the specimen").
inline constexpr double kMaxCrackPlaneAspect = 4;
DcbMeshLines dcb_mesh_lines(const specimen::Specimen& specimen, const FemParameters& p);
/// The element length along the crack plane, a0 / round(a0 / Element size): a mesh line at the
/// notch end so that every advance is one element (the generated and the read meshes alike).
/// Throws InputError if the notch spans too few elements for the far-field J domain.
double crack_plane_step(const specimen::Specimen& specimen, const FemParameters& p);

/// Parasitic-shear indicator of Q1 elements of length `element_length` in an arm of thickness
/// `arm_thickness`: in pure bending (curvature k) a bilinear element cannot represent
/// u_y = k x^2 / 2 and carries a shear strain k (x - x_c) whatever its height, so the spurious
/// shear energy over the bending energy is (G_LT / E_L)(element_length / arm_thickness)^2.
/// Measured on the thin composite arm (docs/verification.md, "Thin arms after the fix"): the Q1
/// load at fixed J is 1.2 to 1.8 times the indicator too high (kQ1LoadErrorPerIndicator, used in
/// the note, is a round middle value).
double q1_bending_indicator(const specimen::Material& material, double element_length,
                            double arm_thickness);
inline constexpr double kQ1LoadErrorPerIndicator = 1.3;
/// Above this indicator Q1 is not accurate enough (a load error of about 0.5 to 0.7 %): auto
/// takes Q2.
inline constexpr double kQ1BendingBound = 0.004;

/// The polynomial degree of the run: FemParameters::Mesh::degree, or for 0 (auto) Q2 where Q1 would
/// lock in bending (indicator above kQ1BendingBound) and Q1 elsewhere; notes the choice, and a
/// forced Q1 past the bound.
unsigned resolve_degree(const specimen::Specimen& specimen, const specimen::Material& material,
                        const FemParameters& p, std::vector<std::string>& notes);

/// The shared steady-state rule (result::find_steady_state) with FEM/Steady state window and
/// FEM/Plateau tolerance; the root has moved once it passes a0 by more than round-off.
result::SteadyStateRule steady_state_rule(const FemParameters& p,
                                          const specimen::Specimen& specimen);

/// Small strain stops being good enough where the arms rotate far: the beam model's comparison
/// with the elastica (docs/verification.md, "Finite rotations of the beam arms", a0 = 35 mm)
/// measured the small-rotation load low by kSmallRotationLoadError (opening/a)^2, 1 % at
/// opening/a = 0.28; the FEM's own small/finite pair measures the same (docs/verification.md,
/// "Finite rotations of the FEM arms"). Adds a note to a small-strain `result` when the largest
/// load-point opening over crack length of its R curve passes it; returns that largest ratio.
inline constexpr double kSmallRotationLoadError = 0.13;
inline constexpr double kSmallRotationBound = 0.01;
double note_small_strain_bound(result::SimulationResult& result);

/// Stress components [Pa] for DataOut (xx, xy, yy in 2D; the six in 3D): with `finite`, the
/// Cauchy stress of the St Venant-Kirchhoff state (fem/finite_strain.h), shown on the reference
/// mesh.
template <int dim>
class StressPostprocessor : public dealii::DataPostprocessor<dim> {
public:
  StressPostprocessor(const dealii::SymmetricTensor<4, dim>& C, bool finite)
      : C_(C), finite_(finite) {}
  void evaluate_vector_field(const dealii::DataPostprocessorInputs::Vector<dim>& in,
                             std::vector<dealii::Vector<double>>& out) const override {
    for (unsigned int q = 0; q < in.solution_gradients.size(); ++q) {
      dealii::Tensor<2, dim> H; // H[i][j] = d u_i / d x_j
      for (unsigned int i = 0; i < dim; ++i)
        H[i] = in.solution_gradients[q][i];
      const dealii::SymmetricTensor<2, dim> s =
          finite_ ? SvkPoint<dim>(C_, H).cauchy()
                  : dealii::SymmetricTensor<2, dim>(C_ * dealii::symmetrize(H));
      unsigned k = 0;
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = i; j < dim; ++j)
          out[q](k++) = s[i][j];
    }
  }
  std::vector<std::string> get_names() const override {
    const char* axis = "xyz";
    std::vector<std::string> n;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = i; j < dim; ++j)
        n.push_back(std::string("stress_") + axis[i] + axis[j] + "_Pa");
    return n;
  }
  dealii::UpdateFlags get_needed_update_flags() const override { return dealii::update_gradients; }

private:
  dealii::SymmetricTensor<4, dim> C_;
  bool finite_;
};

} // namespace fiberbridge::fem
