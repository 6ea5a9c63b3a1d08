#include "fiberbridge/core/plot.h"

#include "fiberbridge/core/output_guard.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>

namespace fiberbridge {

std::string gnuplot_png_preamble(const std::string& png_name, int width, int height) {
  return "set terminal pngcairo size " + std::to_string(width) + "," + std::to_string(height) +
         " font 'Sans,11'\nset output '" + png_name +
         "'\nset datafile separator ','\nset grid\nset key top left\n";
}

bool run_gnuplot(const std::string& dir, const std::string& script) {
  if (!output_enabled()) // an MPI rank other than 0 (output_guard.h)
    return false;
  static const bool have_gnuplot = std::system("command -v gnuplot >/dev/null 2>&1") == 0;
  if (!have_gnuplot)
    return false;
  const std::string script_path = dir + "/.plot.gp";
  {
    std::ofstream out(script_path);
    out << script;
  }
  const std::string cmd = "cd '" + dir + "' && gnuplot .plot.gp >/dev/null 2>&1";
  const int rc = std::system(cmd.c_str());
  std::remove(script_path.c_str());
  return rc == 0;
}

} // namespace fiberbridge
