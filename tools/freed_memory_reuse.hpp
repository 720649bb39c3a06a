#pragma once
// Rendering a large mesh allocates and frees buffers of tens of megabytes in
// turn (the file's soup, the edge records, the half-edge structure, the
// surface arrays). glibc serves each block over 32 MB with its own mmap and
// hands it back on free, so every one of them is faulted in page by page
// from the kernel again: about a fifth of a 1.2M-triangle render.

namespace umbra {

// Keeps blocks of up to 256 MiB in the heap once freed, for the next
// allocation to reuse (mallopt's M_MMAP_THRESHOLD): every transient of a
// 1.2M-triangle render (90 MB at most) is then reused (measured when this
// was added: 1.53-1.68 s down to 1.30-1.38 s, peak 500 MB up to 577 MB).
// Larger blocks still go to mmap: keeping them too gained
// nothing at 4.8M triangles (bench/check_benchmark.sh measures both). Freed
// memory at the top of the heap is kept too (M_TRIM_THRESHOLD, which
// otherwise stays at 128 KiB once the mmap threshold is set): llvmpipe frees
// and takes again buffers of that size during every draw, and each trim
// faults them in afresh (umbra view of the 1.2M-triangle bunny spent 6-10 s
// of system time in 40 frames that way, 1.2 s without). Every thread
// allocates from the one heap (M_ARENA_MAX 1): a worker thread's arena is a
// string of 64 MiB heaps, which serves any larger block with its own mmap
// and unmaps heaps as they empty, so the loading threads' transients were
// faulted in afresh too (a 4.8M-triangle render: 33,000 faults and 1.49 GB
// down to 7,100 and 1.18 GB, 6.7 s down to 5.3; bench/huge_page_malloc.sh).
// For the commands that render; umbra check keeps glibc's default, to hold
// its memory low and its --jobs threads apart.
void keep_freed_memory_for_reuse();

}  // namespace umbra
