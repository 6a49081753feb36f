#include "core/util/process_memory.h"

#include <fstream>
#include <string>

namespace mq {
namespace {

double statusKilobytes(const std::string& field) {
  std::ifstream status("/proc/self/status");
  std::string name;
  double kilobytes = 0.0;
  while (status >> name) {
    if (name == field + ":" && status >> kilobytes) return kilobytes;
    status.ignore(4096, '\n');
  }
  return 0.0;
}

}  // namespace

double residentMegabytes() { return statusKilobytes("VmRSS") / 1024.0; }
double peakResidentMegabytes() { return statusKilobytes("VmHWM") / 1024.0; }

}  // namespace mq
