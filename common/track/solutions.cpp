// track_name() for the programs linked with the solutions track (strahl/program.hpp).
#include "strahl/program.hpp"

const char* strahl::track_name() { return "solutions"; }
