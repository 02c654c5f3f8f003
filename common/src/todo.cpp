// STRAHL_TODO's body, compiled once (see strahl/todo.hpp).
#include "strahl/todo.hpp"

namespace strahl {

void todo(const char* id, const char* file, int line) { throw not_implemented(id, file, line); }

}  // namespace strahl
