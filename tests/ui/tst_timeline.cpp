// The timeline dock's widget on its own: cursor and keys, mouse scrubbing and its x-to-frame mapping, track clicks
// and tooltips, adaptive ruler labels, zoom and pan, playback against an injected clock (speed, loop, end), stale
// and progress display, and the cost of a repaint while scrubbing a 10-minute bake.
#include "bake/Bake.h"
#include "timeline/TimelineView.h"
#include "timeline/TimelineWidget.h"
#include "ui/GuiTestSetup.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QElapsedTimer>
#include <QHelpEvent>
#include <QImage>
#include <QLabel>
#include <QSignalSpy>
#include <QTest>
#include <QToolTip>

#include <algorithm>
#include <cmath>
#include <memory>

using rl::Bake;
using rl::BakeDiagnostic;
using rl::TimelineView;
using rl::TimelineWidget;

namespace {

constexpr qint64 kSecond = 1'000'000'000;

// A ball dropped from 2 m that bounces with restitution 0.7: energy steps down at each bounce, penetration and
// contacts show at the bounces, the body falls asleep once it rests.
std::shared_ptr<Bake> makeBake(int frames, double fps = 60.0, bool diagnostics = true) {
    std::vector<rl::BakeBodyInfo> bodies(1);
    bodies[0].name = "Ball";
    auto bake = std::make_shared<Bake>(bodies, fps);
    if (diagnostics)
        bake->enableDiagnostics();
    bake->reserveFrames(static_cast<size_t>(frames));
    const double dt = 1.0 / fps;
    const double mass = 2.0;
    const double g = 9.81;
    double y = 2.0;
    double v = 0.0;
    for (int f = 0; f < frames; ++f) {
        const size_t i = bake->addFrame();
        rl::BakeBodyState state;
        state.position = glm::vec3(0.0f, static_cast<float>(y), 0.0f);
        state.linearVelocity = glm::vec3(0.0f, static_cast<float>(v), 0.0f);
        bake->setState(i, 0, state);
        if (diagnostics) {
            const bool contact = y <= 0.002;
            bake->setDiagnostic(i, BakeDiagnostic::KineticEnergy, static_cast<float>(0.5 * mass * v * v));
            bake->setDiagnostic(i, BakeDiagnostic::PotentialEnergy, static_cast<float>(mass * g * y));
            bake->setDiagnostic(i, BakeDiagnostic::MaxPenetration, contact ? 0.001f : 0.0f);
            bake->setDiagnostic(i, BakeDiagnostic::ContactCount, contact ? 1.0f : 0.0f);
            bake->setDiagnostic(i, BakeDiagnostic::AwakeBodies, std::abs(v) > 0.05 || y > 0.01 ? 1.0f : 0.0f);
        }
        v -= g * dt;
        y += v * dt;
        if (y < 0.0 && v < 0.0) {
            y = 0.0;
            v = -0.7 * v;
        }
    }
    return bake;
}

// A widget shown at a known size with the given frame range.
struct Fixture {
    TimelineWidget widget;
    explicit Fixture(int first = 0, int last = 100, QSize size = QSize(900, 220)) {
        widget.setFrameRange(first, last);
        widget.resize(size);
        widget.show();
        exposed = QTest::qWaitForWindowExposed(&widget);
    }
    bool exposed = false;
    TimelineView* view() const { return widget.view(); }
    QPoint rulerPoint(double frame) const {
        return QPoint(static_cast<int>(std::lround(view()->xForFrame(frame))), TimelineView::kRulerHeight / 2);
    }
};

QList<int> framesOf(const QSignalSpy& spy) {
    QList<int> frames;
    for (const QList<QVariant>& args : spy)
        frames << args.at(0).toInt();
    return frames;
}

int countPixels(const QImage& image, const QRect& area, const std::function<bool(QColor)>& match) {
    int n = 0;
    for (int y = area.top(); y <= area.bottom(); ++y)
        for (int x = area.left(); x <= area.right(); ++x)
            if (match(image.pixelColor(x, y)))
                ++n;
    return n;
}

// Counts the paint events a widget receives, to check that a timing loop really painted.
class PaintCounter : public QObject {
public:
    int paints = 0;
    bool eventFilter(QObject*, QEvent* event) override {
        if (event->type() == QEvent::Paint)
            ++paints;
        return false;
    }
};

bool orangeish(QColor c) {
    return c.red() > 150 && c.red() - c.blue() > 70 && c.green() > 80 && c.green() < c.red();
}

bool greenish(QColor c) {
    return c.green() > 120 && c.green() - c.red() > 50 && c.green() - c.blue() > 30;
}

} // namespace

class TestTimeline : public QObject {
    Q_OBJECT
public:
    static void initMain() { rl::test::prepareGuiTest(); }

private slots:
    void setCurrentFrameClampsAndEmits_data() {
        QTest::addColumn<int>("start");
        QTest::addColumn<int>("requested");
        QTest::addColumn<int>("expected");
        QTest::addColumn<bool>("emitted");
        QTest::newRow("inside") << 10 << 50 << 50 << true;
        QTest::newRow("below first") << 10 << -5 << 5 << true;
        QTest::newRow("above last") << 10 << 500 << 95 << true;
        QTest::newRow("same frame") << 10 << 10 << 10 << false;
        QTest::newRow("at last, above") << 95 << 96 << 95 << false;
    }
    void setCurrentFrameClampsAndEmits() {
        QFETCH(int, start);
        QFETCH(int, requested);
        QFETCH(int, expected);
        QFETCH(bool, emitted);
        TimelineWidget widget;
        widget.setFrameRange(5, 95);
        widget.setCurrentFrame(start);
        QCOMPARE(widget.currentFrame(), start);
        QSignalSpy spy(&widget, &TimelineWidget::currentFrameChanged);
        widget.setCurrentFrame(requested);
        QCOMPARE(widget.currentFrame(), expected);
        QCOMPARE(framesOf(spy), emitted ? QList<int>{expected} : QList<int>{});
    }

    void rangeChangeClampsCursor() {
        TimelineWidget widget;
        widget.setFrameRange(0, 100);
        widget.setCurrentFrame(80);
        QSignalSpy spy(&widget, &TimelineWidget::currentFrameChanged);
        widget.setFrameRange(0, 40);
        QCOMPARE(widget.currentFrame(), 40);
        QCOMPARE(framesOf(spy), QList<int>{40});
        widget.setFrameRange(30, 10); // reversed: taken as 10..30
        QCOMPARE(widget.firstFrame(), 10);
        QCOMPARE(widget.lastFrame(), 30);
        QCOMPARE(widget.currentFrame(), 30);
    }

    void keys_data() {
        QTest::addColumn<int>("start");
        QTest::addColumn<int>("key");
        QTest::addColumn<int>("expected");
        QTest::addColumn<bool>("emitted");
        QTest::newRow("right") << 10 << int(Qt::Key_Right) << 11 << true;
        QTest::newRow("left") << 10 << int(Qt::Key_Left) << 9 << true;
        QTest::newRow("left at first") << 5 << int(Qt::Key_Left) << 5 << false;
        QTest::newRow("right at last") << 95 << int(Qt::Key_Right) << 95 << false;
        QTest::newRow("home") << 40 << int(Qt::Key_Home) << 5 << true;
        QTest::newRow("end") << 40 << int(Qt::Key_End) << 95 << true;
        QTest::newRow("home at first") << 5 << int(Qt::Key_Home) << 5 << false;
    }
    void keys() {
        QFETCH(int, start);
        QFETCH(int, key);
        QFETCH(int, expected);
        QFETCH(bool, emitted);
        Fixture f(5, 95);
        QVERIFY(f.exposed);
        f.widget.setCurrentFrame(start);
        QSignalSpy spy(&f.widget, &TimelineWidget::currentFrameChanged);
        // Keys reach the canvas (the focus proxy) and travel up to the widget.
        QTest::keyClick(f.view(), Qt::Key(key));
        QCOMPARE(f.widget.currentFrame(), expected);
        QCOMPARE(framesOf(spy), emitted ? QList<int>{expected} : QList<int>{});
    }

    void slotsForTheWindowsActions() {
        TimelineWidget widget;
        widget.setFrameRange(0, 20);
        QSignalSpy spy(&widget, &TimelineWidget::currentFrameChanged);
        widget.stepForward();
        widget.stepForward();
        widget.stepBackward();
        widget.jumpToLast();
        widget.jumpToFirst();
        widget.nextFrameAction()->trigger();
        widget.lastFrameAction()->trigger();
        widget.previousFrameAction()->trigger();
        widget.firstFrameAction()->trigger();
        QCOMPARE(framesOf(spy), (QList<int>{1, 2, 1, 20, 0, 1, 20, 19, 0}));
    }

    // A window-wide shortcut on Home (the viewport's "frame everything") must not steal the key from the timeline.
    void timelineKeysWinOverWindowShortcuts() {
        QWidget window;
        auto* timeline = new TimelineWidget(&window);
        timeline->setFrameRange(0, 50);
        timeline->setCurrentFrame(30);
        timeline->resize(800, 200);
        auto* home = new QAction(&window);
        home->setShortcut(Qt::Key_Home);
        home->setShortcutContext(Qt::WindowShortcut);
        window.addAction(home);
        QSignalSpy triggered(home, &QAction::triggered);
        window.resize(800, 200);
        window.show();
        window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&window));
        timeline->setFocus();
        QTRY_VERIFY(timeline->view()->hasFocus());
        QTest::keyClick(timeline->view(), Qt::Key_Home);
        QCOMPARE(timeline->currentFrame(), 0);
        QCOMPARE(triggered.count(), 0);
        // Elsewhere the window's shortcut still works.
        timeline->clearFocus();
        window.setFocus();
        QTest::keyClick(&window, Qt::Key_Home);
        QCOMPARE(triggered.count(), 1);
    }

    // The mapping used by clicks matches the layout: the frame range plus a 2 % margin across the plot width.
    void mappingMatchesLayout() {
        Fixture f(0, 100, QSize(900, 200));
        QVERIFY(f.exposed);
        const QRectF plot = f.view()->plotRect();
        QCOMPARE(plot.left(), double(TimelineView::kGutterWidth + 10));
        QCOMPARE(plot.right(), double(f.view()->width() - 12));
        QCOMPARE(f.view()->viewStart(), -2.0);
        QCOMPARE(f.view()->viewEnd(), 102.0);
        for (double frame : {-2.0, 0.0, 37.0, 102.0})
            QCOMPARE(f.view()->xForFrame(frame), plot.left() + (frame + 2.0) * plot.width() / 104.0);
    }

    void pressMapsXToFrame_data() {
        QTest::addColumn<double>("frame"); // where to press, in frames (fractions fall between ticks)
        QTest::addColumn<int>("expected");
        QTest::newRow("first") << 0.0 << 0;
        QTest::newRow("one") << 1.0 << 1;
        QTest::newRow("middle") << 50.0 << 50;
        QTest::newRow("last") << 100.0 << 100;
        QTest::newRow("just past 37") << 37.3 << 37;
        QTest::newRow("just before 38") << 37.7 << 38;
        QTest::newRow("left of the range") << -1.6 << 0;
        QTest::newRow("right of the range") << 101.7 << 100;
    }
    void pressMapsXToFrame() {
        QFETCH(double, frame);
        QFETCH(int, expected);
        Fixture f(0, 100, QSize(1100, 200)); // 10 px per frame, so the fractions land on distinct pixels
        QVERIFY(f.exposed);
        f.widget.setCurrentFrame(60); // no row expects 60, so every press moves the cursor
        QTest::mousePress(f.view(), Qt::LeftButton, {}, f.rulerPoint(frame));
        QCOMPARE(f.widget.currentFrame(), expected);
        QTest::mouseRelease(f.view(), Qt::LeftButton, {}, f.rulerPoint(frame));
        QCOMPARE(f.view()->frameAt(f.view()->xForFrame(frame)), expected);
        // A click gives the timeline the keys (focus needs an active window).
        f.widget.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&f.widget));
        f.view()->clearFocus();
        QTest::mouseClick(f.view(), Qt::LeftButton, {}, f.rulerPoint(frame));
        QVERIFY(f.view()->hasFocus());
    }

    void dragScrubs() {
        Fixture f(0, 100);
        QVERIFY(f.exposed);
        QSignalSpy spy(&f.widget, &TimelineWidget::currentFrameChanged);
        QTest::mousePress(f.view(), Qt::LeftButton, {}, f.rulerPoint(10));
        QTest::mouseMove(f.view(), f.rulerPoint(20));
        QTest::mouseMove(f.view(), f.rulerPoint(35));
        QTest::mouseMove(f.view(), QPoint(f.view()->width() - 2, 20)); // past the end clamps
        QTest::mouseRelease(f.view(), Qt::LeftButton, {}, QPoint(f.view()->width() - 2, 20));
        QCOMPARE(framesOf(spy), (QList<int>{10, 20, 35, 100}));
        // After the release, moving does nothing.
        QTest::mouseMove(f.view(), f.rulerPoint(50));
        QCOMPARE(f.widget.currentFrame(), 100);
    }

    void clickOnTrackJumps_data() {
        QTest::addColumn<int>("track");
        QTest::addColumn<QString>("name");
        QTest::newRow("energy") << 0 << "Energy";
        QTest::newRow("penetration") << 1 << "Max penetration";
        QTest::newRow("contacts") << 2 << "Contacts";
        QTest::newRow("awake") << 3 << "Awake bodies";
    }
    void clickOnTrackJumps() {
        QFETCH(int, track);
        QFETCH(QString, name);
        Fixture f(0, 100, QSize(900, 260));
        QVERIFY(f.exposed);
        f.widget.setBake(makeBake(120));
        QCOMPARE(f.widget.lastFrame(), 119); // the range grew to hold the bake
        QCOMPARE(f.view()->trackCount(), 4);
        QCOMPARE(f.view()->trackName(track), name);
        const QRect r = f.view()->trackRect(track);
        QVERIFY(r.height() >= TimelineView::kTrackHeight);
        QVERIFY(r.top() >= TimelineView::kRulerHeight);
        const QPoint p(static_cast<int>(std::lround(f.view()->xForFrame(42))), r.center().y());
        QSignalSpy spy(&f.widget, &TimelineWidget::currentFrameChanged);
        QTest::mouseClick(f.view(), Qt::LeftButton, {}, p);
        QCOMPARE(framesOf(spy), QList<int>{42});
        // The gutter (names) is not a place to scrub.
        QTest::mouseClick(f.view(), Qt::LeftButton, {}, QPoint(20, r.center().y()));
        QCOMPARE(f.widget.currentFrame(), 42);
    }

    void trackToolTip_data() {
        QTest::addColumn<int>("track");
        QTest::addColumn<QStringList>("lines");
        QTest::newRow("energy") << 0
                                << QStringList{"Frame 42 · 0.700 s", "Kinetic: 1.23 kJ", "Potential: -20 J",
                                               "Total: 1.21 kJ", "Total change since frame 0: 1.11 kJ"};
        QTest::newRow("penetration") << 1 << QStringList{"Frame 42 · 0.700 s", "Max penetration: 12.30 mm"};
        QTest::newRow("contacts") << 2 << QStringList{"Frame 42 · 0.700 s", "Contacts: 7"};
        QTest::newRow("awake") << 3 << QStringList{"Frame 42 · 0.700 s", "Awake bodies: 3"};
    }
    void trackToolTip() {
        QFETCH(int, track);
        QFETCH(QStringList, lines);
        auto bake = makeBake(100);
        for (size_t frame : {size_t(0), size_t(42)}) {
            const bool at42 = frame == 42;
            bake->setDiagnostic(frame, BakeDiagnostic::KineticEnergy, at42 ? 1234.5f : 0.0f);
            bake->setDiagnostic(frame, BakeDiagnostic::PotentialEnergy, at42 ? -20.0f : 100.0f);
            bake->setDiagnostic(frame, BakeDiagnostic::MaxPenetration, at42 ? 0.0123f : 0.0f);
            bake->setDiagnostic(frame, BakeDiagnostic::ContactCount, at42 ? 7.0f : 0.0f);
            bake->setDiagnostic(frame, BakeDiagnostic::AwakeBodies, at42 ? 3.0f : 1.0f);
        }
        Fixture f(0, 99, QSize(900, 260));
        QVERIFY(f.exposed);
        f.widget.setBake(bake);
        const QPoint p(static_cast<int>(std::lround(f.view()->xForFrame(42))), f.view()->trackRect(track).center().y());
        QCOMPARE(f.view()->toolTipAt(p), lines.join('\n'));
        // The same text through Qt's help event, as a hover shows it.
        QHelpEvent help(QEvent::ToolTip, p, f.view()->mapToGlobal(p));
        QApplication::sendEvent(f.view(), &help);
        QTRY_COMPARE(QToolTip::text(), lines.join('\n'));
        QToolTip::hideText();
        // Past the baked frames there are no values.
        f.widget.setFrameRange(0, 150);
        f.widget.zoomToFit();
        const QPoint beyond(static_cast<int>(std::lround(f.view()->xForFrame(130))), p.y());
        QCOMPARE(f.view()->toolTipAt(beyond), QStringLiteral("Frame 130: not baked"));
    }

    void rulerLabelsNeverOverlap_data() {
        QTest::addColumn<int>("width");
        QTest::addColumn<int>("last");
        QTest::addColumn<bool>("seconds");
        QTest::addColumn<double>("zoom");
        for (int width : {360, 800, 1600})
            for (int last : {10, 250, 35999})
                for (bool seconds : {false, true})
                    for (double zoom : {1.0, 7.0, 300.0})
                        QTest::addRow("w%d last%d %s x%g", width, last, seconds ? "s" : "frames", zoom)
                            << width << last << seconds << zoom;
    }
    void rulerLabelsNeverOverlap() {
        QFETCH(int, width);
        QFETCH(int, last);
        QFETCH(bool, seconds);
        QFETCH(double, zoom);
        Fixture f(0, last, QSize(width, 120));
        QVERIFY(f.exposed);
        f.widget.setShowSeconds(seconds);
        f.view()->zoomAround(last / 3.0, zoom);
        const std::vector<rl::RulerLabel> labels = f.view()->rulerLabels();
        QVERIFY2(labels.size() >= 2, qPrintable(QString::number(labels.size())));
        for (size_t i = 1; i < labels.size(); ++i) {
            QVERIFY(labels[i].frame > labels[i - 1].frame);
            QVERIFY2(labels[i].rect.left() >= labels[i - 1].rect.right() + 4.0,
                     qPrintable(labels[i - 1].text + " / " + labels[i].text));
            QVERIFY(labels[i].text != labels[i - 1].text);
        }
        // Labels stay dense enough to read positions from: never fewer than one per ~250 px.
        QVERIFY2(labels.size() >= static_cast<size_t>(f.view()->plotRect().width() / 250.0),
                 qPrintable(QString::number(labels.size())));
    }

    void labelsAdaptToZoom() {
        Fixture f(0, 35999, QSize(1000, 120));
        QVERIFY(f.exposed);
        auto step = [&] {
            const auto labels = f.view()->rulerLabels();
            return labels.size() >= 2 ? labels[1].frame - labels[0].frame : 0.0;
        };
        const double wide = step();
        f.view()->zoomAround(18000, 50.0);
        const double close = step();
        QVERIFY2(close > 0.0 && close * 20.0 <= wide, qPrintable(QStringLiteral("%1 vs %2").arg(close).arg(wide)));
        // Seconds mode labels whole seconds once they fit (60 frames at 60 fps).
        f.widget.setShowSeconds(true);
        f.view()->setViewRange(0, 1200);
        const auto labels = f.view()->rulerLabels();
        QVERIFY(labels.size() >= 2);
        QVERIFY(std::fmod(labels[1].frame - labels[0].frame, 60.0) == 0.0);
        QCOMPARE(labels[0].text, QStringLiteral("0"));
    }

    void ctrlTSwitchesFramesAndSeconds() {
        Fixture f(0, 600, QSize(900, 120));
        QVERIFY(f.exposed);
        QCOMPARE(f.view()->rulerLabels().back().text, QStringLiteral("600"));
        QTest::keyClick(f.view(), Qt::Key_T, Qt::ControlModifier);
        QVERIFY(f.widget.showSeconds());
        QVERIFY(f.widget.findChild<QAction*>("TimelineSeconds")->isChecked());
        QCOMPARE(f.view()->rulerLabels().back().text, QStringLiteral("10")); // 600 frames at 60 fps
        QTest::keyClick(f.view(), Qt::Key_T, Qt::ControlModifier);
        QVERIFY(!f.widget.showSeconds());
    }

    void wheelZoomsAroundCursorAndPans() {
        Fixture f(0, 1000, QSize(1000, 120));
        QVERIFY(f.exposed);
        f.widget.setCurrentFrame(300);
        const double x300 = f.view()->xForFrame(300);
        const double span = f.view()->viewEnd() - f.view()->viewStart();
        const QPoint at(700, 20);
        auto wheel = [&](int dy, Qt::KeyboardModifiers mods, QPoint angle = QPoint()) {
            QWheelEvent e(at, f.view()->mapToGlobal(at), QPoint(), angle.isNull() ? QPoint(0, dy) : angle, Qt::NoButton,
                          mods, Qt::NoScrollPhase, false);
            QApplication::sendEvent(f.view(), &e);
        };
        wheel(120, Qt::NoModifier);
        const double zoomed = f.view()->viewEnd() - f.view()->viewStart();
        QVERIFY(std::abs(zoomed - span / 1.25) < 1e-6);
        QVERIFY(std::abs(f.view()->xForFrame(300) - x300) < 1e-6); // the current frame stays put
        wheel(-240, Qt::NoModifier);
        QVERIFY(std::abs(f.view()->viewEnd() - f.view()->viewStart() - zoomed * 1.25 * 1.25) < 1e-6);
        // Ctrl+wheel pans by a tenth of the width per notch, keeping the span.
        const double start = f.view()->viewStart();
        const double spanBefore = f.view()->viewEnd() - start;
        wheel(-120, Qt::ControlModifier);
        const double perPixel = spanBefore / f.view()->plotRect().width();
        QVERIFY(std::abs(f.view()->viewStart() - (start + 0.1 * f.view()->plotRect().width() * perPixel)) < 1e-6);
        QVERIFY(std::abs(f.view()->viewEnd() - f.view()->viewStart() - spanBefore) < 1e-6);
        // Middle drag pans with the pointer: dragging right shows earlier frames.
        const double before = f.view()->viewStart();
        QTest::mousePress(f.view(), Qt::MiddleButton, {}, QPoint(400, 60));
        QTest::mouseMove(f.view(), QPoint(500, 60));
        QTest::mouseRelease(f.view(), Qt::MiddleButton, {}, QPoint(500, 60));
        QVERIFY(std::abs(f.view()->viewStart() - (before - 100 * perPixel)) < 1e-6);
        QCOMPARE(f.widget.currentFrame(), 300); // panning is not scrubbing
        // Zoom to fit restores the whole range.
        f.widget.zoomToFit();
        QCOMPARE(f.view()->viewStart(), -20.0);
        QCOMPARE(f.view()->viewEnd(), 1020.0);
    }

    void theCursorStaysInView() {
        Fixture f(0, 1000, QSize(900, 120));
        QVERIFY(f.exposed);
        f.widget.setBake(makeBake(1001));
        QCOMPARE(f.view()->viewEnd(), 1020.0); // the view followed the range
        f.view()->setViewRange(100, 200);
        QTest::keyClick(f.view(), Qt::Key_End);
        QVERIFY(f.view()->viewStart() <= 1000 && f.view()->viewEnd() >= 1000);
        QTest::keyClick(f.view(), Qt::Key_Home);
        QVERIFY(f.view()->viewStart() <= 0 && f.view()->viewEnd() >= 0);
        // Playback pages along.
        qint64 clock = 0;
        f.widget.setClock([&] { return clock; });
        f.view()->setViewRange(0, 100);
        f.widget.play();
        clock = 3 * kSecond;
        f.widget.advancePlayback();
        QCOMPARE(f.widget.currentFrame(), 180);
        QVERIFY(f.view()->viewStart() <= 180 && f.view()->viewEnd() >= 180);
        QVERIFY(std::abs(f.view()->viewEnd() - f.view()->viewStart() - 100.0) < 1e-9); // the zoom is kept
        f.widget.pause();
    }

    void playbackFollowsTheClock_data() {
        QTest::addColumn<double>("speed");
        QTest::addColumn<qint64>("elapsed");
        QTest::addColumn<int>("expected");
        for (double speed : {0.25, 0.5, 1.0, 2.0, 4.0}) {
            QTest::addRow("%gx 1 s", speed) << speed << kSecond << int(60 * speed);
            QTest::addRow("%gx 1.5 s", speed) << speed << kSecond * 3 / 2 << int(std::floor(90 * speed));
        }
        QTest::newRow("1x just before frame 7") << 1.0 << qint64(116'000'000) << 6;
        QTest::newRow("1x at frame 7") << 1.0 << qint64(116'666'667) << 7;
    }
    void playbackFollowsTheClock() {
        QFETCH(double, speed);
        QFETCH(qint64, elapsed);
        QFETCH(int, expected);
        TimelineWidget widget;
        qint64 clock = 5 * kSecond;
        widget.setClock([&] { return clock; });
        widget.setBake(makeBake(1200)); // 4x for 4.5 s stays short of the end
        widget.setSpeed(speed);
        QCOMPARE(widget.speed(), speed);
        widget.play();
        QVERIFY(widget.isPlaying());
        clock += elapsed;
        widget.advancePlayback();
        QCOMPARE(widget.currentFrame(), expected);
        // A slow tick skips frames rather than lagging: three seconds later it is where the clock says.
        clock += 3 * kSecond;
        widget.advancePlayback();
        QCOMPARE(widget.currentFrame(), int(std::floor((elapsed + 3 * kSecond) * 60.0 * speed / kSecond + 1e-9)));
        widget.pause();
    }

    void theTimerDrivesPlayback() {
        TimelineWidget widget;
        qint64 clock = 0;
        widget.setClock([&] { return clock; });
        widget.setBake(makeBake(600));
        QSignalSpy playing(&widget, &TimelineWidget::playingChanged);
        widget.play();
        clock = kSecond;
        QTRY_COMPARE_WITH_TIMEOUT(widget.currentFrame(), 60, 10000);
        widget.pause();
        QCOMPARE(playing.count(), 2);
        clock = 2 * kSecond;
        QTest::qWait(50);
        QCOMPARE(widget.currentFrame(), 60); // paused: the clock no longer moves it
    }

    // With the real clock the cursor never runs ahead of real time.
    void realClockKeepsRealTime() {
        TimelineWidget widget;
        widget.setBake(makeBake(6000));
        QElapsedTimer timer;
        int ahead = 0;
        connect(&widget, &TimelineWidget::currentFrameChanged, &widget, [&](int frame) {
            if (frame > timer.nsecsElapsed() * 60.0 / kSecond + 1.0)
                ++ahead;
        });
        timer.start();
        widget.play();
        QTRY_VERIFY_WITH_TIMEOUT(widget.currentFrame() >= 12, 10000);
        widget.pause();
        QCOMPARE(ahead, 0);
        QVERIFY(widget.currentFrame() <= timer.nsecsElapsed() * 60.0 / kSecond + 1.0);
    }

    void speedChangeKeepsPosition() {
        TimelineWidget widget;
        qint64 clock = 0;
        widget.setClock([&] { return clock; });
        widget.setBake(makeBake(600));
        widget.play();
        clock = kSecond;
        widget.advancePlayback();
        QCOMPARE(widget.currentFrame(), 60);
        clock = kSecond + kSecond / 4; // 15 frames further at 1x, not shown yet
        widget.setSpeed(2.0);
        clock += kSecond / 2; // 60 frames further at 2x
        widget.advancePlayback();
        QCOMPARE(widget.currentFrame(), 135);
        // Scrubbing while playing carries on from the new frame.
        widget.setCurrentFrame(300);
        clock += kSecond / 4;
        widget.advancePlayback();
        QCOMPARE(widget.currentFrame(), 330);
        widget.pause();
    }

    void loopWraps() {
        TimelineWidget widget;
        qint64 clock = 0;
        widget.setClock([&] { return clock; });
        widget.setBake(makeBake(100));
        widget.setLoop(true);
        widget.setCurrentFrame(90);
        widget.play();
        QCOMPARE(widget.currentFrame(), 90);
        clock = kSecond / 2; // 30 frames: 90 + 30 = 120 wraps to 20
        widget.advancePlayback();
        QCOMPARE(widget.currentFrame(), 20);
        QVERIFY(widget.isPlaying());
        clock = kSecond / 2 + 5 * kSecond; // five more loops of 100 frames and 0 frames: 20 + 300 = 320 -> 20
        widget.advancePlayback();
        QCOMPARE(widget.currentFrame(), 20);
        clock += kSecond / 4; // +15
        widget.advancePlayback();
        QCOMPARE(widget.currentFrame(), 35);
        widget.pause();
    }

    void withoutLoopStopsAtTheEnd() {
        TimelineWidget widget;
        qint64 clock = 0;
        widget.setClock([&] { return clock; });
        widget.setBake(makeBake(100));
        widget.setLoop(false);
        QVERIFY(!widget.loopAction()->isChecked());
        widget.setCurrentFrame(90);
        QSignalSpy playing(&widget, &TimelineWidget::playingChanged);
        widget.play();
        clock = kSecond / 10; // 6 frames
        widget.advancePlayback();
        QCOMPARE(widget.currentFrame(), 96);
        clock = kSecond; // far past the end
        widget.advancePlayback();
        QCOMPARE(widget.currentFrame(), 99);
        QVERIFY(!widget.isPlaying());
        QCOMPARE(playing.count(), 2);
        QCOMPARE(playing.at(1).at(0).toBool(), false);
        // Play again from the end starts over.
        widget.play();
        QCOMPARE(widget.currentFrame(), 0);
        widget.pause();
    }

    // With a bake, playback covers the baked frames only, even when the ruler shows more.
    void playsOnlyTheBakedFrames() {
        TimelineWidget widget;
        qint64 clock = 0;
        widget.setClock([&] { return clock; });
        widget.setFrameRange(0, 250);
        widget.setBake(makeBake(100));
        QCOMPARE(widget.lastFrame(), 250);
        QCOMPARE(widget.playFirst(), 0);
        QCOMPARE(widget.playLast(), 99);
        widget.setCurrentFrame(200); // outside the bake: playback starts at its first frame
        widget.setLoop(false);
        widget.play();
        QCOMPARE(widget.currentFrame(), 0);
        clock = 2 * kSecond;
        widget.advancePlayback();
        QCOMPARE(widget.currentFrame(), 99);
        QVERIFY(!widget.isPlaying());
        // Without a bake the whole range plays.
        widget.setBake(nullptr);
        QCOMPARE(widget.playLast(), 250);
        // Nothing to play: a bake of one frame.
        widget.setBake(makeBake(1));
        widget.play();
        QVERIFY(!widget.isPlaying());
        QVERIFY(!widget.playAction()->isChecked());
    }

    void spaceAndPlayButtonToggle() {
        Fixture f(0, 100);
        QVERIFY(f.exposed);
        qint64 clock = 0;
        f.widget.setClock([&] { return clock; });
        f.widget.setBake(makeBake(100));
        QSignalSpy playing(&f.widget, &TimelineWidget::playingChanged);
        QTest::keyClick(f.view(), Qt::Key_Space);
        QVERIFY(f.widget.isPlaying());
        QVERIFY(f.widget.playAction()->isChecked());
        QTest::keyClick(f.view(), Qt::Key_Space);
        QVERIFY(!f.widget.isPlaying());
        f.widget.playAction()->trigger();
        QVERIFY(f.widget.isPlaying());
        f.widget.playAction()->trigger();
        QVERIFY(!f.widget.isPlaying());
        QCOMPARE(playing.count(), 4);
        // Stepping pauses.
        f.widget.play();
        QTest::keyClick(f.view(), Qt::Key_Right);
        QVERIFY(!f.widget.isPlaying());
    }

    void speedControl() {
        Fixture f(0, 100);
        QVERIFY(f.exposed);
        auto* combo = f.widget.findChild<QComboBox*>("TimelineSpeed");
        QVERIFY(combo);
        QCOMPARE(combo->count(), 5);
        QCOMPARE(combo->currentData().toDouble(), 1.0);
        QSignalSpy spy(&f.widget, &TimelineWidget::speedChanged);
        combo->setFocus();
        QTest::keyClick(combo, Qt::Key_Down);
        QCOMPARE(f.widget.speed(), 2.0);
        QTest::keyClick(combo, Qt::Key_Down);
        QCOMPARE(f.widget.speed(), 4.0);
        QCOMPARE(spy.count(), 2);
        f.widget.setSpeed(0.1);
        QCOMPARE(f.widget.speed(), 0.25);
        QCOMPARE(combo->currentData().toDouble(), 0.25);
        f.widget.setSpeed(100.0);
        QCOMPARE(f.widget.speed(), 4.0);
        f.widget.setSpeed(1.5); // between presets: gets an entry of its own
        QCOMPARE(combo->currentData().toDouble(), 1.5);
        QCOMPARE(combo->itemData(combo->currentIndex() - 1).toDouble(), 1.0);
    }

    void staleBake() {
        Fixture f(0, 100, QSize(900, 240));
        QVERIFY(f.exposed);
        f.widget.setBake(makeBake(60));
        const QPoint inBake = f.rulerPoint(30);
        QVERIFY(!f.widget.isStale());
        QCOMPARE(f.view()->toolTipAt(inBake), QStringLiteral("Frame 30 · 0.500 s\nBaked (frames 0–59)"));
        const QRect bar(static_cast<int>(f.view()->xForFrame(5)), TimelineView::kRulerHeight - 5,
                        static_cast<int>(f.view()->xForFrame(55) - f.view()->xForFrame(5)), 5);
        QCOMPARE(countPixels(f.view()->grab().toImage(), bar, orangeish), 0);

        f.widget.setStale(true);
        QVERIFY(f.widget.isStale());
        QCOMPARE(f.view()->toolTipAt(inBake), QStringLiteral("Frame 30 · 0.500 s\nScene changed since this bake"));
        QVERIFY(f.view()
                    ->toolTipAt(QPoint(inBake.x(), f.view()->trackRect(0).center().y()))
                    .endsWith(QStringLiteral("\nScene changed since this bake")));
        QVERIFY(countPixels(f.view()->grab().toImage(), bar, orangeish) > bar.width() / 4); // hatched
        QCOMPARE(f.view()->toolTipAt(f.rulerPoint(80)), QStringLiteral("Frame 80 · 1.333 s\nNot baked"));
        f.widget.setStale(false);
        QCOMPARE(countPixels(f.view()->grab().toImage(), bar, orangeish), 0);
    }

    void bakeProgress() {
        Fixture f(0, 600, QSize(900, 120));
        QVERIFY(f.exposed);
        auto* label = f.widget.findChild<QLabel*>("TimelineProgress");
        QVERIFY(label);
        QVERIFY(!label->isVisible());
        QCOMPARE(f.widget.progress(), -1.0);
        f.widget.setProgress(0.25, QStringLiteral("frame 150 of 600, 4 s left"));
        QCOMPARE(f.widget.progress(), 0.25);
        QVERIFY(label->isVisible());
        QCOMPARE(label->text(), QStringLiteral("Baking 25 % · frame 150 of 600, 4 s left"));
        const QImage image = f.view()->grab().toImage();
        auto barAt = [&](double frame) {
            return QRect(static_cast<int>(f.view()->xForFrame(frame)) - 2, TimelineView::kRulerHeight - 5, 5, 4);
        };
        QVERIFY(countPixels(image, barAt(60), greenish) >= 10); // baked so far
        QCOMPARE(countPixels(image, barAt(400), greenish), 0);  // still to come
        QVERIFY(f.view()->toolTipAt(f.rulerPoint(100)).contains("Baking: 25 % · frame 150 of 600, 4 s left"));
        f.widget.setProgress(1.5);
        QCOMPARE(f.widget.progress(), 1.0);
        f.widget.setProgress(-1.0);
        QVERIFY(!label->isVisible());
        QCOMPARE(f.widget.progress(), -1.0);
        QCOMPARE(countPixels(f.view()->grab().toImage(), barAt(60), greenish), 0);
    }

    void bakeSetsFpsAndTracks() {
        Fixture f(0, 100, QSize(900, 260));
        QVERIFY(f.exposed);
        QCOMPARE(f.view()->trackCount(), 0);
        f.widget.setBake(makeBake(400, 30.0));
        QCOMPARE(f.widget.fps(), 30.0);
        QCOMPARE(f.widget.lastFrame(), 399);
        QCOMPARE(f.view()->trackCount(), 4);
        QCOMPARE(f.view()->sizeHint().height(), TimelineView::kRulerHeight + 4 * TimelineView::kTrackHeight);
        // The tracks ask for their room, so that a bottom dock grows to show them.
        QCOMPARE(f.view()->minimumSizeHint().height(), TimelineView::kRulerHeight + 4 * TimelineView::kTrackHeight);
        // Folding the tracks away (the toolbar button) gives it back.
        f.widget.findChild<QAction*>("TimelineTracks")->trigger();
        QVERIFY(!f.widget.tracksVisible());
        QVERIFY(f.view()->trackRect(0).isEmpty());
        QCOMPARE(f.view()->sizeHint().height(), TimelineView::kRulerHeight);
        QCOMPARE(f.view()->minimumSizeHint().height(), TimelineView::kRulerHeight);
        f.widget.setTracksVisible(true);
        // A bake without diagnostics (an original-project file) has no tracks.
        f.widget.setBake(makeBake(50, 200.0, false));
        QCOMPARE(f.view()->trackCount(), 0);
        QCOMPARE(f.widget.fps(), 200.0);
        f.widget.setBake(nullptr);
        QCOMPARE(f.view()->trackCount(), 0);
    }

    // The figure for the report: what one step of a scrub costs over a 10-minute bake (36,000 frames at 60 fps)
    // with every diagnostic. RL_TIMELINE_SCREENSHOT=<file.png> also saves a picture of the widget.
    void scrubRepaintCost() {
        auto bake = makeBake(36000);
        Fixture f(0, 100, QSize(1280, 40 + 26 + 4 * 30 + 30));
        QVERIFY(f.exposed);
        f.widget.setBake(bake);
        f.widget.setCurrentFrame(9000);
        QVERIFY(QTest::qWaitForWindowExposed(&f.widget));
        QApplication::processEvents();

        QElapsedTimer timer;
        // Cold: the background (ticks, decimated tracks) is drawn again, as after a resize or a zoom.
        qint64 cold = 0;
        for (int i = 0; i < 5; ++i) {
            f.view()->invalidate();
            timer.start();
            f.view()->repaint();
            cold += timer.nsecsElapsed();
        }
        // A scrub step: the cursor moves, the widget repaints (old and new cursor columns, the frame read-out).
        const int steps = 400;
        PaintCounter counter;
        f.view()->installEventFilter(&counter);
        qint64 scrub = 0;
        qint64 worst = 0;
        for (int i = 0; i < steps; ++i) {
            timer.start();
            f.widget.setCurrentFrame((i * 97) % 36000);
            QApplication::processEvents();
            const qint64 t = timer.nsecsElapsed();
            scrub += t;
            worst = std::max(worst, t);
        }
        QVERIFY2(counter.paints >= steps * 9 / 10, qPrintable(QString::number(counter.paints)));
        // The whole widget repainted synchronously for each frame.
        qint64 full = 0;
        for (int i = 0; i < 100; ++i) {
            timer.start();
            f.widget.setCurrentFrame((i * 131) % 36000);
            f.widget.repaint();
            full += timer.nsecsElapsed();
        }
        // A running bake's progress update (the controller sends ten a second).
        qint64 progress = 0;
        for (int i = 0; i < 100; ++i) {
            timer.start();
            f.widget.setProgress(i / 100.0, QStringLiteral("frame %1 of 36000").arg(i * 360));
            QApplication::processEvents();
            progress += timer.nsecsElapsed();
        }
        f.widget.setProgress(-1.0);
        const double progressMs = progress / 100.0 / 1e6;
        const double coldMs = cold / 5 / 1e6;
        const double scrubMs = scrub / double(steps) / 1e6;
        const double fullMs = full / 100.0 / 1e6;
        qInfo("scrub_ms_mean=%.3f scrub_ms_max=%.3f full_repaint_ms=%.3f cold_repaint_ms=%.3f progress_ms=%.3f "
              "size=%dx%d frames=%zu",
              scrubMs, worst / 1e6, fullMs, coldMs, progressMs, f.widget.width(), f.widget.height(),
              bake->frameCount());
        // Far below a 60 Hz frame even on the shared machine; a repaint that decimated 36,000 frames per track on
        // every step would not be.
        QVERIFY2(scrubMs < 20.0, qPrintable(QString::number(scrubMs)));
        QVERIFY2(coldMs < 200.0, qPrintable(QString::number(coldMs)));
        QVERIFY2(progressMs < 20.0, qPrintable(QString::number(progressMs)));
        if (const QByteArray path = qgetenv("RL_TIMELINE_SCREENSHOT"); !path.isEmpty()) {
            f.widget.setCurrentFrame(5400);
            f.widget.setProgress(-1.0);
            f.widget.grab().save(QString::fromLocal8Bit(path));
        }
    }
};

QTEST_MAIN(TestTimeline)
#include "tst_timeline.moc"
