// rigidlab-cli accuracy: the accuracy-versus-cost study (error against exact solutions, CPU time, fitted orders)
// printed as a table, and optionally written as CSV and as a log-log SVG plot of error against CPU time.
#include "Cli.h"
#include "analysis/Accuracy.h"

#include <QCommandLineParser>

namespace rl::cli {

int runAccuracy(const QStringList& arguments) {
    QCommandLineParser parser;
    parser.setApplicationDescription(
        "Integrate problems with exact solutions (the original project's sin(t) experiment, a projectile with and "
        "without drag, torque-free tumbling, a frictional incline, a bouncing drop) with every integrator, step size "
        "and substep count; print error, CPU time and the fitted convergence order.");
    parser.addHelpOption();
    parser.addOption({"csv", "Write every row to <file> as CSV.", "file"});
    parser.addOption({"plot", "Write a log-log plot of error against CPU time to <file> (SVG).", "file"});
    if (const std::optional<int> done = parseArguments(parser, arguments, "accuracy"))
        return *done;
    if (!parser.positionalArguments().isEmpty()) {
        printError(QStringLiteral("rigidlab-cli accuracy: takes no positional arguments (see --help)"));
        return kExitUsage;
    }
    printError(QStringLiteral("running the accuracy study..."));
    const AccuracyReport report = runAccuracyStudy();
    printOut(QString::fromStdString(formatAccuracyTable(report)));
    if (parser.isSet("csv")) {
        Status s = writeAccuracyCsv(report, parser.value("csv").toStdString());
        if (!s) {
            printError(s.error().toString());
            return kExitFailure;
        }
    }
    if (parser.isSet("plot")) {
        Status s = writeAccuracySvg(report, parser.value("plot").toStdString());
        if (!s) {
            printError(s.error().toString());
            return kExitFailure;
        }
    }
    return kExitOk;
}

} // namespace rl::cli
