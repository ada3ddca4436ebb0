// Autosaved copies of unsaved work in QStandardPaths::AppDataLocation/recovery, one per editor window. Each copy is
// guarded by a QLockFile held while its window lives, so a copy whose lock is free was left by an editor that
// crashed; this also holds with several editors open at once, where a "newer than the last clean exit" rule would
// offer a running editor's copy or hide a crashed one's.
#pragma once

#include <QDateTime>
#include <QString>

#include <memory>
#include <optional>

class QLockFile;

namespace rl {

class SceneDocument;

class RecoveryStore {
public:
    RecoveryStore();
    // Removes this window's copy: a window that closes normally leaves nothing to recover.
    ~RecoveryStore();
    RecoveryStore(const RecoveryStore&) = delete;
    RecoveryStore& operator=(const RecoveryStore&) = delete;

    static QString directory();
    // This window's recovery file (it exists only after write()).
    QString path() const;
    // Writes the document (and the path of its own file, to offer it again on restore). False with a message that
    // names the file and the problem.
    bool write(const SceneDocument& document, QString* errorMessage);
    void remove();

    // A copy whose editor is gone, with the file it was a copy of (empty for an untitled scene).
    struct Orphan {
        QString path;
        QString sourcePath;
        QDateTime saved;
        std::shared_ptr<QLockFile> lock; // held while the copy is offered, so that no other editor offers it too
    };
    // The newest copy left by an editor that is no longer running, if any.
    std::optional<Orphan> findOrphan() const;
    // Deletes an orphan's files (after it was restored or the user declined it).
    static void discard(Orphan& orphan);

private:
    QString m_id;
    std::unique_ptr<QLockFile> m_lock;
};

} // namespace rl
