#include "files/RecoveryStore.h"

#include "document/SceneDocument.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QLockFile>
#include <QRandomGenerator>
#include <QSaveFile>
#include <QStandardPaths>

namespace rl {

namespace {

QString filePath(const QString& id, const char* suffix) {
    return RecoveryStore::directory() + QLatin1Char('/') + id + QLatin1String(suffix);
}

std::unique_ptr<QLockFile> makeLock(const QString& id) {
    auto lock = std::make_unique<QLockFile>(filePath(id, ".lock"));
    lock->setStaleLockTime(0); // an editor may run for days: only a dead owner makes a lock stale, never its age
    return lock;
}

} // namespace

RecoveryStore::RecoveryStore()
    : m_id(QStringLiteral("%1-%2")
               .arg(QCoreApplication::applicationPid())
               .arg(QRandomGenerator::global()->generate(), 8, 16, QLatin1Char('0'))) {}

RecoveryStore::~RecoveryStore() {
    remove();
}

QString RecoveryStore::directory() {
    return QStandardPaths::writableLocation(QStandardPaths::AppDataLocation) + QStringLiteral("/recovery");
}

QString RecoveryStore::path() const {
    return filePath(m_id, ".rlscene");
}

bool RecoveryStore::write(const SceneDocument& document, QString* errorMessage) {
    if (!QDir().mkpath(directory())) {
        if (errorMessage)
            *errorMessage = QCoreApplication::translate("rl::RecoveryStore", "%1: cannot create the folder")
                                .arg(QDir::toNativeSeparators(directory()));
        return false;
    }
    if (!m_lock) {
        m_lock = makeLock(m_id);
        m_lock->tryLock(0);
    }
    if (!document.writeCopy(path(), errorMessage))
        return false;
    QSaveFile source(filePath(m_id, ".source"));
    if (source.open(QIODevice::WriteOnly)) {
        source.write(document.filePath().toUtf8());
        source.commit();
    }
    return true;
}

void RecoveryStore::remove() {
    QFile::remove(path());
    QFile::remove(filePath(m_id, ".source"));
    if (m_lock)
        m_lock->unlock(); // removes the lock file
    m_lock.reset();
}

std::optional<RecoveryStore::Orphan> RecoveryStore::findOrphan() const {
    const QFileInfoList copies =
        QDir(directory()).entryInfoList({QStringLiteral("*.rlscene")}, QDir::Files, QDir::Time); // newest first
    for (const QFileInfo& copy : copies) {
        const QString id = copy.completeBaseName();
        if (id == m_id)
            continue;
        std::shared_ptr<QLockFile> lock = makeLock(id);
        if (!lock->tryLock(0))
            continue; // its editor is still running
        Orphan orphan{copy.absoluteFilePath(), {}, copy.lastModified(), std::move(lock)};
        QFile source(filePath(id, ".source"));
        if (source.open(QIODevice::ReadOnly))
            orphan.sourcePath = QString::fromUtf8(source.readAll());
        return orphan;
    }
    return std::nullopt;
}

void RecoveryStore::discard(Orphan& orphan) {
    const QFileInfo copy(orphan.path);
    QFile::remove(orphan.path);
    QFile::remove(copy.absolutePath() + QLatin1Char('/') + copy.completeBaseName() + QStringLiteral(".source"));
    if (orphan.lock)
        orphan.lock->unlock();
    orphan.lock.reset();
}

} // namespace rl
