// The namespace that holds code compiled for one instruction set.
//
// The tracer's hot kernel is compiled once per instruction set (baseline
// x86-64, x86-64-v2, x86-64-v3, x86-64-v4; core/CMakeLists.txt), each object with
// WHITTED_ISA naming its set. Every inline function and template those objects
// compile (packets, lane operations, intersection) lives in
// whitted::isa_<WHITTED_ISA>, so its mangled name carries the set: the linker
// cannot merge an AVX2 copy into the baseline path, which would crash with
// SIGILL on an older CPU. Code built with the project's own flags uses
// whitted::isa_build. The namespace is inline: callers write whitted::RayPacket.
#pragma once

#ifndef WHITTED_ISA
#define WHITTED_ISA build
#endif

#define WHITTED_ISA_JOIN2(a, b) a##b
#define WHITTED_ISA_JOIN(a, b) WHITTED_ISA_JOIN2(a, b)
#define WHITTED_ISA_NAMESPACE WHITTED_ISA_JOIN(isa_, WHITTED_ISA)
#define WHITTED_ISA_STR2(a) #a
#define WHITTED_ISA_STR(a) WHITTED_ISA_STR2(a)
