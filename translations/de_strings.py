# German translations for RigidLab, keyed by Qt context and English source text.
# translations/fill_ts.py writes them into rigidlab_de.ts. Plural (numerus) messages map to [singular, plural].
# Conventions: German quotes „…“, a space before an ellipsis ("Öffnen …"), units and placeholders unchanged,
# menu accelerators unique within each menu (checked by tests/ui/tst_translations.cpp).

T = {}

T["QObject"] = {
    "diverged": "divergiert",
}

T["main"] = {
    "RigidLab rigid-body scene editor": "RigidLab – Editor für Starrkörperszenen",
    "Scene file to open.": "Zu öffnende Szenendatei.",
}

T["rl::AccuracyPanel"] = {
    "Accuracy": "Genauigkeit",
    "Integrators on exact solutions": "Integratoren an exakten Lösungen",
    "This scene": "Diese Szene",
    "&Run study": "Studie &ausführen",
    "Every integrator on problems with exact answers, at several step sizes.":
        "Jeder Integrator an Aufgaben mit exakter Lösung, bei mehreren Schrittweiten.",
    "Problem:": "Aufgabe:",
    "Error against CPU time": "Fehler über CPU-Zeit",
    "Integrator": "Integrator",
    "Steps": "Schritte",
    "Substeps": "Teilschritte",
    "Step (s)": "Schritt (s)",
    "Error": "Fehler",
    "CPU (µs)": "CPU (µs)",
    "Settings to compare": "Zu vergleichende Einstellungen",
    " s": " s",
    "Duration:": "Dauer:",
    "Substeps:": "Teilschritte:",
    "Integrators:": "Integratoren:",
    "&Compare": "&Vergleichen",
    "Cancel": "Abbrechen",
    "Bakes the scene under each setting and compares it with a reference bake at RK4 and 64 substeps: position error (RMS over bodies and frames) against CPU time.":
        "Backt die Szene mit jeder Einstellung und vergleicht sie mit einem Referenz-Bake (RK4, 64 Teilschritte): "
        "Positionsfehler (RMS über Körper und Frames) über CPU-Zeit.",
    "Position error against CPU time": "Positionsfehler über CPU-Zeit",
    "RMS error (m)": "RMS (m)",
    "Max error (m)": "Max. (m)",
    "CPU (ms)": "CPU (ms)",
    "Running the study (each row is timed several times)…":
        "Studie läuft (jede Zeile wird mehrmals gemessen) …",
    "%n rows. Points with zero error (exact up to rounding) are not drawn.": [
        "%n Zeile. Punkte ohne Fehler (bis auf Rundung exakt) werden nicht gezeichnet.",
        "%n Zeilen. Punkte ohne Fehler (bis auf Rundung exakt) werden nicht gezeichnet.",
    ],
    "CPU time per run (µs)": "CPU-Zeit je Lauf (µs)",
    "%1: error against CPU time": "%1: Fehler über CPU-Zeit",
    "Tick at least one substep count and one integrator.":
        "Mindestens eine Teilschrittzahl und einen Integrator ankreuzen.",
    "Baking %n setting(s) and the reference…": [
        "%n Einstellung und die Referenz werden gebacken …",
        "%n Einstellungen und die Referenz werden gebacken …",
    ],
    "Cancelled.": "Abgebrochen.",
    "Cannot compare: %1": "Vergleich nicht möglich: %1",
    "CPU time of the bake (ms)": "CPU-Zeit des Backens (ms)",
    "Position error, RMS (m)": "Positionsfehler, RMS (m)",
    "%1 frames of %2 dynamic bodies against %3 × %4 substeps (reference: %5 ms CPU).":
        "%1 Frames von %2 dynamischen Körpern gegen %3 × %4 Teilschritte (Referenz: %5 ms CPU).",
    "Only the first %1 of %2 dynamic bodies were simulated.":
        "Nur die ersten %1 von %2 dynamischen Körpern wurden simuliert.",
    # Integrator names, for when the panel shows them through tr() instead of core's ids.
    "Explicit Euler": "Expliziter Euler",
    "Symplectic Euler": "Symplektischer Euler",
    "Verlet": "Verlet",
    "RK4": "RK4",
}

T["rl::AnalysisController"] = {
    "&Bake (.bake)…": "&Bake-Datei (.bake) …",
    "Write the current bake as a .bake file the original project can read":
        "Das aktuelle Backergebnis als .bake-Datei schreiben, die das ursprüngliche Projekt lesen kann",
    "&CSV…": "&CSV …",
    "Write all or selected bodies and frames of the current bake as CSV":
        "Alle oder ausgewählte Körper und Frames des aktuellen Backergebnisses als CSV schreiben",
    "&Accuracy…": "&Genauigkeit …",
    "Error against CPU time per integrator and substep count":
        "Fehler über CPU-Zeit je Integrator und Teilschrittzahl",
    "&Compare Bakes…": "Backergebnisse &vergleichen …",
    "Find the first frame where two bakes diverge":
        "Den ersten Frame finden, an dem zwei Backergebnisse auseinanderlaufen",
    "&Pre-flight Check…": "Vorab&prüfung …",
    "List what in the scene may simulate badly": "Auflisten, was in der Szene schlecht simuliert werden könnte",
    "Export Bake": "Backergebnis exportieren",
    "There is nothing to export yet: bake the scene first or open a .bake file.":
        "Es gibt noch nichts zu exportieren: Backen Sie zuerst die Szene oder öffnen Sie eine .bake-Datei.",
    "untitled": "unbenannt",
    "Exporting %1…": "%1 wird exportiert …",
    "Cancel": "Abbrechen",
    "Exported %1": "%1 exportiert",
    "Export cancelled; %1 was not changed.": "Export abgebrochen; %1 wurde nicht verändert.",
}

T["rl::BakeDialog"] = {
    "Bake": "Backen",
    "Records the simulation in the background, starting from the edit pose at the first frame; before it the "
    "bodies hold the edit pose. The timeline plays and scrubs the result.":
        "Zeichnet die Simulation im Hintergrund auf, beginnend mit der Bearbeitungspose im ersten Frame; davor "
        "behalten die Körper die Bearbeitungspose. Die Zeitleiste spielt das Ergebnis ab und lässt darin navigieren.",
    " s": " s",
    "&Duration:": "&Dauer:",
    "to": "bis",
    "&Frames:": "&Frames:",
    "Frame rate:": "Bildrate:",
    "%1 Hz (the scene's world settings)": "%1 Hz (aus den Welteinstellungen der Szene)",
    "&Bake": "&Backen",
}

T["rl::BakeDiffModel"] = {
    "NaN": "NaN",
    "—": "—",
    "#": "#",
    "Body": "Körper",
    "First diverging frame": "Erster abweichender Frame",
    "Max Δ position (mm)": "Max. Δ Position (mm)",
    "at frame": "bei Frame",
    "Max Δ rotation (°)": "Max. Δ Drehung (°)",
}

T["rl::Commands"] = {
    "Add %1": "%1 hinzufügen",
    "Duplicate as %1": "Als %1 duplizieren",
    "Import %1": "%1 importieren",
    "Delete %1": "%1 löschen",
    "Rename %1 to %2": "%1 in %2 umbenennen",
    "Rotate %1": "%1 drehen",
    "Move %1": "%1 verschieben",
    "Rotate %n bodies": ["%n Körper drehen", "%n Körper drehen"],
    "Move %n bodies": ["%n Körper verschieben", "%n Körper verschieben"],
}

T["rl::CompareBakesDialog"] = {
    "Compare Bakes": "Backergebnisse vergleichen",
    "Bakes": "Backergebnisse",
    "Current bake": "Aktuelles Backergebnis",
    "File A:": "Datei A:",
    "Browse…": "Durchsuchen …",
    "File B:": "Datei B:",
    " mm": " mm",
    " °": " °",
    "&Compare": "&Vergleichen",
    "Tolerance:": "Toleranz:",
    "Choose two bakes and press Compare.": "Wählen Sie zwei Backergebnisse und klicken Sie auf „Vergleichen“.",
    "Open Bake": "Backergebnis öffnen",
    "Bake files (*.bake);;All files (*)": "Bake-Dateien (*.bake);;Alle Dateien (*)",
    "Choose a .bake file.": "Wählen Sie eine .bake-Datei.",
    "There is no current bake: bake the scene or choose file A.":
        "Es gibt kein aktuelles Backergebnis: Backen Sie die Szene oder wählen Sie Datei A.",
    "<b>Cannot compare:</b> %1": "<b>Vergleich nicht möglich:</b> %1",
    "<b>The bakes diverge at frame %1</b> (t = %2 s), first in body %3 '%4'.":
        "<b>Die Backergebnisse weichen ab Frame %1 voneinander ab</b> (t = %2 s), zuerst bei Körper %3 „%4“.",
    "<b>Equal within the tolerance</b> over %n frame(s).": [
        "<b>Gleich innerhalb der Toleranz</b> über %n Frame.",
        "<b>Gleich innerhalb der Toleranz</b> über %n Frames.",
    ],
    "The frame counts differ: %1 and %2; the first %3 were compared.":
        "Die Anzahl der Frames unterscheidet sich: %1 und %2; die ersten %3 wurden verglichen.",
    "%1 of %2 bodies differ by more than the tolerance.":
        "%1 von %2 Körpern weichen stärker als die Toleranz ab.",
}

# The core's body warnings (core/scene/BodyProperties.cpp) and effect reasons (core/world/Effects.cpp), shown
# through ui/document/CoreText.cpp.
T["rl::CoreText"] = {
    "concave: simulated as its convex hull": "konkav: wird als seine konvexe Hülle simuliert",
    "smaller than 2 cm: may need more substeps": "kleiner als 2 cm: braucht eventuell mehr Teilschritte",
    "forced on": "erzwungen ein",
    "forced off": "erzwungen aus",
    "dynamic bodies and non-zero gravity": "dynamische Körper und Schwerkraft ungleich null",
    "no dynamic body or zero gravity": "kein dynamischer Körper oder keine Schwerkraft",
    "some pair has friction above zero": "ein Paar hat Reibung über null",
    "every pair's combined friction is zero": "die kombinierte Reibung jedes Paars ist null",
    "bodies can rotate": "Körper können sich drehen",
    "only frictionless, non-spinning spheres (rotation cannot change)":
        "nur reibungsfreie, nicht rotierende Kugeln (die Drehung kann sich nicht ändern)",
    "some pair has restitution above zero": "ein Paar hat Restitution über null",
    "every pair's combined restitution is zero": "die kombinierte Restitution jedes Paars ist null",
    "damping is set": "Dämpfung ist gesetzt",
    "no damping is set": "keine Dämpfung gesetzt",
    "bodies can come to rest on anchors": "Körper können auf Ankern zur Ruhe kommen",
    "nothing to come to rest on (no gravity or no anchor)":
        "nichts, worauf Körper zur Ruhe kommen (keine Schwerkraft oder kein Anker)",
    "some body may move more than half its size in one frame":
        "ein Körper kann sich in einem Frame um mehr als seine halbe Größe bewegen",
    "no body moves fast relative to its size": "kein Körper ist schnell im Verhältnis zu seiner Größe",
}

T["rl::EditController"] = {
    "Edit": "Bearbeiten",
    "&Undo": "&Rückgängig",
    "&Redo": "&Wiederholen",
    "&Delete": "&Löschen",
    "Delete the selected bodies": "Die ausgewählten Körper löschen",
    "Toggle &Anchor": "&Anker umschalten",
    "Make the selected bodies static, or dynamic again when all are static":
        "Die ausgewählten Körper statisch machen, oder wieder dynamisch, wenn alle statisch sind",
    "D&uplicate": "&Duplizieren",
    "Copy the selected bodies and move the copies with the mouse; click to place":
        "Die ausgewählten Körper kopieren und die Kopien mit der Maus verschieben; Klicken setzt sie ab",
    "Re&name...": "&Umbenennen …",
    "Rename the active body in the outliner": "Den aktiven Körper in der Gliederung umbenennen",
    "Select &All": "Alles au&swählen",
    "Select &None": "&Nichts auswählen",
    "&Invert Selection": "Auswahl &invertieren",
    "&Grab": "&Greifen",
    "Move the selection with the mouse in the view plane; click to confirm, Esc cancels":
        "Die Auswahl mit der Maus in der Ansichtsebene verschieben; Klicken bestätigt, Esc bricht ab",
    "R&otate": "Dr&ehen",
    "Turn the selection about the view axis with the mouse; click to confirm":
        "Die Auswahl mit der Maus um die Blickachse drehen; Klicken bestätigt",
    "&Tool": "Werk&zeug",
    "A&dd": "Hin&zufügen",
    "Add a %1 on the ground, or on top of the selection":
        "%1 auf dem Boden oder auf der Auswahl hinzufügen",
    "Add Menu": "Menü „Hinzufügen“",
    "&Select": "&Auswählen",
    "Select tool: click or drag a box to select": "Auswahlwerkzeug: Klicken oder Rahmen aufziehen zum Auswählen",
    "&Move": "&Verschieben",
    "Move tool: drag an arrow or a square of the gizmo; Ctrl snaps to 0.1 m":
        "Verschieben: Einen Pfeil oder ein Quadrat des Gizmos ziehen; Strg rastet auf 0,1 m ein",
    "&Rotate": "&Drehen",
    "Rotate tool: drag a ring of the gizmo; Ctrl snaps to 15 degrees":
        "Drehen: Einen Ring des Gizmos ziehen; Strg rastet auf 15 Grad ein",
    "Tools": "Werkzeuge",
    "Rename": "Umbenennen",
    "Unanchor": "Verankerung lösen",
    "Anchor": "Verankern",
    "Anchor %1": "%1 verankern",
    "Unanchor %1": "Verankerung von %1 lösen",
    "The body is hidden by the outliner's filter; clear it to rename.":
        "Der Körper ist durch den Filter der Gliederung ausgeblendet; leeren Sie den Filter, um ihn umzubenennen.",
}

T["rl::ExportDialog"] = {
    "Export Bake": "Backergebnis exportieren",
    "RigidLab bake (.bake)": "RigidLab-Backergebnis (.bake)",
    "CSV table (.csv)": "CSV-Tabelle (.csv)",
    "&Format:": "&Format:",
    "Browse…": "Durchsuchen …",
    "&File:": "&Datei:",
    "CSV rows": "CSV-Zeilen",
    "All %n bodies": ["Alle Körper (%n)", "Alle Körper (%n)"],
    "Selected bodies (%n)": ["Ausgewählte Körper (%n)", "Ausgewählte Körper (%n)"],
    "Bodies:": "Körper:",
    "All frames (0 to %1)": "Alle Frames (0 bis %1)",
    "Frames": "Frames",
    "to": "bis",
    "Frames:": "Frames:",
    "Export": "Exportieren",
    "%1 rows: %2 frames (%3 s to %4 s) × %5 bodies.": "%1 Zeilen: %2 Frames (%3 s bis %4 s) × %5 Körper.",
    "Centres of mass, rotations and velocities.": "Massenschwerpunkte, Drehungen und Geschwindigkeiten.",
    "Centres of mass and rotations; this bake was read from a .bake file, which holds no velocities, so those fields stay empty.":
        "Massenschwerpunkte und Drehungen; dieses Backergebnis stammt aus einer .bake-Datei, die keine "
        "Geschwindigkeiten enthält, daher bleiben diese Felder leer.",
    "Every body and frame (%1 × %2), with the scene as OBJ text, readable by the original project's reader.":
        "Jeder Körper und Frame (%1 × %2), mit der Szene als OBJ-Text; das ursprüngliche Projekt kann die Datei lesen.",
    "CSV files (*.csv)": "CSV-Dateien (*.csv)",
    "Bake files (*.bake)": "Bake-Dateien (*.bake)",
    "Choose a file to export to.": "Wählen Sie eine Datei für den Export.",
    "The first frame (%1) is after the last (%2).": "Der erste Frame (%1) liegt nach dem letzten (%2).",
}

T["rl::FileController"] = {
    "File": "Datei",
    "&New": "&Neu",
    "Start an empty scene with the default world and materials":
        "Eine leere Szene mit Standardwelt und -materialien beginnen",
    "&Open...": "Ö&ffnen …",
    "Open a scene (.rlscene, OBJ, glTF, FBX, ...) or a .bake":
        "Eine Szene (.rlscene, OBJ, glTF, FBX, …) oder eine .bake-Datei öffnen",
    "Open": "Öffnen",
    "Open &Recent": "&Zuletzt geöffnet",
    "&Import...": "&Importieren …",
    "Add the bodies of other scene files to this scene": "Die Körper anderer Szenendateien zu dieser Szene hinzufügen",
    "Import": "Importieren",
    "&Save": "&Speichern",
    "Save the scene as .rlscene": "Die Szene als .rlscene speichern",
    "Save &As...": "Speichern &unter …",
    "Save the scene under a new name": "Die Szene unter einem neuen Namen speichern",
    "Re&vert to Saved": "Gespeicherte &Version wiederherstellen",
    "Drop the changes made since the last save": "Die Änderungen seit dem letzten Speichern verwerfen",
    "&Quit": "&Beenden",
    "Quit RigidLab": "RigidLab beenden",
    "No Recent Files": "Keine zuletzt geöffneten Dateien",
    "&Clear Recent Files": "Liste &leeren",
    "Open Recent": "Zuletzt geöffnet",
    "“%1” no longer exists.": "„%1“ existiert nicht mehr.",
    "It was moved, renamed or deleted, so it was removed from the recent files.\n\n%1":
        "Die Datei wurde verschoben, umbenannt oder gelöscht und daher aus der Liste der zuletzt geöffneten "
        "Dateien entfernt.\n\n%1",
    "New scene": "Neue Szene",
    "Could not open “%1”.": "„%1“ konnte nicht geöffnet werden.",
    "Opened %1: %n bodies": ["%1 geöffnet: %n Körper", "%1 geöffnet: %n Körper"],
    "%1: the file holds no bodies": "%1: Die Datei enthält keine Körper",
    "Could not import “%1”.": "„%1“ konnte nicht importiert werden.",
    "%n of %1 files could not be imported.": [
        "%n von %1 Dateien konnte nicht importiert werden.",
        "%n von %1 Dateien konnten nicht importiert werden.",
    ],
    "%n files": ["%n Datei", "%n Dateien"],
    "Imported %n bodies from %1": ["%n Körper aus %1 importiert", "%n Körper aus %1 importiert"],
    "; %n renamed to keep names unique": [
        "; %n umbenannt, damit die Namen eindeutig bleiben",
        "; %n umbenannt, damit die Namen eindeutig bleiben",
    ],
    "Untitled": "Unbenannt",
    "Save Scene As": "Szene speichern unter",
    "RigidLab scenes (*.rlscene)": "RigidLab-Szenen (*.rlscene)",
    "Could not save “%1”.": "„%1“ konnte nicht gespeichert werden.",
    "%1\n\nNothing was overwritten and your changes are still open. Try File > Save As with another name or folder.":
        "%1\n\nEs wurde nichts überschrieben, und Ihre Änderungen sind noch geöffnet. Versuchen Sie "
        "Datei > Speichern unter mit einem anderen Namen oder Ordner.",
    "Saved %1": "%1 gespeichert",
    "Revert to Saved": "Gespeicherte Version wiederherstellen",
    "Revert “%1” to the saved version?": "„%1“ auf die gespeicherte Version zurücksetzen?",
    "The changes since the last save are undone; Redo brings them back.":
        "Die Änderungen seit dem letzten Speichern werden rückgängig gemacht; „Wiederholen“ holt sie zurück.",
    "The file is read again; the changes since the last save are lost.":
        "Die Datei wird neu eingelesen; die Änderungen seit dem letzten Speichern gehen verloren.",
    "&Revert": "&Zurücksetzen",
    "Reverted to the saved %1": "Auf die gespeicherte Version von %1 zurückgesetzt",
    "RigidLab cannot open %1.": "RigidLab kann %1 nicht öffnen.",
    "It opens scenes (.rlscene, OBJ, glTF, FBX, COLLADA, PLY, STL, 3DS) and .bake files.":
        "Geöffnet werden Szenen (.rlscene, OBJ, glTF, FBX, COLLADA, PLY, STL, 3DS) und .bake-Dateien.",
    "Ignored: %1 (only one bake opens, and never together with scenes)":
        "Ignoriert: %1 (nur ein Backergebnis lässt sich öffnen, und nie zusammen mit Szenen)",
    "Do you want to save the changes to “%1” before closing?":
        "Möchten Sie die Änderungen an „%1“ vor dem Schließen speichern?",
    "Do you want to save the changes to “%1” before starting a new scene?":
        "Möchten Sie die Änderungen an „%1“ speichern, bevor Sie eine neue Szene beginnen?",
    "Do you want to save the changes to “%1” before opening another scene?":
        "Möchten Sie die Änderungen an „%1“ speichern, bevor Sie eine andere Szene öffnen?",
    "Unsaved Changes": "Ungespeicherte Änderungen",
    "Your changes will be lost if you don't save them.":
        "Ihre Änderungen gehen verloren, wenn Sie sie nicht speichern.",
    "Autosave failed: %1": "Automatisches Speichern fehlgeschlagen: %1",
    "Autosaved unsaved changes at %1": "Ungespeicherte Änderungen um %1 automatisch gesichert",
    "Recover Unsaved Work": "Ungespeicherte Arbeit wiederherstellen",
    "RigidLab did not close normally. Unsaved changes to “%1” were autosaved on %2.":
        "RigidLab wurde nicht normal beendet. Ungespeicherte Änderungen an „%1“ wurden am %2 automatisch gesichert.",
    "Restore opens them as an unsaved scene; Discard deletes the autosaved copy; Not Now keeps it for the next start.":
        "„Wiederherstellen“ öffnet sie als ungespeicherte Szene; „Verwerfen“ löscht die gesicherte Kopie; "
        "„Nicht jetzt“ behält sie für den nächsten Start.",
    "&Restore": "&Wiederherstellen",
    "&Not Now": "&Nicht jetzt",
    "Could not restore the autosaved copy.": "Die automatisch gesicherte Kopie konnte nicht wiederhergestellt werden.",
    "%1\n\nThe copy was kept at %2.": "%1\n\nDie Kopie wurde unter %2 behalten.",
    "Restored unsaved changes to %1": "Ungespeicherte Änderungen an %1 wiederhergestellt",
    "Unsaved changes to “%1” from a session that did not close normally were kept; start RigidLab without a file to restore them.":
        "Ungespeicherte Änderungen an „%1“ aus einer nicht normal beendeten Sitzung wurden aufbewahrt; starten Sie "
        "RigidLab ohne Datei, um sie wiederherzustellen.",
    "Scenes (%1)": "Szenen (%1)",
    "Scenes and bakes (%1 *.bake)": "Szenen und Backergebnisse (%1 *.bake)",
    "Bakes (*.bake)": "Backergebnisse (*.bake)",
    "Wavefront OBJ (*.obj)": "Wavefront OBJ (*.obj)",
    "All files (*)": "Alle Dateien (*)",
    "RigidLab": "RigidLab",
}

T["rl::InspectorWidget"] = {
    "Select a body to inspect it.": "Wählen Sie einen Körper aus, um seine Eigenschaften zu sehen.",
    "Body": "Körper",
    "Rename": "Umbenennen",
    "Name": "Name",
    "Static (does not move)": "Statisch (bewegt sich nicht)",
    "Anchor": "Verankern",
    "Unanchor": "Verankerung lösen",
    "Set Material": "Material festlegen",
    "Material": "Material",
    "Overrides": "Überschreibungen",
    " kg/m³": " kg/m³",
    "Set Density": "Dichte festlegen",
    "Density must be above 0 kg/m³.": "Die Dichte muss größer als 0 kg/m³ sein.",
    " kg": " kg",
    "Set Mass": "Masse festlegen",
    "Mass must be above 0 kg.": "Die Masse muss größer als 0 kg sein.",
    "Set Friction": "Reibung festlegen",
    "Friction must be 0 or more.": "Die Reibung muss 0 oder größer sein.",
    "Set Restitution": "Restitution festlegen",
    "Restitution must be between 0 (no bounce) and 1 (elastic).":
        "Die Restitution muss zwischen 0 (kein Abprallen) und 1 (elastisch) liegen.",
    "Density": "Dichte",
    "Mass": "Masse",
    "Friction": "Reibung",
    "Restitution": "Restitution",
    "Placement": "Platzierung",
    "Move": "Verschieben",
    "Rotate": "Drehen",
    "Position (m)": "Position (m)",
    "Rotation XYZ (°)": "Drehung XYZ (°)",
    "Initial motion": "Anfangsbewegung",
    "Set Velocity": "Geschwindigkeit festlegen",
    "Set Angular Velocity": "Winkelgeschwindigkeit festlegen",
    "Velocity (m/s)": "Geschw. (m/s)",
    "Angular velocity (rad/s)": "Winkelgeschw. (rad/s)",
    "Computed": "Berechnet",
    "Volume": "Volumen",
    "Centre of mass": "Schwerpunkt",
    "Principal inertia": "Hauptträgheitsmomente",
    "Hull vertices": "Hüllenpunkte",
    "Warnings": "Warnungen",
    "%1 m³ (total)": "%1 m³ (gesamt)",
    "%1 kg (total)": "%1 kg (gesamt)",
    "%n bodies cannot be simulated": [
        "%n Körper kann nicht simuliert werden",
        "%n Körper können nicht simuliert werden",
    ],
    "none": "keine",
    "%1 m³": "%1 m³",
    "%1 kg": "%1 kg",
    "%1 kg m²": "%1 kg m²",
    "none (sphere)": "keine (Kugel)",
}

T["rl::MainWindow"] = {
    "&About RigidLab": "&Über RigidLab",
    "About RigidLab": "Über RigidLab",
    "<b>RigidLab</b> %1<br>An editor and simulator for 3D rigid-body scenes.":
        "<b>RigidLab</b> %1<br>Ein Editor und Simulator für 3D-Starrkörperszenen.",
    "nothing selected": "nichts ausgewählt",
    "frame %1 ms": "Framezeit %1 ms",
    "Outliner": "Gliederung",
    "Filter by name": "Nach Namen filtern",
    "Inspector": "Eigenschaften",
    "History": "Verlauf",
    "<opened scene>": "<geöffnete Szene>",
    "&File": "&Datei",
    "&Edit": "&Bearbeiten",
    "A&dd": "Hin&zufügen",
    "&View": "Ans&icht",
    "&Simulation": "&Simulation",
    "A&nalysis": "Ana&lyse",
    "&Window": "&Fenster",
    "&Help": "&Hilfe",
    "&Export": "&Exportieren",
    "&Language": "&Sprache",
    "System default": "Systemstandard",
    "The language changes when RigidLab is restarted.": "Die Sprache ändert sich beim nächsten Start von RigidLab.",
    "selected: %1": "ausgewählt: %1",
    "%n selected": ["%n ausgewählt", "%n ausgewählt"],
    "%1[*] - RigidLab": "%1[*] – RigidLab",
    "%n bodies": ["%n Körper", "%n Körper"],
    "%n anchors": ["%n Anker", "%n Anker"],
    "Frame &Selected\tF": "&Auswahl zeigen\tF",
    "Frame &All\tHome": "A&lles zeigen\tHome",
}

T["rl::MaterialLibrary"] = {
    "A material needs a name.": "Ein Material braucht einen Namen.",
    "The name \"%1\" starts or ends with a space.": "Der Name „%1“ beginnt oder endet mit einem Leerzeichen.",
    "\"%1\" is a built-in preset and keeps its name; duplicate it to make a material of your own.":
        "„%1“ ist eine eingebaute Vorgabe und behält ihren Namen; duplizieren Sie sie für ein eigenes Material.",
    "\"%1\" is the name of a built-in preset; choose another name.":
        "„%1“ ist der Name einer eingebauten Vorgabe; wählen Sie einen anderen Namen.",
    "The library already has a material called \"%1\".": "Die Bibliothek enthält bereits ein Material „%1“.",
    "Density of \"%1\" must be above 0 and at most %2 kg/m³ (got %3).":
        "Die Dichte von „%1“ muss größer als 0 und höchstens %2 kg/m³ sein (erhalten: %3).",
    "Friction of \"%1\" must be between 0 and %2 (got %3).":
        "Die Reibung von „%1“ muss zwischen 0 und %2 liegen (erhalten: %3).",
    "Restitution of \"%1\" must be between 0 (no bounce) and 1 (elastic) (got %2).":
        "Die Restitution von „%1“ muss zwischen 0 (kein Abprallen) und 1 (elastisch) liegen (erhalten: %2).",
    "geometric mean": "geometrisches Mittel",
    "average": "Mittelwert",
    "minimum": "Minimum",
    "maximum": "Maximum",
    "product": "Produkt",
}

T["rl::MaterialLibraryModel"] = {
    "Built-in preset, changed for this scene (built-in: %1 kg/m³, friction %2, restitution %3).":
        "Eingebaute Vorgabe, für diese Szene geändert (eingebaut: %1 kg/m³, Reibung %2, Restitution %3).",
    "Built-in preset": "Eingebaute Vorgabe",
    "Material of this scene": "Material dieser Szene",
    "Material": "Material",
    "kg/m³": "kg/m³",
    "μ": "μ",
    "e": "e",
    "Bodies": "Körper",
    "Density in kg/m³": "Dichte in kg/m³",
    "Coulomb friction coefficient": "Coulombscher Reibungskoeffizient",
    "Restitution: 0 = no bounce, 1 = elastic": "Restitution: 0 = kein Abprallen, 1 = elastisch",
    "Bodies (anchors included) that use the material": "Körper (einschließlich Anker), die das Material verwenden",
}

T["rl::MaterialPairModel"] = {
    "%1 on %2\nfriction %3 = %4\nrestitution %5 = %6": "%1 auf %2\nReibung %3 = %4\nRestitution %5 = %6",
}

T["rl::MaterialsWidget"] = {
    "1 body": "1 Körper",
    "%1 bodies": "%1 Körper",
    "Add": "Hinzufügen",
    "Add a new material": "Ein neues Material hinzufügen",
    "Duplicate": "Duplizieren",
    "Add a copy of the selected material": "Eine Kopie des ausgewählten Materials hinzufügen",
    "Delete": "Löschen",
    "Delete the selected material; bodies that use it move to Default":
        "Das ausgewählte Material löschen; Körper, die es verwenden, erhalten „Default“",
    "Reset preset": "Zurücksetzen",
    "Give the selected preset its built-in values back": "Der ausgewählten Vorgabe ihre eingebauten Werte zurückgeben",
    "Selected material": "Ausgewähltes Material",
    "Rename Material": "Material umbenennen",
    "Name": "Name",
    " kg/m³": " kg/m³",
    "Mass per volume; above 0, at most %1 kg/m³": "Masse pro Volumen; größer als 0, höchstens %1 kg/m³",
    "Set Material Density": "Materialdichte festlegen",
    "Density": "Dichte",
    "Coulomb friction coefficient μ, 0 to %1": "Coulombscher Reibungskoeffizient μ, 0 bis %1",
    "Set Material Friction": "Materialreibung festlegen",
    "Friction μ": "Reibung μ",
    "Restitution e: 0 = no bounce, 1 = elastic": "Restitution e: 0 = kein Abprallen, 1 = elastisch",
    "Set Material Restitution": "Materialrestitution festlegen",
    "Restitution e": "Restitution e",
    "Library": "Bibliothek",
    "Contact pairs": "Kontaktpaare",
    "Friction and restitution of every pair of materials the scene's bodies use":
        "Reibung und Restitution jedes Materialpaars, das die Körper der Szene verwenden",
    "Presets keep their names; duplicate one to make your own":
        "Vorgaben behalten ihre Namen; duplizieren Sie eine für ein eigenes Material",
    "No body uses it.": "Kein Körper verwendet es.",
    "Used by %1.": "Für %1 verwendet.",
    "Built-in preset, changed for this scene (built-in: %1 kg/m³, μ %2, e %3). %4":
        "Eingebaute Vorgabe, für diese Szene geändert (eingebaut: %1 kg/m³, μ %2, e %3). %4",
    "Built-in preset; changes apply to this scene only. %1":
        "Eingebaute Vorgabe; Änderungen gelten nur für diese Szene. %1",
    "Material of this scene. %1": "Material dieser Szene. %1",
    "Presets cannot be deleted; Reset preset gives back their built-in values":
        "Vorgaben lassen sich nicht löschen; „Zurücksetzen“ stellt ihre eingebauten Werte wieder her",
    "Each cell: friction μ / restitution e. μ = %1 (%2), e = %3 (%4); World settings choose the rules.":
        "Jede Zelle: Reibung μ / Restitution e. μ = %1 (%2), e = %3 (%4); die Regeln legen die "
        "Welteinstellungen fest.",
    "No bodies in the scene.": "Keine Körper in der Szene.",
    "Not included: %1 with their own friction or restitution (set in the inspector).":
        "Nicht enthalten: %1 mit eigener Reibung oder Restitution (in den Eigenschaften festgelegt).",
    "Renamed \"%1\" to \"%2\" on %3 too.": "„%1“ auch für %3 in „%2“ umbenannt.",
    "Material": "Material",
    "Add Material": "Material hinzufügen",
    "%1 copy": "%1-Kopie",
    "Duplicate Material": "Material duplizieren",
    "\"%1\" is a built-in preset and cannot be deleted; Reset preset gives back its built-in values.":
        "„%1“ ist eine eingebaute Vorgabe und kann nicht gelöscht werden; „Zurücksetzen“ stellt ihre "
        "eingebauten Werte wieder her.",
    "Delete Material %1": "Material %1 löschen",
    "Deleted \"%1\"; no body used it.": "„%1“ gelöscht; kein Körper hat es verwendet.",
    "Deleted \"%1\" and moved the %2 that used it to Default (Undo brings it back).":
        "„%1“ gelöscht und durch „Default“ ersetzt für %2 („Rückgängig“ stellt es wieder her).",
    "Reset Preset %1": "Vorgabe %1 zurücksetzen",
}

T["rl::MessageBar"] = {
    "Close": "Schließen",
}

T["rl::OutlinerModel"] = {
    "%1 (anchor: static)": "%1 (Anker: statisch)",
    "%1 (dynamic)": "%1 (dynamisch)",
    "Anchored (static): click to make it dynamic": "Verankert (statisch): Klicken macht ihn dynamisch",
    "Dynamic: click to anchor it": "Dynamisch: Klicken verankert ihn",
    "anchored": "verankert",
    "dynamic": "dynamisch",
    "Anchor: click a row's pin to make that body static or dynamic":
        "Anker: Klick auf die Nadel einer Zeile macht den Körper statisch oder dynamisch",
    "Name": "Name",
    "Material": "Material",
    "A body needs a name.": "Ein Körper braucht einen Namen.",
    "Another body is already called \"%1\". Names must be unique.":
        "Ein anderer Körper heißt bereits „%1“. Namen müssen eindeutig sein.",
    "Rename %1 to %2": "%1 in %2 umbenennen",
}

T["rl::OverlayController"] = {
    "&Contact Points and Normals": "&Kontaktpunkte und Normalen",
    "Show contact points and their normals": "Kontaktpunkte und ihre Normalen anzeigen",
    "&Velocities": "&Geschwindigkeiten",
    "Show an arrow per body along its velocity, longer the faster it moves (capped)":
        "Einen Pfeil je Körper in Richtung seiner Geschwindigkeit zeigen, länger je schneller (begrenzt)",
    "Centres of &Mass": "&Massenschwerpunkte",
    "Mark each body's centre of mass with a cross": "Den Massenschwerpunkt jedes Körpers mit einem Kreuz markieren",
    "&Bounding Boxes": "&Hüllquader",
    "Show each body's axis-aligned bounding box (AABB)": "Den achsenparallelen Hüllquader (AABB) jedes Körpers anzeigen",
    "&Sleeping Bodies": "&Schlafende Körper",
    "Draw sleeping bodies washed out": "Schlafende Körper blass zeichnen",
    "Motion &Trails of the Selection": "Bewegungsspuren der &Auswahl",
    "Trace the path of the selected bodies over the last frames":
        "Den Weg der ausgewählten Körper über die letzten Frames nachzeichnen",
    "&Overlays": "&Überlagerungen",
    "Show &Legend": "&Legende anzeigen",
    "Explain the overlay colours in a corner of the viewport":
        "Die Farben der Überlagerungen in einer Ecke des Ansichtsfensters erklären",
    "Contact point": "Kontaktpunkt",
    "Contact normal": "Kontaktnormale",
    "Velocity": "Geschwindigkeit",
    "Centre of mass": "Massenschwerpunkt",
    "Bounding box": "Hüllquader",
    "Sleeping (washed out)": "Schlafend (blass)",
    "Trail of the selection": "Spur der Auswahl",
}

T["rl::PreflightDialog"] = {
    "Very small body": "Sehr kleiner Körper",
    "May pass through": "Kann durchdringen",
    "Concave body": "Konkaver Körper",
    "Extreme mass ratio": "Extremes Massenverhältnis",
    "Cannot be simulated": "Nicht simulierbar",
    "'%1' is %2 cm across, below %3 cm.": "„%1“ misst %2 cm, weniger als %3 cm.",
    "'%1' may reach %2 m/s and move %3 m per frame, more than its thickness of %4 m.":
        "„%1“ kann %2 m/s erreichen und sich %3 m pro Frame bewegen, mehr als seine Dicke von %4 m.",
    "'%1' is concave: it collides as its convex hull, so its hollows are filled.":
        "„%1“ ist konkav: Er kollidiert als seine konvexe Hülle, Vertiefungen sind also gefüllt.",
    "'%1' touches '%2' at the start; '%2' is %3 times heavier.":
        "„%1“ berührt zu Beginn „%2“; „%2“ ist %3-mal schwerer.",
    "Coordinates are metres: if the model was made in centimetres, scale it up by 100. Contacts start 2 cm before bodies touch, so smaller bodies jitter and sink.":
        "Koordinaten sind Meter: Wurde das Modell in Zentimetern erstellt, skalieren Sie es mit 100. "
        "Kontakte beginnen 2 cm, bevor sich Körper berühren, daher zittern und sinken kleinere Körper.",
    "CCD is switched off for this scene: turn it back on, or raise the frame rate to at least %1 fps, or make the body thicker.":
        "CCD ist für diese Szene ausgeschaltet: Schalten Sie es wieder ein, erhöhen Sie die Bildrate auf "
        "mindestens %1 fps oder machen Sie den Körper dicker.",
    "CCD sweeps such bodies; to be safe without it, raise the frame rate to at least %1 fps or make the body thicker.":
        "CCD verfolgt solche Körper über den ganzen Weg; um auch ohne CCD sicher zu sein, erhöhen Sie die "
        "Bildrate auf mindestens %1 fps oder machen Sie den Körper dicker.",
    "Split it into convex parts in Blender (one object each), make it an anchor, or accept the hull.":
        "Zerlegen Sie ihn in Blender in konvexe Teile (je ein Objekt), machen Sie ihn zum Anker oder "
        "akzeptieren Sie die Hülle.",
    "Bring the masses closer (below %1:1), or raise substeps and iterations; otherwise the lighter body may sink or jitter.":
        "Gleichen Sie die Massen an (unter %1:1) oder erhöhen Sie Teilschritte und Iterationen; sonst kann "
        "der leichtere Körper einsinken oder zittern.",
    "Fix the body's shape, size or mass; the bake cannot run with it.":
        "Korrigieren Sie Form, Größe oder Masse des Körpers; so kann nicht gebacken werden.",
    "Pre-flight check": "Vorabprüfung",
    "No problems found in this scene.": "In dieser Szene wurden keine Probleme gefunden.",
    "%n finding(s) in this scene may make the bake inaccurate or unstable. Bake anyway?": [
        "%n Befund in dieser Szene kann das Backergebnis ungenau oder instabil machen. Trotzdem backen?",
        "%n Befunde in dieser Szene können das Backergebnis ungenau oder instabil machen. Trotzdem backen?",
    ],
    "%n finding(s) in this scene may make a bake inaccurate or unstable.": [
        "%n Befund in dieser Szene kann ein Backergebnis ungenau oder instabil machen.",
        "%n Befunde in dieser Szene können ein Backergebnis ungenau oder instabil machen.",
    ],
    "Problem": "Problem",
    "Body": "Körper",
    "Details": "Details",
    "Fix: %1": "Abhilfe: %1",
    "<b>Suggested fix for '%1':</b> %2": "<b>Vorgeschlagene Abhilfe für „%1“:</b> %2",
    "Don't show again for this scene": "Für diese Szene nicht mehr anzeigen",
    "Bake anyway": "Trotzdem backen",
}

T["rl::Primitives"] = {
    "&Cube": "&Würfel",
    "&Sphere": "&Kugel",
    "C&ylinder": "&Zylinder",
    "C&one": "K&egel",
}

T["rl::RecoveryStore"] = {
    "%1: cannot create the folder": "%1: Der Ordner kann nicht angelegt werden",
}

T["rl::SceneDocument"] = {
    "Untitled": "Unbenannt",
}

T["rl::SettingsController"] = {
    "World": "Welt",
    "Materials": "Materialien",
    "&World Settings": "&Welteinstellungen",
    "&Materials": "&Materialien",
}

T["rl::SimulationController"] = {
    "Timeline": "Zeitleiste",
    "The bake has %n bodies and the scene %1: re-bake to scrub it.": [
        "Das Backergebnis hat %n Körper und die Szene %1: Neu backen, um darin zu navigieren.",
        "Das Backergebnis hat %n Körper und die Szene %1: Neu backen, um darin zu navigieren.",
    ],
    "Simulation": "Simulation",
    "&Play": "&Abspielen",
    "&Step": "&Einzelschritt",
    "Advance one frame (while paused)": "Einen Frame weiter (wenn angehalten)",
    "&Reset": "&Zurücksetzen",
    "Back to the edit pose (frame 0)": "Zurück zur Bearbeitungspose (Frame 0)",
    "&Bake…": "&Backen …",
    "Record the simulation in the background for playback and export":
        "Die Simulation im Hintergrund für Wiedergabe und Export aufzeichnen",
    "Re-&bake": "&Neu backen",
    "Bake the edited scene again, as long as the last bake":
        "Die bearbeitete Szene erneut backen, so lange wie beim letzten Mal",
    "&Cancel Bake": "Backen abbre&chen",
    "Stop baking and keep the frames done so far": "Backen beenden und die bisherigen Frames behalten",
    "C&lear Bake": "Backergebnis &verwerfen",
    "Drop the bake and simulate live again": "Das Backergebnis verwerfen und wieder live simulieren",
    "&Pause": "&Pause",
    "Play or pause the bake": "Backergebnis abspielen oder anhalten",
    "Run or pause the simulation": "Simulation starten oder anhalten",
    "edit pose": "Bearbeitungspose",
    "live · %1 s · frame %2 · %3 steps/s": "live · %1 s · Frame %2 · %3 Schritte/s",
    "bake · %1 s · frame %2/%3": "gebacken · %1 s · Frame %2/%3",
    " · stale": " · veraltet",
    "Nothing to simulate: the scene has no bodies.": "Nichts zu simulieren: Die Szene enthält keine Körper.",
    "The scene cannot be simulated:\n%1": "Die Szene kann nicht simuliert werden:\n%1",
    "The scene was edited: the simulation went back to the edit pose.":
        "Die Szene wurde bearbeitet: Die Simulation ist zur Bearbeitungspose zurückgekehrt.",
    "Nothing to bake: the scene has no bodies.": "Nichts zu backen: Die Szene enthält keine Körper.",
    "Bake": "Backen",
    "The scene cannot be baked:\n%1": "Die Szene kann nicht gebacken werden:\n%1",
    "starting": "startet",
    "Baking %n frames…": ["%n Frame wird gebacken …", "%n Frames werden gebacken …"],
    "frame %1 of %2": "Frame %1 von %2",
    "frame %1 of %2, %3 s left": "Frame %1 von %2, noch %3 s",
    "baking · %1": "backt · %1",
    "Bake cancelled: kept frames 0 to %1.": "Backen abgebrochen: Frames 0 bis %1 behalten.",
    "Baked frames 0 to %1 in %2 s.": "Frames 0 bis %1 in %2 s gebacken.",
    "Baked frames 0 to %1 in %2 s; the simulation starts at frame %3.":
        "Frames 0 bis %1 in %2 s gebacken; die Simulation beginnt bei Frame %3.",
    "The scene was edited meanwhile, so the bake is stale.":
        "Die Szene wurde inzwischen bearbeitet, das Backergebnis ist daher veraltet.",
    "Open Bake": "Backergebnis öffnen",
    "Could not open the bake:\n%1": "Das Backergebnis konnte nicht geöffnet werden:\n%1",
    "The bake holds no scene; its shapes come from %1.": "Das Backergebnis enthält keine Szene; die Formen stammen aus %1.",
    "The bake holds no scene: each body is shown as a small box at its vertex mean. Put the OBJ it was recorded from next to it as %1 to see the shapes.":
        "Das Backergebnis enthält keine Szene: Jeder Körper erscheint als kleiner Quader im Mittel seiner "
        "Eckpunkte. Legen Sie die OBJ-Datei, aus der es aufgezeichnet wurde, als %1 daneben, um die Formen zu sehen.",
    "Opened %1: frames 0 to %2 at %3 Hz, %n bodies.": [
        "%1 geöffnet: Frames 0 bis %2 mit %3 Hz, %n Körper.",
        "%1 geöffnet: Frames 0 bis %2 mit %3 Hz, %n Körper.",
    ],
}

T["rl::TimelineView"] = {
    "Energy": "Energie",
    "Kinetic": "Kinetisch",
    "Potential": "Potenziell",
    "Total": "Gesamt",
    "Max penetration": "Max. Eindringtiefe",
    "Contacts": "Kontakte",
    "Awake bodies": "Wache Körper",
    "%1 GJ": "%1 GJ",
    "%1 MJ": "%1 MJ",
    "%1 kJ": "%1 kJ",
    "%1 mJ": "%1 mJ",
    "%1 J": "%1 J",
    "%1 m": "%1 m",
    "%1 mm": "%1 mm",
    "Frame %1 · %2 s": "Frame %1 · %2 s",
    "Scene changed since this bake": "Szene seit diesem Backen geändert",
    "Ruler in seconds (Ctrl+T shows frames)": "Lineal in Sekunden (Strg+T zeigt Frames)",
    "Ruler in frames (Ctrl+T shows seconds)": "Lineal in Frames (Strg+T zeigt Sekunden)",
    "Frame %1 is outside the range %2–%3": "Frame %1 liegt außerhalb des Bereichs %2–%3",
    "Baking: %1 %": "Backen: %1 %",
    "Baked (frames 0–%1)": "Gebacken (Frames 0–%1)",
    "Not baked": "Nicht gebacken",
    "Scale %1 to %2": "Skala %1 bis %2",
    "Kinetic, potential and their total. A flat total means energy is conserved; it steps down where contacts and damping dissipate it.":
        "Kinetisch, potenziell und die Summe. Eine flache Summe bedeutet Energieerhaltung; sie fällt dort ab, "
        "wo Kontakte und Dämpfung Energie abführen.",
    "Frame %1: not baked": "Frame %1: nicht gebacken",
    "%1: %2": "%1: %2",
    "Total change since frame 0: %1": "Gesamtänderung seit Frame 0: %1",
    "Bake the simulation to scrub it here and to see its energy, contacts and penetration.":
        "Backen Sie die Simulation, um hier darin zu navigieren und Energie, Kontakte und Eindringtiefe zu sehen.",
    "This bake carries no diagnostics (bake files store positions only).":
        "Dieses Backergebnis enthält keine Diagnosedaten (Bake-Dateien speichern nur Positionen).",
    "Diagnostic tracks hidden.": "Diagnosespuren ausgeblendet.",
    "Seconds": "Sekunden",
    "Frames": "Frames",
}

T["rl::TimelineWidget"] = {
    "First Frame": "Erster Frame",
    "Jump to the first frame (Home)": "Zum ersten Frame springen (Pos1)",
    "Previous Frame": "Vorheriger Frame",
    "Step back one frame (Left)": "Einen Frame zurück (Links)",
    "Play": "Abspielen",
    "Play at real time (Space)": "In Echtzeit abspielen (Leertaste)",
    "Next Frame": "Nächster Frame",
    "Step forward one frame (Right)": "Einen Frame vor (Rechts)",
    "Last Frame": "Letzter Frame",
    "Jump to the last frame (End)": "Zum letzten Frame springen (Ende)",
    "Loop": "Schleife",
    "Loop playback; off stops at the end": "Wiedergabe wiederholen; aus: hält am Ende an",
    "Show Seconds": "Sekunden anzeigen",
    "Ruler in seconds instead of frames (Ctrl+T)": "Lineal in Sekunden statt Frames (Strg+T)",
    "Show Diagnostic Tracks": "Diagnosespuren anzeigen",
    "Show energy, penetration, contacts and awake bodies under the ruler":
        "Energie, Eindringtiefe, Kontakte und wache Körper unter dem Lineal anzeigen",
    "Zoom to Fit": "Alles zeigen",
    "Show the whole frame range": "Den gesamten Frame-Bereich zeigen",
    "Frame": "Frame",
    "Current frame": "Aktueller Frame",
    "Time of the current frame": "Zeit des aktuellen Frames",
    "Speed": "Tempo",
    "Playback speed": "Wiedergabegeschwindigkeit",
    "Baking %1 %": "Backen %1 %",
    "%1 s": "%1 s",
    "Pause": "Pause",
    "Pause (Space)": "Pause (Leertaste)",
}

T["rl::TransformGizmo"] = {
    "%1  %2 m": "%1  %2 m",
    "Move  %1, %2, %3 m": "Verschieben  %1, %2, %3 m",
    "View": "Ansicht",
    "%1  %2°": "%1  %2°",
}

T["rl::WorldSettingsWidget"] = {
    "Earth": "Erde",
    "Moon": "Mond",
    "Mars": "Mars",
    "Zero g": "Schwerelos",
    "Gravity": "Schwerkraft",
    "Rotation": "Drehung",
    "Friction": "Reibung",
    "Restitution": "Restitution",
    "Damping": "Dämpfung",
    "Sleeping": "Schlafen",
    "CCD": "CCD",
    "Auto: on when a dynamic body exists and gravity is not zero":
        "Auto: ein, wenn es einen dynamischen Körper gibt und die Schwerkraft nicht null ist",
    "Auto: on unless every dynamic body is a sphere that cannot start spinning":
        "Auto: ein, außer jeder dynamische Körper ist eine Kugel, die nicht ins Drehen kommen kann",
    "Auto: on when some pair of bodies has a combined friction above zero":
        "Auto: ein, wenn ein Körperpaar eine kombinierte Reibung über null hat",
    "Auto: on when some pair of bodies has a combined restitution above zero":
        "Auto: ein, wenn ein Körperpaar eine kombinierte Restitution über null hat",
    "Auto: on when linear or angular damping is above zero":
        "Auto: ein, wenn lineare oder Winkeldämpfung über null liegt",
    "Auto: on when gravity acts and there is an anchor to come to rest on":
        "Auto: ein, wenn Schwerkraft wirkt und es einen Anker gibt, auf dem Körper zur Ruhe kommen",
    "Continuous collision detection. Auto: on when some body may move more than half its size in one frame":
        "Kontinuierliche Kollisionserkennung. Auto: ein, wenn sich ein Körper in einem Frame um mehr als "
        "seine halbe Größe bewegen kann",
    "%1 (%2 m/s²)": "%1 (%2 m/s²)",
    "Custom": "Benutzerdefiniert",
    "Sets gravity straight down (−Y) with the planet's surface gravity":
        "Setzt die Schwerkraft senkrecht nach unten (−Y) mit der Oberflächenschwerkraft des Himmelskörpers",
    "Set Gravity": "Schwerkraft festlegen",
    "Preset": "Vorgabe",
    "Gravity %1 in m/s² (Y is up)": "Schwerkraft %1 in m/s² (Y zeigt nach oben)",
    "X, Y, Z (m/s²)": "X, Y, Z (m/s²)",
    "Magnitude": "Betrag",
    "Time stepping": "Zeitschritte",
    " Hz": " Hz",
    "Frames per second; one simulation step per frame (above 0, at most %L1 Hz)":
        "Frames pro Sekunde; ein Simulationsschritt pro Frame (größer als 0, höchstens %L1 Hz)",
    "Set Frame Rate": "Bildrate festlegen",
    "Frame rate": "Bildrate",
    " per frame": " pro Frame",
    "Solver substeps per frame, 1 to %1. More substeps make stacks stiffer and contacts more accurate.":
        "Teilschritte des Lösers pro Frame, 1 bis %1. Mehr Teilschritte machen Stapel steifer und Kontakte genauer.",
    "Set Substeps": "Teilschritte festlegen",
    "Substeps": "Teilschritte",
    " per substep": " pro Teilschritt",
    "Velocity iterations of the contact solver per substep, 1 to %1":
        "Geschwindigkeitsiterationen des Kontaktlösers pro Teilschritt, 1 bis %1",
    "Set Iterations": "Iterationen festlegen",
    "Iterations": "Iterationen",
    "First order; gains energy (the original project's choice)":
        "Erster Ordnung; gewinnt Energie (die Wahl des ursprünglichen Projekts)",
    "First order at the same cost; energy stays bounded (default)":
        "Erster Ordnung bei gleichem Aufwand; die Energie bleibt beschränkt (Standard)",
    "Second order; exact for free fall": "Zweiter Ordnung; exakt für den freien Fall",
    "Fourth order in free flight; costs more per step": "Vierter Ordnung im freien Flug; teurer pro Schritt",
    "Explicit Euler": "Expliziter Euler",
    "Symplectic Euler": "Symplektischer Euler",
    "Verlet": "Verlet",
    "RK4": "RK4",
    "Where contacts act, every scheme is first order": "Wo Kontakte wirken, ist jedes Verfahren erster Ordnung",
    "Set Integrator": "Integrator festlegen",
    "Integrator": "Integrator",
    " 1/s": " 1/s",
    "Velocity lost per second, as a rate": "Geschwindigkeitsverlust pro Sekunde, als Rate",
    "Set Linear Damping": "Lineare Dämpfung festlegen",
    "Linear": "Linear",
    "Angular velocity lost per second, as a rate": "Verlust an Winkelgeschwindigkeit pro Sekunde, als Rate",
    "Set Angular Damping": "Winkeldämpfung festlegen",
    "Angular": "Winkel",
    "Contact combine rules": "Kombinationsregeln für Kontakte",
    "How the friction of two materials combines at a contact":
        "Wie sich die Reibung zweier Materialien an einem Kontakt kombiniert",
    "Set Friction Rule": "Reibungsregel festlegen",
    "How the restitution of two materials combines at a contact":
        "Wie sich die Restitution zweier Materialien an einem Kontakt kombiniert",
    "Set Restitution Rule": "Restitutionsregel festlegen",
    "Effects": "Effekte",
    "Auto simulates only what the scene calls for; a skipped effect costs nothing.":
        "Auto simuliert nur, was die Szene erfordert; ein übersprungener Effekt kostet nichts.",
    "Auto": "Auto",
    "On": "Ein",
    "Off": "Aus",
    "Set Effect %1": "Effekt %1 festlegen",
    "Linear only: no rotation (the original project's mode)":
        "Nur linear, ohne Drehung (wie im Original)",
    "The same as Rotation: Off": "Dasselbe wie Drehung: Aus",
    "Linear Only": "Nur linear",
    "Allow Rotation": "Drehung erlauben",
    "All Auto": "Alle auf Auto",
    "All Effects Auto": "Alle Effekte auf Auto",
    "Restore Defaults": "Standardwerte",
    "Earth gravity, %1 Hz, %2 substeps × %3 iterations, symplectic Euler, no damping, geometric-mean friction, maximum restitution, every effect on Auto":
        "Erdschwerkraft, %1 Hz, %2 Teilschritte × %3 Iterationen, symplektischer Euler, keine Dämpfung, "
        "Reibung als geometrisches Mittel, maximale Restitution, alle Effekte auf Auto",
    "Restore World Defaults": "Standardwerte der Welt wiederherstellen",
    "The frame rate must be above 0 and at most %L1 Hz (got %2 Hz).":
        "Die Bildrate muss größer als 0 und höchstens %L1 Hz sein (erhalten: %2 Hz).",
    "Substeps must be between 1 and %1 per frame (got %2).":
        "Die Teilschritte müssen zwischen 1 und %1 pro Frame liegen (erhalten: %2).",
    "Iterations must be between 1 and %1 per substep (got %2).":
        "Die Iterationen müssen zwischen 1 und %1 pro Teilschritt liegen (erhalten: %2).",
    "Each component of gravity must be a number between −%1 and %1 m/s².":
        "Jede Komponente der Schwerkraft muss eine Zahl zwischen −%1 und %1 m/s² sein.",
    "Linear damping must be between 0 and %1 1/s (got %2).":
        "Die lineare Dämpfung muss zwischen 0 und %1 1/s liegen (erhalten: %2).",
    "Angular damping must be between 0 and %1 1/s (got %2).":
        "Die Winkeldämpfung muss zwischen 0 und %1 1/s liegen (erhalten: %2).",
    "%L1 m/s²": "%L1 m/s²",
    "Step %L1 ms, substep %L2 ms; %3 solver passes per frame":
        "Schritt %L1 ms, Teilschritt %L2 ms; %3 Löserdurchläufe pro Frame",
    "Auto cannot decide for this scene: %1": "Auto kann für diese Szene nicht entscheiden: %1",
    "on": "ein",
    "off": "aus",
    "deciding…": "entscheidet …",
    "forced": "erzwungen",
    "Auto: %1": "Auto: %1",
    "Auto would turn it %1: %2": "Auto würde es auf „%1“ stellen: %2",
}
