#include "world/Profile.h"

namespace rl {

namespace {
constexpr std::string_view kStageNames[kStageCount] = {"update_broadphase",
                                                       "find_pairs",
                                                       "narrowphase",
                                                       "build_islands",
                                                       "prepare_contacts",
                                                       "integrate_velocities",
                                                       "warm_start",
                                                       "solve",
                                                       "integrate_positions",
                                                       "relax",
                                                       "restitution",
                                                       "store_impulses",
                                                       "push_out",
                                                       "ccd",
                                                       "separate",
                                                       "sleep",
                                                       "store_frame"};
constexpr std::string_view kCounterNames[kCounterCount] = {
    "pairs",           "pairs_tested",     "manifolds",       "contact_points",     "normal_rows",
    "friction_rows",   "restitution_rows", "swept_batches",   "awake_bodies",       "integrated_bodies",
    "ccd_bodies",      "ccd_hits",         "steps",           "islands_shared_out", "islands_cut",
    "solved_in_parts", "part_imbalance",   "steps_alone",     "team_steps",         "islands_in_body_order",
    "pushed_contacts", "bounded_bounces",  "separated_pairs", "blow_rows"};
} // namespace

std::string_view stageName(Stage stage) {
    return kStageNames[static_cast<int>(stage)];
}
std::string_view counterName(Counter counter) {
    return kCounterNames[static_cast<int>(counter)];
}

double Profile::totalMs() const {
    double sum = 0.0;
    for (double ms : milliseconds)
        sum += ms;
    return sum;
}

} // namespace rl
