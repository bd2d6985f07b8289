#pragma once
#include <string>

namespace lightpath {

// "Intel(R) Xeon(R) ... , 2 hardware threads": benchmarks say which machine measured them.
std::string describeMachine();

}  // namespace lightpath
