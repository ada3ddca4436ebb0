#include "world/TeamPacer.h"

#include <algorithm>

namespace rl {

void TeamPacer::record(double stepSeconds, double waitSeconds) {
    ++m_steps;
    switch (m_mode) {
    case Mode::Team:
        m_stepSum += stepSeconds;
        m_waitSum += waitSeconds;
        if (m_steps < kWindow)
            return;
        if (m_waitSum > m_maxWaitShare * m_stepSum) {
            m_mode = Mode::Alone;
            m_aloneCount = 0;
        }
        break;
    case Mode::Alone:
        m_alone[static_cast<size_t>(m_aloneCount % kAloneSamples)] = stepSeconds;
        ++m_aloneCount;
        if (m_steps < m_backoff)
            return;
        m_mode = Mode::Probe;
        break;
    case Mode::Probe: {
        const int aloneSamples = std::min(m_aloneCount, kAloneSamples);
        double aloneSum = 0.0;
        for (int k = 0; k < aloneSamples; ++k)
            aloneSum += m_alone[static_cast<size_t>(k)];
        const double aloneMean = aloneSamples > 0 ? aloneSum / aloneSamples : 0.0;
        // The first step of a try is not counted (the others wake, their caches cold), unless member 0 waited in it
        // longer than kProbeGiveUp steps alone: the others are not running, and the try is lost already.
        const bool lost = m_steps == 1 && waitSeconds > kProbeGiveUp * aloneMean;
        if (m_steps > 1) {
            m_stepSum += stepSeconds;
            m_waitSum += waitSeconds;
        }
        if (m_steps < kProbeSteps && !lost)
            return;
        // The team comes back if its counted steps were faster than the last steps alone (by kProbeGain) and member
        // 0 waited in them no more than it may while the team steps (above).
        const double probeMean = m_stepSum / (kProbeSteps - 1);
        if (!lost && aloneSamples > 0 && probeMean < kProbeGain * aloneMean &&
            m_waitSum <= m_maxWaitShare * m_stepSum) {
            m_mode = Mode::Team;
            m_backoff = kFirstBackoff;
        } else {
            m_mode = Mode::Alone;
            m_aloneCount = 0;
            m_backoff = std::min(kBackoffGrowth * m_backoff, kMaxBackoff);
        }
        break;
    }
    }
    m_steps = 0;
    m_stepSum = m_waitSum = 0.0;
}

} // namespace rl
