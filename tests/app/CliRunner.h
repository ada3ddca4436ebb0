// Runs the built rigidlab-cli (RL_CLI_PATH) as a user would and captures its exit code, stdout and stderr.
// Shared by the tests of the command-line subcommands.
#pragma once

#include <QProcess>
#include <QProcessEnvironment>
#include <QStringList>

namespace rl::test {

struct CliRun {
    int exitCode = -1; // -2 when the process crashed, -1 when it timed out
    QByteArray out;
    QByteArray err;
};

inline CliRun runCli(const QStringList& args,
                     const QProcessEnvironment& environment = QProcessEnvironment::systemEnvironment()) {
    QProcess p;
    p.setProcessEnvironment(environment);
    p.start(QStringLiteral(RL_CLI_PATH), args);
    CliRun r;
    if (!p.waitForFinished(120000)) {
        p.kill();
        p.waitForFinished();
        return r;
    }
    r.exitCode = p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -2;
    r.out = p.readAllStandardOutput();
    r.err = p.readAllStandardError();
    return r;
}

} // namespace rl::test
