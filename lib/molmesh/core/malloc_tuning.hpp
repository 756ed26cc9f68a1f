#pragma once
// Allocator settings for molmesh's programs (today the CLI only). The library never
// calls this itself: process-wide allocator behaviour is the program's choice, not a
// library's (a Python session keeps the interpreter's).
namespace molmesh {

// Keeps freed large blocks in the heap for reuse instead of handing them back to the kernel.
// By default glibc serves blocks above a threshold (128 KiB, rising as large blocks are
// freed) with fresh mmap pages and trims the heap top eagerly, so every stage that frees and
// reallocates arrays of a few MB (matrices, vectors, grids) pays a page fault per 4 KiB
// again; which stage pays depends on the order of earlier frees. Fixed thresholds make the
// reuse predictable. Measured: docs/benchmarks.md (issue 16, "Session 17"). Costs up
// to ~10 % more peak memory. Does nothing outside glibc.
void keep_freed_memory_for_reuse();

}  // namespace molmesh
