#pragma once
#include <string>

namespace lightpath {

// "Intel(R) Xeon(R) ... (vendor Intel, family 6 model 85), 2 hardware threads": benchmarks say
// which machine, and which vendor's microarchitecture, measured them.
std::string describeMachine();

}  // namespace lightpath
