#include "bench/machine.h"

#include <cstring>
#include <thread>

#if defined(__x86_64__) || defined(__i386__)
#include <cpuid.h>
#else
#include <fstream>
#endif

namespace lightpath {
namespace {

// The vendor and the family/model numbers name the microarchitecture, which a virtual machine's
// model string ("AMD EPYC") often does not: traversal figures differ between vendors (issue #27).
std::string processorIdentity() {
#if defined(__x86_64__) || defined(__i386__)
    unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
    if (__get_cpuid(0, &eax, &ebx, &ecx, &edx) == 0) return "unknown vendor";
    char vendorId[13] = {};
    std::memcpy(vendorId, &ebx, 4);
    std::memcpy(vendorId + 4, &edx, 4);
    std::memcpy(vendorId + 8, &ecx, 4);
    std::string vendor = vendorId;
    if (vendor == "GenuineIntel") vendor = "Intel";
    else if (vendor == "AuthenticAMD") vendor = "AMD";

    std::string brand;
    if (__get_cpuid(0x80000000u, &eax, &ebx, &ecx, &edx) != 0 && eax >= 0x80000004u) {
        char text[49] = {};
        for (unsigned leaf = 0; leaf < 3; ++leaf) {
            unsigned regs[4];
            __get_cpuid(0x80000002u + leaf, &regs[0], &regs[1], &regs[2], &regs[3]);
            std::memcpy(text + 16 * leaf, regs, 16);
        }
        brand = text;
        brand.erase(0, brand.find_first_not_of(' '));
        brand.erase(brand.find_last_not_of(' ') + 1);
    }
    // Family and model as the vendors' manuals define them (extended fields added when family is 0xF,
    // or 6 for Intel's model).
    __get_cpuid(1, &eax, &ebx, &ecx, &edx);
    const unsigned baseFamily = (eax >> 8) & 0xF, baseModel = (eax >> 4) & 0xF;
    const unsigned family = baseFamily == 0xF ? baseFamily + ((eax >> 20) & 0xFF) : baseFamily;
    const unsigned model = baseFamily == 0xF || baseFamily == 6 ? baseModel + (((eax >> 16) & 0xF) << 4) : baseModel;
    return (brand.empty() ? "unknown model" : brand) + " (vendor " + vendor + ", family " + std::to_string(family) +
           " model " + std::to_string(model) + ")";
#else
    std::ifstream cpuinfo("/proc/cpuinfo");
    for (std::string line; std::getline(cpuinfo, line);)
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2) + " (vendor unknown)";
    return "unknown CPU (vendor unknown)";
#endif
}

}  // namespace

std::string describeMachine() {
    return processorIdentity() + ", " + std::to_string(std::thread::hardware_concurrency()) + " hardware threads";
}

}  // namespace lightpath
