#pragma once
// One timing loop for the collision-query benchmarks: runs query(i) for
// i in [0, count) per iteration (query returns whether it hit) and reports
// ns_per_query (CPU time: the machine may be shared), queries and hits.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstddef>
#include <ctime>

namespace mq::bench {

template <class Query>
void timeQueries(benchmark::State& state, size_t count, Query&& query) {
  double cpuSeconds = 0.0;
  size_t queries = 0;
  int hits = 0;
  for (auto _ : state) {
    const std::clock_t cpuStart = std::clock();
    hits = 0;
    for (size_t i = 0; i < count; ++i) hits += query(i) ? 1 : 0;
    cpuSeconds += double(std::clock() - cpuStart) / CLOCKS_PER_SEC;
    queries += count;
  }
  state.counters["ns_per_query"] = 1e9 * cpuSeconds / double(std::max<size_t>(1, queries));
  state.counters["queries"] = double(queries) / double(std::max<int64_t>(1, state.iterations()));
  state.counters["hits"] = hits;
}

}  // namespace mq::bench
