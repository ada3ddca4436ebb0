// rigidlab-cli diff: compares two .bake files frame by frame (core/analysis/BakeDiff) and says where they diverge.
// Exit codes follow cmp(1) within DESIGN.md §6: 0 equal within the tolerances, 1 different (or an unreadable
// input, with the message on stderr and nothing on stdout), 2 bad usage.
#include "Cli.h"
#include "analysis/BakeDiff.h"
#include "io/BakeLoad.h"

#include <QCommandLineParser>

#include <cmath>

namespace rl::cli {

int runDiff(const QStringList& arguments) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        "Compare two .bake files frame by frame: the first frame where a body's position or rotation differs by "
        "more than the tolerance, and each body's largest differences.\n"
        "Exit code 0 when they are equal within the tolerances, 1 when they differ or a file cannot be read, "
        "2 on bad usage.");
    parser.addHelpOption();
    parser.addPositionalArgument("a", "First .bake file.");
    parser.addPositionalArgument("b", "Second .bake file.");
    parser.addOption({"tolerance", "Position tolerance in metres (default 1e-5).", "m"});
    parser.addOption({"angle-tolerance", "Rotation tolerance in degrees (default 1e-3).", "deg"});
    parser.addOption({"csv", "Print one CSV row per body instead of the text report."});
    if (const std::optional<int> done = parseArguments(parser, arguments, "diff"))
        return *done;
    if (parser.positionalArguments().size() != 2) {
        printError(QStringLiteral("rigidlab-cli diff: expected two .bake files (see --help)"));
        return kExitUsage;
    }
    BakeDiffOptions options;
    auto tolerance = [&](const char* name, Real& out) {
        if (!parser.isSet(name))
            return true;
        bool ok = false;
        out = parser.value(name).toDouble(&ok);
        return ok && std::isfinite(out) && out >= 0.0;
    };
    if (!tolerance("tolerance", options.positionTolerance) ||
        !tolerance("angle-tolerance", options.rotationToleranceDegrees)) {
        printError(QStringLiteral("rigidlab-cli diff: --tolerance and --angle-tolerance take numbers >= 0"));
        return kExitUsage;
    }

    LoadedBake bakes[2];
    for (int i = 0; i < 2; ++i) {
        Result<LoadedBake> loaded = loadBake(parser.positionalArguments().at(i).toStdString());
        if (!loaded) {
            printError(loaded.error().toString());
            return kExitFailure;
        }
        bakes[i] = std::move(loaded).value();
    }
    const BakeDiffResult result = diffBakes(bakes[0].bake, bakes[1].bake, options);
    if (!result.comparable()) {
        printError(QStringLiteral("rigidlab-cli diff: ") + QString::fromStdString(result.incompatibility));
        return kExitFailure;
    }
    printOut(QString::fromStdString(parser.isSet("csv") ? bakeDiffCsv(result) : formatBakeDiff(result, options)));
    return result.equal() ? kExitOk : kExitFailure;
}

} // namespace rl::cli
