// rigidlab-cli bench: steps named library scenes or scene files at default settings and prints, per scene, one line
// of wall-clock cost per step (median, p95), the work left at the end, and with --scaling the cost exponent vs n.
#include "Cli.h"
#include "io/SceneImport.h"
#include "scene/SceneLibrary.h"
#include "world/World.h"

#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QFileInfo>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <unistd.h>
#include <vector>

namespace rl::cli {

namespace {

constexpr int kDefaultFrames = 300;
constexpr int kQuickFrames = 120;
constexpr int kScalingFrames = 60;

// What one bench argument names: a library scene or a scene file.
struct BenchTarget {
    std::string label; // the name or the path as given
    bool named = false;
    int frames = kDefaultFrames;
};

struct BenchResult {
    size_t bodies = 0;
    int frames = 0;
    double medianMs = 0.0;
    double p95Ms = 0.0;
    double meanMs = 0.0;
    int awake = 0;
    int contacts = 0;
    // Profile totals over the run, grouped: broadphase, narrowphase, solver (islands through restitution), other.
    double broadMs = 0.0, narrowMs = 0.0, solveMs = 0.0, otherMs = 0.0;
};

// Nearest-rank percentile of sorted values (p in (0, 1]).
double percentile(const std::vector<double>& sorted, double p) {
    if (sorted.empty())
        return 0.0;
    const size_t rank = static_cast<size_t>(std::ceil(p * static_cast<double>(sorted.size())));
    return sorted[std::clamp<size_t>(rank, 1, sorted.size()) - 1];
}

double median(const std::vector<double>& sorted) {
    if (sorted.empty())
        return 0.0;
    const size_t n = sorted.size();
    return n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
}

double groupMs(const Profile& profile, std::initializer_list<Stage> stages) {
    double sum = 0.0;
    for (Stage s : stages)
        sum += profile.ms(s);
    return sum;
}

QString namesList() {
    QStringList list;
    for (const std::string& n : scenes::names())
        list << QString::fromStdString(n);
    return list.join(", ");
}

// A name that is not in the library is taken as a file when it looks like a path or exists.
bool looksLikeFile(const QString& arg) {
    return arg.contains('/') || arg.contains('.') || QFileInfo::exists(arg);
}

// Steps the world `frames` times, timing each step; false if a body left the finite numbers.
bool runWorld(World& world, int frames, const QString& label, bool quiet, BenchResult& out) {
    using Clock = std::chrono::steady_clock;
    std::vector<double> stepMs;
    stepMs.reserve(static_cast<size_t>(frames));
    world.resetProfile();
    QElapsedTimer clock;
    clock.start();
    qint64 lastReport = 0;
    // On a terminal the progress line is rewritten in place; in a log it is one line per report.
    const bool terminal = isatty(fileno(stderr)) != 0;
    for (int f = 0; f < frames; ++f) {
        const Clock::time_point start = Clock::now();
        world.step();
        stepMs.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
        const qint64 now = clock.elapsed();
        if (!quiet && now - lastReport >= (terminal ? 500 : 5000)) {
            lastReport = now;
            std::fprintf(stderr, "%sbench: %s frame %d/%d, %.1f s elapsed%s", terminal ? "\r" : "", qPrintable(label),
                         f + 1, frames, now / 1000.0, terminal ? "   " : "\n");
            std::fflush(stderr);
        }
    }
    if (!quiet && terminal && lastReport > 0)
        std::fputc('\n', stderr);

    out.bodies = world.bodyCount();
    out.frames = frames;
    double total = 0.0;
    for (double ms : stepMs)
        total += ms;
    out.meanMs = frames > 0 ? total / frames : 0.0;
    std::sort(stepMs.begin(), stepMs.end());
    out.medianMs = median(stepMs);
    out.p95Ms = percentile(stepMs, 0.95);
    const FrameDiagnostics d = world.diagnostics();
    out.awake = d.awakeBodies;
    out.contacts = d.contactPoints;
    const Profile& p = world.profile();
    out.broadMs = groupMs(p, {Stage::UpdateBroadphase, Stage::FindPairs});
    out.narrowMs = groupMs(p, {Stage::Narrowphase});
    out.solveMs = groupMs(p, {Stage::BuildIslands, Stage::IntegrateVelocities, Stage::WarmStart, Stage::Solve,
                              Stage::IntegratePositions, Stage::Relax, Stage::Restitution});
    out.otherMs = groupMs(p, {Stage::Ccd, Stage::Sleep, Stage::StoreFrame});

    for (size_t i = 0; i < world.bodyCount(); ++i) {
        const Vec3 c = world.centerOfMass(i);
        if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) {
            printError(label + ": '" + QString::fromStdString(world.name(i)) +
                       "': the simulation produced a non-finite position");
            return false;
        }
    }
    return true;
}

QString resultLine(const QString& label, const BenchResult& r) {
    return QString("scene=%1 bodies=%2 frames=%3 median_ms=%4 p95_ms=%5 mean_ms=%6 awake=%7 contacts=%8 "
                   "broad_ms=%9 narrow_ms=%10 solve_ms=%11 other_ms=%12\n")
        .arg(label)
        .arg(r.bodies)
        .arg(r.frames)
        .arg(r.medianMs, 0, 'f', 3)
        .arg(r.p95Ms, 0, 'f', 3)
        .arg(r.meanMs, 0, 'f', 3)
        .arg(r.awake)
        .arg(r.contacts)
        .arg(r.broadMs, 0, 'f', 1)
        .arg(r.narrowMs, 0, 'f', 1)
        .arg(r.solveMs, 0, 'f', 1)
        .arg(r.otherMs, 0, 'f', 1);
}

// Slope of the least-squares line through (log x, log y): the exponent k of y ~ x^k.
std::optional<double> logLogSlope(const std::vector<double>& x, const std::vector<double>& y) {
    const size_t n = std::min(x.size(), y.size());
    if (n < 2)
        return std::nullopt;
    double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    for (size_t i = 0; i < n; ++i) {
        if (!(x[i] > 0.0) || !(y[i] > 0.0))
            return std::nullopt;
        const double lx = std::log(x[i]), ly = std::log(y[i]);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
    }
    const double dn = static_cast<double>(n);
    const double denominator = dn * sxx - sx * sx;
    if (!(std::abs(denominator) > 0.0))
        return std::nullopt;
    return (dn * sxy - sx * sy) / denominator;
}

} // namespace

int runBench(const QStringList& arguments) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        "Step scenes at their default settings and print the wall-clock cost per step, one line per scene:\n"
        "scene= bodies= frames= median_ms= p95_ms= mean_ms= awake= contacts= broad_ms= narrow_ms= solve_ms= "
        "other_ms=\n(awake and contacts after the last step; the *_ms stage groups are totals over the run).\n"
        "Without scenes, runs stack20, pyramid20 and boxes1000 for 120 frames.\nNamed scenes: " +
        namesList());
    parser.addHelpOption();
    parser.addPositionalArgument("scenes", "Library scene names or scene files (.rlscene, .obj, ...).",
                                 "[SCENE|NAME ...]");
    parser.addOption({"frames",
                      QString("Steps per scene (default %1; %2 for the default set, %3 for --scaling).")
                          .arg(kDefaultFrames)
                          .arg(kQuickFrames)
                          .arg(kScalingFrames),
                      "n"});
    parser.addOption({"threads", "Worker threads for the narrowphase (default 1).", "t"});
    parser.addOption({"scaling", "Run scale1k ... scale16k and fit the exponent of cost vs bodies (log-log)."});
    parser.addOption({"quiet", "No progress on stderr."});
    if (const std::optional<int> done = parseArguments(parser, arguments, "bench"))
        return *done;

    std::optional<int> frames;
    if (parser.isSet("frames")) {
        bool ok = false;
        const int n = parser.value("frames").toInt(&ok);
        if (!ok || n <= 0) {
            printError(QStringLiteral("rigidlab-cli bench: --frames takes a positive whole number"));
            return kExitUsage;
        }
        frames = n;
    }
    int threads = 1;
    if (parser.isSet("threads")) {
        bool ok = false;
        threads = parser.value("threads").toInt(&ok);
        if (!ok || threads <= 0 || threads > 64) {
            printError(QStringLiteral("rigidlab-cli bench: --threads takes a whole number from 1 to 64"));
            return kExitUsage;
        }
    }
    const bool scaling = parser.isSet("scaling");
    const bool quiet = parser.isSet("quiet");
    const QStringList positional = parser.positionalArguments();
    if (scaling && !positional.isEmpty()) {
        printError(QStringLiteral("rigidlab-cli bench: --scaling runs its own scenes; give no scenes with it"));
        return kExitUsage;
    }

    std::vector<BenchTarget> targets;
    if (scaling) {
        for (const char* name : {"scale1k", "scale2k", "scale4k", "scale8k", "scale16k"})
            targets.push_back({name, true, frames.value_or(kScalingFrames)});
    } else if (positional.isEmpty()) {
        for (const char* name : {"stack20", "pyramid20", "boxes1000"})
            targets.push_back({name, true, frames.value_or(kQuickFrames)});
    } else {
        for (const QString& arg : positional) {
            const std::string s = arg.toStdString();
            const bool named = scenes::byName(s).has_value();
            if (!named && !looksLikeFile(arg)) {
                printError("rigidlab-cli bench: unknown scene '" + arg + "'; named scenes: " + namesList() +
                           " (or give a scene file)");
                return kExitUsage;
            }
            targets.push_back({s, named, frames.value_or(kDefaultFrames)});
        }
    }

    WorldOptions options;
    options.threads = threads;
    bool failed = false;
    std::vector<double> scalingN, scalingMs;
    for (const BenchTarget& target : targets) {
        const QString label = QString::fromStdString(target.label);
        Scene scene;
        if (target.named) {
            scene = *scenes::byName(target.label);
        } else {
            Result<Scene> imported = importScene(target.label);
            if (!imported) {
                printError(imported.error().toString());
                failed = true;
                continue;
            }
            scene = std::move(imported).value();
        }
        Result<World> created = World::create(scene, options);
        if (!created) {
            printError(created.error().toString());
            failed = true;
            continue;
        }
        if (!quiet)
            printError(
                QString("bench: %1: %2 bodies, %3 frames").arg(label).arg(scene.bodies.size()).arg(target.frames));
        BenchResult result;
        if (!runWorld(created.value(), target.frames, label, quiet, result)) {
            failed = true;
            continue;
        }
        printOut(resultLine(label, result));
        std::fflush(stdout);
        if (scaling) {
            size_t dynamicBodies = 0;
            for (const BodyDef& b : scene.bodies)
                dynamicBodies += b.anchor ? 0 : 1;
            scalingN.push_back(static_cast<double>(dynamicBodies));
            scalingMs.push_back(result.medianMs);
        }
    }

    if (scaling && !failed) {
        const std::optional<double> exponent = logLogSlope(scalingN, scalingMs);
        if (!exponent) {
            printError(QStringLiteral("rigidlab-cli bench: cannot fit the exponent (a step took no measurable time)"));
            return kExitFailure;
        }
        printOut(QString("scaling exponent=%1 fit=median_ms_vs_dynamic_bodies n=%2..%3 points=%4\n")
                     .arg(*exponent, 0, 'f', 3)
                     .arg(scalingN.front())
                     .arg(scalingN.back())
                     .arg(scalingN.size()));
    }
    return failed ? kExitFailure : kExitOk;
}

} // namespace rl::cli
