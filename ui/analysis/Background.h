// Runs a piece of work on its own thread and calls back on the GUI thread when it is done. The work must only touch
// state it owns or shares by shared_ptr: the receiver may be gone by the time the work ends, and then the callback
// is simply not called.
#pragma once

#include <QObject>
#include <QThread>

#include <utility>

namespace rl {

template <class Work, class Done>
void runInBackground(QObject* receiver, Work work, Done done) {
    QThread* thread = QThread::create(std::move(work));
    QObject::connect(thread, &QThread::finished, receiver, std::move(done));
    QObject::connect(thread, &QThread::finished, thread, &QObject::deleteLater);
    thread->start(QThread::LowPriority);
}

} // namespace rl
