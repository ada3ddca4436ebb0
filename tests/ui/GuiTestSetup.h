// Shared setup of the UI test binaries, called from each test class's initMain(): the GL surface format the
// viewport needs (set before QApplication exists) and a private runtime directory for Qt under Xvfb.
#pragma once

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QSurfaceFormat>

namespace rl::test {

inline void prepareGuiTest() {
    if (qEnvironmentVariableIsEmpty("XDG_RUNTIME_DIR")) {
        const QString dir = QDir::tempPath() + QStringLiteral("/rigidlab-test-runtime");
        QDir().mkpath(dir);
        QFile::setPermissions(dir, QFileDevice::ReadOwner | QFileDevice::WriteOwner | QFileDevice::ExeOwner);
        qputenv("XDG_RUNTIME_DIR", dir.toLocal8Bit());
    }
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(8);
    QSurfaceFormat::setDefaultFormat(format);
    // Keeps the tests' QSettings apart from a user's.
    QCoreApplication::setOrganizationName("RigidLabTests");
}

} // namespace rl::test
