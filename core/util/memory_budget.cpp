#include "core/util/memory_budget.h"

#include <cstdlib>

#include "core/util/error.h"

namespace mq {

size_t memoryBudgetBytes() {
  constexpr size_t kDefaultMegabytes = 8192;
  const char* given = std::getenv("MANNEQUIN_MEMORY_LIMIT_MB");
  const long long megabytes = given ? std::atoll(given) : 0;
  return size_t(megabytes > 0 ? megabytes : kDefaultMegabytes) << 20;
}

void checkMemoryBudget(const std::string& what, double bytes) {
  const size_t budget = memoryBudgetBytes();
  if (bytes <= double(budget)) return;
  throw Error(what + " would need about " + std::to_string(static_cast<long long>(bytes / 1048576.0)) +
              " MB (the limit is " + std::to_string(budget >> 20) + " MB; MANNEQUIN_MEMORY_LIMIT_MB sets it)");
}

}  // namespace mq
