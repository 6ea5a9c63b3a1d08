#pragma once
// The MPM's SIMD lanes (private to source/mpm): several particles per instruction in the two hot
// kernels of an explicit step, the uGIMP weights along one axis and the particle update after the
// gather, and the pairs of doubles the scatter and the gather move. Every lane does the scalar
// code's arithmetic in the scalar code's order, so the results are the scalar ones to the bit on
// any lane width (simd_lanes.cc; compiled with -ffp-contract=off, source/mpm/CMakeLists.txt).
// Split from explicit_solver.cc (issue 30 item 7).
#include "fiberbridge/mpm/grid.h"
#include "fiberbridge/mpm/shape_function.h"

#include <cstddef>
#include <cstring>

namespace fiberbridge::mpm::lanes {

// Two doubles in one SSE2 register (GCC/Clang vector extension; plain pairs of scalars where
// the target has no such register). Every lane does the scalar code's arithmetic in the
// scalar code's order (no reassociation, no fused multiply-add on the baseline x86-64 target),
// so the results are the scalar ones to the bit.
typedef double v2d __attribute__((vector_size(16)));
typedef long long v2i __attribute__((vector_size(16)));

inline v2d load2(const double* p) {
  v2d v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
inline void store2(double* p, v2d v) {
  std::memcpy(p, &v, sizeof v);
}
// NodeField as pairs of doubles: (mass, unused), (px, py), (mux, muy), (fx, fy), (vx, vy),
// (vx_new, vy_new).
static_assert(sizeof(NodeField) == 12 * sizeof(double) && alignof(NodeField) == 16,
              "NodeField: six pairs of doubles");
static_assert(offsetof(NodeField, px) == 2 * sizeof(double) &&
                  offsetof(NodeField, mux) == 4 * sizeof(double) &&
                  offsetof(NodeField, fx) == 6 * sizeof(double) &&
                  offsetof(NodeField, vx) == 8 * sizeof(double) &&
                  offsetof(NodeField, vx_new) == 10 * sizeof(double),
              "NodeField: the pairs the scatter and gather move together");

/// What update_lanes reads and writes (particle arrays, the gathered link sums and energy
/// terms, structure of arrays with stride n, and the constants of the step).
struct LaneUpdate {
  double *vx, *vy, *x, *y;
  const double *mass, *volume;
  double *F, *strain, *stress; ///< 4, 3, 3 per particle
  double* g;                   ///< ExplicitSolver::gathered_
  long n;
  double dt, beta, q11, q12, q22, q66x2; ///< q66x2: 2 Q66
};

/// The uGIMP weights of particles [begin, end) along one axis (positions pos, node origin, n
/// particles in all): the lowest node in `first`, weight k and its derivative of particle p at
/// S[k n + p], dS[k n + p], and the number of links in n_links (2 when the third node's weight and
/// derivative are zero). On the widest lanes this processor runs (simd_lane_width).
void weights_axis(const double* pos, long begin, long end, long n, double origin,
                  const UgimpAxis& A, int* first, double* S, double* dS, unsigned char* n_links);

/// ExplicitSolver::update_particles after the gather for particles [begin, end): velocity,
/// position, deformation gradient, strain and stress, and the energy terms into u.g (8 n: damping
/// loss, 9 n: FLIP gain, 10 n: strain-energy increment), on the widest lanes.
void update_particles(const LaneUpdate& u, long begin, long end);

/// The widest lane count this processor runs (8: AVX-512 F and DQ, 4: AVX2, 2: SSE2), asked
/// once: both kernels use it.
int simd_lane_width();

} // namespace fiberbridge::mpm::lanes
