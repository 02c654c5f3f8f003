// Embree's own account of itself, read once from the report a device prints when created with verbose=1:
// its version, the instruction sets this CPU supports and those the library was compiled for, and so the
// kernels it runs (the widest in both lists). Empty strings where the course was built without Embree.
// The race names it beside its table, and every measured CSV records the kernels (machine.hpp).
#pragma once
#include <string>

namespace strahl {

struct embree_report {
    std::string version;    // "3.13.5"
    std::string supported;  // "SSE2 SSE4.2 AVX AVX2 AVX512"
    std::string compiled;   // "SSE2 SSE4.2 AVX AVX2 AVX512"
    std::string kernels;    // "AVX512": the widest target in both
    std::string summary() const;  // "Embree 3.13.5, AVX512 kernels", or "no Embree"
};
const embree_report& embree_configuration();

}  // namespace strahl
