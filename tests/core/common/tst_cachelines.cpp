// claimLines(): keeps every byte and touches none outside its range (a guard page on either side would fault).
#include "common/CacheLines.h"

#include <QtTest>

#include <cstddef>
#include <sys/mman.h>
#include <unistd.h>

using namespace rl;

class TestCacheLines : public QObject {
    Q_OBJECT

private slots:
    void keepsBytesAndStaysInRange_data() {
        QTest::addColumn<int>("offset");
        QTest::addColumn<int>("bytes");
        // At the page's start (a guard page before it) and at its end (a guard page after it), on and off line
        // boundaries, empty and one byte.
        QTest::newRow("empty") << 0 << 0;
        QTest::newRow("one byte at the start") << 0 << 1;
        QTest::newRow("one line") << 0 << 64;
        QTest::newRow("a line and a byte") << 0 << 65;
        QTest::newRow("from mid-line") << 5 << 200;
        QTest::newRow("one byte at the end") << -1 << 1;
        QTest::newRow("up to the end, off a line") << -3 << 3;
        QTest::newRow("up to the end, from mid-line") << -1000 << 1000;
        QTest::newRow("the whole page") << 0 << -1;
    }

    void keepsBytesAndStaysInRange() {
        QFETCH(int, offset);
        QFETCH(int, bytes);
        const size_t page = static_cast<size_t>(sysconf(_SC_PAGESIZE));
        void* map = mmap(nullptr, 3 * page, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        QVERIFY(map != MAP_FAILED);
        char* const base = static_cast<char*>(map);
        char* const middle = base + page;
        for (size_t i = 0; i < page; ++i)
            middle[i] = static_cast<char>(i * 7 + 3);
        QCOMPARE(mprotect(base, page, PROT_NONE), 0);
        QCOMPARE(mprotect(middle + page, page, PROT_NONE), 0);

        const size_t length = bytes < 0 ? page : static_cast<size_t>(bytes);
        const size_t start = offset < 0 ? page - static_cast<size_t>(-offset) : static_cast<size_t>(offset);
        QVERIFY(start + length <= page);
        claimLines(middle + start, length);
        for (size_t i = 0; i < page; ++i)
            QCOMPARE(middle[i], static_cast<char>(i * 7 + 3));
        QCOMPARE(munmap(map, 3 * page), 0);
    }
};

QTEST_APPLESS_MAIN(TestCacheLines)
#include "tst_cachelines.moc"
