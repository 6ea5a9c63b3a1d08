#pragma once
// The free arm of a DCB at finite rotation: a planar, inextensible, shearable (Reissner) elastica
// between the load line and the crack tip, loaded by vertical dead forces (docs/design.md section
// 2, "Beam model"; verification in docs/verification.md, "Finite rotations of the beam arms").
//
// Conventions as in arm_on_foundation.h: arc length s runs from the load point (s = 0) into the
// specimen to the root (s = length, the crack tip); w is the deflection away from the crack plane
// and theta the section rotation. With all loads vertical, the vertical resultant V(s) of the
// loads on [0, s] is constant between loads, and the section obeys
//   EI theta' = M,  M' = V x',  x' = cos(theta) - gamma sin(theta),  w' = sin(theta) + gamma
//   cos(theta), gamma = Q/S,  Q = -V cos(theta)  (the shear force across the rotated section),
// which is the linear Timoshenko arm (M = EI theta', M' + Q = 0) when theta is small.
#include <vector>

namespace fiberbridge::beam {

/// A vertical dead force on the free arm at arc length `s` from the load point [m]; positive
/// away from the crack plane, like the load (bridging tractions are negative).
struct ArmPointLoad {
  double s = 0;
  double force = 0; ///< [N]
};

/// The deformed free arm. Positions are relative to the root.
struct ElasticaState {
  double theta_load = 0;  ///< section rotation at the load point
  double rise = 0;        ///< w(root) - w(load point) [m]: minus the load point's deflection
  double projection = 0;  ///< x(root) - x(load point) [m]: the load's lever arm about the root
  double root_moment = 0; ///< M at the root [N m]
  double energy = 0;      ///< strain energy int (M^2/(2 EI) + Q^2/(2 S)) ds [J]
};

/// Solves the elastica of a free arm of `length` with root rotation `theta_root`, load `load` at
/// s = 0 and `loads` at 0 < s < length, by shooting on theta at the load point (M = 0 there)
/// with fourth-order Runge-Kutta steps of at most length/`steps`. S = infinity gives the
/// unshearable (Euler) elastica. Throws ComputationError if the shooting does not converge.
ElasticaState free_arm_elastica(double EI, double S, double length, double theta_root, double load,
                                const std::vector<ArmPointLoad>& loads, int steps = 2000);

} // namespace fiberbridge::beam
