#pragma once
// LIGHTPATH_HOT_PATH puts a function in one output section beside every other function so marked,
// so the linker (GNU ld's default script gathers .text.hot.*) lays the render's per-sample code
// out contiguously. Scattered over the binary, a render's hot code (about 24 KiB, near the 32 KiB
// L1 instruction cache) overfilled some cache sets while others stayed free: callgrind counted
// 2.4 M I1 misses in a 256x256 Whitted render (docs/performance.md, Shading share). Only for
// functions defined in a .cpp file: an inline function has a section of its own per object.
#define LIGHTPATH_HOT_PATH [[gnu::section(".text.hot.lightpath")]]
