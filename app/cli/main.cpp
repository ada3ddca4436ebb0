// rigidlab-cli: the headless front end. Dispatches to one subcommand; exit codes: 0 ok, 1 bad input or failed run,
// 2 bad usage (DESIGN.md §6).
#include "Cli.h"
#include "HugePages.h"

#include <QCommandLineParser>
#include <QCoreApplication>

#include <cstdio>

namespace rl::cli {

void printError(const QString& message) {
    std::fputs(qPrintable(message), stderr);
    std::fputc('\n', stderr);
}

std::optional<int> parseArguments(QCommandLineParser& parser, const QStringList& arguments, const char* command) {
    if (!parser.parse(arguments)) {
        printError(QStringLiteral("rigidlab-cli %1: %2").arg(QLatin1String(command), parser.errorText()));
        return kExitUsage;
    }
    if (parser.isSet("help")) {
        printOut(parser.helpText());
        return kExitOk;
    }
    return std::nullopt;
}

bool parsePositiveInt(const QCommandLineParser& parser, const QString& name, int& out) {
    if (!parser.isSet(name))
        return true;
    bool ok = false;
    out = parser.value(name).toInt(&ok);
    return ok && out > 0;
}

void printError(const std::string& message) {
    printError(QString::fromStdString(message));
}

void printOut(const QString& text) {
    const QByteArray bytes = text.toUtf8();
    std::fwrite(bytes.constData(), 1, static_cast<size_t>(bytes.size()), stdout);
}

} // namespace rl::cli

namespace {

struct Entry {
    const char* name;
    rl::cli::Command run;
    const char* summary;
};

const Entry kCommands[] = {
    {"info", rl::cli::runInfo, "bodies, anchors, materials, volume, mass, centre of mass, inertia, warnings"},
    {"bake", rl::cli::runBake, "simulate a scene and write .bake and/or CSV"},
    {"export", rl::cli::runExport, "convert a .bake to CSV or to a .bake in the current format"},
    {"accuracy", rl::cli::runAccuracy, "error against exact solutions versus CPU time, per integrator"},
    {"bench", rl::cli::runBench, "step scenes and print the wall-clock cost per step (median, p95)"},
    {"diff", rl::cli::runDiff, "compare two .bake files: first diverging frame, largest differences per body"},
};

void printUsage(FILE* out) {
    std::fprintf(out, "Usage: rigidlab-cli <command> [options]\n\nCommands:\n");
    for (const Entry& e : kCommands)
        std::fprintf(out, "  %-10s %s\n", e.name, e.summary);
    std::fprintf(out, "\nRun 'rigidlab-cli <command> --help' for the options of one command.\n");
}

} // namespace

int main(int argc, char* argv[]) {
    rl::app::useHugePages(argv);
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName("rigidlab-cli");
    QCoreApplication::setApplicationVersion(RIGIDLAB_VERSION);
    const QStringList args = QCoreApplication::arguments();
    if (args.size() < 2) {
        printUsage(stderr);
        return rl::cli::kExitUsage;
    }
    const QString command = args.at(1);
    if (command == "--help" || command == "-h" || command == "help") {
        printUsage(stdout);
        return rl::cli::kExitOk;
    }
    if (command == "--version" || command == "-v") {
        std::printf("rigidlab-cli %s\n", RIGIDLAB_VERSION);
        return rl::cli::kExitOk;
    }
    for (const Entry& e : kCommands) {
        if (command == QLatin1String(e.name)) {
            QStringList sub = args.mid(2);
            sub.prepend(args.at(0) + " " + command);
            return e.run(sub);
        }
    }
    std::fprintf(stderr, "rigidlab-cli: unknown command '%s'\n\n", qPrintable(command));
    printUsage(stderr);
    return rl::cli::kExitUsage;
}
