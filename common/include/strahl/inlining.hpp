// Forced inlining where the course measured it to pay, and none under AddressSanitizer.
//
// STRAHL_FLATTEN: [[gnu::flatten]] (every call inside the function inlined, recursively), where chapters 11
// and 13 measured it to pay. STRAHL_ALWAYS_INLINE: [[gnu::always_inline]], on the small steps of the walks
// (a slab test, a triangle test, a push) that the walks' speed needs inlined into their loops.
// STRAHL_INLINE_LAMBDA: the same for a lambda, written after its parameter list (g++'s attribute form, which
// reaches the lambda's call operator).
//
// Under AddressSanitizer both are nothing. Forcing sanitizer-instrumented code inline made single translation
// units compile for minutes, the longest poles of the sanitizer build (ASan + UBSan at -O1, g++ 12: chapter
// 13's traversal.cpp 128 s flattened, 54 s without; chapter 12's packet_tests.cpp 97 s with always_inline,
// 43 s without). Inlining changes no answer (no FMA contraction anywhere: -ffp-contract=off), and the
// sanitizers check the same accesses either way.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define STRAHL_FLATTEN
#define STRAHL_ALWAYS_INLINE
#define STRAHL_INLINE_LAMBDA
#else
#define STRAHL_FLATTEN [[gnu::flatten]]
#define STRAHL_ALWAYS_INLINE [[gnu::always_inline]]
#define STRAHL_INLINE_LAMBDA __attribute__((always_inline))
#endif
