// How a team of threads shares a group's islands out, each island to one member (World::splitByIslands()). Islands
// share no moving body, so any share gives the same frames; what it decides is the balance of the members' work and
// which core holds a body's data from one stage and one step to the next.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rl {

struct IslandShare {
    std::vector<uint32_t> member; // per island, in the order given
    bool inBodyOrder = false;     // the islands went to the members in runs of the order given
    uint64_t largest = 0;         // the most work on one member
    uint64_t all = 0;             // the work of all the islands
};

// `work`: each island's work (bodies plus contacts), listed by its first body. First the islands are tried in runs
// of that order: member m takes those whose work falls mostly in the m-th share of the whole, which keeps each member
// on bodies next to each other in the body order, as the passes over bodies and pairs between solves share them out.
// That is kept when no member gets more than inOrderPercent / members percent of the work (102: 51 % of it on one of
// two); else the islands go largest first, each to the least loaded member (ties: the earlier island). `out`'s
// vectors keep their memory from call to call.
void shareIslandsOut(std::span<const uint32_t> work, size_t members, uint64_t inOrderPercent, IslandShare& out);

} // namespace rl
