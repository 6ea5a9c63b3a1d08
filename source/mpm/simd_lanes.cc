// The MPM's SIMD lanes (simd_lanes.h): the weight kernel and the particle update on 2, 4 or 8
// lanes, chosen once at run time.
#include "simd_lanes.h"

#include <cmath>
#if defined(__SSE2__)
#include <immintrin.h>
#endif

namespace fiberbridge::mpm::lanes {

namespace {

#define FB_INLINE inline __attribute__((always_inline))

/// uGIMP weights and derivatives (detail::ugimp) of W particles at once (VD: W doubles, VI: W
/// 64-bit integers), lane by lane with the same arithmetic.
template <class VD, class VI>
FB_INLINE VD pick(VI m, VD x, VD y) {
  return reinterpret_cast<VD>((m & reinterpret_cast<VI>(x)) | (~m & reinterpret_cast<VI>(y)));
}

template <class VD, class VI>
FB_INLINE void ugimp_lanes(VD r, const UgimpAxis& A, VD& S, VD& dS) {
  const VD zero = VD{}, one = zero + 1.0, minus_one = zero - 1.0;
  const VI sign_bit = VI{} + static_cast<long long>(1ULL << 63);
  const VD a = reinterpret_cast<VD>(reinterpret_cast<VI>(r) & ~sign_bit); // fabs
  const VD sign = pick<VD, VI>(reinterpret_cast<VI>(r < zero), minus_one, one);
  const VD S_in = 1 - (r * r + A.lp * A.lp) * A.inv_2clp, dS_in = -r * A.inv_clp;
  const VD S_mid = 1 - a * A.inv_cell, dS_mid = -sign * A.inv_cell;
  const VD d = A.cell + A.lp - a;
  const VD S_out = d * d * A.inv_4clp, dS_out = -sign * d * A.inv_2clp;
  const VI in = reinterpret_cast<VI>(a < A.lp), mid = reinterpret_cast<VI>(a <= A.cell - A.lp),
           out = reinterpret_cast<VI>(a < A.cell + A.lp);
  S = pick<VD, VI>(in, S_in, pick<VD, VI>(mid, S_mid, pick<VD, VI>(out, S_out, zero)));
  dS = pick<VD, VI>(in, dS_in, pick<VD, VI>(mid, dS_mid, pick<VD, VI>(out, dS_out, zero)));
}

/// The uGIMP weights of particles [begin, end) along one axis (positions pos, node origin): the
/// lowest node, 3 weights and derivatives per particle, and the number of links (2 when the
/// third node's weight and derivative are zero). W particles at a time, the rest one by one
/// with detail::ugimp: the same arithmetic either way, the same weights to the bit.
template <class VD, class VI>
FB_INLINE void weights_axis_lanes(const double* pos, long begin, long end, long n, double origin,
                                  const UgimpAxis& A, int* first, double* S, double* dS,
                                  unsigned char* n_links) {
  constexpr int W = sizeof(VD) / sizeof(double);
  long p = begin;
  for (; p + W <= end; p += W) {
    VD x;
    std::memcpy(&x, pos + p, sizeof x);
    // floor() of the box's left edge in cells (true division, see ugimp_weights), as a
    // truncation corrected for negative values (a true comparison is -1).
    const VD q = (x - A.lp - origin) / A.cell;
    const VI t = __builtin_convertvector(q, VI);
    const VI f = t + reinterpret_cast<VI>(q < __builtin_convertvector(t, VD));
    const VD fd = __builtin_convertvector(f, VD);
    for (int l = 0; l < W; ++l)
      first[p + l] = static_cast<int>(f[l]);
    VD Sk, dSk;
    for (int k = 0; k < 3; ++k) {
      ugimp_lanes<VD, VI>(x - (origin + (fd + k) * A.cell), A, Sk, dSk);
      std::memcpy(S + k * n + p, &Sk, sizeof Sk);
      std::memcpy(dS + k * n + p, &dSk, sizeof dSk);
    }
    // Without a branch: the pattern follows the particles' positions in their cells.
    const VI third = reinterpret_cast<VI>(Sk != 0.0) | reinterpret_cast<VI>(dSk != 0.0);
    for (int l = 0; l < W; ++l)
      n_links[p + l] = static_cast<unsigned char>(2 - third[l]);
  }
  for (; p < end; ++p) {
    const double q = (pos[p] - A.lp - origin) / A.cell;
    const int t = static_cast<int>(q);
    const int f = t - (q < static_cast<double>(t));
    first[p] = f;
    detail::ugimp(pos[p] - (origin + f * A.cell), A, S[p], dS[p]);
    detail::ugimp(pos[p] - (origin + (f + 1) * A.cell), A, S[n + p], dS[n + p]);
    detail::ugimp(pos[p] - (origin + (f + 2) * A.cell), A, S[2 * n + p], dS[2 * n + p]);
    n_links[p] = static_cast<unsigned char>(2 + ((S[2 * n + p] != 0) | (dS[2 * n + p] != 0)));
  }
}

using WeightsAxisFn = void (*)(const double*, long, long, long, double, const UgimpAxis&, int*,
                               double*, double*, unsigned char*);

// The same kernel for 2 lanes (SSE2, any x86-64), and, chosen at run time where the processor
// has them, 4 (AVX2) and 8 (AVX-512) lanes. Only the lane count differs: no fused multiply-add
// (the targets below do not enable FMA), so the weights are the same to the bit on any of them.
void weights_axis_2(const double* pos, long begin, long end, long n, double origin,
                    const UgimpAxis& A, int* first, double* S, double* dS, unsigned char* n_links) {
  weights_axis_lanes<v2d, v2i>(pos, begin, end, n, origin, A, first, S, dS, n_links);
}
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
typedef double v4d __attribute__((vector_size(32)));
typedef long long v4i __attribute__((vector_size(32)));
typedef double v8d __attribute__((vector_size(64)));
typedef long long v8i __attribute__((vector_size(64)));
__attribute__((target("avx2"))) void weights_axis_4(const double* pos, long begin, long end, long n,
                                                    double origin, const UgimpAxis& A, int* first,
                                                    double* S, double* dS, unsigned char* n_links) {
  weights_axis_lanes<v4d, v4i>(pos, begin, end, n, origin, A, first, S, dS, n_links);
}
__attribute__((target("avx512f,avx512dq"))) void
weights_axis_8(const double* pos, long begin, long end, long n, double origin, const UgimpAxis& A,
               int* first, double* S, double* dS, unsigned char* n_links) {
  weights_axis_lanes<v8d, v8i>(pos, begin, end, n, origin, A, first, S, dS, n_links);
}
/// simd_lanes.h: simd_lane_width. Every lane kernel below is picked by it, so all of them use the
/// same width.
int processor_lane_width() {
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq"))
    return 8;
  return __builtin_cpu_supports("avx2") ? 4 : 2;
}
WeightsAxisFn pick_weights_axis() {
  const int w = processor_lane_width();
  return w == 8 ? weights_axis_8 : w == 4 ? weights_axis_4 : weights_axis_2;
}
#else
int processor_lane_width() {
  return 2;
}
WeightsAxisFn pick_weights_axis() {
  return weights_axis_2;
}
#endif
const WeightsAxisFn weights_axis_fn = pick_weights_axis();

typedef double v1d __attribute__((vector_size(8)));

template <class V>
FB_INLINE V lanes_load(const double* a) {
  V v;
  std::memcpy(&v, a, sizeof v);
  return v;
}
template <class V>
FB_INLINE void lanes_store(double* a, V v) {
  std::memcpy(a, &v, sizeof v);
}
template <class V>
FB_INLINE V lanes_load(const double* a, int stride) {
  V v;
  for (int l = 0; l < static_cast<int>(sizeof(V) / sizeof(double)); ++l)
    v[l] = a[stride * l];
  return v;
}
template <class V>
FB_INLINE void lanes_store(double* a, int stride, V v) {
  for (int l = 0; l < static_cast<int>(sizeof(V) / sizeof(double)); ++l)
    a[stride * l] = v[l];
}
/// Square root lane by lane (correctly rounded, like std::sqrt).
template <class V>
FB_INLINE V lanes_sqrt(V v) {
  for (int l = 0; l < static_cast<int>(sizeof(V) / sizeof(double)); ++l)
    v[l] = std::sqrt(v[l]);
  return v;
}

/// The particle update of ExplicitSolver::update_particles after the gather, for the particles
/// p .. p + W - 1 (V: W doubles): every lane does the scalar arithmetic in the scalar order (each
/// expression below is the scalar code's), so the results are the same to the bit. The energy
/// terms go to g (8 n: damping loss, 9 n: FLIP gain, 10 n: strain-energy increment) for the
/// caller to sum in particle order.
template <class V, class Sqrt>
FB_INLINE void update_lanes(const LaneUpdate& u, long p, Sqrt vsqrt) {
  const long n = u.n;
  double* g = u.g;
  const double dt = u.dt, beta = u.beta, one_minus_beta = 1 - u.beta;
  const V vpic_x = lanes_load<V>(g + p), vpic_y = lanes_load<V>(g + n + p);
  const V dvx = lanes_load<V>(g + 2 * n + p), dvy = lanes_load<V>(g + 3 * n + p);
  const V L11 = lanes_load<V>(g + 4 * n + p), L12 = lanes_load<V>(g + 5 * n + p);
  const V L21 = lanes_load<V>(g + 6 * n + p), L22 = lanes_load<V>(g + 7 * n + p);
  const V m = lanes_load<V>(u.mass + p);
  // Velocity: PIC damping blends the FLIP update (energy conserving, keeps the noise that crack
  // growth releases) with the PIC velocity (dissipative); the kinetic energy removed is the
  // damping loss.
  const V fx = lanes_load<V>(u.vx + p) + dvx, fy = lanes_load<V>(u.vy + p) + dvy;
  const V bx = one_minus_beta * fx + beta * vpic_x;
  const V by = one_minus_beta * fy + beta * vpic_y;
  lanes_store<V>(g + 8 * n + p, 0.5 * m * (fx * fx + fy * fy - bx * bx - by * by));
  lanes_store<V>(g + 9 * n + p, 0.5 * m * (dvx * dvx + dvy * dvy));
  lanes_store<V>(u.vx + p, bx);
  lanes_store<V>(u.vy + p, by);
  // Update-stress-last: position, deformation gradient and stress from the new grid velocities.
  lanes_store<V>(u.x + p, lanes_load<V>(u.x + p) + vpic_x * dt);
  lanes_store<V>(u.y + p, lanes_load<V>(u.y + p) + vpic_y * dt);
  // F <- (I + L dt) F, then the corotational small-strain update: F = R U, strain U - I in the
  // material frame (which turns with the arm), Cauchy stress R S R^T.
  double* Fp = u.F + 4 * p;
  const V F0 = lanes_load<V>(Fp, 4), F1 = lanes_load<V>(Fp + 1, 4);
  const V F2 = lanes_load<V>(Fp + 2, 4), F3 = lanes_load<V>(Fp + 3, 4);
  const V a11 = 1 + L11 * dt, a12 = L12 * dt, a21 = L21 * dt, a22 = 1 + L22 * dt;
  const V F11 = a11 * F0 + a12 * F2, F12 = a11 * F1 + a12 * F3;
  const V F21 = a21 * F0 + a22 * F2, F22 = a21 * F1 + a22 * F3;
  lanes_store<V>(Fp, 4, F11);
  lanes_store<V>(Fp + 1, 4, F12);
  lanes_store<V>(Fp + 2, 4, F21);
  lanes_store<V>(Fp + 3, 4, F22);
  // Polar rotation angle th with tan th = (F21 - F12)/(F11 + F22), as cosine and sine directly
  // (no trigonometric calls; F11 + F22 stays near 2, so the plain square root needs none of
  // hypot's overflow care).
  const V rn = 1 / vsqrt((F11 + F22) * (F11 + F22) + (F21 - F12) * (F21 - F12));
  const V c = (F11 + F22) * rn, s = (F21 - F12) * rn;
  const V U11 = c * F11 + s * F21, U22 = -s * F12 + c * F22;
  const V U12 = c * F12 + s * F22, U21 = -s * F11 + c * F21;
  const V eps0 = U11 - 1, eps1 = U22 - 1, eps2 = 0.5 * (U12 + U21);
  // OrthotropicElastic::stress of the strain, and energy_density of its increment.
  const V S0 = u.q11 * eps0 + u.q12 * eps1, S1 = u.q12 * eps0 + u.q22 * eps1;
  const V S2 = u.q66x2 * eps2;
  double* ep = u.strain + 3 * p;
  const V de0 = eps0 - lanes_load<V>(ep, 3), de1 = eps1 - lanes_load<V>(ep + 1, 3);
  const V de2 = eps2 - lanes_load<V>(ep + 2, 3);
  const V t0 = u.q11 * de0 + u.q12 * de1, t1 = u.q12 * de0 + u.q22 * de1, t2 = u.q66x2 * de2;
  lanes_store<V>(g + 10 * n + p,
                 0.5 * (t0 * de0 + t1 * de1 + 2 * t2 * de2) * lanes_load<V>(u.volume + p));
  lanes_store<V>(ep, 3, eps0);
  lanes_store<V>(ep + 1, 3, eps1);
  lanes_store<V>(ep + 2, 3, eps2);
  double* sp = u.stress + 3 * p;
  lanes_store<V>(sp, 3, c * c * S0 - 2 * c * s * S2 + s * s * S1);
  lanes_store<V>(sp + 1, 3, s * s * S0 + 2 * c * s * S2 + c * c * S1);
  lanes_store<V>(sp + 2, 3, c * s * (S0 - S1) + (c * c - s * s) * S2);
}

template <class VD, class Sqrt>
FB_INLINE void update_all_lanes(const LaneUpdate& u, long begin, long end, Sqrt vsqrt) {
  constexpr int W = sizeof(VD) / sizeof(double);
  long p = begin;
  for (; p + W <= end; p += W)
    update_lanes<VD>(u, p, vsqrt);
  for (; p < end; ++p)
    update_lanes<v1d>(u, p, [](v1d v) { return lanes_sqrt(v); });
}

using UpdateLanesFn = void (*)(const LaneUpdate&, long, long);

void update_lanes_2(const LaneUpdate& u, long begin, long end) {
#if defined(__SSE2__)
  update_all_lanes<v2d>(u, begin, end, [](v2d v) -> v2d { return _mm_sqrt_pd(v); });
#else
  update_all_lanes<v2d>(u, begin, end, [](v2d v) { return lanes_sqrt(v); });
#endif
}
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
__attribute__((target("avx2"))) void update_lanes_4(const LaneUpdate& u, long begin, long end) {
  update_all_lanes<v4d>(
      u, begin, end, [](v4d v) __attribute__((target("avx2")))->v4d { return _mm256_sqrt_pd(v); });
}
__attribute__((target("avx512f,avx512dq"))) void update_lanes_8(const LaneUpdate& u, long begin,
                                                                long end) {
  update_all_lanes<v8d>(
      u, begin, end, [](v8d v) __attribute__((target("avx512f")))->v8d {
        return _mm512_mask_sqrt_pd(v, static_cast<__mmask8>(-1), v);
      });
}
UpdateLanesFn pick_update_lanes() {
  const int w = processor_lane_width();
  return w == 8 ? update_lanes_8 : w == 4 ? update_lanes_4 : update_lanes_2;
}
#else
UpdateLanesFn pick_update_lanes() {
  return update_lanes_2;
}
#endif
const UpdateLanesFn update_lanes_fn = pick_update_lanes();

} // namespace

void weights_axis(const double* pos, long begin, long end, long n, double origin,
                  const UgimpAxis& A, int* first, double* S, double* dS, unsigned char* n_links) {
  weights_axis_fn(pos, begin, end, n, origin, A, first, S, dS, n_links);
}

void update_particles(const LaneUpdate& u, long begin, long end) {
  update_lanes_fn(u, begin, end);
}

int simd_lane_width() {
  return processor_lane_width();
}

} // namespace fiberbridge::mpm::lanes
