#include "fiberbridge/core/numerical_fault.h"

#include "fiberbridge/core/units.h"

#include <cmath>
#include <limits>
#include <mutex>
#include <sstream>

namespace fiberbridge {

namespace {
// One simulation runs at a time in a process (the scene items and the study run them in turn);
// the mutex only keeps the context readable when a model evaluates its law on several threads.
std::mutex context_mutex;
std::string context_model = "simulation";
std::size_t context_advances = 0;
double context_a = std::numeric_limits<double>::quiet_NaN();
} // namespace

void begin_fault_context(const std::string& model) {
  std::lock_guard<std::mutex> lock(context_mutex);
  context_model = model;
  context_advances = 0;
  context_a = std::numeric_limits<double>::quiet_NaN();
}

std::string fault_location() {
  std::lock_guard<std::mutex> lock(context_mutex);
  std::ostringstream s;
  s << context_model << ", step " << context_advances + 1;
  if (context_advances == 0)
    s << " (before the first tip advance)";
  else
    s << " (after tip advance " << context_advances << ", a = " << context_a / units::mm << " mm)";
  return s.str();
}

void check_finite(double value, const std::string& quantity) {
  if (!std::isfinite(value)) {
    std::ostringstream s;
    s << fault_location() << ": " << quantity << " is " << value
      << " (numerical fault: the run is stopped, no result is written)";
    throw NumericalFault(s.str());
  }
}

void count_fault_step(double a) {
  std::lock_guard<std::mutex> lock(context_mutex);
  ++context_advances;
  context_a = a;
}

} // namespace fiberbridge
