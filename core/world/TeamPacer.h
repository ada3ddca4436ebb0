// Whether a world's thread team pays, step by step. A step gives the same frames on any number of threads, so the
// world may take each step on its team or on member 0 alone as the machine allows. On a machine whose other cores
// are busy (another program, a second bake), a member of the team is taken off its core for milliseconds at a time,
// and every barrier waits for it: with one busy program beside it on this project's two-core machine, a 10 s bake of
// ramps.obj took 4.9-6.0 s on two threads against 0.90-1.27 s on one (2026-12-02). Then the world steps alone.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

namespace rl {

enum class TeamPacing {
    Adaptive,       // the team while it pays (TeamPacer), alone while it does not
    Always,         // every step on the team (the tests that count what the team did)
    EveryOtherStep, // the team and alone by turns, whatever the timing (the tests of the switch)
};

class TeamPacer {
public:
    // Team steps judged at a time.
    static constexpr int kWindow = 8;
    // Steps alone before the team is tried again, four times as many after each try that lost, up to the most. On a
    // busy machine a try is costly: ramps.obj with another program on the second core took 6-10 ms a team step
    // against 1.4 ms alone, and once 49 ms. With tries after 8, 16, 32, ... steps alone, each of three team steps,
    // the team's steps took 0.28 and 0.31 s of 600-frame runs that took 0.99 and 1.06 s on two threads against 0.85
    // and 0.78 s on one (2026-12-02).
    static constexpr int kFirstBackoff = 4;
    static constexpr int kBackoffGrowth = 4;
    static constexpr int kMaxBackoff = 512;
    // A try is this many team steps; the first is not counted (the other members were asleep, their caches cold).
    // The team comes back if its counted steps took less than kProbeGain of the last steps alone and member 0 waited
    // in them no more than it may while the team steps (maxWaitShare()). A try in whose first step member 0 waited
    // longer than kProbeGiveUp of the last steps alone ends there: the others are not running. (Until 2026-12-06 the
    // first step's whole time was compared: a try that began on a frame costlier than its neighbours was lost and the
    // backoff grew. In ramps.obj's early frames, every fourth or fifth costs 2-5 times the others; in 10 of 20 runs
    // of its first 120 frames on two threads, two tries were lost so and the world stepped 84 frames alone, at 2.1
    // ms a step against 1.2 on the team. With the worker's move of ThreadTeam.cpp, 3 of 20 runs stepped 4 frames
    // alone and none more: 127 ms for the 120 frames on average against 168. tests/benchmarks/LOG.md, 2026-12-06.)
    static constexpr int kProbeSteps = 3;
    static constexpr double kProbeGain = 0.9;
    static constexpr double kProbeGiveUp = 1.5;

    // For a team of `teamSize` threads (at least 2).
    explicit TeamPacer(int teamSize = 2) : m_maxWaitShare(1.0 - 1.0 / std::max(teamSize, 2)) {}

    // Whether the next step runs on the team.
    bool useTeam() const { return m_mode != Mode::Alone; }
    // The step that just ran, as useTeam() said: its wall time and how long member 0 waited for the others (s).
    //
    // On the team, member 0 was busy for step - wait. Each other member's share of the work is at most about as
    // much (the team's jobs are shared out evenly, and member 0 also does the serial parts), so alone the step
    // would take at most n (step - wait) on a team of n: less than the step itself once member 0 waits more than
    // 1 - 1/n of it (half, on two threads). Over a window of team steps where it does, the world goes alone; after
    // a backoff it tries the team again, and keeps it if its steps are faster than the last ones alone.
    void record(double stepSeconds, double waitSeconds);

    int backoff() const { return m_backoff; }
    double maxWaitShare() const { return m_maxWaitShare; }

private:
    enum class Mode { Team, Alone, Probe };
    static constexpr int kAloneSamples = 4;
    double m_maxWaitShare; // member 0's share of waiting above which the team does not pay
    Mode m_mode = Mode::Team;
    int m_steps = 0; // in the current window, stretch alone or try
    double m_stepSum = 0.0, m_waitSum = 0.0;
    std::array<double, kAloneSamples> m_alone{}; // the last steps alone, round robin
    int m_aloneCount = 0;
    int m_backoff = kFirstBackoff;
};

} // namespace rl
