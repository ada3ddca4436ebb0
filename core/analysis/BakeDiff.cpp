#include "analysis/BakeDiff.h"

#include "io/CsvWriter.h"
#include "io/NumberFormat.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace rl {

Real rotationDeltaDegrees(const glm::quat& a, const glm::quat& b) {
    // conj(a) * b in double. Its vector part is exactly zero for equal inputs, so atan2 gives exactly 0 there,
    // where 2 acos(w) would turn the rounding of |q| into a few hundredths of a degree.
    const Quat qa(a.w, a.x, a.y, a.z);
    const Quat qb(b.w, b.x, b.y, b.z);
    const Quat r = glm::conjugate(qa) * qb;
    const Real s = std::sqrt(r.x * r.x + r.y * r.y + r.z * r.z);
    return 2.0 * std::atan2(s, std::abs(r.w)) * 180.0 / kPi; // q and -q are the same rotation
}

BakeDiffResult diffBakes(const Bake& a, const Bake& b, const BakeDiffOptions& options) {
    BakeDiffResult result;
    result.framesA = a.frameCount();
    result.framesB = b.frameCount();
    if (a.bodyCount() != b.bodyCount()) {
        result.incompatibility = "the bakes have different bodies: " + std::to_string(a.bodyCount()) + " and " +
                                 std::to_string(b.bodyCount());
        return result;
    }
    if (a.fps() != b.fps()) {
        result.incompatibility =
            "the bakes have different frame rates: " + formatDouble(a.fps()) + " and " + formatDouble(b.fps()) + " fps";
        return result;
    }
    result.framesCompared = std::min(a.frameCount(), b.frameCount());
    result.bodies.resize(a.bodyCount());
    for (size_t i = 0; i < a.bodyCount(); ++i) {
        result.bodies[i].body = i;
        result.bodies[i].name = a.body(i).name;
    }
    for (size_t f = 0; f < result.framesCompared; ++f) {
        for (size_t i = 0; i < a.bodyCount(); ++i) {
            BakeBodyDiff& d = result.bodies[i];
            const Real dp = glm::length(a.vertexMean(f, i) - b.vertexMean(f, i));
            const Real dr = rotationDeltaDegrees(a.rotation(f, i), b.rotation(f, i));
            // NaN in either bake counts as a divergence (and as the largest delta).
            const bool nanPosition = std::isnan(dp), nanRotation = std::isnan(dr);
            if (nanPosition || dp > d.maxPositionDelta) {
                if (!std::isinf(d.maxPositionDelta)) {
                    d.maxPositionDelta = nanPosition ? std::numeric_limits<Real>::infinity() : dp;
                    d.maxPositionFrame = f;
                }
            }
            if (nanRotation || dr > d.maxRotationDegrees) {
                if (!std::isinf(d.maxRotationDegrees)) {
                    d.maxRotationDegrees = nanRotation ? std::numeric_limits<Real>::infinity() : dr;
                    d.maxRotationFrame = f;
                }
            }
            const bool diverged =
                nanPosition || nanRotation || dp > options.positionTolerance || dr > options.rotationToleranceDegrees;
            if (diverged && !d.firstDivergingFrame) {
                d.firstDivergingFrame = f;
                if (!result.firstDivergingFrame) {
                    result.firstDivergingFrame = f;
                    result.firstDivergingBody = i;
                }
            }
        }
    }
    return result;
}

namespace {

std::string number(Real value, const char* format) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, value);
    return buffer;
}

} // namespace

std::string formatBakeDiff(const BakeDiffResult& result, const BakeDiffOptions& options) {
    if (!result.comparable())
        return "not comparable: " + result.incompatibility + "\n";
    std::string text;
    const std::string tolerances = "tolerance " + formatDouble(options.positionTolerance) + " m, " +
                                   formatDouble(options.rotationToleranceDegrees) + " deg";
    if (result.equal()) {
        text = "equal within " + tolerances + " over " + std::to_string(result.framesCompared) + " frames\n";
    } else if (result.firstDivergingFrame) {
        text = "first diverging frame " + std::to_string(*result.firstDivergingFrame) + " (body " +
               std::to_string(*result.firstDivergingBody) + " '" + result.bodies[*result.firstDivergingBody].name +
               "'), " + tolerances + "\n";
    } else {
        text =
            "equal within " + tolerances + " over the " + std::to_string(result.framesCompared) + " frames both have\n";
    }
    if (result.framesA != result.framesB)
        text +=
            "frame counts differ: " + std::to_string(result.framesA) + " and " + std::to_string(result.framesB) + "\n";
    std::vector<const BakeBodyDiff*> differing;
    for (const BakeBodyDiff& d : result.bodies)
        if (d.maxPositionDelta > 0.0 || d.maxRotationDegrees > 0.0)
            differing.push_back(&d);
    if (differing.empty())
        return text;
    std::stable_sort(differing.begin(), differing.end(), [](const BakeBodyDiff* x, const BakeBodyDiff* y) {
        return x->maxPositionDelta > y->maxPositionDelta;
    });
    text += "  body  first   max_pos_m  at_frame    max_rot_deg  at_frame  name\n";
    for (const BakeBodyDiff* d : differing) {
        text += number(static_cast<Real>(d->body), "%6.0f") + "  " +
                (d->firstDivergingFrame ? number(static_cast<Real>(*d->firstDivergingFrame), "%5.0f")
                                        : std::string("    -")) +
                "  " + number(d->maxPositionDelta, "%10.3e") + "  " +
                number(static_cast<Real>(d->maxPositionFrame), "%8.0f") + "  " +
                number(d->maxRotationDegrees, "%13.3e") + "  " +
                number(static_cast<Real>(d->maxRotationFrame), "%8.0f") + "  " + d->name + "\n";
    }
    return text;
}

std::string bakeDiffCsv(const BakeDiffResult& result) {
    std::string text =
        "body,name,first_diverging_frame,max_position_delta,max_position_frame,max_rotation_deg,max_rotation_frame\n";
    for (const BakeBodyDiff& d : result.bodies) {
        text += std::to_string(d.body) + ',' + csvField(d.name) + ',' +
                (d.firstDivergingFrame ? std::to_string(*d.firstDivergingFrame) : std::string()) + ',' +
                formatDouble(d.maxPositionDelta) + ',' + std::to_string(d.maxPositionFrame) + ',' +
                formatDouble(d.maxRotationDegrees) + ',' + std::to_string(d.maxRotationFrame) + '\n';
    }
    return text;
}

} // namespace rl
