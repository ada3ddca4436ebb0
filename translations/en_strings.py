# English plural forms for RigidLab (lupdate -pluralonly): the sources say "%n bodies", so without this file the
# English editor would say "1 bodies". translations/fill_ts.py en writes them into rigidlab_en.ts.
T = {}

T["rl::AccuracyPanel"] = {
    "%n rows. Points with zero error (exact up to rounding) are not drawn.": [
        "%n row. Points with zero error (exact up to rounding) are not drawn.",
        "%n rows. Points with zero error (exact up to rounding) are not drawn.",
    ],
    "Baking %n setting(s) and the reference…": [
        "Baking %n setting and the reference…",
        "Baking %n settings and the reference…",
    ],
}
T["rl::Commands"] = {
    "Rotate %n bodies": ["Rotate %n body", "Rotate %n bodies"],
    "Move %n bodies": ["Move %n body", "Move %n bodies"],
}
T["rl::CompareBakesDialog"] = {
    "<b>Equal within the tolerance</b> over %n frame(s).": [
        "<b>Equal within the tolerance</b> over %n frame.",
        "<b>Equal within the tolerance</b> over %n frames.",
    ],
}
T["rl::ExportDialog"] = {
    "All %n bodies": ["The %n body", "All %n bodies"],
    "Selected bodies (%n)": ["Selected body (%n)", "Selected bodies (%n)"],
}
T["rl::FileController"] = {
    "Opened %1: %n bodies": ["Opened %1: %n body", "Opened %1: %n bodies"],
    "%n of %1 files could not be imported.": [
        "%n of %1 files could not be imported.",
        "%n of %1 files could not be imported.",
    ],
    "%n files": ["%n file", "%n files"],
    "Imported %n bodies from %1": ["Imported %n body from %1", "Imported %n bodies from %1"],
    "; %n renamed to keep names unique": ["; %n renamed to keep names unique", "; %n renamed to keep names unique"],
}
T["rl::InspectorWidget"] = {
    "%n bodies cannot be simulated": ["%n body cannot be simulated", "%n bodies cannot be simulated"],
}
T["rl::MainWindow"] = {
    "%n selected": ["%n selected", "%n selected"],
    "%n bodies": ["%n body", "%n bodies"],
    "%n anchors": ["%n anchor", "%n anchors"],
}
T["rl::PreflightDialog"] = {
    "%n finding(s) in this scene may make the bake inaccurate or unstable. Bake anyway?": [
        "%n finding in this scene may make the bake inaccurate or unstable. Bake anyway?",
        "%n findings in this scene may make the bake inaccurate or unstable. Bake anyway?",
    ],
    "%n finding(s) in this scene may make a bake inaccurate or unstable.": [
        "%n finding in this scene may make a bake inaccurate or unstable.",
        "%n findings in this scene may make a bake inaccurate or unstable.",
    ],
}
T["rl::SimulationController"] = {
    "The bake has %n bodies and the scene %1: re-bake to scrub it.": [
        "The bake has %n body and the scene %1: re-bake to scrub it.",
        "The bake has %n bodies and the scene %1: re-bake to scrub it.",
    ],
    "Baking %n frames…": ["Baking %n frame…", "Baking %n frames…"],
    "Opened %1: frames 0 to %2 at %3 Hz, %n bodies.": [
        "Opened %1: frames 0 to %2 at %3 Hz, %n body.",
        "Opened %1: frames 0 to %2 at %3 Hz, %n bodies.",
    ],
}
