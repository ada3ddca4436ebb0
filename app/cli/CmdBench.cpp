// rigidlab-cli bench: steps named library scenes or scene files at default settings and prints, per scene, one line
// of wall-clock cost per step (median, p95), the work left at the end, and with --scaling the cost exponent vs n.
// When the build links Debian's Bullet, the same scene is stepped in Bullet right after and the ratio is printed.
#include "BulletReference.h"
#include "Cli.h"
#include "HugePages.h"
#include "dynamics/ContactSolver.h"
#include "io/SceneImport.h"
#include "scene/SceneLibrary.h"
#include "world/CoreRoundTrip.h"
#include "world/World.h"

#include <QCommandLineParser>
#include <QElapsedTimer>
#include <QFileInfo>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <string>
#include <thread>
#include <time.h>
#include <unistd.h>
#include <vector>

namespace rl::cli {

namespace {

constexpr int kDefaultFrames = 300;
constexpr int kQuickFrames = 120;
constexpr int kScalingFrames = 60;
constexpr int kDefaultRuns = 3;

// What one bench argument names: a library scene or a scene file.
struct BenchTarget {
    std::string label; // the name or the path as given
    bool named = false;
    int frames = kDefaultFrames;
};

// The bundled copy of the original project's 642-cube ramps scene, which `bench ramps` names.
const char* const kRampsScene = RL_RESOURCES_DIR "/scenes/ramps.obj";

struct BenchResult {
    size_t bodies = 0;
    int frames = 0;
    int runs = 1;
    double medianMs = 0.0;
    double p95Ms = 0.0;
    double meanMs = 0.0;
    double cpuMedianMs = 0.0; // CPU time of the stepping thread: less disturbed by other jobs on a shared machine
    int awake = 0;
    int contacts = 0;
    // Profile totals over the run, grouped: broadphase, narrowphase, solver (islands through restitution), other.
    double broadMs = 0.0, narrowMs = 0.0, solveMs = 0.0, otherMs = 0.0;
    uint64_t stateHash = 0;  // FNV-1a over the bits of every body's position and orientation after the run
    uint64_t stepsAlone = 0; // steps a threaded world took on one thread, its team not paying (TeamPacer), all runs
    uint64_t teamSteps = 0;  // steps in which its team ran any job (too few bodies and pairs: none), all runs
    std::vector<double> roundTripNs; // the core round trip before each threaded run (measureCoreRoundTripNs())
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
    list << QStringLiteral("ramps");
    return list.join(", ");
}

// A name that is not in the library is taken as a file when it looks like a path or exists.
bool looksLikeFile(const QString& arg) {
    return arg.contains('/') || arg.contains('.') || QFileInfo::exists(arg);
}

double threadCpuMs() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) * 1e3 + static_cast<double>(ts.tv_nsec) * 1e-6;
}

std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    std::string a, b, c;
    in >> a >> b >> c;
    return a + " " + b + " " + c;
}

// The CPU's model name as the kernel reports it (the first "model name" of /proc/cpuinfo), or "unknown".
std::string cpuModel() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("model name", 0) != 0)
            continue;
        const size_t colon = line.find(':');
        if (colon != std::string::npos && colon + 2 <= line.size())
            return line.substr(colon + 2);
    }
    return "unknown";
}

// Per-frame step times of one run, wall clock and the stepping thread's CPU time (ms).
struct FrameTimes {
    std::vector<double> wallMs, cpuMs;
};

// Keeps each frame's least time over the repeats of one engine's run. The runs step the same frames bit for bit, so
// every repeat does the same work; a frame that another job on the machine slowed in one repeat counts at the speed
// it ran at in another.
void keepLeast(FrameTimes& best, const FrameTimes& run) {
    if (best.wallMs.empty()) {
        best = run;
        return;
    }
    for (size_t f = 0; f < std::min(best.wallMs.size(), run.wallMs.size()); ++f) {
        best.wallMs[f] = std::min(best.wallMs[f], run.wallMs[f]);
        best.cpuMs[f] = std::min(best.cpuMs[f], run.cpuMs[f]);
    }
}

// The median, p95 and mean of the frames' times.
void summarize(const FrameTimes& times, BenchResult& out) {
    std::vector<double> wall = times.wallMs, cpu = times.cpuMs;
    out.frames = static_cast<int>(wall.size());
    double total = 0.0;
    for (double ms : wall)
        total += ms;
    out.meanMs = wall.empty() ? 0.0 : total / static_cast<double>(wall.size());
    std::sort(wall.begin(), wall.end());
    std::sort(cpu.begin(), cpu.end());
    out.medianMs = median(wall);
    out.p95Ms = percentile(wall, 0.95);
    out.cpuMedianMs = median(cpu);
}

// Calls step() `frames` times, timing each call (wall and thread CPU), with progress on stderr.
template <class StepFn>
FrameTimes timeSteps(int frames, const QString& label, bool quiet, StepFn&& step) {
    using Clock = std::chrono::steady_clock;
    FrameTimes times;
    times.wallMs.reserve(static_cast<size_t>(frames));
    times.cpuMs.reserve(static_cast<size_t>(frames));
    QElapsedTimer clock;
    clock.start();
    qint64 lastReport = 0;
    // On a terminal the progress line is rewritten in place; in a log it is one line per report.
    const bool terminal = isatty(fileno(stderr)) != 0;
    for (int f = 0; f < frames; ++f) {
        const double c0 = threadCpuMs();
        const Clock::time_point start = Clock::now();
        step();
        times.wallMs.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
        times.cpuMs.push_back(threadCpuMs() - c0);
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
    return times;
}

// Steps the world `frames` times, timing each step; false if a body left the finite numbers. `out` gets the work left
// at the end, the stage totals and the final state's hash; the times are returned in `times`.
bool runWorld(World& world, int frames, const QString& label, bool quiet, FrameTimes& times, BenchResult& out) {
    world.resetProfile();
    times = timeSteps(frames, label, quiet, [&] { world.step(); });
    out.bodies = world.bodyCount();
    const FrameDiagnostics d = world.diagnostics();
    out.awake = d.awakeBodies;
    out.contacts = d.contactPoints;
    const Profile& p = world.profile();
    out.broadMs = groupMs(p, {Stage::UpdateBroadphase, Stage::FindPairs});
    out.narrowMs = groupMs(p, {Stage::Narrowphase});
    out.solveMs =
        groupMs(p, {Stage::BuildIslands, Stage::PrepareContacts, Stage::IntegrateVelocities, Stage::WarmStart,
                    Stage::Solve, Stage::IntegratePositions, Stage::Relax, Stage::Restitution, Stage::StoreImpulses});
    out.otherMs = groupMs(p, {Stage::PushOut, Stage::Ccd, Stage::Separate, Stage::Sleep, Stage::StoreFrame});

    for (size_t i = 0; i < world.bodyCount(); ++i) {
        const Vec3 c = world.centerOfMass(i);
        if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) {
            printError(label + ": '" + QString::fromStdString(world.name(i)) +
                       "': the simulation produced a non-finite position");
            return false;
        }
    }
    out.stateHash = world.stateHash();
    out.stepsAlone = p.counter(Counter::StepsAlone);
    out.teamSteps = p.counter(Counter::TeamSteps);
    return true;
}

// "A..B" ns, the least and the most of the round trips measured, or "n/a" if none was.
QString roundTripRange(const std::vector<double>& ns) {
    if (ns.empty())
        return QStringLiteral("n/a");
    const auto [low, high] = std::minmax_element(ns.begin(), ns.end());
    return QString("%1..%2").arg(*low, 0, 'f', 0).arg(*high, 0, 'f', 0);
}

// The same scene on one thread: the speedup of the threaded run, and whether both ended in the same state, bit for bit.
QString threadsLine(const QString& label, int threads, const BenchResult& threaded, const BenchResult& one) {
    const auto ratio = [](double a, double b) { return b > 0.0 ? a / b : 0.0; };
    return QString("threads scene=%1 threads=%2 one_thread_median_ms=%3 speedup_median=%4 speedup_mean=%5 "
                   "identical=%6 steps_alone=%7/%8 team_steps=%9/%8 core_round_trip_ns=%10\n")
        .arg(label)
        .arg(threads)
        .arg(one.medianMs, 0, 'f', 3)
        .arg(ratio(one.medianMs, threaded.medianMs), 0, 'f', 2)
        .arg(ratio(one.meanMs, threaded.meanMs), 0, 'f', 2)
        .arg(one.stateHash == threaded.stateHash ? "yes" : "no")
        .arg(threaded.stepsAlone)
        .arg(static_cast<qulonglong>(threaded.frames) * static_cast<qulonglong>(threaded.runs))
        .arg(threaded.teamSteps)
        .arg(roundTripRange(threaded.roundTripNs));
}

// The fields both engines' lines share: bodies= frames= median_ms= p95_ms= mean_ms= awake= contacts=.
QString runFields(const BenchResult& r) {
    return QString("bodies=%1 frames=%2 median_ms=%3 p95_ms=%4 mean_ms=%5 awake=%6 contacts=%7")
        .arg(r.bodies)
        .arg(r.frames)
        .arg(r.medianMs, 0, 'f', 3)
        .arg(r.p95Ms, 0, 'f', 3)
        .arg(r.meanMs, 0, 'f', 3)
        .arg(r.awake)
        .arg(r.contacts);
}

QString resultLine(const QString& label, const BenchResult& r) {
    return QString("scene=%1 %2 broad_ms=%3 narrow_ms=%4 solve_ms=%5 other_ms=%6 cpu_median_ms=%7 runs=%8\n")
        .arg(label, runFields(r))
        .arg(r.broadMs, 0, 'f', 1)
        .arg(r.narrowMs, 0, 'f', 1)
        .arg(r.solveMs, 0, 'f', 1)
        .arg(r.otherMs, 0, 'f', 1)
        .arg(r.cpuMedianMs, 0, 'f', 3)
        .arg(r.runs);
}

// Bullet on the same scene, and RigidLab's cost as a ratio of Bullet's (above 1: RigidLab is slower). Bullet steps on
// one thread, so the ratio is RigidLab's on one thread; `threaded`, if given, adds RigidLab's threaded run as a ratio.
QString bulletLines(const QString& label, const BenchResult& ours, const BenchResult& bullet,
                    const BenchResult* threaded) {
    const auto ratio = [](double a, double b) { return b > 0.0 ? a / b : 0.0; };
    QString lines = QString("bullet scene=%1 %2 cpu_median_ms=%3\nratio scene=%1 rigidlab/bullet median=%4 "
                            "cpu_median=%5 mean=%6")
                        .arg(label, runFields(bullet))
                        .arg(bullet.cpuMedianMs, 0, 'f', 3)
                        .arg(ratio(ours.medianMs, bullet.medianMs), 0, 'f', 2)
                        .arg(ratio(ours.cpuMedianMs, bullet.cpuMedianMs), 0, 'f', 2)
                        .arg(ratio(ours.meanMs, bullet.meanMs), 0, 'f', 2);
    if (threaded)
        lines += QString(" threaded_median=%1").arg(ratio(threaded->medianMs, bullet.medianMs), 0, 'f', 2);
    return lines + "\n";
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
        "other_ms= cpu_median_ms= runs=\n(awake and contacts after the last step; the *_ms stage groups are totals "
        "over a run, the least over the runs; the step times are each frame's least over the runs, see --runs).\n"
        "When built with Debian's libbullet-dev, each scene is then stepped in Bullet at its defaults (hull "
        "against hull, same fps, same materials) and two more lines follow: bullet scene=... and ratio scene=... "
        "rigidlab/bullet median= cpu_median= mean= (above 1: RigidLab is slower; with --threads above 1, RigidLab's "
        "one-thread run, and threaded_median= its threaded one).\n"
        "Without scenes, runs stack20, pyramid20, ramps and boxes1000 for 120 frames.\nNamed scenes: " +
        namesList() + " (ramps is the original project's 642-cube scene, resources/scenes/ramps.obj).\n" +
        QString::fromStdString(bench::BulletReference::description()));
    parser.addHelpOption();
    parser.addPositionalArgument("scenes", "Library scene names or scene files (.rlscene, .obj, ...).",
                                 "[SCENE|NAME ...]");
    parser.addOption({"frames",
                      QString("Steps per scene (default %1; %2 for the default set, %3 for --scaling).")
                          .arg(kDefaultFrames)
                          .arg(kQuickFrames)
                          .arg(kScalingFrames),
                      "n"});
    parser.addOption(
        {"threads",
         "Threads for RigidLab's step (default 1). Above 1, each scene is then run again on one thread "
         "and a line threads scene=... one_thread_median_ms= speedup_median= speedup_mean= identical= "
         "steps_alone= team_steps= core_round_trip_ns= compares them (identical: the same final state, bit for bit; "
         "steps_alone: the steps of all runs that the threaded world took on one thread because its team did not "
         "pay, the machine's other cores being busy; team_steps: the steps in which the team shared "
         "any work, none in a scene too small for it, such as stack20; core_round_trip_ns: the least and the "
         "most time, over the runs, that two threads on the first two CPUs took to pass a counter there and back, "
         "measured before each threaded run: on a shared virtual machine it moves with the host's placement of "
         "the virtual CPUs, and the threaded step's cost with it).",
         "t"});
    parser.addOption({"runs",
                      QString("Runs of each engine on each scene (default %1), taking turns; each frame counts at its "
                              "least time over the runs, which all step the same frames, so that another job on the "
                              "machine slowing one run does not count. 1 times a single run.")
                          .arg(kDefaultRuns),
                      "r"});
    parser.addOption({"lanes",
                      "Lanes of doubles for RigidLab's contact sweeps: 8 (the default: eight where the CPU has "
                      "AVX-512, else four) or 4 (four on any CPU). With 4 an AVX-512 machine runs the sweeps an AVX2 "
                      "machine runs: the same frames, not the same time.",
                      "n"});
    parser.addOption({"no-bullet", "Do not run Bullet on the same scenes."});
    parser.addOption({"no-sleep", "Keep every body awake in both engines (RigidLab: effects auto,-sleeping; Bullet: "
                                  "DISABLE_DEACTIVATION)."});
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
    // A whole-number option from 1 to `most`: its value, `fallback` if it is not given, nothing (after the message)
    // if it is out of range.
    const auto wholeOption = [&](const char* name, int fallback, int most) -> std::optional<int> {
        if (!parser.isSet(name))
            return fallback;
        bool ok = false;
        const int n = parser.value(name).toInt(&ok);
        if (!ok || n <= 0 || n > most) {
            printError(QString("rigidlab-cli bench: --%1 takes a whole number from 1 to %2").arg(name).arg(most));
            return std::nullopt;
        }
        return n;
    };
    const std::optional<int> threadsOption = wholeOption("threads", 1, 64);
    const std::optional<int> runsOption = wholeOption("runs", kDefaultRuns, 100);
    if (!threadsOption || !runsOption)
        return kExitUsage;
    if (parser.isSet("lanes")) {
        const QString lanes = parser.value("lanes");
        if (lanes != "4" && lanes != "8") {
            printError(QStringLiteral("rigidlab-cli bench: --lanes takes 4 or 8"));
            return kExitUsage;
        }
        ContactSolver::setWidestLanes(lanes.toInt());
    }
    const int threads = *threadsOption, repeats = *runsOption;
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
        for (const char* name : {"stack20", "pyramid20", "ramps", "boxes1000"})
            targets.push_back({name, true, frames.value_or(kQuickFrames)});
    } else {
        for (const QString& arg : positional) {
            const std::string s = arg.toStdString();
            const bool named = scenes::byName(s).has_value() || s == "ramps";
            if (!named && !looksLikeFile(arg)) {
                printError("rigidlab-cli bench: unknown scene '" + arg + "'; named scenes: " + namesList() +
                           " (or give a scene file)");
                return kExitUsage;
            }
            targets.push_back({s, named, frames.value_or(kDefaultFrames)});
        }
    }

    const bool noSleep = parser.isSet("no-sleep");
    const bool withBullet = !parser.isSet("no-bullet") && bench::BulletReference::available();
    if (!quiet)
        printError(QString("bench: threads %1, sleeping %2; %3; load average %4")
                       .arg(threads)
                       .arg(noSleep ? "off in both engines" : "at each engine's default")
                       .arg(withBullet ? QString::fromStdString(bench::BulletReference::description())
                                       : QStringLiteral("no Bullet comparison"))
                       .arg(QString::fromStdString(loadAverage())));
    // Ratios to Bullet depend on the machine: RigidLab's sweeps run twice the lanes with AVX-512 (README, "Whole
    // steps"), Bullet's scalar step does not change.
    if (!quiet)
        printError(QString("bench: CPU %1, %2 logical CPUs; RigidLab's contact sweeps in %3")
                       .arg(QString::fromStdString(cpuModel()))
                       .arg(std::thread::hardware_concurrency())
                       .arg(QString::fromStdString(ContactSolver::sweepsDescription())));
    // Big scenes step faster with the heap on 2 MiB pages (HugePages.h), which the machine may not give.
    if (!quiet)
        printError(QString("bench: memory pages: %1").arg(QString::fromStdString(rl::app::hugePagesDescription())));

    WorldOptions options;
    options.threads = threads;
    if (noSleep)
        options.effects = EffectsSetting::parse("auto,-sleeping");
    bool failed = false;
    std::vector<double> scalingN, scalingMs, scalingCpuMs;
    for (const BenchTarget& target : targets) {
        const QString label = QString::fromStdString(target.label);
        Scene scene;
        if (target.named && target.label != "ramps") {
            scene = *scenes::byName(target.label);
        } else {
            Result<Scene> imported = importScene(target.label == "ramps" ? std::string(kRampsScene) : target.label);
            if (!imported) {
                printError(imported.error().toString());
                failed = true;
                continue;
            }
            scene = std::move(imported).value();
        }
        if (!quiet)
            printError(QString("bench: %1: %2 bodies, %3 frames, %4 runs of each engine")
                           .arg(label)
                           .arg(scene.bodies.size())
                           .arg(target.frames)
                           .arg(repeats));
        // The engines take turns (the threaded world, then one thread, then Bullet) `repeats` times over, and each
        // frame counts at its least time over the repeats (keepLeast()); each repeat must end in the same state.
        WorldOptions single = options;
        single.threads = 1;
        BenchResult result, one, reference;
        FrameTimes ourTimes, oneTimes, bulletTimes;
        bool ok = true;
        const auto runOurs = [&](const WorldOptions& o, const QString& runLabel, int r, FrameTimes& best,
                                 BenchResult& kept) {
            Result<World> created = World::create(scene, o);
            if (!created) {
                printError(created.error().toString());
                return false;
            }
            BenchResult run;
            FrameTimes times;
            if (!runWorld(created.value(), target.frames, runLabel, quiet, times, run))
                return false;
            keepLeast(best, times);
            if (r == 0) {
                kept = run;
                return true;
            }
            kept.stepsAlone += run.stepsAlone;
            kept.teamSteps += run.teamSteps;
            kept.broadMs = std::min(kept.broadMs, run.broadMs);
            kept.narrowMs = std::min(kept.narrowMs, run.narrowMs);
            kept.solveMs = std::min(kept.solveMs, run.solveMs);
            kept.otherMs = std::min(kept.otherMs, run.otherMs);
            if (run.stateHash != kept.stateHash) {
                printError(runLabel + ": the run ended in a different state from the first run");
                return false;
            }
            return true;
        };
        std::vector<double> roundTrips;
        for (int r = 0; r < repeats && ok; ++r) {
            const QString run = repeats > 1 ? QString(", run %1/%2").arg(r + 1).arg(repeats) : QString();
            if (threads > 1)
                if (const std::optional<double> ns = measureCoreRoundTripNs())
                    roundTrips.push_back(*ns);
            ok = runOurs(options, label + run, r, ourTimes, result);
            if (ok && threads > 1)
                ok = runOurs(single, label + " (1 thread" + run + ")", r, oneTimes, one);
            if (ok && withBullet) {
                std::string error;
                std::unique_ptr<bench::BulletReference> bullet = bench::BulletReference::create(scene, noSleep, &error);
                if (!bullet) {
                    printError(label + ": Bullet: " + QString::fromStdString(error));
                    ok = false;
                    break;
                }
                keepLeast(bulletTimes,
                          timeSteps(target.frames, label + " (Bullet" + run + ")", quiet, [&] { bullet->step(); }));
                reference.bodies = scene.bodies.size();
                reference.awake = bullet->awakeBodies();
                reference.contacts = bullet->contactPoints();
            }
        }
        if (!ok) {
            failed = true;
            continue;
        }
        summarize(ourTimes, result);
        result.runs = repeats;
        result.roundTripNs = roundTrips;
        printOut(resultLine(label, result));
        if (threads > 1) {
            summarize(oneTimes, one);
            printOut(threadsLine(label, threads, result, one));
            if (one.stateHash != result.stateHash) {
                printError(label + ": the run on " + QString::number(threads) +
                           " threads ended in a different state from the run on 1 thread");
                failed = true;
            }
        }
        if (withBullet) {
            summarize(bulletTimes, reference);
            printOut(bulletLines(label, threads > 1 ? one : result, reference, threads > 1 ? &result : nullptr));
        }
        std::fflush(stdout);
        if (scaling) {
            size_t dynamicBodies = 0;
            for (const BodyDef& b : scene.bodies)
                dynamicBodies += b.anchor ? 0 : 1;
            scalingN.push_back(static_cast<double>(dynamicBodies));
            scalingMs.push_back(result.medianMs);
            scalingCpuMs.push_back(result.cpuMedianMs);
        }
    }

    if (scaling && !failed) {
        const std::optional<double> exponent = logLogSlope(scalingN, scalingMs);
        if (!exponent) {
            printError(QStringLiteral("rigidlab-cli bench: cannot fit the exponent (a step took no measurable time)"));
            return kExitFailure;
        }
        // The same fit on the stepping thread's CPU time, which a loaded machine disturbs less than wall time.
        const std::optional<double> cpuExponent = logLogSlope(scalingN, scalingCpuMs);
        printOut(QString("scaling exponent=%1 fit=median_ms_vs_dynamic_bodies n=%2..%3 points=%4 cpu_exponent=%5\n")
                     .arg(*exponent, 0, 'f', 3)
                     .arg(scalingN.front())
                     .arg(scalingN.back())
                     .arg(scalingN.size())
                     .arg(cpuExponent ? QString::number(*cpuExponent, 'f', 3) : QStringLiteral("n/a")));
    }
    return failed ? kExitFailure : kExitOk;
}

} // namespace rl::cli
