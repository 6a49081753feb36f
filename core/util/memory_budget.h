#pragma once
// What one job (a groom, a bake, a simulation's cache) may ask for, checked
// before allocating so a document cannot exhaust the machine: 8 GiB unless
// $MANNEQUIN_MEMORY_LIMIT_MB says otherwise.

#include <cstddef>
#include <string>

namespace mq {

size_t memoryBudgetBytes();

// Throws Error("<what> would need about N MB (the limit is M MB; ...)") when
// `bytes` exceeds the budget.
void checkMemoryBudget(const std::string& what, double bytes);

}  // namespace mq
