// The core round trip that bench prints beside a thread-count comparison: a time in nanoseconds when the thread may
// run on two CPUs, nothing when it may run on one or the arguments ask for no trips.
#include "world/CoreRoundTrip.h"

#include <QTest>

#include <cmath>

#if defined(__linux__)
#include <pthread.h>
#include <sched.h>
#endif

using namespace rl;

class TestCoreRoundTrip : public QObject {
    Q_OBJECT
private slots:
    void measuresBetweenTwoCpus() {
#if defined(__linux__)
        cpu_set_t allowed;
        CPU_ZERO(&allowed);
        QCOMPARE(sched_getaffinity(0, sizeof(allowed), &allowed), 0);
        if (CPU_COUNT(&allowed) < 2) { // nothing to measure between
            QVERIFY(!measureCoreRoundTripNs(3, 200).has_value());
            return;
        }
        // Another test on a CPU can make a trip wait for the scheduler, past the one-second limit: a few tries.
        std::optional<double> ns;
        for (int attempt = 0; attempt < 5 && !ns; ++attempt)
            ns = measureCoreRoundTripNs(3, 200);
        QVERIFY(ns.has_value());
        QVERIFY(std::isfinite(*ns));
        QVERIFY(*ns > 0.0);
        QVERIFY2(*ns < 1e7, qPrintable(QString::number(*ns))); // 200 trips in a second would be 5 ms each
        qInfo("core round trip %.0f ns", *ns);
#else
        QVERIFY(!measureCoreRoundTripNs().has_value());
#endif
    }

    void nothingOnOneCpu() {
#if defined(__linux__)
        cpu_set_t before;
        CPU_ZERO(&before);
        QCOMPARE(pthread_getaffinity_np(pthread_self(), sizeof(before), &before), 0);
        int first = 0;
        while (first < CPU_SETSIZE && !CPU_ISSET(first, &before))
            ++first;
        cpu_set_t one;
        CPU_ZERO(&one);
        CPU_SET(first, &one);
        QCOMPARE(pthread_setaffinity_np(pthread_self(), sizeof(one), &one), 0);
        const std::optional<double> ns = measureCoreRoundTripNs(3, 200);
        QCOMPARE(pthread_setaffinity_np(pthread_self(), sizeof(before), &before), 0);
        QVERIFY(!ns.has_value());
#endif
    }

    void nothingForNoTrips_data() {
        QTest::addColumn<int>("rounds");
        QTest::addColumn<int>("trips");
        QTest::newRow("no rounds") << 0 << 100;
        QTest::newRow("no trips") << 3 << 0;
        QTest::newRow("negative") << -1 << 100;
    }
    void nothingForNoTrips() {
        QFETCH(int, rounds);
        QFETCH(int, trips);
        QVERIFY(!measureCoreRoundTripNs(rounds, trips).has_value());
    }
};

QTEST_APPLESS_MAIN(TestCoreRoundTrip)
#include "tst_coreroundtrip.moc"
