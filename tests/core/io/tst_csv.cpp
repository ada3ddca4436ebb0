// Tests of io/CsvWriter: the exact header, frame-major rows of the centre of mass, rotation and velocities, names
// that need RFC 4180 quoting parsed back by an independent parser, subsets, ranges and errors.
#include "core/bake/BakeFixture.h"
#include "io/CsvWriter.h"
#include "io/NumberFormat.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <fstream>
#include <sstream>
#include <thread>

using namespace rl;

Q_DECLARE_METATYPE(std::string)

namespace {

using Row = std::vector<std::string>;

// RFC 4180: fields split by commas, records by CRLF or LF; a quoted field may hold commas, line breaks and doubled
// quotes. Returns false on malformed input (a quote inside an unquoted field, an unterminated quote).
bool parseCsv(const std::string& text, std::vector<Row>& rows) {
    rows.clear();
    Row row;
    std::string field;
    bool quoted = false, wasQuoted = false;
    size_t i = 0;
    auto endField = [&] {
        row.push_back(field);
        field.clear();
        wasQuoted = false;
    };
    while (i < text.size()) {
        const char c = text[i];
        if (quoted) {
            if (c == '"') {
                if (i + 1 < text.size() && text[i + 1] == '"') {
                    field += '"';
                    i += 2;
                    continue;
                }
                quoted = false;
                wasQuoted = true;
            } else {
                field += c;
            }
            ++i;
            continue;
        }
        if (c == '"') {
            if (!field.empty() || wasQuoted)
                return false;
            quoted = true;
        } else if (c == ',') {
            endField();
        } else if (c == '\r' || c == '\n') {
            if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n')
                ++i;
            endField();
            rows.push_back(row);
            row.clear();
        } else {
            if (wasQuoted)
                return false;
            field += c;
        }
        ++i;
    }
    if (quoted)
        return false;
    if (!field.empty() || !row.empty()) {
        endField();
        rows.push_back(row);
    }
    return true;
}

float toFloat(const std::string& s) {
    return parseFloat(s).value_or(std::nanf(""));
}

std::string toCsv(const Bake& bake, const CsvOptions& options = {}) {
    std::ostringstream out;
    const Status s = writeCsv(bake, out, options);
    return s.ok() ? out.str() : "ERROR " + s.error().toString();
}

} // namespace

class TestCsv : public QObject {
    Q_OBJECT

private slots:
    void headerAndRows() {
        const Bake bake = test::makeFixtureBake(12, 60.0);
        std::vector<Row> rows;
        const std::string text = toCsv(bake);
        QVERIFY(parseCsv(text, rows));
        QCOMPARE(text.substr(0, text.find('\n')), std::string(kCsvHeader));
        QCOMPARE(rows.size(), size_t(1 + 12 * 3));
        for (size_t r = 1; r < rows.size(); ++r) {
            const Row& row = rows[r];
            QCOMPARE(row.size(), size_t(18));
            const size_t f = (r - 1) / 3, b = (r - 1) % 3; // frame-major
            QCOMPARE(row[0], std::to_string(f));
            QCOMPARE(parseDouble(row[1]).value_or(-1), bake.frameTime(f));
            QCOMPARE(row[2], std::to_string(b));
            QCOMPARE(row[3], bake.body(b).name);
            QCOMPARE(row[4], std::string(bake.body(b).anchor ? "1" : "0"));
            const BakeBodyState s = bake.state(f, b);
            // Exact: floats written shortest read back to the same bits.
            QVERIFY(glm::vec3(toFloat(row[5]), toFloat(row[6]), toFloat(row[7])) == s.position);
            QVERIFY(glm::quat(toFloat(row[8]), toFloat(row[9]), toFloat(row[10]), toFloat(row[11])) == s.rotation);
            QVERIFY(glm::vec3(toFloat(row[12]), toFloat(row[13]), toFloat(row[14])) == s.linearVelocity);
            QVERIFY(glm::vec3(toFloat(row[15]), toFloat(row[16]), toFloat(row[17])) == s.angularVelocity);
        }
        // x y z is the centre of mass, not the vertex mean the .bake file holds.
        QVERIFY(glm::length(Vec3(bake.position(0, 2)) - bake.vertexMean(0, 2)) > 0.01);
    }

    void quotedNames_data() {
        QTest::addColumn<std::string>("name");
        QTest::addColumn<bool>("needsQuotes");
        QTest::newRow("plain") << std::string("Cube.001") << false;
        QTest::newRow("space") << std::string("Wedge Part") << false;
        QTest::newRow("comma") << std::string("Left, upper") << true;
        QTest::newRow("quote") << std::string("The \"big\" one") << true;
        QTest::newRow("newline") << std::string("two\nlines") << true;
        QTest::newRow("crlf") << std::string("two\r\nlines") << true;
        QTest::newRow("everything") << std::string("\"a\",\n\"b\"") << true;
        QTest::newRow("empty") << std::string() << false;
    }

    void quotedNames() {
        QFETCH(std::string, name);
        QFETCH(bool, needsQuotes);
        Bake bake = test::makeFixtureBake(3, 60.0);
        bake.body(1).name = name;
        const std::string text = toCsv(bake);
        QCOMPARE(text.find("\"") != std::string::npos, needsQuotes);
        std::vector<Row> rows;
        QVERIFY(parseCsv(text, rows));
        QCOMPARE(rows.size(), size_t(1 + 3 * 3));
        for (size_t r = 1; r < rows.size(); ++r) {
            QCOMPARE(rows[r].size(), size_t(18));
            if (rows[r][2] == "1")
                QCOMPARE(rows[r][3], name);
        }
    }

    void subsetAndRange() {
        const Bake bake = test::makeFixtureBake(10, 30.0);
        CsvOptions options;
        options.bodies = {2, 0};
        options.firstFrame = 3;
        options.lastFrame = 5;
        std::vector<Row> rows;
        QVERIFY(parseCsv(toCsv(bake, options), rows));
        QCOMPARE(rows.size(), size_t(1 + 3 * 2));
        const char* expected[][2] = {{"3", "2"}, {"3", "0"}, {"4", "2"}, {"4", "0"}, {"5", "2"}, {"5", "0"}};
        for (size_t r = 1; r < rows.size(); ++r) {
            QCOMPARE(rows[r][0], std::string(expected[r - 1][0]));
            QCOMPARE(rows[r][2], std::string(expected[r - 1][1]));
        }
        // A last frame beyond the bake is clamped.
        options.lastFrame = 1000;
        QVERIFY(parseCsv(toCsv(bake, options), rows));
        QCOMPARE(rows.size(), size_t(1 + 7 * 2));
    }

    void badOptions_data() {
        QTest::addColumn<int>("body");
        QTest::addColumn<int>("first");
        QTest::addColumn<int>("last");
        QTest::addColumn<QString>("message");
        QTest::newRow("body out of range") << 3 << 0 << 100 << "no body 3";
        QTest::newRow("first beyond end") << 0 << 10 << 100 << "empty frame range";
        QTest::newRow("first after last") << 0 << 5 << 4 << "empty frame range";
    }

    void badOptions() {
        QFETCH(int, body);
        QFETCH(int, first);
        QFETCH(int, last);
        QFETCH(QString, message);
        const Bake bake = test::makeFixtureBake(10, 60.0);
        CsvOptions options;
        options.bodies = {size_t(body)};
        options.firstFrame = size_t(first);
        options.lastFrame = size_t(last);
        QTemporaryDir dir;
        const std::string path = dir.filePath("out.csv").toStdString();
        Status s = writeCsvFile(bake, path, options);
        QVERIFY(!s.ok());
        QCOMPARE(s.error().file, path);
        QVERIFY2(s.error().message.find(message.toStdString()) != std::string::npos, s.error().toString().c_str());
        QVERIFY(!QFile::exists(QString::fromStdString(path)));
    }

    void bakeWithoutVelocitiesLeavesThemEmpty() {
        Bake bake = test::makeFixtureBake(2, 60.0);
        bake.setHasVelocities(false);
        std::vector<Row> rows;
        QVERIFY(parseCsv(toCsv(bake), rows));
        for (size_t r = 1; r < rows.size(); ++r) {
            QCOMPARE(rows[r].size(), size_t(18));
            for (size_t c = 12; c < 18; ++c)
                QVERIFY(rows[r][c].empty());
            QVERIFY(!rows[r][5].empty());
        }
    }

    // Rows formatted on several threads (CsvOptions::threads) are the same bytes as on one: a bake of 300 bodies and
    // 200 frames is eight blocks of 27 frames (framesPerBlock()) whole, and four blocks of 54 frames as a subset of
    // 150 bodies (every other one, last first) over a range of 171 frames.
    void threadsWriteTheSameBytes_data() {
        QTest::addColumn<int>("threads");
        QTest::addColumn<bool>("subset");
        for (int threads : {2, 3, 8})
            for (bool subset : {false, true})
                QTest::addRow("%d threads%s", threads, subset ? ", subset and range" : "") << threads << subset;
    }
    void threadsWriteTheSameBytes() {
        QFETCH(int, threads);
        QFETCH(bool, subset);
        const Bake bake = test::makeMovingBake(300, 200);
        CsvOptions options;
        if (subset) {
            for (size_t b = 300; b >= 2; b -= 2)
                options.bodies.push_back(b - 1);
            options.firstFrame = 20;
            options.lastFrame = 190;
        }
        const std::string one = toCsv(bake, options);
        options.threads = threads;
        const std::string many = toCsv(bake, options);
        QVERIFY(one.size() > 1000);
        QCOMPARE(many.size(), one.size());
        QVERIFY(many == one);
    }

    // Progress comes on the calling thread, in order, up to the whole range; returning false cancels the export
    // with an error, and the file is left as it was.
    void progressAndCancel_data() {
        QTest::addColumn<int>("threads");
        for (int threads : {1, 2, 4})
            QTest::addRow("%d threads", threads) << threads;
    }
    void progressAndCancel() {
        QFETCH(int, threads);
        const Bake bake = test::makeMovingBake(300, 200);
        std::vector<std::pair<size_t, size_t>> calls;
        bool onCaller = true;
        const std::thread::id caller = std::this_thread::get_id();
        CsvOptions options;
        options.threads = threads;
        options.progress = [&](size_t done, size_t total) {
            calls.emplace_back(done, total);
            onCaller = onCaller && std::this_thread::get_id() == caller;
            return true;
        };
        QVERIFY(!toCsv(bake, options).starts_with("ERROR"));
        QVERIFY(onCaller);
        QCOMPARE(calls.size(), size_t(200)); // one a frame
        for (size_t k = 0; k < calls.size(); ++k)
            QCOMPARE(calls[k], std::make_pair(k + 1, size_t(200)));

        QTemporaryDir dir;
        const std::string path = dir.filePath("cancelled.csv").toStdString();
        {
            std::ofstream before(path);
            before << "kept\n";
        }
        options.progress = [](size_t done, size_t) { return done < 50; };
        const Status s = writeCsvFile(bake, path, options);
        QVERIFY(!s.ok());
        QVERIFY2(s.error().message.find("cancelled") != std::string::npos, s.error().toString().c_str());
        std::ifstream in(path);
        std::stringstream kept;
        kept << in.rdbuf();
        QCOMPARE(kept.str(), std::string("kept\n"));
    }

    void writesFile() {
        QTemporaryDir dir;
        const std::string path = dir.filePath("run.csv").toStdString();
        const Bake bake = test::makeFixtureBake(4, 60.0);
        QVERIFY(writeCsvFile(bake, path).ok());
        std::ifstream in(path, std::ios::binary);
        std::stringstream ss;
        ss << in.rdbuf();
        QCOMPARE(ss.str(), toCsv(bake));
    }
};

QTEST_APPLESS_MAIN(TestCsv)
#include "tst_csv.moc"
