// The median the benchmarks print: the middle value, or the mean of the two middle ones; 0 for no values.
#pragma once

#include <algorithm>
#include <vector>

namespace rl::bench {

inline double median(std::vector<double> v) {
    if (v.empty())
        return 0.0;
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

} // namespace rl::bench
