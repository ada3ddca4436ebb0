// Tests of io/Json and io/NumberFormat: exact number round trips, strings and escapes, key order, and errors that
// point at the right line and column for every kind of malformed input. No raw string literals: Qt 6.4's moc
// loses track of the class when a raw string contains a backslash-quote.
#include "io/Json.h"
#include "io/NumberFormat.h"

#include <QTest>

#include <bit>
#include <cmath>
#include <cstring>
#include <random>

using namespace rl;

Q_DECLARE_METATYPE(std::string)

class TestJson : public QObject {
    Q_OBJECT

private slots:
    // Random bit patterns cover subnormals, huge and tiny exponents and every mantissa length.
    void numbersRoundTripExactly() {
        std::mt19937_64 rng(12345);
        JsonValue array = JsonValue::array();
        std::vector<double> values = {0.0,
                                      -0.0,
                                      0.1,
                                      1.0 / 3.0,
                                      1e308,
                                      4.9406564584124654e-324,
                                      -2.2250738585072014e-308,
                                      9007199254740993.0,
                                      123456789012345678.0};
        while (values.size() < 20000) {
            const double d = std::bit_cast<double>(rng());
            if (std::isfinite(d))
                values.push_back(d);
        }
        for (double d : values)
            array.push(d);
        for (int indent : {0, 2}) {
            const std::string text = writeJson(array, indent);
            Result<JsonValue> back = parseJson(text);
            QVERIFY2(back.ok(), back.ok() ? "" : back.error().toString().c_str());
            const JsonValue::Array& items = back->asArray();
            QCOMPARE(items.size(), values.size());
            for (size_t i = 0; i < values.size(); ++i)
                QCOMPARE(std::bit_cast<uint64_t>(items[i].asNumber()), std::bit_cast<uint64_t>(values[i]));
        }
    }

    void floatsRoundTripExactly() {
        std::mt19937 rng(777);
        int checked = 0;
        for (int i = 0; i < 20000; ++i) {
            const float f = std::bit_cast<float>(static_cast<uint32_t>(rng()));
            if (!std::isfinite(f))
                continue;
            const std::optional<float> back = parseFloat(formatFloat(f));
            QVERIFY(back);
            QCOMPARE(std::bit_cast<uint32_t>(*back), std::bit_cast<uint32_t>(f));
            ++checked;
        }
        QVERIFY(checked > 19000);
    }

    void strictNumberParsing_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<bool>("valid");
        QTest::addColumn<double>("value");
        QTest::newRow("integer") << "42" << true << 42.0;
        QTest::newRow("plus sign") << "+1.5" << true << 1.5;
        QTest::newRow("negative exponent") << "-2.5e-3" << true << -0.0025;
        QTest::newRow("%g style") << "1e+06" << true << 1e6;
        QTest::newRow("leading dot") << ".5" << true << 0.5;
        QTest::newRow("empty") << "" << false << 0.0;
        QTest::newRow("nan") << "nan" << false << 0.0;
        QTest::newRow("inf") << "-inf" << false << 0.0;
        QTest::newRow("overflow") << "1e999" << false << 0.0;
        QTest::newRow("leading space") << " 1" << false << 0.0;
        QTest::newRow("trailing text") << "1.0x" << false << 0.0;
        QTest::newRow("hex") << "0x10" << false << 0.0;
        QTest::newRow("double sign") << "+-1" << false << 0.0;
        QTest::newRow("bare exponent") << "1e" << false << 0.0;
    }

    void strictNumberParsing() {
        QFETCH(QString, text);
        QFETCH(bool, valid);
        QFETCH(double, value);
        const std::optional<double> parsed = parseDouble(text.toStdString());
        QCOMPARE(parsed.has_value(), valid);
        if (valid)
            QCOMPARE(*parsed, value);
    }

    void integers() {
        QCOMPARE(parseInt("644").value_or(-1), 644);
        QCOMPARE(parseInt("+7").value_or(-1), 7);
        QVERIFY(!parseInt("1.0"));
        QVERIFY(!parseInt("99999999999999999999"));
        QVERIFY(!parseInt(""));
    }

    void keepsKeyOrderAndStructure() {
        const std::string text = "{\"zeta\":1,\"alpha\":[true,false,null],\"mid\":{\"x\":\"y\"},\"e\":[],\"o\":{}}";
        Result<JsonValue> v = parseJson(text);
        QVERIFY(v.ok());
        const JsonValue::Object& members = v->asObject();
        QCOMPARE(members.size(), size_t(5));
        QCOMPARE(members[0].key, std::string("zeta"));
        QCOMPARE(members[1].key, std::string("alpha"));
        QCOMPARE(members[4].key, std::string("o"));
        QCOMPARE(writeJson(*v, 0), text);
        QVERIFY(v->find("mid")->find("x")->isString());
        QVERIFY(v->find("missing") == nullptr);
    }

    void recordsPositions() {
        Result<JsonValue> v = parseJson("{\n  \"a\": [1,\n    \"two\"]\n}");
        QVERIFY(v.ok());
        const JsonValue& a = *v->find("a");
        QCOMPARE(a.line(), 2);
        QCOMPARE(a.column(), 8);
        QCOMPARE(a.asArray()[1].line(), 3);
        QCOMPARE(a.asArray()[1].column(), 5);
        QCOMPARE(v->asObject()[0].line, 2);
        QCOMPARE(v->asObject()[0].column, 3);
    }

    void stringEscapes_data() {
        QTest::addColumn<std::string>("json");
        QTest::addColumn<std::string>("expected");
        QTest::newRow("simple escapes") << std::string("\"a\\\"b\\\\c\\/d\\n\\t\\r\\b\\f\"")
                                        << std::string("a\"b\\c/d\n\t\r\b\f");
        QTest::newRow("latin") << std::string("\"caf\\u00e9\"") << std::string("caf\xC3\xA9");
        QTest::newRow("bmp") << std::string("\"\\u20AC\"") << std::string("\xE2\x82\xAC");
        QTest::newRow("surrogate pair") << std::string("\"\\ud83d\\ude00\"") << std::string("\xF0\x9F\x98\x80");
        QTest::newRow("raw utf8") << std::string("\"\xF0\x9F\x98\x80 ok\"") << std::string("\xF0\x9F\x98\x80 ok");
        QTest::newRow("nul escape") << std::string("\"a\\u0000b\"") << std::string("a\0b", 3);
    }

    void stringEscapes() {
        QFETCH(std::string, json);
        QFETCH(std::string, expected);
        Result<JsonValue> v = parseJson(json);
        QVERIFY2(v.ok(), v.ok() ? "" : v.error().toString().c_str());
        QCOMPARE(v->asString(), expected);
        // What we write reads back to the same bytes.
        Result<JsonValue> again = parseJson(writeJson(*v, 0));
        QVERIFY(again.ok());
        QCOMPARE(again->asString(), expected);
    }

    void writesEveryControlCharacter() {
        std::string all;
        for (int c = 1; c < 0x80; ++c)
            all += static_cast<char>(c);
        const std::string text = writeJson(JsonValue(all), 0);
        for (char c : text)
            QVERIFY(static_cast<unsigned char>(c) >= 0x20);
        QCOMPARE(parseJson(text)->asString(), all);
    }

    void syntaxErrors_data() {
        QTest::addColumn<std::string>("json");
        QTest::addColumn<int>("line");
        QTest::addColumn<int>("column");
        QTest::addColumn<QString>("message");
        QTest::newRow("missing comma") << std::string("{\n  \"a\": 1\n    \"b\": 2\n}") << 3 << 5
                                       << "expected ',' or '}'";
        QTest::newRow("trailing comma") << std::string("[1,]") << 1 << 4 << "expected a value";
        QTest::newRow("duplicate key") << std::string("{\"a\": 1, \"a\": 2}") << 1 << 10 << "duplicate key 'a'";
        QTest::newRow("unterminated string") << std::string("[\"abc") << 1 << 2 << "unterminated string";
        QTest::newRow("raw newline in string") << std::string("[\"a\nb\"]") << 1 << 4 << "raw line break";
        QTest::newRow("leading zero") << std::string("[01]") << 1 << 3 << "leading zero";
        QTest::newRow("lone high surrogate") << std::string("\"\\ud800x\"") << 1 << 2 << "high surrogate";
        QTest::newRow("lone low surrogate") << std::string("\"\\udc00\"") << 1 << 2 << "low surrogate";
        QTest::newRow("bad escape") << std::string("\"\\x\"") << 1 << 2 << "invalid escape";
        QTest::newRow("bad hex") << std::string("\"\\u12G4\"") << 1 << 6 << "hex digits";
        QTest::newRow("empty") << std::string("") << 1 << 1 << "unexpected end of file";
        QTest::newRow("only spaces") << std::string("  \n ") << 2 << 2 << "unexpected end of file";
        QTest::newRow("two values") << std::string("1 2") << 1 << 3 << "unexpected text";
        QTest::newRow("number too large") << std::string("[1e999]") << 1 << 2 << "out of range";
        QTest::newRow("misspelt literal") << std::string("tru") << 1 << 1 << "expected a value";
        QTest::newRow("missing colon") << std::string("{\"a\" 1}") << 1 << 6 << "expected ':'";
        QTest::newRow("non-string key") << std::string("{1: 2}") << 1 << 2 << "expected a string key";
        QTest::newRow("comment") << std::string("// no\n{}") << 1 << 1 << "expected a value";
        QTest::newRow("nan literal") << std::string("[NaN]") << 1 << 2 << "expected a value";
        QTest::newRow("invalid utf8") << std::string("\"\xFF\"") << 1 << 2 << "UTF-8";
        QTest::newRow("encoded surrogate") << std::string("\"\xED\xA0\x80\"") << 1 << 2 << "UTF-8";
        QTest::newRow("truncated object") << std::string("{\"a\": [1, 2") << 1 << 12 << "end of file";
        QTest::newRow("dot without digits") << std::string("1.") << 1 << 3 << "after '.'";
    }

    void syntaxErrors() {
        QFETCH(std::string, json);
        QFETCH(int, line);
        QFETCH(int, column);
        QFETCH(QString, message);
        Result<JsonValue> v = parseJson(json, "scene.rlscene");
        QVERIFY(!v.ok());
        const Error& e = v.error();
        QVERIFY2(e.message.find(message.toStdString()) != std::string::npos, e.toString().c_str());
        QCOMPARE(e.line, line);
        QCOMPARE(e.column, column);
        QCOMPARE(e.toString().rfind("scene.rlscene:" + std::to_string(line) + ":" + std::to_string(column) + ": ", 0),
                 size_t(0));
    }

    void duplicateKeyInLargeObject() {
        std::string text = "{";
        for (int i = 0; i < 100; ++i)
            text += "\"k" + std::to_string(i) + "\": " + std::to_string(i) + ",";
        text += "\"k57\": 0}";
        Result<JsonValue> v = parseJson(text);
        QVERIFY(!v.ok());
        QVERIFY(v.error().message.find("'k57'") != std::string::npos);
    }

    void depthLimit_data() {
        QTest::addColumn<int>("depth");
        QTest::addColumn<bool>("accepted");
        QTest::newRow("at the limit") << 128 << true;
        QTest::newRow("one beyond") << 129 << false;
        QTest::newRow("far beyond") << 100000 << false;
    }

    void depthLimit() {
        QFETCH(int, depth);
        QFETCH(bool, accepted);
        const std::string text = std::string(depth, '[') + std::string(depth, ']');
        Result<JsonValue> v = parseJson(text);
        QCOMPARE(v.ok(), accepted);
        if (!accepted)
            QVERIFY(v.error().message.find("nesting") != std::string::npos);
    }

    void sizeLimit() {
        JsonReadOptions options;
        options.maxBytes = 16;
        QVERIFY(parseJson("[1, 2, 3]", "", options).ok());
        Result<JsonValue> v = parseJson("[1, 2, 3, 4, 5, 6, 7]", "big.json", options);
        QVERIFY(!v.ok());
        QCOMPARE(v.error().file, std::string("big.json"));
        QVERIFY(v.error().message.find("larger") != std::string::npos);
    }

    void prettyWriter() {
        JsonValue root = JsonValue::object();
        root.set("format", "rigidlab-scene");
        root.set("gravity", JsonValue(JsonValue::Array{0, -9.81, 0}));
        JsonValue& nested = root.set("nested", JsonValue::object());
        nested.set("list", JsonValue(JsonValue::Array{JsonValue(JsonValue::Array{1, 2}), JsonValue::object()}));
        root.set("format", "replaced keeps position");
        const std::string text = writeJson(root);
        QVERIFY(text.find("\"gravity\": [0, -9.81, 0]") != std::string::npos);
        QVERIFY(text.find("\n  \"nested\": {\n    \"list\": [\n      [1, 2],\n      {}\n    ]\n  }") !=
                std::string::npos);
        QVERIFY(text.rfind("{\n  \"format\": \"replaced keeps position\"", 0) == 0);
        Result<JsonValue> back = parseJson(text);
        QVERIFY(back.ok());
        QVERIFY(*back == root);
    }

    void integersOfEveryWidth() {
        JsonValue v = JsonValue::array();
        v.push(size_t(644));
        v.push(int64_t(-5));
        v.push(uint8_t(7));
        v.push(true);
        QCOMPARE(writeJson(v, 0), std::string("[644,-5,7,true]"));
    }

    void byteOrderMarkIsSkipped() {
        Result<JsonValue> v = parseJson("\xEF\xBB\xBF{\"a\": 1}");
        QVERIFY(v.ok());
        QCOMPARE(v->find("a")->asNumber(), 1.0);
    }
};

QTEST_APPLESS_MAIN(TestJson)
#include "tst_json.moc"
