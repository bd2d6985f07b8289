// Debian's tinyobjloader is a shared library built without coverage instrumentation: libFuzzer
// would see nothing of the OBJ/MTL parser. The fuzz binary compiles the parser itself (with
// -fsanitize=fuzzer-no-link and the sanitizers); its definitions take precedence over the
// library's, so fuzz_obj explores OBJ syntax with feedback and ASan checks the parser too.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
