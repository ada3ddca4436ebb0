// Both mains' first call: the process asks glibc for 2 MiB pages under its heap, then starts itself again.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

// (After the standard headers, which define __GLIBC__.)
#if defined(__linux__) && defined(__GLIBC__)
#include <gnu/libc-version.h>
#include <unistd.h>
#endif

namespace rl::app {

// The kernel's setting for transparent huge pages, the bracketed word of /sys/kernel/mm/transparent_hugepage/enabled
// ("always", "madvise" or "never"), or "unknown".
inline std::string transparentHugePagesMode() {
#if defined(__linux__)
    std::FILE* setting = std::fopen("/sys/kernel/mm/transparent_hugepage/enabled", "r");
    if (!setting)
        return "unknown";
    char mode[128] = {};
    const size_t read = std::fread(mode, 1, sizeof mode - 1, setting);
    std::fclose(setting);
    const std::string text(mode, read);
    const size_t open = text.find('['), close = text.find(']');
    if (open != std::string::npos && close != std::string::npos && close > open)
        return text.substr(open + 1, close - open - 1);
#endif
    return "unknown";
}

// A big scene's step reads its contact manifolds and bodies in the solver's order, not in the order they lie in
// memory, and on 4 KiB pages the 5,050-cube pyramid's step touches more pages than the core's TLB holds. glibc
// (2.35 on) puts its heap on transparent 2 MiB pages when the tunable glibc.malloc.hugetlb=1 is set, which its loader
// reads only when a process starts: so where the kernel gives such pages on request (transparent_hugepage "madvise",
// the setting of Debian and of the machines measured), the process sets it and executes itself again, once, with
// the same arguments. Measured on an AMD EPYC (Zen 3) machine, 2026-12-07: large_pyramid's first 45 frames faster
// in 28 of 40 pairs of runs at once on the two CPUs, 32.2 ms a step against 33.8 on average (tests/benchmarks/LOG.md).
// The frames are the same either way (the pages change where data lie, not what is computed).
//
// Left alone: other systems; the tunable already given (by the user, or by the first start); RIGIDLAB_HUGE_PAGES=0;
// a run under valgrind, whose tools would lose the restarted process; the kernel's setting "always" (nothing to ask
// for) or "never" (nothing to get). If the restart fails, the process goes on as it is.
inline void useHugePages(char* argv[]) {
#if defined(__linux__) && defined(__GLIBC__)
    const char* optOut = std::getenv("RIGIDLAB_HUGE_PAGES");
    if (optOut && std::strcmp(optOut, "0") == 0)
        return;
    const char* tunables = std::getenv("GLIBC_TUNABLES");
    if (tunables && std::strstr(tunables, "glibc.malloc.hugetlb"))
        return;
    const char* preload = std::getenv("LD_PRELOAD");
    if (preload && std::strstr(preload, "vgpreload"))
        return;
    int major = 0, minor = 0;
    if (std::sscanf(gnu_get_libc_version(), "%d.%d", &major, &minor) != 2 || major < 2 || (major == 2 && minor < 35))
        return;
    if (transparentHugePagesMode() != "madvise")
        return;
    std::string value = "glibc.malloc.hugetlb=1";
    if (tunables && *tunables)
        value = std::string(tunables) + ":" + value;
    if (setenv("GLIBC_TUNABLES", value.c_str(), 1) != 0)
        return;
    execv("/proc/self/exe", argv);
    // Not restarted: go on without (the tunable stays set, so a child started from here has it).
#else
    (void)argv;
#endif
}

// For bench's report: the kernel's setting for transparent huge pages and glibc's tunable as this process has it,
// e.g. "transparent huge pages madvise, glibc.malloc.hugetlb=1" (or "... hugetlb not set").
inline std::string hugePagesDescription() {
#if defined(__linux__) && defined(__GLIBC__)
    std::string tunable = "glibc.malloc.hugetlb not set";
    if (const char* tunables = std::getenv("GLIBC_TUNABLES")) {
        const std::string all(tunables), key = "glibc.malloc.hugetlb=";
        if (const size_t at = all.find(key); at != std::string::npos) {
            const size_t end = all.find(':', at);
            tunable = all.substr(at, end == std::string::npos ? std::string::npos : end - at);
        }
    }
    return "transparent huge pages " + transparentHugePagesMode() + ", " + tunable;
#else
    return "not known on this system";
#endif
}

} // namespace rl::app
