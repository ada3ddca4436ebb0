#include "world/IslandShare.h"

#include <algorithm>
#include <numeric>

namespace rl {

void shareIslandsOut(std::span<const uint32_t> work, size_t members, uint64_t inOrderPercent, IslandShare& out) {
    members = std::max<size_t>(members, 1);
    out.member.assign(work.size(), 0);
    out.all = std::accumulate(work.begin(), work.end(), uint64_t{0});
    out.inBodyOrder = true;
    if (out.all == 0 || members == 1) {
        out.largest = out.all;
        return;
    }
    uint64_t before = 0;
    for (size_t k = 0; k < work.size(); ++k) {
        const uint64_t middle = 2 * before + work[k]; // twice the work up to the island's middle
        out.member[k] = static_cast<uint32_t>(std::min<uint64_t>(members - 1, middle * members / (2 * out.all)));
        before += work[k];
    }
    thread_local std::vector<uint64_t> total;
    total.assign(members, 0);
    for (size_t k = 0; k < work.size(); ++k)
        total[out.member[k]] += work[k];
    out.largest = *std::max_element(total.begin(), total.end());
    if (100 * out.largest * members <= inOrderPercent * out.all)
        return;

    out.inBodyOrder = false;
    thread_local std::vector<uint32_t> order;
    order.resize(work.size());
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(),
              [&](uint32_t l, uint32_t r) { return work[l] != work[r] ? work[l] > work[r] : l < r; });
    total.assign(members, 0);
    for (const uint32_t k : order) {
        const size_t least = static_cast<size_t>(std::min_element(total.begin(), total.end()) - total.begin());
        total[least] += work[k];
        out.member[k] = static_cast<uint32_t>(least);
    }
    out.largest = *std::max_element(total.begin(), total.end());
}

} // namespace rl
