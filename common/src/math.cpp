// Printing GLM vectors (strahl/math.hpp).
#include "strahl/math.hpp"
#include <ostream>

namespace glm {

namespace {
template <class V>
std::ostream& print(std::ostream& os, const V& v) {
    const auto old = os.precision(9);
    os << '(';
    for (int i = 0; i < V::length(); ++i) os << (i ? ", " : "") << v[i];
    os.precision(old);
    return os << ')';
}
}  // namespace

std::ostream& operator<<(std::ostream& os, const vec2& v) { return print(os, v); }
std::ostream& operator<<(std::ostream& os, const vec3& v) { return print(os, v); }
std::ostream& operator<<(std::ostream& os, const ivec3& v) { return print(os, v); }
std::ostream& operator<<(std::ostream& os, const uvec3& v) { return print(os, v); }

}  // namespace glm
