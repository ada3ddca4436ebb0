// rigidlab-cli bake: simulates a scene headless and writes .bake and/or CSV through the core's writers, with
// progress and an ETA on stderr and, with --profile, the cost of every stage and effect.
#include "Cli.h"
#include "io/BakeFile.h"
#include "io/CsvWriter.h"
#include "io/SceneImport.h"
#include "world/Baker.h"
#include "world/World.h"

#include <QCommandLineParser>
#include <QElapsedTimer>

#include <cmath>
#include <cstdio>

namespace rl::cli {

namespace {

bool parsePositive(const QCommandLineParser& parser, const QString& name, double& out) {
    if (!parser.isSet(name))
        return true;
    bool ok = false;
    out = parser.value(name).toDouble(&ok);
    return ok && std::isfinite(out) && out > 0.0;
}

} // namespace

int runBake(const QStringList& arguments) {
    QCommandLineParser parser;
    parser.setApplicationDescription("Simulate a scene and write the frames as .bake and/or CSV.");
    parser.addHelpOption();
    parser.addPositionalArgument("scene", "Scene file (.rlscene, .obj or any format assimp reads).");
    parser.addOption({{"o", "output"}, "Write the bake to <file> (.bake).", "file"});
    parser.addOption({"csv", "Write CSV to <file>.", "file"});
    parser.addOption({"seconds", "Simulate <s> seconds (default 10).", "s"});
    parser.addOption({"frames", "Simulate <n> frames after frame 0.", "n"});
    parser.addOption({"start-frame",
                      "Start the simulation at frame <n> (default 0); frames 0..n hold the initial state, and "
                      "--seconds/--frames count from there.",
                      "n"});
    parser.addOption({"fps", "Frames (steps) per second, overriding the scene.", "f"});
    parser.addOption({"substeps", "Solver substeps per step, overriding the scene.", "k"});
    parser.addOption({"iterations", "Solver iterations per substep, overriding the scene.", "i"});
    parser.addOption({"integrator", "explicit-euler, symplectic-euler, verlet or rk4.", "name"});
    parser.addOption({"effects", "auto, none, all, linear-only, or a list such as auto,-sleeping,+ccd.", "list"});
    parser.addOption({"threads",
                      "Worker threads of the simulation and of writing the files (results are identical for "
                      "any count). While other programs keep the machine's cores busy, steps run on one thread "
                      "(--profile: counter=steps_alone).",
                      "t"});
    parser.addOption({"profile", "Print per-stage times, the active effects and counters to stdout."});
    parser.addOption({"quiet", "No progress on stderr."});
    if (const std::optional<int> done = parseArguments(parser, arguments, "bake"))
        return *done;
    if (parser.positionalArguments().size() != 1) {
        printError(QStringLiteral("rigidlab-cli bake: expected exactly one scene file (see --help)"));
        return kExitUsage;
    }
    if (parser.isSet("seconds") && parser.isSet("frames")) {
        printError(QStringLiteral("rigidlab-cli bake: give --seconds or --frames, not both"));
        return kExitUsage;
    }

    WorldOptions options;
    double fps = 0.0, seconds = 10.0;
    int substeps = 0, iterations = 0, frames = 0, threads = 1, startFrame = 0;
    if (!parsePositive(parser, "fps", fps) || !parsePositive(parser, "seconds", seconds) ||
        !parsePositiveInt(parser, "substeps", substeps) || !parsePositiveInt(parser, "iterations", iterations) ||
        !parsePositiveInt(parser, "frames", frames) || !parsePositiveInt(parser, "threads", threads)) {
        printError(QStringLiteral("rigidlab-cli bake: --fps, --seconds, --frames, --substeps, --iterations and "
                                  "--threads take positive numbers"));
        return kExitUsage;
    }
    if (parser.isSet("start-frame")) {
        bool ok = false;
        startFrame = parser.value("start-frame").toInt(&ok);
        if (!ok || startFrame < 0) {
            printError(QStringLiteral("rigidlab-cli bake: --start-frame takes a frame number of 0 or more"));
            return kExitUsage;
        }
    }
    if (fps > 0.0)
        options.fps = fps;
    if (substeps > 0)
        options.substeps = substeps;
    if (iterations > 0)
        options.iterations = iterations;
    options.threads = threads;
    if (parser.isSet("integrator")) {
        options.integrator = parseIntegrator(parser.value("integrator").toStdString());
        if (!options.integrator) {
            printError("rigidlab-cli bake: unknown integrator '" + parser.value("integrator") +
                       "' (explicit-euler, symplectic-euler, verlet, rk4)");
            return kExitUsage;
        }
    }
    if (parser.isSet("effects")) {
        std::string error;
        options.effects = EffectsSetting::parse(parser.value("effects").toStdString(), &error);
        if (!options.effects) {
            printError("rigidlab-cli bake: --effects: " + QString::fromStdString(error));
            return kExitUsage;
        }
    }

    const std::string path = parser.positionalArguments().constFirst().toStdString();
    Result<Scene> scene = importScene(path);
    if (!scene) {
        printError(scene.error().toString());
        return kExitFailure;
    }
    Result<World> created = World::create(*scene, options);
    if (!created) {
        printError(created.error().toString());
        return kExitFailure;
    }
    World& world = created.value();
    if (world.bodyCount() == 0) {
        printError(QString::fromStdString(path) + ": the scene has no bodies to simulate");
        return kExitFailure;
    }
    const size_t frameCount =
        static_cast<size_t>(startFrame) +
        (frames > 0 ? static_cast<size_t>(frames) : static_cast<size_t>(std::llround(seconds * world.fps())));

    Bake bake = startBake(world);
    if (!scene->sourceObjText.empty()) {
        bake.setSceneObjText(scene->sourceObjText);
    } else {
        Result<std::string> obj = sceneToObjText(*scene);
        if (!obj) {
            printError(obj.error().toString());
            return kExitFailure;
        }
        bake.setSceneObjText(std::move(obj).value());
    }

    const bool quiet = parser.isSet("quiet");
    QElapsedTimer clock;
    clock.start();
    qint64 lastReport = -1000;
    BakeRequest request;
    request.frames = frameCount;
    request.startFrame = static_cast<size_t>(startFrame);
    request.progress = [&](size_t done, size_t total) {
        const qint64 now = clock.elapsed();
        if (!quiet && (now - lastReport >= 500 || done == total)) {
            lastReport = now;
            const double perFrame = static_cast<double>(now) / 1000.0 / static_cast<double>(done);
            const double eta = perFrame * static_cast<double>(total - done);
            std::fprintf(stderr, "\rbaking frame %zu/%zu (%.0f%%), %.1f s elapsed, ETA %.1f s   ", done, total,
                         100.0 * static_cast<double>(done) / static_cast<double>(total), now / 1000.0, eta);
            if (done == total)
                std::fputc('\n', stderr);
            std::fflush(stderr);
        }
        return true;
    };
    bakeRun(world, bake, request);
    const qint64 bakeMs = clock.elapsed();

    for (size_t i = 0; i < world.bodyCount(); ++i) {
        const Vec3 p = world.centerOfMass(i);
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            printError(QString::fromStdString(path) + ": '" + QString::fromStdString(world.name(i)) +
                       "': the simulation produced a non-finite position");
            return kExitFailure;
        }
    }

    if (parser.isSet("output")) {
        Status s = writeBakeFile(bake, parser.value("output").toStdString(), threads);
        if (!s) {
            printError(s.error().toString());
            return kExitFailure;
        }
    }
    if (parser.isSet("csv")) {
        CsvOptions csvOptions;
        csvOptions.threads = threads;
        Status s = writeCsvFile(bake, parser.value("csv").toStdString(), csvOptions);
        if (!s) {
            printError(s.error().toString());
            return kExitFailure;
        }
    }

    if (parser.isSet("profile")) {
        const Profile& profile = world.profile();
        QString text;
        for (int s = 0; s < kStageCount; ++s)
            text += QString("stage=%1 ms=%2 calls=%3\n")
                        .arg(QString::fromUtf8(stageName(static_cast<Stage>(s)).data(),
                                               static_cast<int>(stageName(static_cast<Stage>(s)).size())))
                        .arg(profile.milliseconds[s], 0, 'f', 3)
                        .arg(profile.calls[s]);
        text += QString("effects=%1\n").arg(QString::fromStdString(world.effects().toString()));
        for (int c = 0; c < kCounterCount; ++c)
            text += QString("counter=%1 value=%2\n")
                        .arg(QString::fromUtf8(counterName(static_cast<Counter>(c)).data(),
                                               static_cast<int>(counterName(static_cast<Counter>(c)).size())))
                        .arg(profile.counters[c]);
        const ClampCounters& clamps = world.clampCounters();
        text += QString("counter=clamped_linear value=%1\ncounter=clamped_angular value=%2\n")
                    .arg(clamps.linear)
                    .arg(clamps.angular);
        printOut(text);
    }
    if (!quiet) {
        QString written;
        if (parser.isSet("output") || parser.isSet("csv"))
            written = QString(", wrote the files in %1 s").arg((clock.elapsed() - bakeMs) / 1000.0, 0, 'f', 2);
        printError(QString("baked %1 frames of %2 bodies in %3 s (%4 ms/step)%5")
                       .arg(frameCount)
                       .arg(world.bodyCount())
                       .arg(bakeMs / 1000.0, 0, 'f', 2)
                       .arg(frameCount > 0 ? static_cast<double>(bakeMs) / frameCount : 0.0, 0, 'f', 3)
                       .arg(written));
    }
    return kExitOk;
}

} // namespace rl::cli
