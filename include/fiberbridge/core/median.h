#pragma once
// The medians of the libraries' robust scales and summaries, one of each kind (issue 40 item 6).
// Two kinds, both kept on purpose: the two differ only for an even count of values, and each
// caller keeps the one it has always used so that its results do not move (docs/design.md,
// "Small shared helpers").
#include <vector>

namespace fiberbridge {

/// The median of the finite values of `v`: the middle value, or for an even count the point
/// halfway between the two middle values (computed as lo + 0.5 (hi - lo), bit for bit the 0.5
/// sample quantile of analysis::sample_quantile); NaN when no value is finite. O(n).
/// Used where the median is a reported statistic of a sample (the campaign's G_ss screening).
double median(std::vector<double> v);

/// The upper median of the finite values of `v`: the middle value, or for an even count the
/// larger of the two middle values (std::nth_element at n/2); NaN when no value is finite. O(n).
/// Always one of the values; used for the robust scales (reading spacings, noise levels by MAD,
/// the DIC noise summaries), where it has been the rule since those were written.
double median_upper(std::vector<double> v);

} // namespace fiberbridge
