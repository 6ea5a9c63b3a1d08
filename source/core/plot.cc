#include "fiberbridge/core/plot.h"

#include "fiberbridge/core/output_guard.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <vector>

namespace fiberbridge {

namespace {
// gnuplot writes each PNG under a temporary name; run_gnuplot renames it into place once gnuplot
// has finished, so a run killed while plotting never leaves half a PNG under the real name.
const std::string partial_suffix = ".partial";

/// The files the script's "set output 'NAME.partial'" lines write, without the suffix.
std::vector<std::string> partial_outputs(const std::string& script) {
  std::vector<std::string> names;
  const std::string key = "set output '";
  for (std::size_t at = script.find(key); at != std::string::npos; at = script.find(key, at + 1)) {
    const std::size_t b = at + key.size(), e = script.find('\'', b);
    if (e == std::string::npos)
      break;
    const std::string name = script.substr(b, e - b);
    if (name.size() > partial_suffix.size() &&
        name.compare(name.size() - partial_suffix.size(), partial_suffix.size(), partial_suffix) ==
            0)
      names.push_back(name.substr(0, name.size() - partial_suffix.size()));
  }
  return names;
}
} // namespace

std::string gnuplot_png_preamble(const std::string& png_name, int width, int height) {
  return "set terminal pngcairo size " + std::to_string(width) + "," + std::to_string(height) +
         " font 'Sans,11'\nset output '" + png_name + partial_suffix +
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
  for (const auto& name : partial_outputs(script)) {
    const std::string done = dir + "/" + name;
    const std::string partial = done + partial_suffix;
    if (rc == 0)
      std::rename(partial.c_str(), done.c_str());
    else
      std::remove(partial.c_str());
  }
  return rc == 0;
}

} // namespace fiberbridge
