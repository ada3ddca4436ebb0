// The German translation: it is compiled into the editor, it is complete for the current sources (lupdate is run
// over ui/ and app/rigidlab/ into a scratch file and every string must have a finished German translation), every
// translation keeps the placeholders, tags and accelerator of its source, plurals have both German forms and render
// with the right one, the main window comes up in German when the translator is installed, and in German no two items
// of a menu (nor two titles of the menu bar) share an accelerator letter.
#include "MainWindow.h"
#include "document/CoreText.h"
#include "scene/BodyProperties.h"
#include "settings/Translation.h"
#include "ui/GuiTestSetup.h"
#include "world/Effects.h"

#include <QMenu>
#include <QMenuBar>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>
#include <QTranslator>
#include <QXmlStreamReader>

#include <algorithm>
#include <set>

namespace {

struct TsMessage {
    QString context;
    QString source;
    bool finished = false; // a translation is present and not marked unfinished or vanished
    bool numerus = false;
    bool gone = false; // marked vanished or obsolete: the string left the sources, nothing uses it
    QStringList forms; // the translation, or its plural forms
};

// Reads a Qt Linguist .ts file: one entry per message, keyed by context and source text.
QList<TsMessage> readTs(const QString& path, QString* error) {
    QList<TsMessage> messages;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = path + QStringLiteral(": cannot open");
        return messages;
    }
    QXmlStreamReader xml(&file);
    QString context;
    TsMessage message;
    while (!xml.atEnd()) {
        xml.readNext();
        if (xml.isStartElement()) {
            if (xml.name() == QLatin1String("name")) {
                context = xml.readElementText();
            } else if (xml.name() == QLatin1String("message")) {
                message = TsMessage();
                message.context = context;
                message.numerus = xml.attributes().value(QLatin1String("numerus")) == QLatin1String("yes");
            } else if (xml.name() == QLatin1String("source")) {
                message.source = xml.readElementText();
            } else if (xml.name() == QLatin1String("translation")) {
                const QString type = xml.attributes().value(QLatin1String("type")).toString();
                message.gone = type == QLatin1String("vanished") || type == QLatin1String("obsolete");
                if (message.numerus) {
                    while (xml.readNextStartElement())
                        message.forms.append(xml.readElementText());
                } else {
                    message.forms.append(xml.readElementText());
                }
                message.finished = type.isEmpty() && !message.forms.isEmpty() &&
                                   std::none_of(message.forms.cbegin(), message.forms.cend(),
                                                [](const QString& f) { return f.trimmed().isEmpty(); });
            }
        } else if (xml.isEndElement() && xml.name() == QLatin1String("message")) {
            messages.append(message);
        }
    }
    if (xml.hasError())
        *error = QStringLiteral("%1:%2: %3").arg(path).arg(xml.lineNumber()).arg(xml.errorString());
    return messages;
}

const QString kGermanTs = QStringLiteral(RL_SOURCE_DIR "/translations/rigidlab_de.ts");
const QString kEnglishTs = QStringLiteral(RL_SOURCE_DIR "/translations/rigidlab_en.ts");

// %1..%99, %L1.., %n: the arguments a translation must keep.
QStringList placeholders(const QString& text) {
    static const QRegularExpression re(QStringLiteral("%L?\\d+|%n"));
    QStringList found;
    for (auto it = re.globalMatch(text); it.hasNext();)
        found.append(it.next().captured());
    found.removeDuplicates();
    found.sort();
    return found;
}

// Rich-text tags (<b>, <br>, ...); "<opened scene>" and the like are text, not tags.
QStringList tags(const QString& text) {
    static const QRegularExpression re(QStringLiteral("</?(?:b|i|u|br|p|a|span|tt|code|small|big|font|ul|ol|li|"
                                                      "table|tr|td|h[1-6])\\b[^>]*>"));
    QStringList found;
    for (auto it = re.globalMatch(text); it.hasNext();)
        found.append(it.next().captured());
    found.sort();
    return found;
}

// The accelerator letter of a menu text ("Speichern &unter …" -> 'u'), lower case; a null QChar if none.
QChar mnemonic(const QString& text) {
    for (qsizetype i = 0; i + 1 < text.size(); ++i) {
        if (text[i] != QLatin1Char('&'))
            continue;
        if (text[i + 1] == QLatin1Char('&')) {
            ++i; // "&&" is a literal ampersand
            continue;
        }
        return text[i + 1].toLower();
    }
    return QChar();
}

// Lists every pair of visible items that share an accelerator letter, in the menu and its submenus.
void collectClashes(const QString& where, const QList<QAction*>& actions, QStringList* clashes) {
    QHash<QChar, QString> seen;
    for (QAction* action : actions) {
        if (action->isSeparator() || !action->isVisible())
            continue;
        const QChar letter = mnemonic(action->text());
        if (!letter.isNull()) {
            if (seen.contains(letter))
                clashes->append(QStringLiteral("%1: '%2' in \"%3\" and \"%4\"")
                                    .arg(where, letter, seen.value(letter), action->text()));
            else
                seen.insert(letter, action->text());
        }
        if (QMenu* sub = action->menu())
            collectClashes(where + QStringLiteral(" > ") + sub->title(), sub->actions(), clashes);
    }
}

} // namespace

class TestTranslations : public QObject {
    Q_OBJECT
public:
    static void initMain() { rl::test::prepareGuiTest(); }

private slots:
    void germanFileIsComplete() {
        QString error;
        const QList<TsMessage> messages = readTs(kGermanTs, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QVERIFY(messages.size() > 100);
        QStringList missing;
        for (const TsMessage& m : messages)
            if (!m.finished && !m.gone)
                missing.append(m.context + QStringLiteral(": ") + m.source);
        QVERIFY2(missing.isEmpty(), qPrintable(missing.join(QLatin1Char('\n'))));
    }

#ifdef RL_LUPDATE_PATH
    // lupdate over the current sources: German must translate every string, English (a plural-only file, so that
    // "%n bodies" reads "1 body") every plural.
    void translationFilesCoverTheSources() {
        QTemporaryDir scratch;
        QVERIFY(scratch.isValid());
        const QString fresh = scratch.filePath(QStringLiteral("fresh.ts"));
        QProcess lupdate;
        lupdate.start(QStringLiteral(RL_LUPDATE_PATH),
                      {QStringLiteral("-silent"), QStringLiteral("-locations"), QStringLiteral("none"),
                       QStringLiteral(RL_SOURCE_DIR "/ui"), QStringLiteral(RL_SOURCE_DIR "/app/rigidlab"),
                       QStringLiteral("-ts"), fresh});
        QVERIFY(lupdate.waitForFinished(120000));
        QCOMPARE(lupdate.exitCode(), 0);
        QString error;
        const QList<TsMessage> current = readTs(fresh, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QVERIFY(current.size() > 100);
        const auto finishedIn = [&error](const QString& path) {
            QSet<QString> translated;
            for (const TsMessage& m : readTs(path, &error))
                if (m.finished)
                    translated.insert(m.context + QLatin1Char('\x1f') + m.source);
            return translated;
        };
        const QSet<QString> german = finishedIn(kGermanTs);
        const QSet<QString> english = finishedIn(kEnglishTs);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QStringList missing;
        for (const TsMessage& m : current) {
            const QString key = m.context + QLatin1Char('\x1f') + m.source;
            if (!german.contains(key))
                missing.append(QStringLiteral("de: ") + m.context + QStringLiteral(": ") + m.source);
            if (m.numerus && !english.contains(key))
                missing.append(QStringLiteral("en (plural): ") + m.context + QStringLiteral(": ") + m.source);
        }
        QVERIFY2(missing.isEmpty(), qPrintable(QStringLiteral("untranslated strings (see translations/fill_ts.py):\n") +
                                               missing.join(QLatin1Char('\n'))));
    }
#endif

    void translationsKeepPlaceholdersTagsAndAccelerators() {
        QString error;
        const QList<TsMessage> messages = readTs(kGermanTs, &error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QStringList wrong;
        for (const TsMessage& m : messages) {
            if (!m.finished)
                continue;
            if (m.numerus && m.forms.size() != 2)
                wrong.append(QStringLiteral("%1: %2: German plurals need 2 forms, found %3")
                                 .arg(m.context, m.source)
                                 .arg(m.forms.size()));
            for (const QString& form : m.forms) {
                QStringList expected = placeholders(m.source);
                QStringList got = placeholders(form);
                if (m.numerus) { // a singular form may spell out the number
                    expected.removeAll(QStringLiteral("%n"));
                    got.removeAll(QStringLiteral("%n"));
                }
                if (got != expected)
                    wrong.append(QStringLiteral("%1: %2: placeholders %3 became %4 in \"%5\"")
                                     .arg(m.context, m.source, expected.join(QLatin1Char(' ')),
                                          got.join(QLatin1Char(' ')), form));
                if (tags(form) != tags(m.source))
                    wrong.append(QStringLiteral("%1: %2: tags differ in \"%3\"").arg(m.context, m.source, form));
                if (mnemonic(form).isNull() != mnemonic(m.source).isNull())
                    wrong.append(
                        QStringLiteral("%1: %2: accelerator added or lost in \"%3\"").arg(m.context, m.source, form));
            }
        }
        QVERIFY2(wrong.isEmpty(), qPrintable(wrong.join(QLatin1Char('\n'))));
    }

    // main.cpp loads the translator with rl::loadEditorTranslation: a German system locale (any region) or the "de"
    // setting finds the German file, every other locale the English one (its plural forms).
    void languageSettingFindsTheTranslation_data() {
        QTest::addColumn<QString>("locale");
        QTest::addColumn<QString>("language"); // of the file found; empty: none
        QTest::newRow("setting de") << QStringLiteral("de") << QStringLiteral("de_DE");
        QTest::newRow("system de_DE") << QStringLiteral("de_DE") << QStringLiteral("de_DE");
        QTest::newRow("system de_AT") << QStringLiteral("de_AT") << QStringLiteral("de_DE");
        QTest::newRow("setting en") << QStringLiteral("en") << QStringLiteral("en");
        QTest::newRow("system en_GB") << QStringLiteral("en_GB") << QStringLiteral("en");
        QTest::newRow("system fr_FR") << QStringLiteral("fr_FR") << QStringLiteral("en");
        QTest::newRow("C locale") << QStringLiteral("C") << QStringLiteral("en");
    }
    void languageSettingFindsTheTranslation() {
        QFETCH(QString, locale);
        QFETCH(QString, language);
        QTranslator translator;
        QVERIFY(rl::loadEditorTranslation(translator, QLocale(locale)));
        QCOMPARE(translator.language(), language);
        // The plural forms work whichever file it is.
        QCoreApplication::installTranslator(&translator);
        const QString one = QCoreApplication::translate("rl::PreflightDialog",
                                                        "%n finding(s) in this scene may make a bake inaccurate or "
                                                        "unstable.",
                                                        "", 1);
        QCoreApplication::removeTranslator(&translator);
        QVERIFY2(!one.contains(QLatin1String("(s)")), qPrintable(one));
    }

    void pluralsRenderInEnglish_data() {
        QTest::addColumn<int>("n");
        QTest::addColumn<QString>("expected");
        QTest::newRow("1") << 1 << QStringLiteral("1 anchor");
        QTest::newRow("5") << 5 << QStringLiteral("5 anchors");
    }
    void pluralsRenderInEnglish() {
        QFETCH(int, n);
        QFETCH(QString, expected);
        QTranslator translator;
        QVERIFY(translator.load(QStringLiteral(":/i18n/rigidlab_en.qm")));
        QCoreApplication::installTranslator(&translator);
        const QString text = QCoreApplication::translate("rl::MainWindow", "%n anchors", nullptr, n);
        QCoreApplication::removeTranslator(&translator);
        QCOMPARE(text, expected);
    }

    void pluralsRenderInGerman_data() {
        QTest::addColumn<QByteArray>("context");
        QTest::addColumn<QByteArray>("source");
        QTest::addColumn<int>("n");
        QTest::addColumn<QString>("expected");
        QTest::newRow("1 file") << QByteArray("rl::FileController") << QByteArray("%n files") << 1
                                << QStringLiteral("1 Datei");
        QTest::newRow("5 files") << QByteArray("rl::FileController") << QByteArray("%n files") << 5
                                 << QStringLiteral("5 Dateien");
        QTest::newRow("0 files") << QByteArray("rl::FileController") << QByteArray("%n files") << 0
                                 << QStringLiteral("0 Dateien");
        QTest::newRow("1 frame baking") << QByteArray("rl::SimulationController") << QByteArray("Baking %n frames…")
                                        << 1 << QStringLiteral("1 Frame wird gebacken …");
        QTest::newRow("250 frames baking") << QByteArray("rl::SimulationController") << QByteArray("Baking %n frames…")
                                           << 250 << QStringLiteral("250 Frames werden gebacken …");
        QTest::newRow("1 body cannot") << QByteArray("rl::InspectorWidget")
                                       << QByteArray("%n bodies cannot be simulated") << 1
                                       << QStringLiteral("1 Körper kann nicht simuliert werden");
        QTest::newRow("5 bodies cannot") << QByteArray("rl::InspectorWidget")
                                         << QByteArray("%n bodies cannot be simulated") << 5
                                         << QStringLiteral("5 Körper können nicht simuliert werden");
    }
    void pluralsRenderInGerman() {
        QFETCH(QByteArray, context);
        QFETCH(QByteArray, source);
        QFETCH(int, n);
        QFETCH(QString, expected);
        QTranslator translator;
        QVERIFY(translator.load(QStringLiteral(":/i18n/rigidlab_de.qm")));
        QCoreApplication::installTranslator(&translator);
        const QString text = QCoreApplication::translate(context.constData(), source.constData(), nullptr, n);
        QCoreApplication::removeTranslator(&translator);
        QCOMPARE(text, expected);
    }

    // Alt+letter opens a menu of the bar and a letter picks an item of an open menu: in German every menu's
    // letters are unique, and no title of the bar takes a letter that an Alt+letter shortcut already uses.
    void germanMenusHaveUniqueAccelerators() {
        QTranslator translator;
        QVERIFY(translator.load(QStringLiteral(":/i18n/rigidlab_de.qm")));
        QCoreApplication::installTranslator(&translator);
        QStringList clashes;
        {
            rl::MainWindow window;
            const QList<QAction*> bar = window.menuBar()->actions();
            QVERIFY(bar.size() >= 8);
            collectClashes(QStringLiteral("menu bar"), bar, &clashes);
            QSet<QChar> altLetters;
            for (QAction* action : window.findChildren<QAction*>())
                for (const QKeySequence& shortcut : action->shortcuts())
                    if (shortcut.count() == 1 && shortcut[0].keyboardModifiers() == Qt::AltModifier &&
                        shortcut[0].key() >= Qt::Key_A && shortcut[0].key() <= Qt::Key_Z)
                        altLetters.insert(QChar(u'a' + (shortcut[0].key() - Qt::Key_A)));
            QVERIFY(altLetters.contains(QLatin1Char('a'))); // Alt+A toggles the anchor
            for (QAction* title : bar)
                if (altLetters.contains(mnemonic(title->text())))
                    clashes.append(QStringLiteral("menu bar: \"%1\" takes Alt+%2, a shortcut")
                                       .arg(title->text(), mnemonic(title->text()).toUpper()));
        }
        QCoreApplication::removeTranslator(&translator);
        QVERIFY2(clashes.isEmpty(), qPrintable(clashes.join(QLatin1Char('\n'))));
    }

    // The core's body warnings and effect reasons reach the inspector and the World dock through coreText(): every
    // phrase the core can give (all 128 combinations of scene facts, with and without damping, in auto and forced
    // modes, and the warnings of a concave body, a 1 cm one and an Anchor_Cube) has a German translation.
    void corePhrasesAreTranslated() {
        std::set<std::string> phrases;
        for (int bits = 0; bits < 128; ++bits) {
            rl::SceneFacts facts;
            bool* flags[] = {&facts.anyDynamic,  &facts.anyAnchor,     &facts.anyNonSphereDynamic,
                             &facts.anySpinning, &facts.frictionPairs, &facts.restitutionPairs,
                             &facts.fastBodies};
            for (int k = 0; k < 7; ++k)
                *flags[k] = (bits >> k) & 1;
            for (const double damping : {0.0, 0.5}) {
                rl::Scene scene;
                scene.world.linearDamping = damping;
                for (const rl::EffectMode mode : {rl::EffectMode::Auto, rl::EffectMode::On, rl::EffectMode::Off}) {
                    rl::EffectsSetting setting;
                    setting.modes.fill(mode);
                    for (const std::string& reason : rl::decideEffects(scene, setting, facts).reasons)
                        phrases.insert(reason.rfind("auto: ", 0) == 0 ? reason.substr(6) : reason);
                }
            }
        }
        rl::Scene scene;
        rl::BodyDef concave; // an L of two unit cubes: its hull is larger than the mesh
        concave.name = "L";
        concave.shape.type = rl::ShapeType::Mesh;
        concave.shape.points = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0},
                                {0, 0, 1}, {2, 0, 1}, {2, 1, 1}, {1, 1, 1}, {1, 2, 1}, {0, 2, 1}};
        concave.shape.triangles = {{0, 2, 1},   {0, 3, 2},  {0, 5, 3},  {3, 5, 4},   {6, 7, 8}, {6, 8, 9}, {6, 9, 11},
                                   {9, 10, 11}, {0, 1, 7},  {0, 7, 6},  {1, 2, 8},   {1, 8, 7}, {2, 3, 9}, {2, 9, 8},
                                   {3, 4, 10},  {3, 10, 9}, {4, 5, 11}, {4, 11, 10}, {5, 0, 6}, {5, 6, 11}};
        rl::BodyDef tiny;
        tiny.name = "Tiny";
        tiny.shape.halfExtents = rl::Vec3(0.005);
        rl::BodyDef legacy; // an "Anchor" floor with its mesh's name, as Blender's legacy OBJ exporter writes it
        legacy.name = "Anchor_Cube";
        legacy.shape.halfExtents = rl::Vec3(5.0, 0.5, 5.0);
        size_t warnings = 0;
        for (const rl::BodyDef& body : {concave, tiny, legacy}) {
            const auto props = rl::computeBodyProperties(scene, body);
            QVERIFY2(props, body.name.c_str());
            for (const std::string& warning : props->warnings) {
                phrases.insert(warning);
                ++warnings;
            }
        }
        QVERIFY2(warnings >= 3, "the concave, the 1 cm and the Anchor_Cube body should each have a warning");
        QVERIFY(phrases.size() >= 16);

        QTranslator translator;
        QVERIFY(translator.load(QStringLiteral(":/i18n/rigidlab_de.qm")));
        QCoreApplication::installTranslator(&translator);
        QStringList untranslated;
        for (const std::string& phrase : phrases)
            if (rl::coreText(phrase) == QString::fromStdString(phrase))
                untranslated << QString::fromStdString(phrase);
        const QString concaveGerman = rl::coreText("concave: simulated as its convex hull");
        QCoreApplication::removeTranslator(&translator);
        QVERIFY2(untranslated.isEmpty(), qPrintable(untranslated.join(QLatin1Char('\n'))));
        QCOMPARE(concaveGerman, QStringLiteral("konkav: wird als seine konvexe Hülle simuliert"));
        QCOMPARE(rl::coreText("concave: simulated as its convex hull"),
                 QStringLiteral("concave: simulated as its convex hull"));
    }

    void mainWindowComesUpInGerman() {
        QTranslator translator;
        QVERIFY(translator.load(QStringLiteral(":/i18n/rigidlab_de.qm")));
        QCoreApplication::installTranslator(&translator);
        {
            rl::MainWindow window;
            QCOMPARE(window.menu(rl::MainWindow::Menu::File)->title(), QStringLiteral("&Datei"));
            QCOMPARE(window.menu(rl::MainWindow::Menu::Edit)->title(), QStringLiteral("&Bearbeiten"));
            QCOMPARE(window.menu(rl::MainWindow::Menu::Help)->title(), QStringLiteral("&Hilfe"));
        }
        QCoreApplication::removeTranslator(&translator);
        rl::MainWindow english;
        QCOMPARE(english.menu(rl::MainWindow::Menu::File)->title(), QStringLiteral("&File"));
    }
};

QTEST_MAIN(TestTranslations)
#include "tst_translations.moc"
