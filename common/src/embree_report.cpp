// What Embree runs on this machine (embree_report.hpp): its version and the instruction set of the kernels
// it chose, read from a verbose device's own report. Compiled with STRAHL_HAVE_EMBREE where Embree was found.
#include "strahl/embree_report.hpp"

namespace strahl {

std::string embree_report::summary() const {
    if (version.empty()) return "no Embree";
    return "Embree " + version + ", " + (kernels.empty() ? std::string("unknown") : kernels) + " kernels";
}

}  // namespace strahl

#ifndef STRAHL_HAVE_EMBREE

namespace strahl {
const embree_report& embree_configuration() {
    static const embree_report none;
    return none;
}
}  // namespace strahl

#else

#include "strahl/denormals.hpp"
#include <embree3/rtcore.h>
#include <iostream>
#include <sstream>
#include <string>

namespace strahl {

const embree_report& embree_configuration() {
    static const embree_report report = [] {
        embree_report r;
        // A device created with verbose=1 prints Embree's configuration on std::cout (the same stream object:
        // libstdc++ is shared), read here through a string buffer.
        std::ostringstream captured;
        std::streambuf* const saved = std::cout.rdbuf(captured.rdbuf());
        RTCDevice device;
        {
            const denormals_flushed flushed;
            device = rtcNewDevice("verbose=1,threads=1");
        }
        std::cout.rdbuf(saved);
        if (!device) return r;
        const long v = long(rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_VERSION));
        r.version = std::to_string(v / 10000) + "." + std::to_string(v / 100 % 100) + "." + std::to_string(v % 100);
        rtcReleaseDevice(device);
        // "    Targets : SSE2 SSE4.2 AVX AVX2 AVX512  (supported)" then "    ... (compile time enabled)".
        std::istringstream lines(captured.str());
        for (std::string line; std::getline(lines, line);) {
            const auto list = [&](const char* tag) {
                const std::size_t end = line.find(tag);
                if (end == std::string::npos) return false;
                std::size_t begin = line.find("Targets :");
                begin = begin == std::string::npos ? 0 : begin + 9;
                std::istringstream words(line.substr(begin, end - begin));
                std::string all, w;
                while (words >> w) all += (all.empty() ? "" : " ") + w;
                (std::string(tag) == "(supported)" ? r.supported : r.compiled) = all;
                return true;
            };
            if (!list("(supported)")) list("(compile time enabled)");
        }
        // Embree runs the widest target both compiled in and supported by the CPU.
        std::istringstream supported(r.supported);
        for (std::string t; supported >> t;)
            if ((" " + r.compiled + " ").find(" " + t + " ") != std::string::npos) r.kernels = t;
        return r;
    }();
    return report;
}

}  // namespace strahl

#endif
