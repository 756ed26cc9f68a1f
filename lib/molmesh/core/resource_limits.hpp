#pragma once
// Memory limits stated and enforced before large allocations (docs/cli.md, "Resource
// limits"): a grid or mesh that would need more than the limit stops at once with the amount
// it would take and the option to change, instead of being killed by the OOM killer or
// swapping for minutes.
#include <string>

namespace molmesh {

// Half the physical memory (sysconf), the default of --max-memory: room for the rest of the
// process and the system. 4 GiB when the size cannot be determined.
double default_memory_limit();

// Throws Error "<what> would need <bytes>, more than the memory limit of <limit>
// (--max-memory); <hint>" when bytes > limit.
void check_memory(double bytes, double limit, const std::string& what, const std::string& hint);

// "1.5 GB", "820 MB": for messages.
std::string format_bytes(double bytes);

}  // namespace molmesh
