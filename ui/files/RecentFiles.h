// The Open Recent list: most recent first, no duplicates, at most kMaxCount entries, kept in QSettings so that every
// window and every session shares it.
#pragma once

#include <QString>
#include <QStringList>

namespace rl::RecentFiles {

inline constexpr int kMaxCount = 10;
inline constexpr const char* kSettingsKey = "files/recent";

// Absolute paths, most recent first.
QStringList list();
// Moves `path` (made absolute; a symlink and its target count as one file) to the front and drops the oldest
// entries beyond kMaxCount.
void add(const QString& path);
void remove(const QString& path);
void clear();

} // namespace rl::RecentFiles
