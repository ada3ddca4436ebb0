#include "files/RecentFiles.h"

#include <QDir>
#include <QFileInfo>
#include <QSettings>

namespace rl::RecentFiles {

namespace {

// One spelling per file, so that "a/../b.obj", a symlink and the file itself are one entry.
QString normalized(const QString& path) {
    const QFileInfo info(path);
    const QString canonical = info.canonicalFilePath(); // empty when the file no longer exists
    return canonical.isEmpty() ? QDir::cleanPath(info.absoluteFilePath()) : canonical;
}

void store(const QStringList& paths) {
    QSettings().setValue(QLatin1String(kSettingsKey), paths);
}

} // namespace

QStringList list() {
    QStringList paths = QSettings().value(QLatin1String(kSettingsKey)).toStringList();
    paths.removeAll(QString());
    return paths.mid(0, kMaxCount);
}

void add(const QString& path) {
    const QString entry = normalized(path);
    QStringList paths = list();
    paths.removeIf([&](const QString& p) { return normalized(p) == entry; });
    paths.prepend(entry);
    store(paths.mid(0, kMaxCount));
}

void remove(const QString& path) {
    const QString entry = normalized(path);
    QStringList paths = list();
    paths.removeIf([&](const QString& p) { return p == path || normalized(p) == entry; });
    store(paths);
}

void clear() {
    store({});
}

} // namespace rl::RecentFiles
