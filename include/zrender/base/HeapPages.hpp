#pragma once

namespace zrender {

// Asks glibc's malloc to serve the process's blocks below 32 MiB from its main heap, grown
// 128 MiB at a time and never given back, and marks that heap for transparent huge pages
// (where the system grants them on request: Debian's default "madvise"). A fresh process then
// faults its arrays in (the mesh, the frame's geometry, the image's rows) 2 MiB at a time
// instead of 4 KiB: a first write costs a page fault, a few microseconds in a virtual machine,
// and the bunny's process made about 6,000 of them (docs/performance.md, The whole process).
// For a command's main() only, before any thread starts; the blocks of other threads come from
// malloc's arenas of their own, untouched. Returns whether the heap was marked.
bool useHugePagesForHeap();

}  // namespace zrender
