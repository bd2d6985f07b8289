// A loadable shared module without lightpath's image entry point: the image module check's
// "foreign library" case (tests/CMakeLists.txt, cli/image-module-foreign).
extern "C" __attribute__((visibility("default"))) int notAnImageCodec() { return 42; }
