#include "report/machine.hpp"

#include <fstream>
#include <thread>

#include "dyop/batch.hpp"

namespace dyop::report {

std::string machine_description() {
  std::string model = "unknown CPU";
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);) {
    if (line.rfind("model name", 0) != 0) continue;
    const std::size_t colon = line.find(':');
    if (colon != std::string::npos && colon + 2 <= line.size()) model = line.substr(colon + 2);
    break;
  }
  return model + ", " + std::to_string(std::thread::hardware_concurrency()) + " hardware threads";
}

std::string batch_kernel_description() {
  return std::string("batch kernel ") + name(batch_kernel_used());
}

}  // namespace dyop::report
