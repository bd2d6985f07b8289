#pragma once
// Documented exit codes of the lightpath command (README, "Errors and limits").
namespace lightpath {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;     // a run that could not complete (e.g. output not writable)
inline constexpr int kExitBadInput = 2;    // bad arguments, scene file or light path expression

}  // namespace lightpath
