#pragma once
// ISO 15024 / ASTM D5528's large-displacement correction F and end-block correction N of a DCB
// (Williams 1987, J. Compos. Mater. 21:330). One implementation, used by the reduction of test
// records (analysis::reduce_record) and by identify's map of a small-rotation beam run onto arms
// that rotate far (identify::with_large_displacements).
//
// With delta the load-point opening, a the crack length from the load line, l1 the load-pin axis
// to the arm's mid-plane and l2 the pin axis to the end block's inner edge (0 without blocks):
//   F = 1 - 3/10 (delta/a)^2 - 3/2 (delta l1 / a^2)
//   N = 1 - (l2/a)^3 - 9/8 (1 - (l2/a)^2) (delta l1 / a^2) - 9/35 (delta/a)^2
// G = 3 P delta F / (2 B a N); the compliance of the arms is (2 a^3 / (3 E I)) N. N's last term is
// the elastica's own geometric stiffening, so it applies with hinges (l2 = 0) too: F/N, not F, is
// the ratio of the exact G of the elastica to 3 P delta / (2 B a)
// (RecordReduction.ElasticaDcbIsReducedExactlyWithFOverN).

namespace fiberbridge::specimen {

/// F at opening `delta`, crack length `a` and pin-to-mid-plane distance `l1` (SI, a > 0).
double large_displacement_F(double delta, double a, double l1);

/// N at opening `delta`, crack length `a`, pin-to-mid-plane `l1` and pin-to-block-edge `l2`
/// (0: hinges, no end blocks).
double end_block_N(double delta, double a, double l1, double l2);

} // namespace fiberbridge::specimen
