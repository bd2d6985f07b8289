// Debian's toml++ is a shared library built without coverage instrumentation: libFuzzer would see
// nothing of the TOML parser. The fuzz binary compiles the parser's implementation itself (with
// -fsanitize=fuzzer-no-link and the sanitizers); its definitions take precedence over the
// library's, so fuzz_scene explores TOML syntax with feedback and ASan checks the parser too.
#define TOML_IMPLEMENTATION 1
#include <toml++/toml.h>
