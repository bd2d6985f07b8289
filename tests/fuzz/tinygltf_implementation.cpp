// Debian's tinygltf is a shared library built without coverage instrumentation (and with stb_image,
// which Debian's libstb-dev provides and this build does not need): the fuzz binary compiles the
// reader itself, without images (lightpath decodes none, shapes/gltf_loader.cpp), so that fuzz_gltf
// explores glTF's JSON and binary layout with feedback and ASan checks the reader too.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
