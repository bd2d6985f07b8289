#pragma once
// Documented exit codes of the lightpath command (docs/robustness.md, "Errors and limits").
namespace lightpath {

inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;     // a run that could not complete (e.g. output not writable)
inline constexpr int kExitBadInput = 2;    // bad arguments, scene file or light path expression
inline constexpr int kExitInterrupted = 130;  // Ctrl-C (128 + SIGINT, the shell's convention)

}  // namespace lightpath
