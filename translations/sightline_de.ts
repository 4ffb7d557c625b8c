<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>sightline::ButtonPickerPresenter</name>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="40"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="83"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="87"/>
        <source>Stopped</source>
        <translation>Gestoppt</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="42"/>
        <source>Waiting for Yes</source>
        <translation>Warte auf Ja</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="44"/>
        <source>Button lost</source>
        <translation>Knopf verloren</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="46"/>
        <source>Button unclear</source>
        <translation>Knopf unklar</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="48"/>
        <source>Measuring the button</source>
        <translation>Knopf wird vermessen</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="50"/>
        <source>Measuring again</source>
        <translation>Neue Messung</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="52"/>
        <source>Measuring the distance</source>
        <translation>Abstand wird gemessen</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="54"/>
        <source>Panel unclear</source>
        <translation>Tastenfeld unklar</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="56"/>
        <source>Position not sure yet</source>
        <translation>Position noch unsicher</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="58"/>
        <source>Panel direction not sure yet</source>
        <translation>Richtung des Tastenfelds noch unsicher</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="60"/>
        <source>Button out of reach</source>
        <translation>Knopf außer Reichweite</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="71"/>
        <source>The picture changed: tap again</source>
        <translation>Das Bild hat sich geändert: bitte neu antippen</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="73"/>
        <source>The picture was too old: tap again</source>
        <translation>Das Bild war zu alt: bitte neu antippen</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="75"/>
        <source>Stopped: press Start again first</source>
        <translation>Gestoppt: zuerst „Neu starten“ drücken</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="82"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="224"/>
        <source>Paused</source>
        <translation>Angehalten</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="85"/>
        <source>Arm link off</source>
        <translation>Arm-Verbindung aus</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="86"/>
        <source>No arm connected</source>
        <translation>Kein Arm verbunden</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="90"/>
        <source>Waiting</source>
        <translation>Warten</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="111"/>
        <source>Button picker (monocular SLAM)</source>
        <translation>Knopfwahl (monokulares SLAM)</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="119"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="143"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="182"/>
        <source>Operator panel</source>
        <translation>Bedienfeld</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="123"/>
        <source>Operator panel full screen</source>
        <translation>Bedienfeld im Vollbild</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="224"/>
        <source>End of the recording</source>
        <translation>Ende der Aufnahme</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="242"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="250"/>
        <source>The picture is paused: press Play, then tap</source>
        <translation>Das Bild ist angehalten: erst Abspielen drücken, dann antippen</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="249"/>
        <source>The recording has ended: nothing to tap</source>
        <translation>Die Aufnahme ist zu Ende: nichts zum Antippen</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="251"/>
        <source>No picture yet: open a camera or a recording</source>
        <translation>Noch kein Bild: Kamera oder Aufnahme öffnen</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="288"/>
        <source>No button at the tap: %1</source>
        <translation>Kein Knopf an der getippten Stelle: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="303"/>
        <source>No metric scale (no arm motion)</source>
        <translation>Kein metrischer Maßstab (keine Armbewegung)</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="305"/>
        <source>Without the arm&apos;s poses the button is tracked and located in map units only; no target is sent.</source>
        <translation>Ohne die Posen des Arms wird der Knopf nur in Karteneinheiten verfolgt und verortet; es wird kein Ziel gesendet.</translation>
    </message>
</context>
<context>
    <name>sightline::CalibrationDialog</name>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="80"/>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="95"/>
        <source>&amp;Calibrate</source>
        <translation>&amp;Kalibrieren</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="96"/>
        <source>&amp;Save YAML...</source>
        <translation>YAML &amp;speichern...</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="93"/>
        <source>Board</source>
        <translation>Kalibriermuster</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="224"/>
        <source>Board found in %1 of %2 %3.</source>
        <translation>Muster in %1 von %2 %3 gefunden.</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="60"/>
        <source>Browse...</source>
        <translation>Durchsuchen...</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="42"/>
        <source>Calibrate camera</source>
        <translation>Kamera kalibrieren</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="218"/>
        <source>Calibration failed: %1</source>
        <translation>Kalibrierung fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="62"/>
        <source>Calibration images</source>
        <translation>Kalibrierbilder</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="108"/>
        <source>Choose a source and the board, then press Calibrate.</source>
        <translation>Quelle und Muster wählen, dann Kalibrieren drücken.</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="175"/>
        <source>Choose a source first.</source>
        <translation>Zuerst eine Quelle wählen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="131"/>
        <source>Coverage (views per cell)</source>
        <translation>Abdeckung (Ansichten je Zelle)</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="129"/>
        <source>Detected corners</source>
        <translation>Gefundene Ecken</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="317"/>
        <source>Detected corners: %1 (%2 px)</source>
        <translation>Gefundene Ecken: %1 (%2 px)</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="181"/>
        <source>Detecting the board...</source>
        <translation>Muster wird gesucht...</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="117"/>
        <source>Error (px)</source>
        <translation>Fehler (px)</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="69"/>
        <source>File name pattern inside a mono image folder, e.g. left*.jpg</source>
        <translation>Dateinamenmuster im Mono-Bildordner, z. B. left*.jpg</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="264"/>
        <source>Hint: %1</source>
        <translation>Hinweis: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="59"/>
        <source>Image folder, stereo folder, recording or camera URI</source>
        <translation>Bildordner, Stereo-Ordner, Aufnahme oder Kamera-URI</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="92"/>
        <source>Image pattern</source>
        <translation>Bildmuster</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="90"/>
        <source>Mode</source>
        <translation>Modus</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="56"/>
        <source>Mono (one camera)</source>
        <translation>Mono (eine Kamera)</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="348"/>
        <source>Nothing to save: calibrate first.</source>
        <translation>Nichts zu speichern: zuerst kalibrieren.</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="362"/>
        <source>OpenCV YAML (*.yaml *.yml)</source>
        <translation>OpenCV-YAML (*.yaml *.yml)</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="251"/>
        <source>RMS %1 px; %2 views used, %3 rejected.</source>
        <translation>RMS %1 px; %2 Ansichten verwendet, %3 verworfen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="243"/>
        <source>RMS left %1 px, right %2 px, stereo %3 px; baseline %4 mm; %5 of %6 pairs used.</source>
        <translation>RMS links %1 px, rechts %2 px, Stereo %3 px; Basislinie %4 mm; %5 von %6 Paaren verwendet.</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="117"/>
        <source>Right error (px)</source>
        <translation>Fehler rechts (px)</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="361"/>
        <source>Save calibration</source>
        <translation>Kalibrierung speichern</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="356"/>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="365"/>
        <source>Saving failed: %1</source>
        <translation>Speichern fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="91"/>
        <source>Source</source>
        <translation>Quelle</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="117"/>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="57"/>
        <source>Stereo (left and right)</source>
        <translation>Stereo (links und rechts)</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="117"/>
        <source>View</source>
        <translation>Ansicht</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="257"/>
        <source>fx %1 fy %2 cx %3 cy %4; coverage: %5</source>
        <translation>fx %1 fy %2 cx %3 cy %4; Abdeckung: %5</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="227"/>
        <source>images</source>
        <translation>Bildern</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="85"/>
        <source>inner corners, squares of</source>
        <translation>innere Ecken, Felder von</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="227"/>
        <source>pairs</source>
        <translation>Paaren</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="289"/>
        <location filename="../app/sightline/calibration_dialog.cpp" line="303"/>
        <source>rejected</source>
        <translation>verworfen</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="289"/>
        <source>used</source>
        <translation>verwendet</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="83"/>
        <source>x</source>
        <translation>x</translation>
    </message>
</context>
<context>
    <name>sightline::CoreText</name>
    <message>
        <location filename="../app/sightline/core_texts.cpp" line="11"/>
        <source>OpenNI2 RGB-D cameras (Kinect, Xtion, Carmine) and .oni recordings</source>
        <translation>OpenNI2-RGB-D-Kameras (Kinect, Xtion, Carmine) und .oni-Aufnahmen</translation>
    </message>
    <message>
        <location filename="../app/sightline/core_texts.cpp" line="13"/>
        <source>GigE Vision / USB3 Vision cameras through Aravis: one camera, or a stereo pair as aravis://LEFT_ID,RIGHT_ID</source>
        <translation>GigE-Vision-/USB3-Vision-Kameras über Aravis: eine Kamera oder ein Stereopaar als aravis://LEFT_ID,RIGHT_ID</translation>
    </message>
    <message>
        <location filename="../app/sightline/core_texts.cpp" line="16"/>
        <source>USB webcams through OpenCV&apos;s V4L2 backend</source>
        <translation>USB-Webcams über das V4L2-Backend von OpenCV</translation>
    </message>
    <message>
        <location filename="../app/sightline/core_texts.cpp" line="17"/>
        <source>A recording played as a live camera (replay://PATH?fps=30&amp;loop=1)</source>
        <translation>Eine Aufnahme, als Live-Kamera abgespielt (replay://PATH?fps=30&amp;loop=1)</translation>
    </message>
</context>
<context>
    <name>sightline::DemoGenerator</name>
    <message>
        <location filename="../app/sightline/demo_generator.cpp" line="48"/>
        <source>cannot create the demo folder %1</source>
        <translation>Demo-Ordner %1 kann nicht angelegt werden</translation>
    </message>
    <message>
        <location filename="../app/sightline/demo_generator.cpp" line="87"/>
        <source>cannot write %1</source>
        <translation>%1 kann nicht geschrieben werden</translation>
    </message>
</context>
<context>
    <name>sightline::EvaluationPanel</name>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="75"/>
        <source>estimated trajectory (TUM or KITTI file)</source>
        <translation>geschätzte Trajektorie (TUM- oder KITTI-Datei)</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="77"/>
        <source>ground truth (TUM or KITTI file)</source>
        <translation>Ground Truth (TUM- oder KITTI-Datei)</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="81"/>
        <source>Browse...</source>
        <translation>Durchsuchen...</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="90"/>
        <source>SE(3): rotation and translation</source>
        <translation>SE(3): Rotation und Translation</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="91"/>
        <source>Sim(3): also scale (monocular)</source>
        <translation>Sim(3): auch Maßstab (monokular)</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="92"/>
        <source>None</source>
        <translation>Keine</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="93"/>
        <source>Evaluate</source>
        <translation>Auswerten</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="100"/>
        <source>Estimate</source>
        <translation>Schätzung</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="100"/>
        <source>Estimated trajectory</source>
        <translation>Geschätzte Trajektorie</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="101"/>
        <source>Ground truth</source>
        <translation>Ground Truth</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="102"/>
        <source>Alignment</source>
        <translation>Ausrichtung</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="104"/>
        <source>Choose two trajectory files and press Evaluate.</source>
        <translation>Zwei Trajektoriendateien wählen und Auswerten drücken.</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="107"/>
        <source>Figure</source>
        <translation>Kennzahl</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="107"/>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="107"/>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="107"/>
        <source>Meaning</source>
        <translation>Bedeutung</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="117"/>
        <source>Figures</source>
        <translation>Kennzahlen</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="118"/>
        <source>Top view</source>
        <translation>Draufsicht</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="119"/>
        <source>Error over time</source>
        <translation>Fehler im Zeitverlauf</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="144"/>
        <source>Trajectories (*.txt *.csv);;All files (*)</source>
        <translation>Trajektorien (*.txt *.csv);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="152"/>
        <source>Evaluating...</source>
        <translation>Auswertung läuft...</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="176"/>
        <source>Evaluation failed: %1</source>
        <translation>Auswertung fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="189"/>
        <source>%1 associated poses, ground-truth path %2 m.</source>
        <translation>%1 zugeordnete Posen, Weglänge der Ground Truth %2 m.</translation>
    </message>
</context>
<context>
    <name>sightline::ImageView</name>
    <message>
        <location filename="../widgets/image_view.cpp" line="47"/>
        <location filename="../widgets/image_view.cpp" line="78"/>
        <location filename="../widgets/image_view.cpp" line="131"/>
        <source>No image</source>
        <translation>Kein Bild</translation>
    </message>
    <message>
        <location filename="../widgets/image_view.cpp" line="81"/>
        <source>Unsupported image type %1</source>
        <translation>Nicht unterstützter Bildtyp %1</translation>
    </message>
</context>
<context>
    <name>sightline::LiveStatusWidget</name>
    <message>
        <location filename="../app/sightline/live_status_widget.cpp" line="25"/>
        <source>closed</source>
        <translation>geschlossen</translation>
    </message>
    <message>
        <location filename="../app/sightline/live_status_widget.cpp" line="27"/>
        <source>streaming</source>
        <translation>läuft</translation>
    </message>
    <message>
        <location filename="../app/sightline/live_status_widget.cpp" line="29"/>
        <source>disconnected</source>
        <translation>getrennt</translation>
    </message>
    <message>
        <location filename="../app/sightline/live_status_widget.cpp" line="40"/>
        <source>&lt;span style=&apos;color:%1&apos;&gt;&amp;#9679;&lt;/span&gt; %2 &amp;nbsp;%3 fps &amp;nbsp;dropped %4 &amp;nbsp;latency %5 ms</source>
        <translation>&lt;span style=&apos;color:%1&apos;&gt;&amp;#9679;&lt;/span&gt; %2 &amp;nbsp;%3 fps &amp;nbsp;verworfen %4 &amp;nbsp;Latenz %5 ms</translation>
    </message>
</context>
<context>
    <name>sightline::LogPanel</name>
    <message>
        <location filename="../widgets/log_panel.cpp" line="36"/>
        <source>Clear messages</source>
        <translation>Meldungen löschen</translation>
    </message>
</context>
<context>
    <name>sightline::MainWindow</name>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="46"/>
        <source>Sightline</source>
        <translation>Sightline</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="81"/>
        <location filename="../app/sightline/main_window.cpp" line="374"/>
        <source>Colour</source>
        <translation>Farbe</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="82"/>
        <location filename="../app/sightline/main_window.cpp" line="375"/>
        <source>Depth</source>
        <translation>Tiefe</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="87"/>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="89"/>
        <source>Log</source>
        <translation>Protokoll</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="92"/>
        <source>Evaluation</source>
        <translation>Auswertung</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="100"/>
        <source>Playback</source>
        <translation>Wiedergabe</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="110"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="111"/>
        <source>&amp;Open dataset folder...</source>
        <translation>Datensatz-Ordner &amp;öffnen...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="114"/>
        <source>Open dataset folder</source>
        <translation>Datensatz-Ordner öffnen</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="119"/>
        <source>Open point cloud</source>
        <translation>Punktwolke öffnen</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="117"/>
        <source>Open recording &amp;file (PCD, ONI)...</source>
        <translation>Aufnahme&amp;datei öffnen (PCD, ONI)...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="120"/>
        <source>Recordings (*.pcd *.oni)</source>
        <translation>Aufnahmen (*.pcd *.oni)</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="123"/>
        <source>Open &amp;recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="128"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="132"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="134"/>
        <source>&amp;Reset 3D view</source>
        <translation>3D-Ansicht &amp;zurücksetzen</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="142"/>
        <source>&amp;Sensors</source>
        <translation>&amp;Sensoren</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="148"/>
        <source> (unavailable)</source>
        <translation> (nicht verfügbar)</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="153"/>
        <source>Connect to the first %1 device</source>
        <translation>Mit dem ersten %1-Gerät verbinden</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="159"/>
        <source>Replay recording</source>
        <translation>Aufnahme abspielen</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="165"/>
        <source>&amp;Pipeline</source>
        <translation>&amp;Pipeline</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="167"/>
        <location filename="../app/sightline/main_window.cpp" line="300"/>
        <source>None (show frames only)</source>
        <translation>Keine (nur Bilder zeigen)</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="174"/>
        <source>&amp;Tools</source>
        <translation>&amp;Werkzeuge</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="175"/>
        <source>&amp;Evaluate trajectory...</source>
        <translation>Trajektorie &amp;auswerten...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="180"/>
        <source>Evaluate &amp;current run</source>
        <translation>&amp;Aktuellen Lauf auswerten</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="182"/>
        <source>Compares the running pipeline&apos;s trajectory with the dataset&apos;s ground truth.</source>
        <translation>Vergleicht die Trajektorie der laufenden Pipeline mit der Referenz des Datensatzes.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="191"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="192"/>
        <source>&amp;About Sightline</source>
        <translation>Ü&amp;ber Sightline</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="193"/>
        <source>About Sightline</source>
        <translation>Über Sightline</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="194"/>
        <source>Sightline: robot perception for assistive and mobile robotics.
Indoor mapping, mobility maps, stereo odometry and monocular button localisation on live sensors or recorded data.</source>
        <translation>Sightline: Roboterwahrnehmung für assistive und mobile Robotik.
Innenraumkartierung, Befahrbarkeitskarten, Stereo-Odometrie und monokulare Knopflokalisierung auf Live-Sensoren oder aufgezeichneten Daten.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="206"/>
        <source>Could not open %1: %2</source>
        <translation>%1 konnte nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="207"/>
        <source>Could not open %1</source>
        <translation>%1 konnte nicht geöffnet werden</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="215"/>
        <source>End of recording.</source>
        <translation>Ende der Aufnahme.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="239"/>
        <source>Demo %p%</source>
        <translation>Demo %p%</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="246"/>
        <source>Generating the demo recordings (only the first time)...</source>
        <translation>Die Demo-Aufnahmen werden erzeugt (nur beim ersten Mal)...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="255"/>
        <source>Demo: a robot drives a simulated office corridor (RGB-D, stereo, wheel odometry, exact ground truth). The arm-camera panel approach is in %1.</source>
        <translation>Demo: Ein Roboter fährt durch einen simulierten Büroflur (RGB-D, Stereo, Radodometrie, exakte Ground Truth). Die Annäherung der Armkamera an das Tastenfeld liegt in %1.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="262"/>
        <source>The demo could not be made: %1</source>
        <translation>Die Demo konnte nicht erzeugt werden: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="318"/>
        <source>No pipeline: showing frames only.</source>
        <translation>Keine Pipeline: nur die Bilder werden gezeigt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="329"/>
        <source>Pipeline: %1</source>
        <translation>Pipeline: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="333"/>
        <source>%1 cannot run on %2 frames; open another dataset.</source>
        <translation>%1 kann nicht auf %2-Bildern laufen; bitte einen anderen Datensatz öffnen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="362"/>
        <location filename="../app/sightline/main_window.cpp" line="363"/>
        <source>Opening %1 ...</source>
        <translation>Öffne %1 ...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="374"/>
        <source>Left</source>
        <translation>Links</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="374"/>
        <source>Image</source>
        <translation>Bild</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="375"/>
        <source>Right</source>
        <translation>Rechts</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="381"/>
        <source>%1: %2, %3 frames, %4x%5%6</source>
        <translation>%1: %2, %3 Bilder, %4x%5%6</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="386"/>
        <source>, ground truth</source>
        <translation>, Ground Truth</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="388"/>
        <source>Opened %1</source>
        <translation>Geöffnet: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="393"/>
        <source>Sightline - %1</source>
        <translation>Sightline - %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="428"/>
        <source>frame %1, read in %2 ms</source>
        <translation>Bild %1, gelesen in %2 ms</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="450"/>
        <source>No dataset open. Use File &gt; Open dataset folder (TUM RGB-D, EuRoC, KITTI, an image folder or PCD files), or drop a folder on this window.</source>
        <translation>Kein Datensatz geöffnet. Datei &gt; Datensatz-Ordner öffnen wählen (TUM RGB-D, EuRoC, KITTI, ein Bildordner oder PCD-Dateien) oder einen Ordner auf dieses Fenster ziehen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="452"/>
        <source>No dataset open</source>
        <translation>Kein Datensatz geöffnet</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="184"/>
        <source>&amp;Calibrate camera...</source>
        <translation>Kamera &amp;kalibrieren...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_recording.cpp" line="19"/>
        <source>Recording</source>
        <translation>Aufnahme</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_recording.cpp" line="37"/>
        <source>Recording: %1</source>
        <translation>Aufnahme: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="35"/>
        <source>&amp;Save results...</source>
        <translation>Ergebnisse &amp;speichern...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="38"/>
        <source>Writes the running pipeline&apos;s results as sightline-cli run does: metrics.json, trajectory, maps, clouds and tables.</source>
        <translation>Schreibt die Ergebnisse der laufenden Pipeline wie sightline-cli run: metrics.json, Trajektorie, Karten, Punktwolken und Tabellen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="44"/>
        <source>Save results into folder</source>
        <translation>Ergebnisse in Ordner speichern</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="55"/>
        <source>Saved %1 in %2</source>
        <translation>%1 in %2 gespeichert</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="56"/>
        <source>Results saved in %1</source>
        <translation>Ergebnisse in %1 gespeichert</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="61"/>
        <source>Could not save results: %1</source>
        <translation>Ergebnisse konnten nicht gespeichert werden: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="75"/>
        <source>Evaluate current run needs a running pipeline on a dataset with ground truth; choose two trajectory files instead.</source>
        <translation>Zum Auswerten des aktuellen Laufs muss eine Pipeline auf einem Datensatz mit Referenz laufen; wählen Sie sonst zwei Trajektoriendateien.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="82"/>
        <source>Could not make a temporary folder for the evaluation.</source>
        <translation>Für die Auswertung konnte kein temporärer Ordner angelegt werden.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="94"/>
        <source>%1 writes no trajectory to evaluate.</source>
        <translation>%1 schreibt keine Trajektorie, die sich auswerten ließe.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_settings.cpp" line="26"/>
        <source>Reset &amp;layout</source>
        <translation>&amp;Layout zurücksetzen</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_settings.cpp" line="60"/>
        <source>Setti&amp;ngs</source>
        <translation>&amp;Einstellungen</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_settings.cpp" line="62"/>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_settings.cpp" line="67"/>
        <source>System language</source>
        <translation>Systemsprache</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_settings.cpp" line="96"/>
        <source>Language: %1</source>
        <translation>Sprache: %1</translation>
    </message>
</context>
<context>
    <name>sightline::MappingPresenter</name>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="91"/>
        <source>Indoor mapping (Manhattan walls)</source>
        <translation>Innenraumkartierung (Manhattan-Wände)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="98"/>
        <source>Occupancy, scan and walls</source>
        <translation>Belegung, Scan und Wände</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="104"/>
        <source>Calibrate floor</source>
        <translation>Boden kalibrieren</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="106"/>
        <source>Fit the floor plane again from the next frames (the robot should see open floor).</source>
        <translation>Die Bodenebene aus den nächsten Bildern neu schätzen (der Roboter sollte freien Boden sehen).</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="109"/>
        <source>Save floor...</source>
        <translation>Boden speichern...</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="111"/>
        <source>Save the floor calibration in use, for mapping.run.floor_file or `sightline-cli run mapping --set mapping.run.floor_file=...`.</source>
        <translation>Die verwendete Bodenkalibrierung speichern, für mapping.run.floor_file oder `sightline-cli run mapping --set mapping.run.floor_file=...`.</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="114"/>
        <source>Save floor calibration</source>
        <translation>Bodenkalibrierung speichern</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="115"/>
        <source>YAML (*.yaml)</source>
        <translation>YAML (*.yaml)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="127"/>
        <source>Stitched map</source>
        <translation>Zusammengesetzte Karte</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="186"/>
        <source>Manhattan reference reset: %1</source>
        <translation>Manhattan-Referenz zurückgesetzt: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="202"/>
        <source>Calibrating the floor again from the next frames.</source>
        <translation>Der Boden wird aus den nächsten Bildern neu kalibriert.</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="215"/>
        <source>Saved the floor calibration to %1</source>
        <translation>Bodenkalibrierung in %1 gespeichert</translation>
    </message>
</context>
<context>
    <name>sightline::MobilityImagePanel</name>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="72"/>
        <source>Projection</source>
        <translation>Projektion</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="73"/>
        <source>Top view</source>
        <translation>Draufsicht</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="74"/>
        <source>GPR surface</source>
        <translation>GPR-Fläche</translation>
    </message>
</context>
<context>
    <name>sightline::MobilityPresenter</name>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="26"/>
        <source>Mobility map</source>
        <translation>Befahrbarkeitskarte</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="36"/>
        <source>Mobility map (red 0, green 1)</source>
        <translation>Befahrbarkeitskarte (rot 0, grün 1)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="40"/>
        <source>Mobility stages (Table II)</source>
        <translation>Befahrbarkeitskarte: Stufen (Tabelle II)</translation>
    </message>
</context>
<context>
    <name>sightline::MobilityTimingPanel</name>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="21"/>
        <source>3D colour:</source>
        <translation>3D-Farbe:</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="23"/>
        <source>Score (rule)</source>
        <translation>Bewertung (Regel)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="23"/>
        <source>Score (GPR)</source>
        <translation>Bewertung (GPR)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="23"/>
        <source>Segment</source>
        <translation>Segment</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="31"/>
        <source>Stage</source>
        <translation>Stufe</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="31"/>
        <source>Time (ms)</source>
        <translation>Zeit (ms)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="31"/>
        <source>Points</source>
        <translation>Punkte</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="52"/>
        <source>Total</source>
        <translation>Gesamt</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="55"/>
        <source>%1 mode, %2 segments</source>
        <translation>Modus %1, %2 Segmente</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="59"/>
        <source>, camera %1 m above the ground</source>
        <translation>, Kamera %1 m über dem Boden</translation>
    </message>
</context>
<context>
    <name>sightline::MonoSlamPresenter</name>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="85"/>
        <source>the arm&apos;s poses</source>
        <translation>Armposen</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="86"/>
        <source>the ground truth</source>
        <translation>Ground Truth</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="87"/>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="125"/>
        <source>Monocular SLAM (PTAM point cloud)</source>
        <translation>Monokulares SLAM (PTAM-Punktwolke)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="137"/>
        <source>Reset map</source>
        <translation>Karte zurücksetzen</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="138"/>
        <source>Pause mapping</source>
        <translation>Kartierung anhalten</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="151"/>
        <source>Tracked features (inliers green, outliers red)</source>
        <translation>Verfolgte Merkmale (Inlier grün, Outlier rot)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="162"/>
        <source>Metric scale (ML solid, single ratio dashed)</source>
        <translation>Metrischer Maßstab (ML durchgezogen, Einzelverhältnis gestrichelt)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="207"/>
        <source>%1: %2 inliers of %3 matches, %4 map points, %5 keyframes, %6 ms</source>
        <translation>%1: %2 Inlier von %3 Zuordnungen, %4 Kartenpunkte, %5 Keyframes, %6 ms</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="217"/>
        <source>Metric scale from %1: ML %2, single ratio %3 map units per metre; map and trajectory in metres.</source>
        <translation>Metrischer Maßstab (Quelle: %1): ML %2, Einzelverhältnis %3 Karteneinheiten pro Meter; Karte und Trajektorie in Metern.</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="223"/>
        <source>Scale unknown (measured motion: %1): the map is in arbitrary units (first baseline = 0.1).</source>
        <translation>Maßstab unbekannt (gemessene Bewegung: %1): Die Karte ist in beliebigen Einheiten (erste Basislinie = 0,1).</translation>
    </message>
</context>
<context>
    <name>sightline::OperatorPanel</name>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="272"/>
        <source>%1 cm</source>
        <translation>%1 cm</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="277"/>
        <location filename="../widgets/operator_panel.cpp" line="319"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="242"/>
        <source>Locating</source>
        <translation>Position wird gemessen</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="246"/>
        <source>Lost - hold still</source>
        <translation>Verloren - still halten</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="236"/>
        <source>No button here - tap again</source>
        <translation>Kein Knopf hier - nochmal tippen</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="234"/>
        <source>Press this button?</source>
        <translation>Diesen Knopf drücken?</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="250"/>
        <source>Holding: nothing sent</source>
        <translation>Halt: nichts gesendet</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="252"/>
        <source>Tap not taken</source>
        <translation>Antippen nicht angenommen</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="254"/>
        <source>Tracking only</source>
        <translation>Nur Verfolgung</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="278"/>
        <source>STOP</source>
        <translation>STOPP</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="314"/>
        <source>Leave</source>
        <translation>Verlassen</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="314"/>
        <source>Leave the operator panel?</source>
        <translation>Bedienfeld verlassen?</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="238"/>
        <source>Searching</source>
        <translation>Suche läuft</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="279"/>
        <source>Start again</source>
        <translation>Neu starten</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="248"/>
        <source>Stopped</source>
        <translation>Gestoppt</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="232"/>
        <source>Tap a button</source>
        <translation>Knopf antippen</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="244"/>
        <source>Target sent</source>
        <translation>Ziel gesendet</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="240"/>
        <source>Tracking</source>
        <translation>Knopf im Blick</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="276"/>
        <location filename="../widgets/operator_panel.cpp" line="318"/>
        <source>Yes</source>
        <translation>Ja</translation>
    </message>
</context>
<context>
    <name>sightline::OptionEditor</name>
    <message>
        <location filename="../widgets/option_editor.cpp" line="47"/>
        <source>Range: %1 … %2%3</source>
        <translation>Bereich: %1 … %2%3</translation>
    </message>
    <message>
        <location filename="../widgets/option_editor.cpp" line="52"/>
        <source>Choices: %1</source>
        <translation>Auswahl: %1</translation>
    </message>
    <message>
        <location filename="../widgets/option_editor.cpp" line="55"/>
        <source>Default: %1%2</source>
        <translation>Standard: %1%2</translation>
    </message>
    <message>
        <location filename="../widgets/option_editor.cpp" line="71"/>
        <source>Reset to default (%1)</source>
        <translation>Auf Standard zurücksetzen (%1)</translation>
    </message>
</context>
<context>
    <name>sightline::ParameterPanel</name>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="45"/>
        <source>Filter options</source>
        <translation>Optionen filtern</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="49"/>
        <source>Load profile…</source>
        <translation>Profil laden…</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="52"/>
        <source>Save profile…</source>
        <translation>Profil speichern…</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="55"/>
        <source>Reset all</source>
        <translation>Alle zurücksetzen</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="155"/>
        <source>All options reset to their defaults.</source>
        <translation>Alle Optionen auf ihre Standardwerte zurückgesetzt.</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="166"/>
        <source>Loaded profile %1</source>
        <translation>Profil %1 geladen</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="177"/>
        <source>Saved profile %1</source>
        <translation>Profil %1 gespeichert</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="184"/>
        <source>Load profile</source>
        <translation>Profil laden</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="184"/>
        <source>YAML profiles (*.yaml *.yml);;All files (*)</source>
        <translation>YAML-Profile (*.yaml *.yml);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="191"/>
        <source>Save profile</source>
        <translation>Profil speichern</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="192"/>
        <source>YAML profiles (*.yaml *.yml)</source>
        <translation>YAML-Profile (*.yaml *.yml)</translation>
    </message>
</context>
<context>
    <name>sightline::PlaybackBar</name>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="35"/>
        <source>Step one frame</source>
        <translation>Ein Bild weiter</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="54"/>
        <source>Playback speed relative to the recording&apos;s timestamps</source>
        <translation>Wiedergabegeschwindigkeit relativ zu den Zeitstempeln der Aufnahme</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="58"/>
        <source>max</source>
        <translation>max</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="64"/>
        <source>Loop</source>
        <translation>Schleife</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="111"/>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="111"/>
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
</context>
<context>
    <name>sightline::RecordingController</name>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="16"/>
        <source>&amp;Record...</source>
        <translation>&amp;Aufnehmen...</translation>
    </message>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="20"/>
        <source>Record what is playing (live sensor or recording) into a folder, in the formats Sightline reads</source>
        <translation>Das Laufende (Live-Sensor oder Aufnahme) in einen Ordner aufnehmen, in den Formaten, die Sightline liest</translation>
    </message>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="22"/>
        <source>&amp;Stop recording</source>
        <translation>Aufnahme &amp;beenden</translation>
    </message>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="41"/>
        <source>Record into folder</source>
        <translation>In Ordner aufnehmen</translation>
    </message>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="60"/>
        <source>Nothing to record: open a sensor or a recording first.</source>
        <translation>Nichts aufzunehmen: zuerst einen Sensor oder eine Aufnahme öffnen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="102"/>
        <source>Recorded %1 frames into %2 (%3 dropped by the recorder), %4 MB at %5 MB/s</source>
        <translation>%1 Bilder in %2 aufgenommen (%3 vom Rekorder verworfen), %4 MB mit %5 MB/s</translation>
    </message>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="122"/>
        <source>REC %1 written, %2 dropped, %3 MB/s</source>
        <translation>REC %1 geschrieben, %2 verworfen, %3 MB/s</translation>
    </message>
</context>
<context>
    <name>sightline::ScalePlot</name>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="44"/>
        <source>scale: waiting for displacement pairs</source>
        <translation>Maßstab: warte auf Verschiebungspaare</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="58"/>
        <source>pairs (map units per metre)</source>
        <translation>Paare (Karteneinheiten pro Meter)</translation>
    </message>
</context>
<context>
    <name>sightline::StatisticsPresenter</name>
    <message>
        <location filename="../app/sightline/statistics_presenter.cpp" line="24"/>
        <source>Statistic</source>
        <translation>Kennzahl</translation>
    </message>
    <message>
        <location filename="../app/sightline/statistics_presenter.cpp" line="24"/>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <location filename="../app/sightline/statistics_presenter.cpp" line="24"/>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <location filename="../app/sightline/statistics_presenter.cpp" line="24"/>
        <source>Meaning</source>
        <translation>Bedeutung</translation>
    </message>
    <message>
        <location filename="../app/sightline/statistics_presenter.cpp" line="30"/>
        <source>Statistics: %1</source>
        <translation>Kennzahlen: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/statistics_presenter.cpp" line="54"/>
        <source>status</source>
        <translation>Status</translation>
    </message>
</context>
<context>
    <name>sightline::StereoVoPresenter</name>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="89"/>
        <source>Stereo visual odometry</source>
        <translation>Visuelle Stereo-Odometrie</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="99"/>
        <source>Tracks (inliers green, outliers red, new blue)</source>
        <translation>Tracks (Inlier grün, Outlier rot, neu blau)</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="103"/>
        <source>Stereo matches (right image)</source>
        <translation>Stereo-Zuordnungen (rechtes Bild)</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="110"/>
        <source>per frame [%1]</source>
        <translation>pro Bild [%1]</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="111"/>
        <source>%1 per stage</source>
        <translation>%1 pro Stufe</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="113"/>
        <source>residual [%1]; red: gated</source>
        <translation>Residuum [%1]; rot: gesperrt</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="118"/>
        <source>Statistics over time</source>
        <translation>Statistik im Zeitverlauf</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="202"/>
        <source>tracked %1, new %2, stereo %3, inliers %4, RANSAC %5 it., residual %6 %7, %8 %9%10</source>
        <translation>verfolgt %1, neu %2, Stereo %3, Inlier %4, RANSAC %5 It., Residuum %6 %7, %8 %9%10</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="212"/>
        <source>, GATED: pose held</source>
        <translation>, GESPERRT: Pose gehalten</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="42"/>
        <source>tracks</source>
        <translation>Tracks</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="44"/>
        <source>anchored</source>
        <translation>verankert</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="46"/>
        <source>stereo</source>
        <translation>Stereo</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="48"/>
        <source>inliers</source>
        <translation>Inlier</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="50"/>
        <source>RANSAC it.</source>
        <translation>RANSAC-It.</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="54"/>
        <source>rectify</source>
        <translation>Rektifizierung</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="56"/>
        <source>pyramid</source>
        <translation>Pyramide</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="58"/>
        <source>tracking</source>
        <translation>Tracking</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="60"/>
        <source>detection</source>
        <translation>Detektion</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="62"/>
        <source>matching</source>
        <translation>Matching</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="64"/>
        <source>RANSAC</source>
        <translation>RANSAC</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="66"/>
        <source>refine</source>
        <translation>Verfeinerung</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="68"/>
        <source>window BA</source>
        <translation>Fenster-BA</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="70"/>
        <source>total</source>
        <translation>gesamt</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="221"/>
        <source>residual</source>
        <translation>Residuum</translation>
    </message>
</context>
</TS>
