// Large blocks from the heap, reused, instead of fresh mappings.
//
// Why: every edit of a scene copies its sphere list for the render worker
// (and, once edits pause, for the prediction): 88 MB at a million spheres.
// glibc serves blocks that large with mmap and unmaps them when freed, so
// each copy faulted in 21,000 fresh pages: an edit of a million-sphere scene
// took the editor's thread 84 ms, and 29 ms without (bench_editor_gestures).
// From the heap, the block freed by the last copy is there for the next.
#pragma once

namespace whitted {

// Call once, at the start of main(), before any thread starts: glibc's
// mallopt settings are process-wide. A no-op elsewhere.
void reuseHeapForLargeBlocks();

}  // namespace whitted
