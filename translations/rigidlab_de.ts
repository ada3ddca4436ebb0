<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>QObject</name>
    <message>
        <source>diverged</source>
        <translation>divergiert</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>RigidLab rigid-body scene editor</source>
        <translation>RigidLab – Editor für Starrkörperszenen</translation>
    </message>
    <message>
        <source>Scene file to open.</source>
        <translation>Zu öffnende Szenendatei.</translation>
    </message>
</context>
<context>
    <name>rl::AccuracyPanel</name>
    <message>
        <source>Accuracy</source>
        <translation>Genauigkeit</translation>
    </message>
    <message>
        <source>Integrators on exact solutions</source>
        <translation>Integratoren an exakten Lösungen</translation>
    </message>
    <message>
        <source>This scene</source>
        <translation>Diese Szene</translation>
    </message>
    <message>
        <source>&amp;Run study</source>
        <translation>Studie &amp;ausführen</translation>
    </message>
    <message>
        <source>Every integrator on problems with exact answers, at several step sizes.</source>
        <translation>Jeder Integrator an Aufgaben mit exakter Lösung, bei mehreren Schrittweiten.</translation>
    </message>
    <message>
        <source>Problem:</source>
        <translation>Aufgabe:</translation>
    </message>
    <message>
        <source>Error against CPU time</source>
        <translation>Fehler über CPU-Zeit</translation>
    </message>
    <message>
        <source>Integrator</source>
        <translation>Integrator</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>Schritte</translation>
    </message>
    <message>
        <source>Substeps</source>
        <translation>Teilschritte</translation>
    </message>
    <message>
        <source>Step (s)</source>
        <translation>Schritt (s)</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>CPU (µs)</source>
        <translation>CPU (µs)</translation>
    </message>
    <message>
        <source>Settings to compare</source>
        <translation>Zu vergleichende Einstellungen</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>Duration:</source>
        <translation>Dauer:</translation>
    </message>
    <message>
        <source>Substeps:</source>
        <translation>Teilschritte:</translation>
    </message>
    <message>
        <source>Integrators:</source>
        <translation>Integratoren:</translation>
    </message>
    <message>
        <source>&amp;Compare</source>
        <translation>&amp;Vergleichen</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Bakes the scene under each setting and compares it with a reference bake at RK4 and 64 substeps: position error (RMS over bodies and frames) against CPU time.</source>
        <translation>Backt die Szene mit jeder Einstellung und vergleicht sie mit einem Referenz-Bake (RK4, 64 Teilschritte): Positionsfehler (RMS über Körper und Frames) über CPU-Zeit.</translation>
    </message>
    <message>
        <source>Position error against CPU time</source>
        <translation>Positionsfehler über CPU-Zeit</translation>
    </message>
    <message>
        <source>RMS error (m)</source>
        <translation>RMS (m)</translation>
    </message>
    <message>
        <source>Max error (m)</source>
        <translation>Max. (m)</translation>
    </message>
    <message>
        <source>CPU (ms)</source>
        <translation>CPU (ms)</translation>
    </message>
    <message>
        <source>Running the study (each row is timed several times)…</source>
        <translation>Studie läuft (jede Zeile wird mehrmals gemessen) …</translation>
    </message>
    <message numerus="yes">
        <source>%n rows. Points with zero error (exact up to rounding) are not drawn.</source>
        <translation>
            <numerusform>%n Zeile. Punkte ohne Fehler (bis auf Rundung exakt) werden nicht gezeichnet.</numerusform>
            <numerusform>%n Zeilen. Punkte ohne Fehler (bis auf Rundung exakt) werden nicht gezeichnet.</numerusform>
        </translation>
    </message>
    <message>
        <source>CPU time per run (µs)</source>
        <translation>CPU-Zeit je Lauf (µs)</translation>
    </message>
    <message>
        <source>%1: error against CPU time</source>
        <translation>%1: Fehler über CPU-Zeit</translation>
    </message>
    <message>
        <source>Tick at least one substep count and one integrator.</source>
        <translation>Mindestens eine Teilschrittzahl und einen Integrator ankreuzen.</translation>
    </message>
    <message numerus="yes">
        <source>Baking %n setting(s) and the reference…</source>
        <translation>
            <numerusform>%n Einstellung und die Referenz werden gebacken …</numerusform>
            <numerusform>%n Einstellungen und die Referenz werden gebacken …</numerusform>
        </translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Abgebrochen.</translation>
    </message>
    <message>
        <source>Cannot compare: %1</source>
        <translation>Vergleich nicht möglich: %1</translation>
    </message>
    <message>
        <source>CPU time of the bake (ms)</source>
        <translation>CPU-Zeit des Backens (ms)</translation>
    </message>
    <message>
        <source>Position error, RMS (m)</source>
        <translation>Positionsfehler, RMS (m)</translation>
    </message>
    <message>
        <source>%1 frames of %2 dynamic bodies against %3 × %4 substeps (reference: %5 ms CPU).</source>
        <translation>%1 Frames von %2 dynamischen Körpern gegen %3 × %4 Teilschritte (Referenz: %5 ms CPU).</translation>
    </message>
    <message>
        <source>Only the first %1 of %2 dynamic bodies were simulated.</source>
        <translation>Nur die ersten %1 von %2 dynamischen Körpern wurden simuliert.</translation>
    </message>
</context>
<context>
    <name>rl::AnalysisController</name>
    <message>
        <source>&amp;Bake (.bake)…</source>
        <translation>&amp;Bake-Datei (.bake) …</translation>
    </message>
    <message>
        <source>Write the current bake as a .bake file the original project can read</source>
        <translation>Das aktuelle Backergebnis als .bake-Datei schreiben, die das ursprüngliche Projekt lesen kann</translation>
    </message>
    <message>
        <source>&amp;CSV…</source>
        <translation>&amp;CSV …</translation>
    </message>
    <message>
        <source>Write all or selected bodies and frames of the current bake as CSV</source>
        <translation>Alle oder ausgewählte Körper und Frames des aktuellen Backergebnisses als CSV schreiben</translation>
    </message>
    <message>
        <source>&amp;Accuracy…</source>
        <translation>&amp;Genauigkeit …</translation>
    </message>
    <message>
        <source>Error against CPU time per integrator and substep count</source>
        <translation>Fehler über CPU-Zeit je Integrator und Teilschrittzahl</translation>
    </message>
    <message>
        <source>&amp;Compare Bakes…</source>
        <translation>Backergebnisse &amp;vergleichen …</translation>
    </message>
    <message>
        <source>Find the first frame where two bakes diverge</source>
        <translation>Den ersten Frame finden, an dem zwei Backergebnisse auseinanderlaufen</translation>
    </message>
    <message>
        <source>&amp;Pre-flight Check…</source>
        <translation>Vorab&amp;prüfung …</translation>
    </message>
    <message>
        <source>List what in the scene may simulate badly</source>
        <translation>Auflisten, was in der Szene schlecht simuliert werden könnte</translation>
    </message>
    <message>
        <source>Export Bake</source>
        <translation>Backergebnis exportieren</translation>
    </message>
    <message>
        <source>There is nothing to export yet: bake the scene first or open a .bake file.</source>
        <translation>Es gibt noch nichts zu exportieren: Backen Sie zuerst die Szene oder öffnen Sie eine .bake-Datei.</translation>
    </message>
    <message>
        <source>untitled</source>
        <translation>unbenannt</translation>
    </message>
    <message>
        <source>Exporting %1…</source>
        <translation>%1 wird exportiert …</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation>%1 exportiert</translation>
    </message>
    <message>
        <source>Export cancelled; %1 was not changed.</source>
        <translation>Export abgebrochen; %1 wurde nicht verändert.</translation>
    </message>
</context>
<context>
    <name>rl::BakeDialog</name>
    <message>
        <source>Bake</source>
        <translation>Backen</translation>
    </message>
    <message>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <source>&amp;Duration:</source>
        <translation>&amp;Dauer:</translation>
    </message>
    <message>
        <source>&amp;Frames:</source>
        <translation>&amp;Frames:</translation>
    </message>
    <message>
        <source>Frame rate:</source>
        <translation>Bildrate:</translation>
    </message>
    <message>
        <source>%1 Hz (the scene&apos;s world settings)</source>
        <translation>%1 Hz (aus den Welteinstellungen der Szene)</translation>
    </message>
    <message>
        <source>&amp;Bake</source>
        <translation>&amp;Backen</translation>
    </message>
    <message>
        <source>Records the simulation in the background, starting from the edit pose at the first frame; before it the bodies hold the edit pose. The timeline plays and scrubs the result.</source>
        <translation>Zeichnet die Simulation im Hintergrund auf, beginnend mit der Bearbeitungspose im ersten Frame; davor behalten die Körper die Bearbeitungspose. Die Zeitleiste spielt das Ergebnis ab und lässt darin navigieren.</translation>
    </message>
    <message>
        <source>to</source>
        <translation>bis</translation>
    </message>
</context>
<context>
    <name>rl::BakeDiffModel</name>
    <message>
        <source>NaN</source>
        <translation>NaN</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <source>Body</source>
        <translation>Körper</translation>
    </message>
    <message>
        <source>First diverging frame</source>
        <translation>Erster abweichender Frame</translation>
    </message>
    <message>
        <source>Max Δ position (mm)</source>
        <translation>Max. Δ Position (mm)</translation>
    </message>
    <message>
        <source>at frame</source>
        <translation>bei Frame</translation>
    </message>
    <message>
        <source>Max Δ rotation (°)</source>
        <translation>Max. Δ Drehung (°)</translation>
    </message>
</context>
<context>
    <name>rl::Commands</name>
    <message>
        <source>Add %1</source>
        <translation>%1 hinzufügen</translation>
    </message>
    <message>
        <source>Duplicate as %1</source>
        <translation>Als %1 duplizieren</translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation>%1 importieren</translation>
    </message>
    <message>
        <source>Delete %1</source>
        <translation>%1 löschen</translation>
    </message>
    <message>
        <source>Rename %1 to %2</source>
        <translation>%1 in %2 umbenennen</translation>
    </message>
    <message>
        <source>Rotate %1</source>
        <translation>%1 drehen</translation>
    </message>
    <message>
        <source>Move %1</source>
        <translation>%1 verschieben</translation>
    </message>
    <message numerus="yes">
        <source>Rotate %n bodies</source>
        <translation>
            <numerusform>%n Körper drehen</numerusform>
            <numerusform>%n Körper drehen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Move %n bodies</source>
        <translation>
            <numerusform>%n Körper verschieben</numerusform>
            <numerusform>%n Körper verschieben</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>rl::CompareBakesDialog</name>
    <message>
        <source>Compare Bakes</source>
        <translation>Backergebnisse vergleichen</translation>
    </message>
    <message>
        <source>Bakes</source>
        <translation>Backergebnisse</translation>
    </message>
    <message>
        <source>Current bake</source>
        <translation>Aktuelles Backergebnis</translation>
    </message>
    <message>
        <source>File A:</source>
        <translation>Datei A:</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Durchsuchen …</translation>
    </message>
    <message>
        <source>File B:</source>
        <translation>Datei B:</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source> °</source>
        <translation> °</translation>
    </message>
    <message>
        <source>&amp;Compare</source>
        <translation>&amp;Vergleichen</translation>
    </message>
    <message>
        <source>Tolerance:</source>
        <translation>Toleranz:</translation>
    </message>
    <message>
        <source>Choose two bakes and press Compare.</source>
        <translation>Wählen Sie zwei Backergebnisse und klicken Sie auf „Vergleichen“.</translation>
    </message>
    <message>
        <source>Open Bake</source>
        <translation>Backergebnis öffnen</translation>
    </message>
    <message>
        <source>Bake files (*.bake);;All files (*)</source>
        <translation>Bake-Dateien (*.bake);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Choose a .bake file.</source>
        <translation>Wählen Sie eine .bake-Datei.</translation>
    </message>
    <message>
        <source>There is no current bake: bake the scene or choose file A.</source>
        <translation>Es gibt kein aktuelles Backergebnis: Backen Sie die Szene oder wählen Sie Datei A.</translation>
    </message>
    <message>
        <source>&lt;b&gt;Cannot compare:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Vergleich nicht möglich:&lt;/b&gt; %1</translation>
    </message>
    <message>
        <source>&lt;b&gt;The bakes diverge at frame %1&lt;/b&gt; (t = %2 s), first in body %3 &apos;%4&apos;.</source>
        <translation>&lt;b&gt;Die Backergebnisse weichen ab Frame %1 voneinander ab&lt;/b&gt; (t = %2 s), zuerst bei Körper %3 „%4“.</translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;Equal within the tolerance&lt;/b&gt; over %n frame(s).</source>
        <translation>
            <numerusform>&lt;b&gt;Gleich innerhalb der Toleranz&lt;/b&gt; über %n Frame.</numerusform>
            <numerusform>&lt;b&gt;Gleich innerhalb der Toleranz&lt;/b&gt; über %n Frames.</numerusform>
        </translation>
    </message>
    <message>
        <source>The frame counts differ: %1 and %2; the first %3 were compared.</source>
        <translation>Die Anzahl der Frames unterscheidet sich: %1 und %2; die ersten %3 wurden verglichen.</translation>
    </message>
    <message>
        <source>%1 of %2 bodies differ by more than the tolerance.</source>
        <translation>%1 von %2 Körpern weichen stärker als die Toleranz ab.</translation>
    </message>
</context>
<context>
    <name>rl::CoreText</name>
    <message>
        <source>concave: simulated as its convex hull</source>
        <translation>konkav: wird als seine konvexe Hülle simuliert</translation>
    </message>
    <message>
        <source>smaller than 2 cm: may need more substeps</source>
        <translation>kleiner als 2 cm: braucht eventuell mehr Teilschritte</translation>
    </message>
    <message>
        <source>named as Blender&apos;s legacy OBJ exporter names an object Anchor whose mesh has another name (object_mesh), which the anchor rule makes dynamic: for an anchor, give the mesh the object&apos;s name or export with File &gt; Export &gt; Wavefront (.obj)</source>
        <translation>so benannt, wie Blenders alter OBJ-Exporter ein Objekt Anchor benennt, dessen Mesh anders heißt (Objekt_Mesh); nach der Anker-Regel ist es damit dynamisch: für einen Anker dem Mesh den Namen des Objekts geben oder mit Datei &gt; Exportieren &gt; Wavefront (.obj) exportieren</translation>
    </message>
    <message>
        <source>forced on</source>
        <translation>erzwungen ein</translation>
    </message>
    <message>
        <source>forced off</source>
        <translation>erzwungen aus</translation>
    </message>
    <message>
        <source>dynamic bodies and non-zero gravity</source>
        <translation>dynamische Körper und Schwerkraft ungleich null</translation>
    </message>
    <message>
        <source>no dynamic body or zero gravity</source>
        <translation>kein dynamischer Körper oder keine Schwerkraft</translation>
    </message>
    <message>
        <source>some pair has friction above zero</source>
        <translation>ein Paar hat Reibung über null</translation>
    </message>
    <message>
        <source>every pair&apos;s combined friction is zero</source>
        <translation>die kombinierte Reibung jedes Paars ist null</translation>
    </message>
    <message>
        <source>bodies can rotate</source>
        <translation>Körper können sich drehen</translation>
    </message>
    <message>
        <source>only frictionless, non-spinning spheres (rotation cannot change)</source>
        <translation>nur reibungsfreie, nicht rotierende Kugeln (die Drehung kann sich nicht ändern)</translation>
    </message>
    <message>
        <source>some pair has restitution above zero</source>
        <translation>ein Paar hat Restitution über null</translation>
    </message>
    <message>
        <source>every pair&apos;s combined restitution is zero</source>
        <translation>die kombinierte Restitution jedes Paars ist null</translation>
    </message>
    <message>
        <source>damping is set</source>
        <translation>Dämpfung ist gesetzt</translation>
    </message>
    <message>
        <source>no damping is set</source>
        <translation>keine Dämpfung gesetzt</translation>
    </message>
    <message>
        <source>bodies can come to rest on anchors</source>
        <translation>Körper können auf Ankern zur Ruhe kommen</translation>
    </message>
    <message>
        <source>nothing to come to rest on (no gravity or no anchor)</source>
        <translation>nichts, worauf Körper zur Ruhe kommen (keine Schwerkraft oder kein Anker)</translation>
    </message>
    <message>
        <source>some body may move more than half its size in one frame</source>
        <translation>ein Körper kann sich in einem Frame um mehr als seine halbe Größe bewegen</translation>
    </message>
    <message>
        <source>no body moves fast relative to its size</source>
        <translation>kein Körper ist schnell im Verhältnis zu seiner Größe</translation>
    </message>
</context>
<context>
    <name>rl::EditController</name>
    <message>
        <source>Edit</source>
        <translation>Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <source>&amp;Delete</source>
        <translation>&amp;Löschen</translation>
    </message>
    <message>
        <source>Delete the selected bodies</source>
        <translation>Die ausgewählten Körper löschen</translation>
    </message>
    <message>
        <source>Toggle &amp;Anchor</source>
        <translation>&amp;Anker umschalten</translation>
    </message>
    <message>
        <source>Make the selected bodies static, or dynamic again when all are static</source>
        <translation>Die ausgewählten Körper statisch machen, oder wieder dynamisch, wenn alle statisch sind</translation>
    </message>
    <message>
        <source>D&amp;uplicate</source>
        <translation>&amp;Duplizieren</translation>
    </message>
    <message>
        <source>Copy the selected bodies and move the copies with the mouse; click to place</source>
        <translation>Die ausgewählten Körper kopieren und die Kopien mit der Maus verschieben; Klicken setzt sie ab</translation>
    </message>
    <message>
        <source>Re&amp;name...</source>
        <translation>&amp;Umbenennen …</translation>
    </message>
    <message>
        <source>Rename the active body in the outliner</source>
        <translation>Den aktiven Körper in der Gliederung umbenennen</translation>
    </message>
    <message>
        <source>Select &amp;All</source>
        <translation>Alles au&amp;swählen</translation>
    </message>
    <message>
        <source>Select &amp;None</source>
        <translation>&amp;Nichts auswählen</translation>
    </message>
    <message>
        <source>&amp;Invert Selection</source>
        <translation>Auswahl &amp;invertieren</translation>
    </message>
    <message>
        <source>&amp;Grab</source>
        <translation>&amp;Greifen</translation>
    </message>
    <message>
        <source>Move the selection with the mouse in the view plane; click to confirm, Esc cancels</source>
        <translation>Die Auswahl mit der Maus in der Ansichtsebene verschieben; Klicken bestätigt, Esc bricht ab</translation>
    </message>
    <message>
        <source>R&amp;otate</source>
        <translation>Dr&amp;ehen</translation>
    </message>
    <message>
        <source>Turn the selection about the view axis with the mouse; click to confirm</source>
        <translation>Die Auswahl mit der Maus um die Blickachse drehen; Klicken bestätigt</translation>
    </message>
    <message>
        <source>&amp;Tool</source>
        <translation>Werk&amp;zeug</translation>
    </message>
    <message>
        <source>A&amp;dd</source>
        <translation>Hin&amp;zufügen</translation>
    </message>
    <message>
        <source>Add a %1 on the ground, or on top of the selection</source>
        <translation>%1 auf dem Boden oder auf der Auswahl hinzufügen</translation>
    </message>
    <message>
        <source>Add Menu</source>
        <translation>Menü „Hinzufügen“</translation>
    </message>
    <message>
        <source>&amp;Select</source>
        <translation>&amp;Auswählen</translation>
    </message>
    <message>
        <source>Select tool: click or drag a box to select</source>
        <translation>Auswahlwerkzeug: Klicken oder Rahmen aufziehen zum Auswählen</translation>
    </message>
    <message>
        <source>&amp;Move</source>
        <translation>&amp;Verschieben</translation>
    </message>
    <message>
        <source>Move tool: drag an arrow or a square of the gizmo; Ctrl snaps to 0.1 m</source>
        <translation>Verschieben: Einen Pfeil oder ein Quadrat des Gizmos ziehen; Strg rastet auf 0,1 m ein</translation>
    </message>
    <message>
        <source>&amp;Rotate</source>
        <translation>&amp;Drehen</translation>
    </message>
    <message>
        <source>Rotate tool: drag a ring of the gizmo; Ctrl snaps to 15 degrees</source>
        <translation>Drehen: Einen Ring des Gizmos ziehen; Strg rastet auf 15 Grad ein</translation>
    </message>
    <message>
        <source>Tools</source>
        <translation>Werkzeuge</translation>
    </message>
    <message>
        <source>Rename</source>
        <translation>Umbenennen</translation>
    </message>
    <message>
        <source>Unanchor</source>
        <translation>Verankerung lösen</translation>
    </message>
    <message>
        <source>Anchor</source>
        <translation>Verankern</translation>
    </message>
    <message>
        <source>Anchor %1</source>
        <translation>%1 verankern</translation>
    </message>
    <message>
        <source>Unanchor %1</source>
        <translation>Verankerung von %1 lösen</translation>
    </message>
    <message>
        <source>The body is hidden by the outliner&apos;s filter; clear it to rename.</source>
        <translation>Der Körper ist durch den Filter der Gliederung ausgeblendet; leeren Sie den Filter, um ihn umzubenennen.</translation>
    </message>
</context>
<context>
    <name>rl::ExportDialog</name>
    <message>
        <source>Export Bake</source>
        <translation>Backergebnis exportieren</translation>
    </message>
    <message>
        <source>RigidLab bake (.bake)</source>
        <translation>RigidLab-Backergebnis (.bake)</translation>
    </message>
    <message>
        <source>CSV table (.csv)</source>
        <translation>CSV-Tabelle (.csv)</translation>
    </message>
    <message>
        <source>&amp;Format:</source>
        <translation>&amp;Format:</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Durchsuchen …</translation>
    </message>
    <message>
        <source>&amp;File:</source>
        <translation>&amp;Datei:</translation>
    </message>
    <message>
        <source>CSV rows</source>
        <translation>CSV-Zeilen</translation>
    </message>
    <message numerus="yes">
        <source>All %n bodies</source>
        <translation>
            <numerusform>Alle Körper (%n)</numerusform>
            <numerusform>Alle Körper (%n)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Selected bodies (%n)</source>
        <translation>
            <numerusform>Ausgewählte Körper (%n)</numerusform>
            <numerusform>Ausgewählte Körper (%n)</numerusform>
        </translation>
    </message>
    <message>
        <source>Bodies:</source>
        <translation>Körper:</translation>
    </message>
    <message>
        <source>All frames (0 to %1)</source>
        <translation>Alle Frames (0 bis %1)</translation>
    </message>
    <message>
        <source>Frames</source>
        <translation>Frames</translation>
    </message>
    <message>
        <source>to</source>
        <translation>bis</translation>
    </message>
    <message>
        <source>Frames:</source>
        <translation>Frames:</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <source>%1 rows: %2 frames (%3 s to %4 s) × %5 bodies.</source>
        <translation>%1 Zeilen: %2 Frames (%3 s bis %4 s) × %5 Körper.</translation>
    </message>
    <message>
        <source>Centres of mass, rotations and velocities.</source>
        <translation>Massenschwerpunkte, Drehungen und Geschwindigkeiten.</translation>
    </message>
    <message>
        <source>Centres of mass and rotations; this bake was read from a .bake file, which holds no velocities, so those fields stay empty.</source>
        <translation>Massenschwerpunkte und Drehungen; dieses Backergebnis stammt aus einer .bake-Datei, die keine Geschwindigkeiten enthält, daher bleiben diese Felder leer.</translation>
    </message>
    <message>
        <source>Every body and frame (%1 × %2), with the scene as OBJ text, readable by the original project&apos;s reader.</source>
        <translation>Jeder Körper und Frame (%1 × %2), mit der Szene als OBJ-Text; das ursprüngliche Projekt kann die Datei lesen.</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
    <message>
        <source>Bake files (*.bake)</source>
        <translation>Bake-Dateien (*.bake)</translation>
    </message>
    <message>
        <source>Choose a file to export to.</source>
        <translation>Wählen Sie eine Datei für den Export.</translation>
    </message>
    <message>
        <source>The first frame (%1) is after the last (%2).</source>
        <translation>Der erste Frame (%1) liegt nach dem letzten (%2).</translation>
    </message>
</context>
<context>
    <name>rl::FileController</name>
    <message>
        <source>File</source>
        <translation>Datei</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Neu</translation>
    </message>
    <message>
        <source>Start an empty scene with the default world and materials</source>
        <translation>Eine leere Szene mit Standardwelt und -materialien beginnen</translation>
    </message>
    <message>
        <source>&amp;Open...</source>
        <translation>Ö&amp;ffnen …</translation>
    </message>
    <message>
        <source>Open a scene (.rlscene, OBJ, glTF, FBX, ...) or a .bake</source>
        <translation>Eine Szene (.rlscene, OBJ, glTF, FBX, …) oder eine .bake-Datei öffnen</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Öffnen</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>&amp;Import...</source>
        <translation>&amp;Importieren …</translation>
    </message>
    <message>
        <source>Add the bodies of other scene files to this scene</source>
        <translation>Die Körper anderer Szenendateien zu dieser Szene hinzufügen</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Importieren</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <source>Save the scene as .rlscene</source>
        <translation>Die Szene als .rlscene speichern</translation>
    </message>
    <message>
        <source>Save &amp;As...</source>
        <translation>Speichern &amp;unter …</translation>
    </message>
    <message>
        <source>Save the scene under a new name</source>
        <translation>Die Szene unter einem neuen Namen speichern</translation>
    </message>
    <message>
        <source>Re&amp;vert to Saved</source>
        <translation>Gespeicherte &amp;Version wiederherstellen</translation>
    </message>
    <message>
        <source>Drop the changes made since the last save</source>
        <translation>Die Änderungen seit dem letzten Speichern verwerfen</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>Quit RigidLab</source>
        <translation>RigidLab beenden</translation>
    </message>
    <message>
        <source>No Recent Files</source>
        <translation>Keine zuletzt geöffneten Dateien</translation>
    </message>
    <message>
        <source>&amp;Clear Recent Files</source>
        <translation>Liste &amp;leeren</translation>
    </message>
    <message>
        <source>Open Recent</source>
        <translation>Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>“%1” no longer exists.</source>
        <translation>„%1“ existiert nicht mehr.</translation>
    </message>
    <message>
        <source>It was moved, renamed or deleted, so it was removed from the recent files.

%1</source>
        <translation>Die Datei wurde verschoben, umbenannt oder gelöscht und daher aus der Liste der zuletzt geöffneten Dateien entfernt.

%1</translation>
    </message>
    <message>
        <source>New scene</source>
        <translation>Neue Szene</translation>
    </message>
    <message>
        <source>Could not open “%1”.</source>
        <translation>„%1“ konnte nicht geöffnet werden.</translation>
    </message>
    <message numerus="yes">
        <source>Opened %1: %n bodies</source>
        <translation>
            <numerusform>%1 geöffnet: %n Körper</numerusform>
            <numerusform>%1 geöffnet: %n Körper</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: the file holds no bodies</source>
        <translation>%1: Die Datei enthält keine Körper</translation>
    </message>
    <message>
        <source>Could not import “%1”.</source>
        <translation>„%1“ konnte nicht importiert werden.</translation>
    </message>
    <message numerus="yes">
        <source>%n of %1 files could not be imported.</source>
        <translation>
            <numerusform>%n von %1 Dateien konnte nicht importiert werden.</numerusform>
            <numerusform>%n von %1 Dateien konnten nicht importiert werden.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n files</source>
        <translation>
            <numerusform>%n Datei</numerusform>
            <numerusform>%n Dateien</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Imported %n bodies from %1</source>
        <translation>
            <numerusform>%n Körper aus %1 importiert</numerusform>
            <numerusform>%n Körper aus %1 importiert</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>; %n renamed to keep names unique</source>
        <translation>
            <numerusform>; %n umbenannt, damit die Namen eindeutig bleiben</numerusform>
            <numerusform>; %n umbenannt, damit die Namen eindeutig bleiben</numerusform>
        </translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <source>Save Scene As</source>
        <translation>Szene speichern unter</translation>
    </message>
    <message>
        <source>RigidLab scenes (*.rlscene)</source>
        <translation>RigidLab-Szenen (*.rlscene)</translation>
    </message>
    <message>
        <source>Could not save “%1”.</source>
        <translation>„%1“ konnte nicht gespeichert werden.</translation>
    </message>
    <message>
        <source>%1

Nothing was overwritten and your changes are still open. Try File &gt; Save As with another name or folder.</source>
        <translation>%1

Es wurde nichts überschrieben, und Ihre Änderungen sind noch geöffnet. Versuchen Sie Datei &gt; Speichern unter mit einem anderen Namen oder Ordner.</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Revert to Saved</source>
        <translation>Gespeicherte Version wiederherstellen</translation>
    </message>
    <message>
        <source>Revert “%1” to the saved version?</source>
        <translation>„%1“ auf die gespeicherte Version zurücksetzen?</translation>
    </message>
    <message>
        <source>The changes since the last save are undone; Redo brings them back.</source>
        <translation>Die Änderungen seit dem letzten Speichern werden rückgängig gemacht; „Wiederholen“ holt sie zurück.</translation>
    </message>
    <message>
        <source>The file is read again; the changes since the last save are lost.</source>
        <translation>Die Datei wird neu eingelesen; die Änderungen seit dem letzten Speichern gehen verloren.</translation>
    </message>
    <message>
        <source>&amp;Revert</source>
        <translation>&amp;Zurücksetzen</translation>
    </message>
    <message>
        <source>Reverted to the saved %1</source>
        <translation>Auf die gespeicherte Version von %1 zurückgesetzt</translation>
    </message>
    <message>
        <source>RigidLab cannot open %1.</source>
        <translation>RigidLab kann %1 nicht öffnen.</translation>
    </message>
    <message>
        <source>It opens scenes (.rlscene, OBJ, glTF, FBX, COLLADA, PLY, STL, 3DS) and .bake files.</source>
        <translation>Geöffnet werden Szenen (.rlscene, OBJ, glTF, FBX, COLLADA, PLY, STL, 3DS) und .bake-Dateien.</translation>
    </message>
    <message>
        <source>Ignored: %1 (only one bake opens, and never together with scenes)</source>
        <translation>Ignoriert: %1 (nur ein Backergebnis lässt sich öffnen, und nie zusammen mit Szenen)</translation>
    </message>
    <message>
        <source>Do you want to save the changes to “%1” before closing?</source>
        <translation>Möchten Sie die Änderungen an „%1“ vor dem Schließen speichern?</translation>
    </message>
    <message>
        <source>Do you want to save the changes to “%1” before starting a new scene?</source>
        <translation>Möchten Sie die Änderungen an „%1“ speichern, bevor Sie eine neue Szene beginnen?</translation>
    </message>
    <message>
        <source>Do you want to save the changes to “%1” before opening another scene?</source>
        <translation>Möchten Sie die Änderungen an „%1“ speichern, bevor Sie eine andere Szene öffnen?</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <source>Your changes will be lost if you don&apos;t save them.</source>
        <translation>Ihre Änderungen gehen verloren, wenn Sie sie nicht speichern.</translation>
    </message>
    <message>
        <source>Autosave failed: %1</source>
        <translation>Automatisches Speichern fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Autosaved unsaved changes at %1</source>
        <translation>Ungespeicherte Änderungen um %1 automatisch gesichert</translation>
    </message>
    <message>
        <source>Recover Unsaved Work</source>
        <translation>Ungespeicherte Arbeit wiederherstellen</translation>
    </message>
    <message>
        <source>RigidLab did not close normally. Unsaved changes to “%1” were autosaved on %2.</source>
        <translation>RigidLab wurde nicht normal beendet. Ungespeicherte Änderungen an „%1“ wurden am %2 automatisch gesichert.</translation>
    </message>
    <message>
        <source>Restore opens them as an unsaved scene; Discard deletes the autosaved copy; Not Now keeps it for the next start.</source>
        <translation>„Wiederherstellen“ öffnet sie als ungespeicherte Szene; „Verwerfen“ löscht die gesicherte Kopie; „Nicht jetzt“ behält sie für den nächsten Start.</translation>
    </message>
    <message>
        <source>&amp;Restore</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <source>&amp;Not Now</source>
        <translation>&amp;Nicht jetzt</translation>
    </message>
    <message>
        <source>Could not restore the autosaved copy.</source>
        <translation>Die automatisch gesicherte Kopie konnte nicht wiederhergestellt werden.</translation>
    </message>
    <message>
        <source>%1

The copy was kept at %2.</source>
        <translation>%1

Die Kopie wurde unter %2 behalten.</translation>
    </message>
    <message>
        <source>Restored unsaved changes to %1</source>
        <translation>Ungespeicherte Änderungen an %1 wiederhergestellt</translation>
    </message>
    <message>
        <source>Scenes (%1)</source>
        <translation>Szenen (%1)</translation>
    </message>
    <message>
        <source>Scenes and bakes (%1 *.bake)</source>
        <translation>Szenen und Backergebnisse (%1 *.bake)</translation>
    </message>
    <message>
        <source>Bakes (*.bake)</source>
        <translation>Backergebnisse (*.bake)</translation>
    </message>
    <message>
        <source>Wavefront OBJ (*.obj)</source>
        <translation>Wavefront OBJ (*.obj)</translation>
    </message>
    <message>
        <source>All files (*)</source>
        <translation>Alle Dateien (*)</translation>
    </message>
    <message>
        <source>RigidLab</source>
        <translation>RigidLab</translation>
    </message>
    <message>
        <source>Unsaved changes to “%1” from a session that did not close normally were kept; start RigidLab without a file to restore them.</source>
        <translation>Ungespeicherte Änderungen an „%1“ aus einer nicht normal beendeten Sitzung wurden aufbewahrt; starten Sie RigidLab ohne Datei, um sie wiederherzustellen.</translation>
    </message>
</context>
<context>
    <name>rl::InspectorWidget</name>
    <message>
        <source>Select a body to inspect it.</source>
        <translation>Wählen Sie einen Körper aus, um seine Eigenschaften zu sehen.</translation>
    </message>
    <message>
        <source>Body</source>
        <translation>Körper</translation>
    </message>
    <message>
        <source>Rename</source>
        <translation>Umbenennen</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Static (does not move)</source>
        <translation>Statisch (bewegt sich nicht)</translation>
    </message>
    <message>
        <source>Anchor</source>
        <translation>Verankern</translation>
    </message>
    <message>
        <source>Unanchor</source>
        <translation>Verankerung lösen</translation>
    </message>
    <message>
        <source>Set Material</source>
        <translation>Material festlegen</translation>
    </message>
    <message>
        <source>Material</source>
        <translation>Material</translation>
    </message>
    <message>
        <source>Overrides</source>
        <translation>Überschreibungen</translation>
    </message>
    <message>
        <source> kg/m³</source>
        <translation> kg/m³</translation>
    </message>
    <message>
        <source>Set Density</source>
        <translation>Dichte festlegen</translation>
    </message>
    <message>
        <source>Density must be above 0 kg/m³.</source>
        <translation>Die Dichte muss größer als 0 kg/m³ sein.</translation>
    </message>
    <message>
        <source> kg</source>
        <translation> kg</translation>
    </message>
    <message>
        <source>Set Mass</source>
        <translation>Masse festlegen</translation>
    </message>
    <message>
        <source>Mass must be above 0 kg.</source>
        <translation>Die Masse muss größer als 0 kg sein.</translation>
    </message>
    <message>
        <source>Set Friction</source>
        <translation>Reibung festlegen</translation>
    </message>
    <message>
        <source>Friction must be 0 or more.</source>
        <translation>Die Reibung muss 0 oder größer sein.</translation>
    </message>
    <message>
        <source>Set Restitution</source>
        <translation>Restitution festlegen</translation>
    </message>
    <message>
        <source>Restitution must be between 0 (no bounce) and 1 (elastic).</source>
        <translation>Die Restitution muss zwischen 0 (kein Abprallen) und 1 (elastisch) liegen.</translation>
    </message>
    <message>
        <source>Density</source>
        <translation>Dichte</translation>
    </message>
    <message>
        <source>Mass</source>
        <translation>Masse</translation>
    </message>
    <message>
        <source>Friction</source>
        <translation>Reibung</translation>
    </message>
    <message>
        <source>Restitution</source>
        <translation>Restitution</translation>
    </message>
    <message>
        <source>Placement</source>
        <translation>Platzierung</translation>
    </message>
    <message>
        <source>Move</source>
        <translation>Verschieben</translation>
    </message>
    <message>
        <source>Rotate</source>
        <translation>Drehen</translation>
    </message>
    <message>
        <source>Position (m)</source>
        <translation>Position (m)</translation>
    </message>
    <message>
        <source>Rotation XYZ (°)</source>
        <translation>Drehung XYZ (°)</translation>
    </message>
    <message>
        <source>Initial motion</source>
        <translation>Anfangsbewegung</translation>
    </message>
    <message>
        <source>Set Velocity</source>
        <translation>Geschwindigkeit festlegen</translation>
    </message>
    <message>
        <source>Set Angular Velocity</source>
        <translation>Winkelgeschwindigkeit festlegen</translation>
    </message>
    <message>
        <source>Velocity (m/s)</source>
        <translation>Geschw. (m/s)</translation>
    </message>
    <message>
        <source>Angular velocity (rad/s)</source>
        <translation>Winkelgeschw. (rad/s)</translation>
    </message>
    <message>
        <source>Computed</source>
        <translation>Berechnet</translation>
    </message>
    <message>
        <source>Volume</source>
        <translation>Volumen</translation>
    </message>
    <message>
        <source>Centre of mass</source>
        <translation>Schwerpunkt</translation>
    </message>
    <message>
        <source>Principal inertia</source>
        <translation>Hauptträgheitsmomente</translation>
    </message>
    <message>
        <source>Hull vertices</source>
        <translation>Hüllenpunkte</translation>
    </message>
    <message>
        <source>Warnings</source>
        <translation>Warnungen</translation>
    </message>
    <message>
        <source>%1 m³ (total)</source>
        <translation>%1 m³ (gesamt)</translation>
    </message>
    <message>
        <source>%1 kg (total)</source>
        <translation>%1 kg (gesamt)</translation>
    </message>
    <message numerus="yes">
        <source>%n bodies cannot be simulated</source>
        <translation>
            <numerusform>%n Körper kann nicht simuliert werden</numerusform>
            <numerusform>%n Körper können nicht simuliert werden</numerusform>
        </translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>%1 m³</source>
        <translation>%1 m³</translation>
    </message>
    <message>
        <source>%1 kg</source>
        <translation>%1 kg</translation>
    </message>
    <message>
        <source>%1 kg m²</source>
        <translation>%1 kg m²</translation>
    </message>
    <message>
        <source>none (sphere)</source>
        <translation>keine (Kugel)</translation>
    </message>
</context>
<context>
    <name>rl::MainWindow</name>
    <message>
        <source>&amp;About RigidLab</source>
        <translation>&amp;Über RigidLab</translation>
    </message>
    <message>
        <source>About RigidLab</source>
        <translation>Über RigidLab</translation>
    </message>
    <message>
        <source>&lt;b&gt;RigidLab&lt;/b&gt; %1&lt;br&gt;An editor and simulator for 3D rigid-body scenes.</source>
        <translation>&lt;b&gt;RigidLab&lt;/b&gt; %1&lt;br&gt;Ein Editor und Simulator für 3D-Starrkörperszenen.</translation>
    </message>
    <message>
        <source>nothing selected</source>
        <translation>nichts ausgewählt</translation>
    </message>
    <message>
        <source>frame %1 ms</source>
        <translation>Framezeit %1 ms</translation>
    </message>
    <message>
        <source>Outliner</source>
        <translation>Gliederung</translation>
    </message>
    <message>
        <source>Filter by name</source>
        <translation>Nach Namen filtern</translation>
    </message>
    <message>
        <source>Inspector</source>
        <translation>Eigenschaften</translation>
    </message>
    <message>
        <source>History</source>
        <translation>Verlauf</translation>
    </message>
    <message>
        <source>&lt;opened scene&gt;</source>
        <translation>&lt;geöffnete Szene&gt;</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>A&amp;dd</source>
        <translation>Hin&amp;zufügen</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>Ans&amp;icht</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulation</translation>
    </message>
    <message>
        <source>A&amp;nalysis</source>
        <translation>Ana&amp;lyse</translation>
    </message>
    <message>
        <source>&amp;Window</source>
        <translation>&amp;Fenster</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Exportieren</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <source>System default</source>
        <translation>Systemstandard</translation>
    </message>
    <message>
        <source>The language changes when RigidLab is restarted.</source>
        <translation>Die Sprache ändert sich beim nächsten Start von RigidLab.</translation>
    </message>
    <message>
        <source>selected: %1</source>
        <translation>ausgewählt: %1</translation>
    </message>
    <message numerus="yes">
        <source>%n selected</source>
        <translation>
            <numerusform>%n ausgewählt</numerusform>
            <numerusform>%n ausgewählt</numerusform>
        </translation>
    </message>
    <message>
        <source>%1[*] - RigidLab</source>
        <translation>%1[*] – RigidLab</translation>
    </message>
    <message numerus="yes">
        <source>%n bodies</source>
        <translation>
            <numerusform>%n Körper</numerusform>
            <numerusform>%n Körper</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n anchors</source>
        <translation>
            <numerusform>%n Anker</numerusform>
            <numerusform>%n Anker</numerusform>
        </translation>
    </message>
    <message>
        <source>Frame &amp;Selected	F</source>
        <translation>&amp;Auswahl zeigen	F</translation>
    </message>
    <message>
        <source>Frame &amp;All	Home</source>
        <translation>A&amp;lles zeigen	Home</translation>
    </message>
</context>
<context>
    <name>rl::MaterialLibrary</name>
    <message>
        <source>A material needs a name.</source>
        <translation>Ein Material braucht einen Namen.</translation>
    </message>
    <message>
        <source>The name &quot;%1&quot; starts or ends with a space.</source>
        <translation>Der Name „%1“ beginnt oder endet mit einem Leerzeichen.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is a built-in preset and keeps its name; duplicate it to make a material of your own.</source>
        <translation>„%1“ ist eine eingebaute Vorgabe und behält ihren Namen; duplizieren Sie sie für ein eigenes Material.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is the name of a built-in preset; choose another name.</source>
        <translation>„%1“ ist der Name einer eingebauten Vorgabe; wählen Sie einen anderen Namen.</translation>
    </message>
    <message>
        <source>The library already has a material called &quot;%1&quot;.</source>
        <translation>Die Bibliothek enthält bereits ein Material „%1“.</translation>
    </message>
    <message>
        <source>Density of &quot;%1&quot; must be above 0 and at most %2 kg/m³ (got %3).</source>
        <translation>Die Dichte von „%1“ muss größer als 0 und höchstens %2 kg/m³ sein (erhalten: %3).</translation>
    </message>
    <message>
        <source>Friction of &quot;%1&quot; must be between 0 and %2 (got %3).</source>
        <translation>Die Reibung von „%1“ muss zwischen 0 und %2 liegen (erhalten: %3).</translation>
    </message>
    <message>
        <source>Restitution of &quot;%1&quot; must be between 0 (no bounce) and 1 (elastic) (got %2).</source>
        <translation>Die Restitution von „%1“ muss zwischen 0 (kein Abprallen) und 1 (elastisch) liegen (erhalten: %2).</translation>
    </message>
    <message>
        <source>geometric mean</source>
        <translation>geometrisches Mittel</translation>
    </message>
    <message>
        <source>average</source>
        <translation>Mittelwert</translation>
    </message>
    <message>
        <source>minimum</source>
        <translation>Minimum</translation>
    </message>
    <message>
        <source>maximum</source>
        <translation>Maximum</translation>
    </message>
    <message>
        <source>product</source>
        <translation>Produkt</translation>
    </message>
</context>
<context>
    <name>rl::MaterialLibraryModel</name>
    <message>
        <source>Built-in preset, changed for this scene (built-in: %1 kg/m³, friction %2, restitution %3).</source>
        <translation>Eingebaute Vorgabe, für diese Szene geändert (eingebaut: %1 kg/m³, Reibung %2, Restitution %3).</translation>
    </message>
    <message>
        <source>Built-in preset</source>
        <translation>Eingebaute Vorgabe</translation>
    </message>
    <message>
        <source>Material of this scene</source>
        <translation>Material dieser Szene</translation>
    </message>
    <message>
        <source>Material</source>
        <translation>Material</translation>
    </message>
    <message>
        <source>kg/m³</source>
        <translation>kg/m³</translation>
    </message>
    <message>
        <source>μ</source>
        <translation>μ</translation>
    </message>
    <message>
        <source>e</source>
        <translation>e</translation>
    </message>
    <message>
        <source>Bodies</source>
        <translation>Körper</translation>
    </message>
    <message>
        <source>Density in kg/m³</source>
        <translation>Dichte in kg/m³</translation>
    </message>
    <message>
        <source>Coulomb friction coefficient</source>
        <translation>Coulombscher Reibungskoeffizient</translation>
    </message>
    <message>
        <source>Restitution: 0 = no bounce, 1 = elastic</source>
        <translation>Restitution: 0 = kein Abprallen, 1 = elastisch</translation>
    </message>
    <message>
        <source>Bodies (anchors included) that use the material</source>
        <translation>Körper (einschließlich Anker), die das Material verwenden</translation>
    </message>
</context>
<context>
    <name>rl::MaterialPairModel</name>
    <message>
        <source>%1 on %2
friction %3 = %4
restitution %5 = %6</source>
        <translation>%1 auf %2
Reibung %3 = %4
Restitution %5 = %6</translation>
    </message>
</context>
<context>
    <name>rl::MaterialsWidget</name>
    <message>
        <source>1 body</source>
        <translation>1 Körper</translation>
    </message>
    <message>
        <source>%1 bodies</source>
        <translation>%1 Körper</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Hinzufügen</translation>
    </message>
    <message>
        <source>Add a new material</source>
        <translation>Ein neues Material hinzufügen</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Duplizieren</translation>
    </message>
    <message>
        <source>Add a copy of the selected material</source>
        <translation>Eine Kopie des ausgewählten Materials hinzufügen</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <source>Delete the selected material; bodies that use it move to Default</source>
        <translation>Das ausgewählte Material löschen; Körper, die es verwenden, erhalten „Default“</translation>
    </message>
    <message>
        <source>Reset preset</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <source>Give the selected preset its built-in values back</source>
        <translation>Der ausgewählten Vorgabe ihre eingebauten Werte zurückgeben</translation>
    </message>
    <message>
        <source>Selected material</source>
        <translation>Ausgewähltes Material</translation>
    </message>
    <message>
        <source>Rename Material</source>
        <translation>Material umbenennen</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source> kg/m³</source>
        <translation> kg/m³</translation>
    </message>
    <message>
        <source>Mass per volume; above 0, at most %1 kg/m³</source>
        <translation>Masse pro Volumen; größer als 0, höchstens %1 kg/m³</translation>
    </message>
    <message>
        <source>Set Material Density</source>
        <translation>Materialdichte festlegen</translation>
    </message>
    <message>
        <source>Density</source>
        <translation>Dichte</translation>
    </message>
    <message>
        <source>Coulomb friction coefficient μ, 0 to %1</source>
        <translation>Coulombscher Reibungskoeffizient μ, 0 bis %1</translation>
    </message>
    <message>
        <source>Set Material Friction</source>
        <translation>Materialreibung festlegen</translation>
    </message>
    <message>
        <source>Friction μ</source>
        <translation>Reibung μ</translation>
    </message>
    <message>
        <source>Restitution e: 0 = no bounce, 1 = elastic</source>
        <translation>Restitution e: 0 = kein Abprallen, 1 = elastisch</translation>
    </message>
    <message>
        <source>Set Material Restitution</source>
        <translation>Materialrestitution festlegen</translation>
    </message>
    <message>
        <source>Restitution e</source>
        <translation>Restitution e</translation>
    </message>
    <message>
        <source>Library</source>
        <translation>Bibliothek</translation>
    </message>
    <message>
        <source>Contact pairs</source>
        <translation>Kontaktpaare</translation>
    </message>
    <message>
        <source>Friction and restitution of every pair of materials the scene&apos;s bodies use</source>
        <translation>Reibung und Restitution jedes Materialpaars, das die Körper der Szene verwenden</translation>
    </message>
    <message>
        <source>Presets keep their names; duplicate one to make your own</source>
        <translation>Vorgaben behalten ihre Namen; duplizieren Sie eine für ein eigenes Material</translation>
    </message>
    <message>
        <source>No body uses it.</source>
        <translation>Kein Körper verwendet es.</translation>
    </message>
    <message>
        <source>Used by %1.</source>
        <translation>Für %1 verwendet.</translation>
    </message>
    <message>
        <source>Built-in preset, changed for this scene (built-in: %1 kg/m³, μ %2, e %3). %4</source>
        <translation>Eingebaute Vorgabe, für diese Szene geändert (eingebaut: %1 kg/m³, μ %2, e %3). %4</translation>
    </message>
    <message>
        <source>Built-in preset; changes apply to this scene only. %1</source>
        <translation>Eingebaute Vorgabe; Änderungen gelten nur für diese Szene. %1</translation>
    </message>
    <message>
        <source>Material of this scene. %1</source>
        <translation>Material dieser Szene. %1</translation>
    </message>
    <message>
        <source>Presets cannot be deleted; Reset preset gives back their built-in values</source>
        <translation>Vorgaben lassen sich nicht löschen; „Zurücksetzen“ stellt ihre eingebauten Werte wieder her</translation>
    </message>
    <message>
        <source>Each cell: friction μ / restitution e. μ = %1 (%2), e = %3 (%4); World settings choose the rules.</source>
        <translation>Jede Zelle: Reibung μ / Restitution e. μ = %1 (%2), e = %3 (%4); die Regeln legen die Welteinstellungen fest.</translation>
    </message>
    <message>
        <source>No bodies in the scene.</source>
        <translation>Keine Körper in der Szene.</translation>
    </message>
    <message>
        <source>Not included: %1 with their own friction or restitution (set in the inspector).</source>
        <translation>Nicht enthalten: %1 mit eigener Reibung oder Restitution (in den Eigenschaften festgelegt).</translation>
    </message>
    <message>
        <source>Renamed &quot;%1&quot; to &quot;%2&quot; on %3 too.</source>
        <translation>„%1“ auch für %3 in „%2“ umbenannt.</translation>
    </message>
    <message>
        <source>Material</source>
        <translation>Material</translation>
    </message>
    <message>
        <source>Add Material</source>
        <translation>Material hinzufügen</translation>
    </message>
    <message>
        <source>%1 copy</source>
        <translation>%1-Kopie</translation>
    </message>
    <message>
        <source>Duplicate Material</source>
        <translation>Material duplizieren</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is a built-in preset and cannot be deleted; Reset preset gives back its built-in values.</source>
        <translation>„%1“ ist eine eingebaute Vorgabe und kann nicht gelöscht werden; „Zurücksetzen“ stellt ihre eingebauten Werte wieder her.</translation>
    </message>
    <message>
        <source>Delete Material %1</source>
        <translation>Material %1 löschen</translation>
    </message>
    <message>
        <source>Deleted &quot;%1&quot;; no body used it.</source>
        <translation>„%1“ gelöscht; kein Körper hat es verwendet.</translation>
    </message>
    <message>
        <source>Deleted &quot;%1&quot; and moved the %2 that used it to Default (Undo brings it back).</source>
        <translation>„%1“ gelöscht und durch „Default“ ersetzt für %2 („Rückgängig“ stellt es wieder her).</translation>
    </message>
    <message>
        <source>Reset Preset %1</source>
        <translation>Vorgabe %1 zurücksetzen</translation>
    </message>
</context>
<context>
    <name>rl::MessageBar</name>
    <message>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
</context>
<context>
    <name>rl::OutlinerModel</name>
    <message>
        <source>%1 (anchor: static)</source>
        <translation>%1 (Anker: statisch)</translation>
    </message>
    <message>
        <source>%1 (dynamic)</source>
        <translation>%1 (dynamisch)</translation>
    </message>
    <message>
        <source>Anchored (static): click to make it dynamic</source>
        <translation>Verankert (statisch): Klicken macht ihn dynamisch</translation>
    </message>
    <message>
        <source>Dynamic: click to anchor it</source>
        <translation>Dynamisch: Klicken verankert ihn</translation>
    </message>
    <message>
        <source>anchored</source>
        <translation>verankert</translation>
    </message>
    <message>
        <source>dynamic</source>
        <translation>dynamisch</translation>
    </message>
    <message>
        <source>Anchor: click a row&apos;s pin to make that body static or dynamic</source>
        <translation>Anker: Klick auf die Nadel einer Zeile macht den Körper statisch oder dynamisch</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Material</source>
        <translation>Material</translation>
    </message>
    <message>
        <source>A body needs a name.</source>
        <translation>Ein Körper braucht einen Namen.</translation>
    </message>
    <message>
        <source>Another body is already called &quot;%1&quot;. Names must be unique.</source>
        <translation>Ein anderer Körper heißt bereits „%1“. Namen müssen eindeutig sein.</translation>
    </message>
    <message>
        <source>Rename %1 to %2</source>
        <translation>%1 in %2 umbenennen</translation>
    </message>
</context>
<context>
    <name>rl::OverlayController</name>
    <message>
        <source>&amp;Contact Points and Normals</source>
        <translation>&amp;Kontaktpunkte und Normalen</translation>
    </message>
    <message>
        <source>Show contact points and their normals</source>
        <translation>Kontaktpunkte und ihre Normalen anzeigen</translation>
    </message>
    <message>
        <source>&amp;Velocities</source>
        <translation>&amp;Geschwindigkeiten</translation>
    </message>
    <message>
        <source>Show an arrow per body along its velocity, longer the faster it moves (capped)</source>
        <translation>Einen Pfeil je Körper in Richtung seiner Geschwindigkeit zeigen, länger je schneller (begrenzt)</translation>
    </message>
    <message>
        <source>Centres of &amp;Mass</source>
        <translation>&amp;Massenschwerpunkte</translation>
    </message>
    <message>
        <source>Mark each body&apos;s centre of mass with a cross</source>
        <translation>Den Massenschwerpunkt jedes Körpers mit einem Kreuz markieren</translation>
    </message>
    <message>
        <source>&amp;Bounding Boxes</source>
        <translation>&amp;Hüllquader</translation>
    </message>
    <message>
        <source>Show each body&apos;s axis-aligned bounding box (AABB)</source>
        <translation>Den achsenparallelen Hüllquader (AABB) jedes Körpers anzeigen</translation>
    </message>
    <message>
        <source>&amp;Sleeping Bodies</source>
        <translation>&amp;Schlafende Körper</translation>
    </message>
    <message>
        <source>Draw sleeping bodies washed out</source>
        <translation>Schlafende Körper blass zeichnen</translation>
    </message>
    <message>
        <source>Motion &amp;Trails of the Selection</source>
        <translation>Bewegungsspuren der &amp;Auswahl</translation>
    </message>
    <message>
        <source>Trace the path of the selected bodies over the last frames</source>
        <translation>Den Weg der ausgewählten Körper über die letzten Frames nachzeichnen</translation>
    </message>
    <message>
        <source>&amp;Overlays</source>
        <translation>&amp;Überlagerungen</translation>
    </message>
    <message>
        <source>Show &amp;Legend</source>
        <translation>&amp;Legende anzeigen</translation>
    </message>
    <message>
        <source>Explain the overlay colours in a corner of the viewport</source>
        <translation>Die Farben der Überlagerungen in einer Ecke des Ansichtsfensters erklären</translation>
    </message>
    <message>
        <source>Contact point</source>
        <translation>Kontaktpunkt</translation>
    </message>
    <message>
        <source>Contact normal</source>
        <translation>Kontaktnormale</translation>
    </message>
    <message>
        <source>Velocity</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>Centre of mass</source>
        <translation>Massenschwerpunkt</translation>
    </message>
    <message>
        <source>Bounding box</source>
        <translation>Hüllquader</translation>
    </message>
    <message>
        <source>Sleeping (washed out)</source>
        <translation>Schlafend (blass)</translation>
    </message>
    <message>
        <source>Trail of the selection</source>
        <translation>Spur der Auswahl</translation>
    </message>
</context>
<context>
    <name>rl::PreflightDialog</name>
    <message>
        <source>Very small body</source>
        <translation>Sehr kleiner Körper</translation>
    </message>
    <message>
        <source>May pass through</source>
        <translation>Kann durchdringen</translation>
    </message>
    <message>
        <source>Concave body</source>
        <translation>Konkaver Körper</translation>
    </message>
    <message>
        <source>Extreme mass ratio</source>
        <translation>Extremes Massenverhältnis</translation>
    </message>
    <message>
        <source>Cannot be simulated</source>
        <translation>Nicht simulierbar</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is %2 cm across, below %3 cm.</source>
        <translation>„%1“ misst %2 cm, weniger als %3 cm.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; may reach %2 m/s and move %3 m per frame, more than its thickness of %4 m.</source>
        <translation>„%1“ kann %2 m/s erreichen und sich %3 m pro Frame bewegen, mehr als seine Dicke von %4 m.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; is concave: it collides as its convex hull, so its hollows are filled.</source>
        <translation>„%1“ ist konkav: Er kollidiert als seine konvexe Hülle, Vertiefungen sind also gefüllt.</translation>
    </message>
    <message>
        <source>&apos;%1&apos; touches &apos;%2&apos; at the start; &apos;%2&apos; is %3 times heavier.</source>
        <translation>„%1“ berührt zu Beginn „%2“; „%2“ ist %3-mal schwerer.</translation>
    </message>
    <message>
        <source>Coordinates are metres: if the model was made in centimetres, scale it up by 100. Contacts start 2 cm before bodies touch, so smaller bodies jitter and sink.</source>
        <translation>Koordinaten sind Meter: Wurde das Modell in Zentimetern erstellt, skalieren Sie es mit 100. Kontakte beginnen 2 cm, bevor sich Körper berühren, daher zittern und sinken kleinere Körper.</translation>
    </message>
    <message>
        <source>CCD is switched off for this scene: turn it back on, or raise the frame rate to at least %1 fps, or make the body thicker.</source>
        <translation>CCD ist für diese Szene ausgeschaltet: Schalten Sie es wieder ein, erhöhen Sie die Bildrate auf mindestens %1 fps oder machen Sie den Körper dicker.</translation>
    </message>
    <message>
        <source>CCD sweeps such bodies; to be safe without it, raise the frame rate to at least %1 fps or make the body thicker.</source>
        <translation>CCD verfolgt solche Körper über den ganzen Weg; um auch ohne CCD sicher zu sein, erhöhen Sie die Bildrate auf mindestens %1 fps oder machen Sie den Körper dicker.</translation>
    </message>
    <message>
        <source>Split it into convex parts in Blender (one object each), make it an anchor, or accept the hull.</source>
        <translation>Zerlegen Sie ihn in Blender in konvexe Teile (je ein Objekt), machen Sie ihn zum Anker oder akzeptieren Sie die Hülle.</translation>
    </message>
    <message>
        <source>Bring the masses closer (below %1:1), or raise substeps and iterations; otherwise the lighter body may sink or jitter.</source>
        <translation>Gleichen Sie die Massen an (unter %1:1) oder erhöhen Sie Teilschritte und Iterationen; sonst kann der leichtere Körper einsinken oder zittern.</translation>
    </message>
    <message>
        <source>Fix the body&apos;s shape, size or mass; the bake cannot run with it.</source>
        <translation>Korrigieren Sie Form, Größe oder Masse des Körpers; so kann nicht gebacken werden.</translation>
    </message>
    <message>
        <source>Pre-flight check</source>
        <translation>Vorabprüfung</translation>
    </message>
    <message>
        <source>No problems found in this scene.</source>
        <translation>In dieser Szene wurden keine Probleme gefunden.</translation>
    </message>
    <message numerus="yes">
        <source>%n finding(s) in this scene may make the bake inaccurate or unstable. Bake anyway?</source>
        <translation>
            <numerusform>%n Befund in dieser Szene kann das Backergebnis ungenau oder instabil machen. Trotzdem backen?</numerusform>
            <numerusform>%n Befunde in dieser Szene können das Backergebnis ungenau oder instabil machen. Trotzdem backen?</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n finding(s) in this scene may make a bake inaccurate or unstable.</source>
        <translation>
            <numerusform>%n Befund in dieser Szene kann ein Backergebnis ungenau oder instabil machen.</numerusform>
            <numerusform>%n Befunde in dieser Szene können ein Backergebnis ungenau oder instabil machen.</numerusform>
        </translation>
    </message>
    <message>
        <source>Problem</source>
        <translation>Problem</translation>
    </message>
    <message>
        <source>Body</source>
        <translation>Körper</translation>
    </message>
    <message>
        <source>Details</source>
        <translation>Details</translation>
    </message>
    <message>
        <source>Fix: %1</source>
        <translation>Abhilfe: %1</translation>
    </message>
    <message>
        <source>&lt;b&gt;Suggested fix for &apos;%1&apos;:&lt;/b&gt; %2</source>
        <translation>&lt;b&gt;Vorgeschlagene Abhilfe für „%1“:&lt;/b&gt; %2</translation>
    </message>
    <message>
        <source>Don&apos;t show again for this scene</source>
        <translation>Für diese Szene nicht mehr anzeigen</translation>
    </message>
    <message>
        <source>Bake anyway</source>
        <translation>Trotzdem backen</translation>
    </message>
</context>
<context>
    <name>rl::Primitives</name>
    <message>
        <source>&amp;Cube</source>
        <translation>&amp;Würfel</translation>
    </message>
    <message>
        <source>&amp;Sphere</source>
        <translation>&amp;Kugel</translation>
    </message>
    <message>
        <source>C&amp;ylinder</source>
        <translation>&amp;Zylinder</translation>
    </message>
    <message>
        <source>C&amp;one</source>
        <translation>K&amp;egel</translation>
    </message>
</context>
<context>
    <name>rl::RecoveryStore</name>
    <message>
        <source>%1: cannot create the folder</source>
        <translation>%1: Der Ordner kann nicht angelegt werden</translation>
    </message>
</context>
<context>
    <name>rl::SceneDocument</name>
    <message>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
</context>
<context>
    <name>rl::SettingsController</name>
    <message>
        <source>World</source>
        <translation>Welt</translation>
    </message>
    <message>
        <source>Materials</source>
        <translation>Materialien</translation>
    </message>
    <message>
        <source>&amp;World Settings</source>
        <translation>&amp;Welteinstellungen</translation>
    </message>
    <message>
        <source>&amp;Materials</source>
        <translation>&amp;Materialien</translation>
    </message>
</context>
<context>
    <name>rl::SimulationController</name>
    <message>
        <source>Timeline</source>
        <translation>Zeitleiste</translation>
    </message>
    <message numerus="yes">
        <source>The bake has %n bodies and the scene %1: re-bake to scrub it.</source>
        <translation>
            <numerusform>Das Backergebnis hat %n Körper und die Szene %1: Neu backen, um darin zu navigieren.</numerusform>
            <numerusform>Das Backergebnis hat %n Körper und die Szene %1: Neu backen, um darin zu navigieren.</numerusform>
        </translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation>Simulation</translation>
    </message>
    <message>
        <source>&amp;Play</source>
        <translation>&amp;Abspielen</translation>
    </message>
    <message>
        <source>&amp;Step</source>
        <translation>&amp;Einzelschritt</translation>
    </message>
    <message>
        <source>Advance one frame (while paused)</source>
        <translation>Einen Frame weiter (wenn angehalten)</translation>
    </message>
    <message>
        <source>&amp;Reset</source>
        <translation>&amp;Zurücksetzen</translation>
    </message>
    <message>
        <source>Back to the edit pose (frame 0)</source>
        <translation>Zurück zur Bearbeitungspose (Frame 0)</translation>
    </message>
    <message>
        <source>&amp;Bake…</source>
        <translation>&amp;Backen …</translation>
    </message>
    <message>
        <source>Record the simulation in the background for playback and export</source>
        <translation>Die Simulation im Hintergrund für Wiedergabe und Export aufzeichnen</translation>
    </message>
    <message>
        <source>Re-&amp;bake</source>
        <translation>&amp;Neu backen</translation>
    </message>
    <message>
        <source>Bake the edited scene again, as long as the last bake</source>
        <translation>Die bearbeitete Szene erneut backen, so lange wie beim letzten Mal</translation>
    </message>
    <message>
        <source>&amp;Cancel Bake</source>
        <translation>Backen abbre&amp;chen</translation>
    </message>
    <message>
        <source>Stop baking and keep the frames done so far</source>
        <translation>Backen beenden und die bisherigen Frames behalten</translation>
    </message>
    <message>
        <source>C&amp;lear Bake</source>
        <translation>Backergebnis &amp;verwerfen</translation>
    </message>
    <message>
        <source>Drop the bake and simulate live again</source>
        <translation>Das Backergebnis verwerfen und wieder live simulieren</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
    <message>
        <source>Play or pause the bake</source>
        <translation>Backergebnis abspielen oder anhalten</translation>
    </message>
    <message>
        <source>Run or pause the simulation</source>
        <translation>Simulation starten oder anhalten</translation>
    </message>
    <message>
        <source>edit pose</source>
        <translation>Bearbeitungspose</translation>
    </message>
    <message>
        <source>live · %1 s · frame %2 · %3 steps/s</source>
        <translation>live · %1 s · Frame %2 · %3 Schritte/s</translation>
    </message>
    <message>
        <source>bake · %1 s · frame %2/%3</source>
        <translation>gebacken · %1 s · Frame %2/%3</translation>
    </message>
    <message>
        <source> · stale</source>
        <translation> · veraltet</translation>
    </message>
    <message>
        <source>Nothing to simulate: the scene has no bodies.</source>
        <translation>Nichts zu simulieren: Die Szene enthält keine Körper.</translation>
    </message>
    <message>
        <source>The scene cannot be simulated:
%1</source>
        <translation>Die Szene kann nicht simuliert werden:
%1</translation>
    </message>
    <message>
        <source>The scene was edited: the simulation went back to the edit pose.</source>
        <translation>Die Szene wurde bearbeitet: Die Simulation ist zur Bearbeitungspose zurückgekehrt.</translation>
    </message>
    <message>
        <source>Nothing to bake: the scene has no bodies.</source>
        <translation>Nichts zu backen: Die Szene enthält keine Körper.</translation>
    </message>
    <message>
        <source>Bake</source>
        <translation>Backen</translation>
    </message>
    <message>
        <source>The scene cannot be baked:
%1</source>
        <translation>Die Szene kann nicht gebacken werden:
%1</translation>
    </message>
    <message>
        <source>starting</source>
        <translation>startet</translation>
    </message>
    <message numerus="yes">
        <source>Baking %n frames…</source>
        <translation>
            <numerusform>%n Frame wird gebacken …</numerusform>
            <numerusform>%n Frames werden gebacken …</numerusform>
        </translation>
    </message>
    <message>
        <source>frame %1 of %2</source>
        <translation>Frame %1 von %2</translation>
    </message>
    <message>
        <source>frame %1 of %2, %3 s left</source>
        <translation>Frame %1 von %2, noch %3 s</translation>
    </message>
    <message>
        <source>baking · %1</source>
        <translation>backt · %1</translation>
    </message>
    <message>
        <source>Bake cancelled: kept frames 0 to %1.</source>
        <translation>Backen abgebrochen: Frames 0 bis %1 behalten.</translation>
    </message>
    <message>
        <source>Baked frames 0 to %1 in %2 s.</source>
        <translation>Frames 0 bis %1 in %2 s gebacken.</translation>
    </message>
    <message>
        <source>The scene was edited meanwhile, so the bake is stale.</source>
        <translation>Die Szene wurde inzwischen bearbeitet, das Backergebnis ist daher veraltet.</translation>
    </message>
    <message>
        <source>Open Bake</source>
        <translation>Backergebnis öffnen</translation>
    </message>
    <message>
        <source>Could not open the bake:
%1</source>
        <translation>Das Backergebnis konnte nicht geöffnet werden:
%1</translation>
    </message>
    <message>
        <source>The bake holds no scene; its shapes come from %1.</source>
        <translation>Das Backergebnis enthält keine Szene; die Formen stammen aus %1.</translation>
    </message>
    <message>
        <source>The bake holds no scene: each body is shown as a small box at its vertex mean. Put the OBJ it was recorded from next to it as %1 to see the shapes.</source>
        <translation>Das Backergebnis enthält keine Szene: Jeder Körper erscheint als kleiner Quader im Mittel seiner Eckpunkte. Legen Sie die OBJ-Datei, aus der es aufgezeichnet wurde, als %1 daneben, um die Formen zu sehen.</translation>
    </message>
    <message numerus="yes">
        <source>Opened %1: frames 0 to %2 at %3 Hz, %n bodies.</source>
        <translation>
            <numerusform>%1 geöffnet: Frames 0 bis %2 mit %3 Hz, %n Körper.</numerusform>
            <numerusform>%1 geöffnet: Frames 0 bis %2 mit %3 Hz, %n Körper.</numerusform>
        </translation>
    </message>
    <message>
        <source>Baked frames 0 to %1 in %2 s; the simulation starts at frame %3.</source>
        <translation>Frames 0 bis %1 in %2 s gebacken; die Simulation beginnt bei Frame %3.</translation>
    </message>
</context>
<context>
    <name>rl::TimelineView</name>
    <message>
        <source>Energy</source>
        <translation>Energie</translation>
    </message>
    <message>
        <source>Kinetic</source>
        <translation>Kinetisch</translation>
    </message>
    <message>
        <source>Potential</source>
        <translation>Potenziell</translation>
    </message>
    <message>
        <source>Total</source>
        <translation>Gesamt</translation>
    </message>
    <message>
        <source>Max penetration</source>
        <translation>Max. Eindringtiefe</translation>
    </message>
    <message>
        <source>Contacts</source>
        <translation>Kontakte</translation>
    </message>
    <message>
        <source>Awake bodies</source>
        <translation>Wache Körper</translation>
    </message>
    <message>
        <source>%1 GJ</source>
        <translation>%1 GJ</translation>
    </message>
    <message>
        <source>%1 MJ</source>
        <translation>%1 MJ</translation>
    </message>
    <message>
        <source>%1 kJ</source>
        <translation>%1 kJ</translation>
    </message>
    <message>
        <source>%1 mJ</source>
        <translation>%1 mJ</translation>
    </message>
    <message>
        <source>%1 J</source>
        <translation>%1 J</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>Frame %1 · %2 s</source>
        <translation>Frame %1 · %2 s</translation>
    </message>
    <message>
        <source>Scene changed since this bake</source>
        <translation>Szene seit diesem Backen geändert</translation>
    </message>
    <message>
        <source>Ruler in seconds (Ctrl+T shows frames)</source>
        <translation>Lineal in Sekunden (Strg+T zeigt Frames)</translation>
    </message>
    <message>
        <source>Ruler in frames (Ctrl+T shows seconds)</source>
        <translation>Lineal in Frames (Strg+T zeigt Sekunden)</translation>
    </message>
    <message>
        <source>Frame %1 is outside the range %2–%3</source>
        <translation>Frame %1 liegt außerhalb des Bereichs %2–%3</translation>
    </message>
    <message>
        <source>Baking: %1 %</source>
        <translation>Backen: %1 %</translation>
    </message>
    <message>
        <source>Baked (frames 0–%1)</source>
        <translation>Gebacken (Frames 0–%1)</translation>
    </message>
    <message>
        <source>Not baked</source>
        <translation>Nicht gebacken</translation>
    </message>
    <message>
        <source>Scale %1 to %2</source>
        <translation>Skala %1 bis %2</translation>
    </message>
    <message>
        <source>Kinetic, potential and their total. A flat total means energy is conserved; it steps down where contacts and damping dissipate it.</source>
        <translation>Kinetisch, potenziell und die Summe. Eine flache Summe bedeutet Energieerhaltung; sie fällt dort ab, wo Kontakte und Dämpfung Energie abführen.</translation>
    </message>
    <message>
        <source>Frame %1: not baked</source>
        <translation>Frame %1: nicht gebacken</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Total change since frame 0: %1</source>
        <translation>Gesamtänderung seit Frame 0: %1</translation>
    </message>
    <message>
        <source>Bake the simulation to scrub it here and to see its energy, contacts and penetration.</source>
        <translation>Backen Sie die Simulation, um hier darin zu navigieren und Energie, Kontakte und Eindringtiefe zu sehen.</translation>
    </message>
    <message>
        <source>This bake carries no diagnostics (bake files store positions only).</source>
        <translation>Dieses Backergebnis enthält keine Diagnosedaten (Bake-Dateien speichern nur Positionen).</translation>
    </message>
    <message>
        <source>Diagnostic tracks hidden.</source>
        <translation>Diagnosespuren ausgeblendet.</translation>
    </message>
    <message>
        <source>Seconds</source>
        <translation>Sekunden</translation>
    </message>
    <message>
        <source>Frames</source>
        <translation>Frames</translation>
    </message>
</context>
<context>
    <name>rl::TimelineWidget</name>
    <message>
        <source>First Frame</source>
        <translation>Erster Frame</translation>
    </message>
    <message>
        <source>Jump to the first frame (Home)</source>
        <translation>Zum ersten Frame springen (Pos1)</translation>
    </message>
    <message>
        <source>Previous Frame</source>
        <translation>Vorheriger Frame</translation>
    </message>
    <message>
        <source>Step back one frame (Left)</source>
        <translation>Einen Frame zurück (Links)</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <source>Play at real time (Space)</source>
        <translation>In Echtzeit abspielen (Leertaste)</translation>
    </message>
    <message>
        <source>Next Frame</source>
        <translation>Nächster Frame</translation>
    </message>
    <message>
        <source>Step forward one frame (Right)</source>
        <translation>Einen Frame vor (Rechts)</translation>
    </message>
    <message>
        <source>Last Frame</source>
        <translation>Letzter Frame</translation>
    </message>
    <message>
        <source>Jump to the last frame (End)</source>
        <translation>Zum letzten Frame springen (Ende)</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>Schleife</translation>
    </message>
    <message>
        <source>Loop playback; off stops at the end</source>
        <translation>Wiedergabe wiederholen; aus: hält am Ende an</translation>
    </message>
    <message>
        <source>Show Seconds</source>
        <translation>Sekunden anzeigen</translation>
    </message>
    <message>
        <source>Ruler in seconds instead of frames (Ctrl+T)</source>
        <translation>Lineal in Sekunden statt Frames (Strg+T)</translation>
    </message>
    <message>
        <source>Show Diagnostic Tracks</source>
        <translation>Diagnosespuren anzeigen</translation>
    </message>
    <message>
        <source>Show energy, penetration, contacts and awake bodies under the ruler</source>
        <translation>Energie, Eindringtiefe, Kontakte und wache Körper unter dem Lineal anzeigen</translation>
    </message>
    <message>
        <source>Zoom to Fit</source>
        <translation>Alles zeigen</translation>
    </message>
    <message>
        <source>Show the whole frame range</source>
        <translation>Den gesamten Frame-Bereich zeigen</translation>
    </message>
    <message>
        <source>Frame</source>
        <translation>Frame</translation>
    </message>
    <message>
        <source>Current frame</source>
        <translation>Aktueller Frame</translation>
    </message>
    <message>
        <source>Time of the current frame</source>
        <translation>Zeit des aktuellen Frames</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Tempo</translation>
    </message>
    <message>
        <source>Playback speed</source>
        <translation>Wiedergabegeschwindigkeit</translation>
    </message>
    <message>
        <source>Baking %1 %</source>
        <translation>Backen %1 %</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>Pause (Space)</source>
        <translation>Pause (Leertaste)</translation>
    </message>
</context>
<context>
    <name>rl::TransformGizmo</name>
    <message>
        <source>%1  %2 m</source>
        <translation>%1  %2 m</translation>
    </message>
    <message>
        <source>Move  %1, %2, %3 m</source>
        <translation>Verschieben  %1, %2, %3 m</translation>
    </message>
    <message>
        <source>View</source>
        <translation>Ansicht</translation>
    </message>
    <message>
        <source>%1  %2°</source>
        <translation>%1  %2°</translation>
    </message>
</context>
<context>
    <name>rl::WorldSettingsWidget</name>
    <message>
        <source>Earth</source>
        <translation>Erde</translation>
    </message>
    <message>
        <source>Moon</source>
        <translation>Mond</translation>
    </message>
    <message>
        <source>Mars</source>
        <translation>Mars</translation>
    </message>
    <message>
        <source>Zero g</source>
        <translation>Schwerelos</translation>
    </message>
    <message>
        <source>Gravity</source>
        <translation>Schwerkraft</translation>
    </message>
    <message>
        <source>Rotation</source>
        <translation>Drehung</translation>
    </message>
    <message>
        <source>Friction</source>
        <translation>Reibung</translation>
    </message>
    <message>
        <source>Restitution</source>
        <translation>Restitution</translation>
    </message>
    <message>
        <source>Damping</source>
        <translation>Dämpfung</translation>
    </message>
    <message>
        <source>Sleeping</source>
        <translation>Schlafen</translation>
    </message>
    <message>
        <source>CCD</source>
        <translation>CCD</translation>
    </message>
    <message>
        <source>Auto: on when a dynamic body exists and gravity is not zero</source>
        <translation>Auto: ein, wenn es einen dynamischen Körper gibt und die Schwerkraft nicht null ist</translation>
    </message>
    <message>
        <source>Auto: on unless every dynamic body is a sphere that cannot start spinning</source>
        <translation>Auto: ein, außer jeder dynamische Körper ist eine Kugel, die nicht ins Drehen kommen kann</translation>
    </message>
    <message>
        <source>Auto: on when some pair of bodies has a combined friction above zero</source>
        <translation>Auto: ein, wenn ein Körperpaar eine kombinierte Reibung über null hat</translation>
    </message>
    <message>
        <source>Auto: on when some pair of bodies has a combined restitution above zero</source>
        <translation>Auto: ein, wenn ein Körperpaar eine kombinierte Restitution über null hat</translation>
    </message>
    <message>
        <source>Auto: on when linear or angular damping is above zero</source>
        <translation>Auto: ein, wenn lineare oder Winkeldämpfung über null liegt</translation>
    </message>
    <message>
        <source>Auto: on when gravity acts and there is an anchor to come to rest on</source>
        <translation>Auto: ein, wenn Schwerkraft wirkt und es einen Anker gibt, auf dem Körper zur Ruhe kommen</translation>
    </message>
    <message>
        <source>Continuous collision detection. Auto: on when some body may move more than half its size in one frame</source>
        <translation>Kontinuierliche Kollisionserkennung. Auto: ein, wenn sich ein Körper in einem Frame um mehr als seine halbe Größe bewegen kann</translation>
    </message>
    <message>
        <source>%1 (%2 m/s²)</source>
        <translation>%1 (%2 m/s²)</translation>
    </message>
    <message>
        <source>Custom</source>
        <translation>Benutzerdefiniert</translation>
    </message>
    <message>
        <source>Sets gravity straight down (−Y) with the planet&apos;s surface gravity</source>
        <translation>Setzt die Schwerkraft senkrecht nach unten (−Y) mit der Oberflächenschwerkraft des Himmelskörpers</translation>
    </message>
    <message>
        <source>Set Gravity</source>
        <translation>Schwerkraft festlegen</translation>
    </message>
    <message>
        <source>Preset</source>
        <translation>Vorgabe</translation>
    </message>
    <message>
        <source>Gravity %1 in m/s² (Y is up)</source>
        <translation>Schwerkraft %1 in m/s² (Y zeigt nach oben)</translation>
    </message>
    <message>
        <source>X, Y, Z (m/s²)</source>
        <translation>X, Y, Z (m/s²)</translation>
    </message>
    <message>
        <source>Magnitude</source>
        <translation>Betrag</translation>
    </message>
    <message>
        <source>Time stepping</source>
        <translation>Zeitschritte</translation>
    </message>
    <message>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <source>Frames per second; one simulation step per frame (above 0, at most %L1 Hz)</source>
        <translation>Frames pro Sekunde; ein Simulationsschritt pro Frame (größer als 0, höchstens %L1 Hz)</translation>
    </message>
    <message>
        <source>Set Frame Rate</source>
        <translation>Bildrate festlegen</translation>
    </message>
    <message>
        <source>Frame rate</source>
        <translation>Bildrate</translation>
    </message>
    <message>
        <source> per frame</source>
        <translation> pro Frame</translation>
    </message>
    <message>
        <source>Solver substeps per frame, 1 to %1. More substeps make stacks stiffer and contacts more accurate.</source>
        <translation>Teilschritte des Lösers pro Frame, 1 bis %1. Mehr Teilschritte machen Stapel steifer und Kontakte genauer.</translation>
    </message>
    <message>
        <source>Set Substeps</source>
        <translation>Teilschritte festlegen</translation>
    </message>
    <message>
        <source>Substeps</source>
        <translation>Teilschritte</translation>
    </message>
    <message>
        <source> per substep</source>
        <translation> pro Teilschritt</translation>
    </message>
    <message>
        <source>Velocity iterations of the contact solver per substep, 1 to %1</source>
        <translation>Geschwindigkeitsiterationen des Kontaktlösers pro Teilschritt, 1 bis %1</translation>
    </message>
    <message>
        <source>Set Iterations</source>
        <translation>Iterationen festlegen</translation>
    </message>
    <message>
        <source>Iterations</source>
        <translation>Iterationen</translation>
    </message>
    <message>
        <source>First order; gains energy (the original project&apos;s choice)</source>
        <translation>Erster Ordnung; gewinnt Energie (die Wahl des ursprünglichen Projekts)</translation>
    </message>
    <message>
        <source>First order at the same cost; energy stays bounded (default)</source>
        <translation>Erster Ordnung bei gleichem Aufwand; die Energie bleibt beschränkt (Standard)</translation>
    </message>
    <message>
        <source>Second order; exact for free fall</source>
        <translation>Zweiter Ordnung; exakt für den freien Fall</translation>
    </message>
    <message>
        <source>Fourth order in free flight; costs more per step</source>
        <translation>Vierter Ordnung im freien Flug; teurer pro Schritt</translation>
    </message>
    <message>
        <source>Explicit Euler</source>
        <translation>Expliziter Euler</translation>
    </message>
    <message>
        <source>Symplectic Euler</source>
        <translation>Symplektischer Euler</translation>
    </message>
    <message>
        <source>Verlet</source>
        <translation>Verlet</translation>
    </message>
    <message>
        <source>RK4</source>
        <translation>RK4</translation>
    </message>
    <message>
        <source>Where contacts act, every scheme is first order</source>
        <translation>Wo Kontakte wirken, ist jedes Verfahren erster Ordnung</translation>
    </message>
    <message>
        <source>Set Integrator</source>
        <translation>Integrator festlegen</translation>
    </message>
    <message>
        <source>Integrator</source>
        <translation>Integrator</translation>
    </message>
    <message>
        <source> 1/s</source>
        <translation> 1/s</translation>
    </message>
    <message>
        <source>Velocity lost per second, as a rate</source>
        <translation>Geschwindigkeitsverlust pro Sekunde, als Rate</translation>
    </message>
    <message>
        <source>Set Linear Damping</source>
        <translation>Lineare Dämpfung festlegen</translation>
    </message>
    <message>
        <source>Linear</source>
        <translation>Linear</translation>
    </message>
    <message>
        <source>Angular velocity lost per second, as a rate</source>
        <translation>Verlust an Winkelgeschwindigkeit pro Sekunde, als Rate</translation>
    </message>
    <message>
        <source>Set Angular Damping</source>
        <translation>Winkeldämpfung festlegen</translation>
    </message>
    <message>
        <source>Angular</source>
        <translation>Winkel</translation>
    </message>
    <message>
        <source>Contact combine rules</source>
        <translation>Kombinationsregeln für Kontakte</translation>
    </message>
    <message>
        <source>How the friction of two materials combines at a contact</source>
        <translation>Wie sich die Reibung zweier Materialien an einem Kontakt kombiniert</translation>
    </message>
    <message>
        <source>Set Friction Rule</source>
        <translation>Reibungsregel festlegen</translation>
    </message>
    <message>
        <source>How the restitution of two materials combines at a contact</source>
        <translation>Wie sich die Restitution zweier Materialien an einem Kontakt kombiniert</translation>
    </message>
    <message>
        <source>Set Restitution Rule</source>
        <translation>Restitutionsregel festlegen</translation>
    </message>
    <message>
        <source>Effects</source>
        <translation>Effekte</translation>
    </message>
    <message>
        <source>Auto simulates only what the scene calls for; a skipped effect costs nothing.</source>
        <translation>Auto simuliert nur, was die Szene erfordert; ein übersprungener Effekt kostet nichts.</translation>
    </message>
    <message>
        <source>Auto</source>
        <translation>Auto</translation>
    </message>
    <message>
        <source>On</source>
        <translation>Ein</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <source>Set Effect %1</source>
        <translation>Effekt %1 festlegen</translation>
    </message>
    <message>
        <source>Linear only: no rotation (the original project&apos;s mode)</source>
        <translation>Nur linear, ohne Drehung (wie im Original)</translation>
    </message>
    <message>
        <source>The same as Rotation: Off</source>
        <translation>Dasselbe wie Drehung: Aus</translation>
    </message>
    <message>
        <source>Linear Only</source>
        <translation>Nur linear</translation>
    </message>
    <message>
        <source>Allow Rotation</source>
        <translation>Drehung erlauben</translation>
    </message>
    <message>
        <source>All Auto</source>
        <translation>Alle auf Auto</translation>
    </message>
    <message>
        <source>All Effects Auto</source>
        <translation>Alle Effekte auf Auto</translation>
    </message>
    <message>
        <source>Restore Defaults</source>
        <translation>Standardwerte</translation>
    </message>
    <message>
        <source>Restore World Defaults</source>
        <translation>Standardwerte der Welt wiederherstellen</translation>
    </message>
    <message>
        <source>The frame rate must be above 0 and at most %L1 Hz (got %2 Hz).</source>
        <translation>Die Bildrate muss größer als 0 und höchstens %L1 Hz sein (erhalten: %2 Hz).</translation>
    </message>
    <message>
        <source>Substeps must be between 1 and %1 per frame (got %2).</source>
        <translation>Die Teilschritte müssen zwischen 1 und %1 pro Frame liegen (erhalten: %2).</translation>
    </message>
    <message>
        <source>Iterations must be between 1 and %1 per substep (got %2).</source>
        <translation>Die Iterationen müssen zwischen 1 und %1 pro Teilschritt liegen (erhalten: %2).</translation>
    </message>
    <message>
        <source>Each component of gravity must be a number between −%1 and %1 m/s².</source>
        <translation>Jede Komponente der Schwerkraft muss eine Zahl zwischen −%1 und %1 m/s² sein.</translation>
    </message>
    <message>
        <source>Linear damping must be between 0 and %1 1/s (got %2).</source>
        <translation>Die lineare Dämpfung muss zwischen 0 und %1 1/s liegen (erhalten: %2).</translation>
    </message>
    <message>
        <source>Angular damping must be between 0 and %1 1/s (got %2).</source>
        <translation>Die Winkeldämpfung muss zwischen 0 und %1 1/s liegen (erhalten: %2).</translation>
    </message>
    <message>
        <source>%L1 m/s²</source>
        <translation>%L1 m/s²</translation>
    </message>
    <message>
        <source>Step %L1 ms, substep %L2 ms; %3 solver passes per frame</source>
        <translation>Schritt %L1 ms, Teilschritt %L2 ms; %3 Löserdurchläufe pro Frame</translation>
    </message>
    <message>
        <source>Auto cannot decide for this scene: %1</source>
        <translation>Auto kann für diese Szene nicht entscheiden: %1</translation>
    </message>
    <message>
        <source>on</source>
        <translation>ein</translation>
    </message>
    <message>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <source>deciding…</source>
        <translation>entscheidet …</translation>
    </message>
    <message>
        <source>forced</source>
        <translation>erzwungen</translation>
    </message>
    <message>
        <source>Auto: %1</source>
        <translation>Auto: %1</translation>
    </message>
    <message>
        <source>Auto would turn it %1: %2</source>
        <translation>Auto würde es auf „%1“ stellen: %2</translation>
    </message>
    <message>
        <source>Earth gravity, %1 Hz, %2 substeps × %3 iterations, symplectic Euler, no damping, geometric-mean friction, maximum restitution, every effect on Auto</source>
        <translation>Erdschwerkraft, %1 Hz, %2 Teilschritte × %3 Iterationen, symplektischer Euler, keine Dämpfung, Reibung als geometrisches Mittel, maximale Restitution, alle Effekte auf Auto</translation>
    </message>
</context>
</TS>
