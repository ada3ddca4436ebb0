// Shared pieces of rigidlab-cli: exit codes, the subcommand signature and output helpers.
// Each subcommand lives in its own Cmd*.cpp file and is listed once in main.cpp.
#pragma once

#include <QString>
#include <QStringList>

#include <optional>
#include <string>

class QCommandLineParser;

namespace rl::cli {

enum ExitCode { kExitOk = 0, kExitFailure = 1, kExitUsage = 2 };

// A subcommand gets its own arguments (argv[0] is "rigidlab-cli <name>") and returns an ExitCode.
using Command = int (*)(const QStringList& arguments);

int runInfo(const QStringList& arguments);
int runExport(const QStringList& arguments);
int runBake(const QStringList& arguments);
int runAccuracy(const QStringList& arguments);
int runBench(const QStringList& arguments);
int runDiff(const QStringList& arguments);

// Parses a subcommand's arguments. Returns the exit code when the command is already done (bad usage: 2, with the
// parser's message on stderr; --help: 0, with the help on stdout), or nothing when the command should go on.
std::optional<int> parseArguments(QCommandLineParser& parser, const QStringList& arguments, const char* command);

// An option that takes a whole number above 0: false when it is set to anything else; `out` is left alone when the
// option is not set.
bool parsePositiveInt(const QCommandLineParser& parser, const QString& name, int& out);

// Messages for people go to stderr; data goes to stdout or files.
void printError(const QString& message);
void printError(const std::string& message);
void printOut(const QString& text);

} // namespace rl::cli
