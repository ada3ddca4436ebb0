// Taking cache lines for this core ahead of the stores that need them.
#pragma once

#include <cstddef>
#include <cstdint>

namespace rl {

// Takes every cache line of [first, first + bytes) for this core now, by storing the first byte of each line that
// lies in the range over itself; the bytes keep their values. For data that another core read since this one last
// wrote it: a store to such a line must wait for the line to come back from that core, and in a loop that computes
// between its stores those waits come one after the other, while here they come back to back and overlap.
// (PREFETCHW ahead of the stores did not help on this project's virtual machines, and neither did claiming each
// element a few elements ahead of the loop.) Touches no byte outside the range, so two threads may claim the two
// sides of a line they share.
inline void claimLines(void* first, size_t bytes) {
    volatile char* p = static_cast<char*>(first);
    volatile char* const end = p + bytes;
    while (p < end) {
        *p = *p;
        p = reinterpret_cast<volatile char*>((reinterpret_cast<uintptr_t>(p) | 63) + 1);
    }
}

} // namespace rl
