// STRAHL_FLATTEN: [[gnu::flatten]] (every call inside the function inlined, recursively) where chapters 11
// and 13 measured it to pay, and nothing under AddressSanitizer. Flattening sanitizer-instrumented code
// made single translation units compile for two minutes and more (chapter 13's traversal.cpp, ASan + UBSan
// at -O1, g++ 12: 128 s with it, 54 s without), the longest poles of the sanitizer build. Inlining changes
// no answer, and the sanitizers check the same accesses either way.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define STRAHL_FLATTEN
#else
#define STRAHL_FLATTEN [[gnu::flatten]]
#endif
