// rigidlab-cli export: converts a .bake (ours or the original project's) to CSV and/or to a .bake in our format.
#include "Cli.h"
#include "io/BakeFile.h"
#include "io/BakeLoad.h"
#include "io/CsvWriter.h"

#include <QCommandLineParser>

namespace rl::cli {

namespace {

// "A:B" (inclusive), "A:" (to the end) or "A" (one frame).
bool parseFrameRange(const QString& text, CsvOptions& options) {
    const QStringList parts = text.split(':');
    if (parts.size() > 2 || parts.value(0).isEmpty())
        return false;
    bool ok = true;
    options.firstFrame = parts[0].toULongLong(&ok);
    if (!ok)
        return false;
    if (parts.size() == 1) {
        options.lastFrame = options.firstFrame;
        return true;
    }
    if (parts[1].isEmpty())
        return true;
    options.lastFrame = parts[1].toULongLong(&ok);
    return ok && options.lastFrame >= options.firstFrame;
}

// Comma-separated body indices or names.
bool parseBodies(const QString& text, const Bake& bake, CsvOptions& options, QString& error) {
    for (const QString& item : text.split(',', Qt::SkipEmptyParts)) {
        bool isNumber = false;
        const qulonglong index = item.toULongLong(&isNumber);
        if (isNumber) {
            if (index >= bake.bodyCount()) {
                error = QString("body index %1 out of range (0..%2)").arg(index).arg(bake.bodyCount() - 1);
                return false;
            }
            options.bodies.push_back(index);
            continue;
        }
        bool found = false;
        for (size_t i = 0; i < bake.bodyCount() && !found; ++i)
            if (QString::fromStdString(bake.body(i).name) == item) {
                options.bodies.push_back(i);
                found = true;
            }
        if (!found) {
            error = QString("no body named '%1'").arg(item);
            return false;
        }
    }
    return true;
}

} // namespace

int runExport(const QStringList& arguments) {
    QCommandLineParser parser;
    parser.setApplicationDescription("Convert a .bake file to CSV (centres of mass, rotations since frame 0) and/or "
                                     "rewrite it in the current .bake format.");
    parser.addHelpOption();
    parser.addPositionalArgument("bake", "Input .bake file (RigidLab's or the original project's).");
    parser.addOption({"csv", "Write CSV to <file>.", "file"});
    parser.addOption({"bake", "Write a .bake in the current format to <file>.", "file"});
    parser.addOption({"frames", "CSV only: frame range A:B (inclusive), A: or A.", "range"});
    parser.addOption({"bodies", "CSV only: comma-separated body indices or names.", "list"});
    parser.addOption({"threads", "Threads that format the numbers (the files are the same for any count).", "t"});
    if (const std::optional<int> done = parseArguments(parser, arguments, "export"))
        return *done;
    if (parser.positionalArguments().size() != 1) {
        printError(QStringLiteral("rigidlab-cli export: expected exactly one input .bake file (see --help)"));
        return kExitUsage;
    }
    if (!parser.isSet("csv") && !parser.isSet("bake")) {
        printError(QStringLiteral("rigidlab-cli export: nothing to do; give --csv FILE and/or --bake FILE"));
        return kExitUsage;
    }
    CsvOptions csvOptions;
    if (!parsePositiveInt(parser, "threads", csvOptions.threads)) {
        printError("rigidlab-cli export: bad --threads '" + parser.value("threads") + "' (a positive number)");
        return kExitUsage;
    }
    if (parser.isSet("frames") && !parseFrameRange(parser.value("frames"), csvOptions)) {
        printError("rigidlab-cli export: bad --frames '" + parser.value("frames") + "' (expected A:B, A: or A)");
        return kExitUsage;
    }

    const std::string input = parser.positionalArguments().constFirst().toStdString();
    Result<LoadedBake> loaded = loadBake(input);
    if (!loaded) {
        printError(loaded.error().toString());
        return kExitFailure;
    }
    const Bake& bake = loaded->bake;
    if (parser.isSet("bodies")) {
        QString error;
        if (!parseBodies(parser.value("bodies"), bake, csvOptions, error)) {
            printError(QString::fromStdString(input) + ": " + error);
            return kExitFailure;
        }
    }
    if (!loaded->centred)
        printError(QString::fromStdString(input) +
                   ": note: no matching OBJ part, so CSV positions are the stored vertex means, not centres of mass");

    if (parser.isSet("csv")) {
        const std::string out = parser.value("csv").toStdString();
        Status s = writeCsvFile(bake, out, csvOptions);
        if (!s) {
            printError(s.error().toString());
            return kExitFailure;
        }
        printError(QString("wrote %1 (%2 frames x %3 bodies)")
                       .arg(QString::fromStdString(out))
                       .arg(bake.frameCount())
                       .arg(csvOptions.bodies.empty() ? bake.bodyCount() : csvOptions.bodies.size()));
    }
    if (parser.isSet("bake")) {
        const std::string out = parser.value("bake").toStdString();
        Status s = writeBakeFile(bake, out, csvOptions.threads);
        if (!s) {
            printError(s.error().toString());
            return kExitFailure;
        }
        printError(QString("wrote %1").arg(QString::fromStdString(out)));
    }
    return kExitOk;
}

} // namespace rl::cli
