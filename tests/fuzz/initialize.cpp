// libFuzzer calls LLVMFuzzerInitialize once, before any input; every fuzz_<name> binary links this.
//
// libstdc++ counts shared_ptr references without atomics while glibc says the process has never
// started a thread (__libc_single_threaded), and libFuzzer starts its own watchdog thread at a
// moment that depends on timing. So the same input took different branches from run to run, and
// the gate's corpus differed between two runs of one commit (tests/fuzz/README.md). One thread
// started and joined here makes the process multi-threaded for good before the first input.
#include <thread>

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    std::thread([] {}).join();
    return 0;
}
