// track_name() for the programs linked with the exercises track (strahl/program.hpp).
#include "strahl/program.hpp"

const char* strahl::track_name() { return "exercises"; }
