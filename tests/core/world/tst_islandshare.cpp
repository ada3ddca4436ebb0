// How a team shares a group's islands out (world/IslandShare.h): in runs of body order when that is fair within the
// given share, else largest first to the least loaded member; every island to exactly one member.
#include "world/IslandShare.h"

#include <QTest>

#include <algorithm>
#include <vector>

using namespace rl;

Q_DECLARE_METATYPE(std::vector<uint32_t>)

class TestIslandShare : public QObject {
    Q_OBJECT
private slots:
    void sharesOut_data() {
        QTest::addColumn<std::vector<uint32_t>>("work");
        QTest::addColumn<int>("members");
        QTest::addColumn<std::vector<uint32_t>>("expected"); // each island's member
        QTest::addColumn<bool>("inBodyOrder");
        QTest::addColumn<int>("largest");
        QTest::newRow("ten equal islands, two members")
            << std::vector<uint32_t>(10, 1) << 2 << std::vector<uint32_t>{0, 0, 0, 0, 0, 1, 1, 1, 1, 1} << true << 5;
        QTest::newRow("a larger first island")
            << std::vector<uint32_t>{3, 1, 1, 1, 1, 1} << 2 << std::vector<uint32_t>{0, 0, 1, 1, 1, 1} << true << 4;
        // In order, member 0 would take 60 % of the work: largest first, then each to the least loaded.
        QTest::newRow("one island of most of the work")
            << std::vector<uint32_t>{60, 10, 10, 10, 10} << 2 << std::vector<uint32_t>{0, 1, 1, 1, 1} << false << 60;
        // Each run takes one of the two large islands: 2 + 6 | 6 + 2.
        QTest::newRow("two large in the middle")
            << std::vector<uint32_t>{2, 6, 6, 2} << 2 << std::vector<uint32_t>{0, 0, 1, 1} << true << 8;
        // 9 + 1 | 1 + 9.
        QTest::newRow("heavy ends") << std::vector<uint32_t>{9, 1, 1, 9} << 2 << std::vector<uint32_t>{0, 0, 1, 1}
                                    << true << 10;
        // 5 | 4 + 1: the 4's middle is at 7 of 10, in the second half.
        QTest::newRow("uneven three") << std::vector<uint32_t>{5, 4, 1} << 2 << std::vector<uint32_t>{0, 1, 1} << true
                                      << 5;
        // In order 9 | 3 (75 %); largest first 8 | 4, the islands of equal work taken earliest first.
        QTest::newRow("fallback ties") << std::vector<uint32_t>{1, 8, 1, 1, 1} << 2
                                       << std::vector<uint32_t>{1, 0, 1, 1, 1} << false << 8;
        QTest::newRow("three members") << std::vector<uint32_t>(9, 2) << 3
                                       << std::vector<uint32_t>{0, 0, 0, 1, 1, 1, 2, 2, 2} << true << 6;
        QTest::newRow("one member") << std::vector<uint32_t>{4, 1, 7} << 1 << std::vector<uint32_t>{0, 0, 0} << true
                                    << 12;
        QTest::newRow("no islands") << std::vector<uint32_t>{} << 2 << std::vector<uint32_t>{} << true << 0;
    }
    void sharesOut() {
        QFETCH(std::vector<uint32_t>, work);
        QFETCH(int, members);
        QFETCH(std::vector<uint32_t>, expected);
        QFETCH(bool, inBodyOrder);
        QFETCH(int, largest);
        IslandShare share;
        shareIslandsOut(work, static_cast<size_t>(members), 102, share);
        QCOMPARE(share.member, expected);
        QCOMPARE(share.inBodyOrder, inBodyOrder);
        QCOMPARE(share.largest, uint64_t(largest));
        uint64_t all = 0;
        for (uint32_t w : work)
            all += w;
        QCOMPARE(share.all, all);
    }

    // The share in body order keeps to its limit: with a larger allowance the same islands stay in order.
    void limitDecidesTheOrder() {
        const std::vector<uint32_t> work{60, 10, 10, 10, 10};
        IslandShare share;
        shareIslandsOut(work, 2, 120, share); // up to 60 % on one of two members
        QVERIFY(share.inBodyOrder);
        QCOMPARE(share.member, (std::vector<uint32_t>{0, 1, 1, 1, 1}));
        shareIslandsOut(work, 2, 119, share);
        QVERIFY(!share.inBodyOrder);
    }

    // Many random groups: every island goes to a member of the team; in body order the members never go back; the
    // largest share is what the islands add up to.
    void randomGroupsAreShared() {
        uint32_t seed = 12345;
        const auto next = [&seed] {
            seed = seed * 1664525u + 1013904223u;
            return seed >> 8;
        };
        IslandShare share;
        int inOrder = 0;
        for (int trial = 0; trial < 500; ++trial) {
            std::vector<uint32_t> work(1 + next() % 40);
            for (uint32_t& w : work)
                w = 1 + (next() % 8 == 0 ? next() % 200 : next() % 6);
            const size_t members = 1 + next() % 4;
            shareIslandsOut(work, members, 102, share);
            QCOMPARE(share.member.size(), work.size());
            std::vector<uint64_t> total(members, 0);
            for (size_t k = 0; k < work.size(); ++k) {
                QVERIFY(share.member[k] < members);
                total[share.member[k]] += work[k];
                if (share.inBodyOrder && k > 0)
                    QVERIFY(share.member[k] >= share.member[k - 1]);
            }
            QCOMPARE(share.largest, *std::max_element(total.begin(), total.end()));
            if (share.inBodyOrder)
                QVERIFY(100 * share.largest * members <= 102 * share.all || members == 1);
            inOrder += share.inBodyOrder ? 1 : 0;
        }
        QVERIFY(inOrder > 0 && inOrder < 500); // both ways were taken
    }
};

QTEST_APPLESS_MAIN(TestIslandShare)
#include "tst_islandshare.moc"
