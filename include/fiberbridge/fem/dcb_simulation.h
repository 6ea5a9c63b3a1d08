#pragma once
// deal.II finite-element model of the DCB specimen with cohesive segments inserted dynamically at
// the propagating crack tip (docs/design.md section 2, "FEM").
//
// Geometry: the beam runs from x = 0 to x = Length; the load line is the left end face x = 0
// (no overhang), where the two arms are pulled apart by prescribed vertical displacements
// +Delta/2 and -Delta/2 on the whole end face of each arm (a rigid loading block that leaves the
// arm ends free to rotate). The crack plane is y = 0, the sawn notch is 0 < x < a0, the arms are
// -h < y < 0 and 0 < y < h. The crack-plane point at x = Length is held (u = 0) to remove the
// rigid-body rotation and translation; it carries no load under symmetric opening.
#include "fiberbridge/law/traction_law.h"
#include "fiberbridge/result/rcurve.h"
#include "fiberbridge/result/virtual_dic.h"
#include "fiberbridge/specimen/specimen.h"

#include <functional>
#include <string>
#include <vector>

namespace dealii {
class ParameterHandler;
}

namespace fiberbridge::fem {

/// The "FEM" section of a scene (step-44's AllParameters pattern; the caller enters the
/// subsection). Each group declares, parses and validates its own keys; all keys stay directly in
/// the FEM section (scenes name them FEM/<key>). Plane stress/strain comes from the Material
/// section.
struct FemParameters {
  /// The mesh and its elements.
  struct Mesh {
    /// FEM/Element size = auto: the run chooses the size from the specimen and the law
    /// (fem/auto_mesh.h, fem::choose_mesh).
    static constexpr double automatic = -1;
    /// Along the crack plane = tip advance per release [m], or `automatic` (the default). On the
    /// seed DCB with the PVA control law, 2 mm (what auto takes there) gives G_ss and R_J within
    /// 0.1 % of the law's values.
    double element_size = automatic;
    bool automatic_size() const { return element_size == automatic; }
    double grading = 1.3;        ///< growth ratio of element heights away from the crack plane
    unsigned int min_layers = 4; ///< at least this many layers per arm (heights <= h/min_layers)
    /// Polynomial degree of the FE_Q displacement elements; 0: auto (Q2 where Q1 would lock in
    /// bending on thin arms, fem::resolve_degree in dcb_common.h).
    unsigned int degree = 0;
    /// Space dimension of the model: 2 (plane stress/strain) or 3 (the specimen extruded over
    /// Specimen/Width, free side faces).
    unsigned int dimension = 2;
    /// 3D only: element layers across the width (0: width / element size, rounded, at least 1).
    unsigned int width_elements = 0;
    /// A specimen mesh to read instead of the generated rectangle (specimen_mesh.h): a Gmsh .geo
    /// (meshed by gmsh at run time) or .msh file; empty: the generated rectangle. The app
    /// resolves a relative path against the scene's directory.
    std::string file;
    /// Gmsh numbers for a .geo file beyond those the scene gives it (specimen_mesh.h), as
    /// "name: value, name: value".
    std::string file_parameters;

    static void declare_parameters(dealii::ParameterHandler& prm);
    void parse_parameters(dealii::ParameterHandler& prm);
    void validate() const;
  };

  /// 3D shear moduli (Wood Handbook, Douglas-fir: G_LR/E_L = 0.064, G_RT/E_L = 0.007). A group
  /// of their own rather than Mesh's: they are elastic constants that complete
  /// specimen::Material's for 3D (which holds the out-of-plane E_R, nu_LR, nu_RT).
  struct Elasticity3d {
    double G_LR_over_E_L = 0.064;
    double G_RT_over_E_L = 0.007;

    static void declare_parameters(dealii::ParameterHandler& prm);
    void parse_parameters(dealii::ParameterHandler& prm);
    void validate() const;
  };

  /// The cohesive crack plane. (The deprecated, ignored key Rigid law stiffness factor is
  /// declared here and only leaves a note.)
  struct Interface {
    /// Sub-intervals of the composite Lobatto rule on each crack-plane element (1: nodal rule).
    unsigned int subintervals = 4;
    double contact_stiffness_factor = 10; ///< contact penalty = factor * E_T / element size

    static void declare_parameters(dealii::ParameterHandler& prm);
    void parse_parameters(dealii::ParameterHandler& prm, std::vector<std::string>& notes);
    void validate() const;
  };

  /// The load stepping and the equilibrium solves.
  struct Nonlinear {
    double max_opening_increment = 0.5e-3; ///< load-point opening per nonlinear solve [m]
    double tip_tolerance = 1e-3;           ///< |J_tip/J_tip,c - 1| accepted at an advance
    double newton_tolerance = 1e-9;        ///< residual relative to the load-line reaction
    unsigned int max_newton_iterations = 25;
    /// Nonlinear solver of one equilibrium. Both use the exact Jacobian, a line search and the
    /// same convergence test (`newton_tolerance`, `max_newton_iterations`).
    enum class Solver {
      newton, ///< own Newton with backtracking line search on the condensed residual
      kinsol  ///< SUNDIALS KINSOL, line-search strategy; its result is re-checked here
    };
    Solver solver = Solver::newton;
    /// Bulk kinematics: small strain (linear elasticity, the bulk stiffness assembled once) or
    /// finite (total Lagrangian, orthotropic St Venant-Kirchhoff, fem/finite_strain.h; the load
    /// line holds its mean opening so that the loaded end rotates freely, and the bulk tangent is
    /// assembled and factorized again unless Newton's last step left under 0.3 of the residual).
    enum class Kinematics { small, finite };
    Kinematics kinematics = Kinematics::small;

    static void declare_parameters(dealii::ParameterHandler& prm);
    void parse_parameters(dealii::ParameterHandler& prm);
    void validate() const;
  };

  /// The Jacobian systems. (The deprecated key Engine is declared here: it chose the solver
  /// stack; app/run/simulation_tasks.cc still reads its value distributed, docs/cluster.md.)
  struct Linear {
    /// Solver of the condensed Jacobian systems. The direct solvers factorize once per release
    /// and take the interface points that change branch in between as a low-rank (Woodbury)
    /// update (FEM/Linear solver = umfpack is a deprecated alias of klu).
    enum class Solver {
      klu,       ///< Trilinos Amesos KLU (on several ranks the matrix is gathered on one)
      mumps,     ///< Trilinos Amesos MUMPS, distributed
      cg_amg,    ///< CG + Trilinos ML AMG on an SPD (secant) Jacobian
      condensed, ///< the arms condensed onto the crack plane (2D, one rank, small strain)
      automatic  ///< auto: condensed where it applies, else klu (resolved by the model)
    };
    Solver solver = Solver::automatic;
    /// cg_amg only: CG stops at this residual relative to the right-hand side.
    double tolerance = 1e-10;

    static void declare_parameters(dealii::ParameterHandler& prm);
    void parse_parameters(dealii::ParameterHandler& prm, std::vector<std::string>& notes);
    void validate() const;
  };

  /// The tip J domain integral.
  struct JDomain {
    unsigned int half_width_elements = 4; ///< half-width of the tip J domain in elements

    static void declare_parameters(dealii::ParameterHandler& prm);
    void parse_parameters(dealii::ParameterHandler& prm);
    void validate() const;
  };

  /// When the run stops: the steady-state rule shared by every model
  /// (result::find_steady_state), under the same key names in the Beam, FEM and MPM sections.
  struct SteadyState {
    double window = 10e-3;           ///< crack growth over which the plateau is judged [m]
    double plateau_tolerance = 0.01; ///< relative spread of R_J accepted as a plateau

    static void declare_parameters(dealii::ParameterHandler& prm);
    void parse_parameters(dealii::ParameterHandler& prm, std::vector<std::string>& notes);
    void validate() const;
  };

  /// Field output.
  struct Output {
    unsigned int vtu_every = 0; ///< VTU every N advances (0: only the final state)

    static void declare_parameters(dealii::ParameterHandler& prm);
    void parse_parameters(dealii::ParameterHandler& prm);
  };

  /// The virtual test (subsection FEM/Virtual DIC; result/virtual_dic.h): the frames a DIC
  /// system and the record a testing machine would write for this run (2D, one rank).
  struct VirtualDic {
    result::VirtualDicSettings settings;

    static void declare_parameters(dealii::ParameterHandler& prm);
    void parse_parameters(dealii::ParameterHandler& prm);
    void validate() const { settings.validate("FEM/Virtual DIC"); }
  };

  Mesh mesh;
  Elasticity3d elasticity_3d;
  Interface interface;
  Nonlinear nonlinear;
  Linear linear;
  JDomain j_domain;
  SteadyState steady_state;
  Output output;
  VirtualDic virtual_dic;

  /// Notes for the run on deprecated keys met by parse_parameters (FEM/Engine, umfpack).
  std::vector<std::string> deprecation_notes;

  static void declare_parameters(dealii::ParameterHandler& prm);
  void parse_parameters(dealii::ParameterHandler& prm);
  /// Throws InputError naming the FEM/<key> that is out of range.
  void validate() const;
};

/// What a run measured beyond the R curve, for verification (one entry per RCurvePoint).
struct FemRunDetails {
  std::vector<double> zone_dissipated; ///< damage dissipation of the zone, exact from history [J]
  std::vector<double> zone_integral;   ///< int sigma d(delta) along the zone (Eq. 1 term) [J/m^2]
  /// Energy released at the tip so far: sum over releases of the drop of bulk + zone recoverable
  /// + zone damage energy at fixed opening [J]. W_ext = U + U_zone + D_zone + this (closure).
  std::vector<double> tip_dissipated;
  /// Tip J right after the release that preceded this record (NaN for the first) [J/m^2]: the
  /// tip energy release rate falls from J_tip to this value while a release happens.
  std::vector<double> j_after_release;
  unsigned unstable_advances = 0; ///< advances at fixed load-point opening
  double simulated_law_area = 0;  ///< area of the law simulated (after regularization)
};

/// Runs the DCB under load-point opening control from the initial crack until steady state (the
/// notch root has moved and R_J has a plateau over `steady_state_window`) or until the ligament
/// runs out. One RCurvePoint per accepted tip advance (the critical state just before the tip
/// node is released). `output_dir` empty: no files. `progress` gets one line per few advances.
/// Throws ComputationError with a diagnosis when equilibrium cannot be found.
result::SimulationResult simulate_dcb(const specimen::Specimen& specimen,
                                      const specimen::Material& material,
                                      const law::TractionLaw& law, double j_tip,
                                      const FemParameters& parameters,
                                      const std::string& output_dir = "",
                                      const std::function<void(const std::string&)>& progress = {});

/// The same, also filling `details`.
result::SimulationResult
simulate_dcb(const specimen::Specimen& specimen, const specimen::Material& material,
             const law::TractionLaw& law, double j_tip, const FemParameters& parameters,
             const std::string& output_dir, const std::function<void(const std::string&)>& progress,
             FemRunDetails& details);

} // namespace fiberbridge::fem
