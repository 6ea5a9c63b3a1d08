#pragma once
// PNG plots through gnuplot. A missing gnuplot is not an error of the analysis: the CSV files
// hold the numbers; plot() then returns false and the caller reports that no PNG was made.
#include <string>

namespace fiberbridge {

/// Runs `script` (gnuplot commands; the caller sets the output file) in directory `dir`.
/// Returns true when gnuplot ran and exited 0.
bool run_gnuplot(const std::string& dir, const std::string& script);

/// Common preamble: PNG terminal of a readable size, grid, key placement.
std::string gnuplot_png_preamble(const std::string& png_name, int width = 900, int height = 600);

} // namespace fiberbridge
