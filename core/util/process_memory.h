#pragma once
// This process's memory as the kernel counts it (Linux /proc/self/status),
// for the long-run checks that memory stays flat. 0 when unknown.

namespace mq {

double residentMegabytes();      // VmRSS
double peakResidentMegabytes();  // VmHWM

}  // namespace mq
