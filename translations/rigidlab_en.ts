<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
<context>
    <name>rl::AccuracyPanel</name>
    <message numerus="yes">
        <source>%n rows. Points with zero error (exact up to rounding) are not drawn.</source>
        <translation>
            <numerusform>%n row. Points with zero error (exact up to rounding) are not drawn.</numerusform>
            <numerusform>%n rows. Points with zero error (exact up to rounding) are not drawn.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Baking %n setting(s) and the reference…</source>
        <translation>
            <numerusform>Baking %n setting and the reference…</numerusform>
            <numerusform>Baking %n settings and the reference…</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rl::Commands</name>
    <message numerus="yes">
        <source>Rotate %n bodies</source>
        <translation>
            <numerusform>Rotate %n body</numerusform>
            <numerusform>Rotate %n bodies</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Move %n bodies</source>
        <translation>
            <numerusform>Move %n body</numerusform>
            <numerusform>Move %n bodies</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rl::CompareBakesDialog</name>
    <message numerus="yes">
        <source>&lt;b&gt;Equal within the tolerance&lt;/b&gt; over %n frame(s).</source>
        <translation>
            <numerusform>&lt;b&gt;Equal within the tolerance&lt;/b&gt; over %n frame.</numerusform>
            <numerusform>&lt;b&gt;Equal within the tolerance&lt;/b&gt; over %n frames.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rl::ExportDialog</name>
    <message numerus="yes">
        <source>All %n bodies</source>
        <translation>
            <numerusform>The %n body</numerusform>
            <numerusform>All %n bodies</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Selected bodies (%n)</source>
        <translation>
            <numerusform>Selected body (%n)</numerusform>
            <numerusform>Selected bodies (%n)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rl::FileController</name>
    <message numerus="yes">
        <source>Opened %1: %n bodies</source>
        <translation>
            <numerusform>Opened %1: %n body</numerusform>
            <numerusform>Opened %1: %n bodies</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n of %1 files could not be imported.</source>
        <translation>
            <numerusform>%n of %1 files could not be imported.</numerusform>
            <numerusform>%n of %1 files could not be imported.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n files</source>
        <translation>
            <numerusform>%n file</numerusform>
            <numerusform>%n files</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Imported %n bodies from %1</source>
        <translation>
            <numerusform>Imported %n body from %1</numerusform>
            <numerusform>Imported %n bodies from %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>; %n renamed to keep names unique</source>
        <translation>
            <numerusform>; %n renamed to keep names unique</numerusform>
            <numerusform>; %n renamed to keep names unique</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rl::InspectorWidget</name>
    <message numerus="yes">
        <source>%n bodies cannot be simulated</source>
        <translation>
            <numerusform>%n body cannot be simulated</numerusform>
            <numerusform>%n bodies cannot be simulated</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rl::MainWindow</name>
    <message numerus="yes">
        <source>%n selected</source>
        <translation>
            <numerusform>%n selected</numerusform>
            <numerusform>%n selected</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n bodies</source>
        <translation>
            <numerusform>%n body</numerusform>
            <numerusform>%n bodies</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n anchors</source>
        <translation>
            <numerusform>%n anchor</numerusform>
            <numerusform>%n anchors</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rl::PreflightDialog</name>
    <message numerus="yes">
        <source>%n finding(s) in this scene may make the bake inaccurate or unstable. Bake anyway?</source>
        <translation>
            <numerusform>%n finding in this scene may make the bake inaccurate or unstable. Bake anyway?</numerusform>
            <numerusform>%n findings in this scene may make the bake inaccurate or unstable. Bake anyway?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n finding(s) in this scene may make a bake inaccurate or unstable.</source>
        <translation>
            <numerusform>%n finding in this scene may make a bake inaccurate or unstable.</numerusform>
            <numerusform>%n findings in this scene may make a bake inaccurate or unstable.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rl::SimulationController</name>
    <message numerus="yes">
        <source>The bake has %n bodies and the scene %1: re-bake to scrub it.</source>
        <translation>
            <numerusform>The bake has %n body and the scene %1: re-bake to scrub it.</numerusform>
            <numerusform>The bake has %n bodies and the scene %1: re-bake to scrub it.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Baking %n frames…</source>
        <translation>
            <numerusform>Baking %n frame…</numerusform>
            <numerusform>Baking %n frames…</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Opened %1: frames 0 to %2 at %3 Hz, %n bodies.</source>
        <translation>
            <numerusform>Opened %1: frames 0 to %2 at %3 Hz, %n body.</numerusform>
            <numerusform>Opened %1: frames 0 to %2 at %3 Hz, %n bodies.</numerusform>
        </translation>
    </message>
</context>
</TS>
