<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>ImageView</name>
    <message>
        <location filename="../widgets/image_view.cpp" line="47"/>
        <location filename="../widgets/image_view.cpp" line="78"/>
        <location filename="../widgets/image_view.cpp" line="131"/>
        <source>No image</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/image_view.cpp" line="81"/>
        <source>Unsupported image type %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>LogPanel</name>
    <message>
        <location filename="../widgets/log_panel.cpp" line="36"/>
        <source>Clear messages</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="34"/>
        <source>Sightline</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="64"/>
        <location filename="../app/sightline/main_window.cpp" line="169"/>
        <source>Colour</source>
        <translation>Farbe</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="65"/>
        <location filename="../app/sightline/main_window.cpp" line="170"/>
        <source>Depth</source>
        <translation>Tiefe</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="69"/>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="71"/>
        <source>Log</source>
        <translation>Protokoll</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="74"/>
        <source>Playback</source>
        <translation>Wiedergabe</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="84"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="85"/>
        <source>&amp;Open dataset folder...</source>
        <translation>Datensatz-Ordner &amp;öffnen...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="88"/>
        <source>Open dataset folder</source>
        <translation>Datensatz-Ordner öffnen</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="91"/>
        <source>Open point cloud &amp;file...</source>
        <translation>Punktwolken-&amp;Datei öffnen...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="93"/>
        <source>Open point cloud</source>
        <translation>Punktwolke öffnen</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="94"/>
        <source>Point clouds (*.pcd)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="97"/>
        <source>Open &amp;recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="100"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="104"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="105"/>
        <source>&amp;Reset 3D view</source>
        <translation>3D-Ansicht &amp;zurücksetzen</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="111"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="112"/>
        <source>&amp;About Sightline</source>
        <translation>Ü&amp;ber Sightline</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="113"/>
        <source>About Sightline</source>
        <translation>Über Sightline</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="114"/>
        <source>Sightline: robot perception for assistive and mobile robotics.
Indoor mapping, mobility maps, stereo odometry and monocular button localisation on live sensors or recorded data.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="126"/>
        <source>Could not open %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="127"/>
        <source>Could not open %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="135"/>
        <source>End of recording.</source>
        <translation>Ende der Aufnahme.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="157"/>
        <location filename="../app/sightline/main_window.cpp" line="158"/>
        <source>Opening %1 ...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="169"/>
        <source>Left</source>
        <translation>Links</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="169"/>
        <source>Image</source>
        <translation>Bild</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="170"/>
        <source>Right</source>
        <translation>Rechts</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="176"/>
        <source>%1: %2, %3 frames, %4x%5%6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="181"/>
        <source>, ground truth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="183"/>
        <source>Opened %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="188"/>
        <source>Sightline - %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="216"/>
        <source>frame %1, read in %2 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="237"/>
        <source>No dataset open. Use File &gt; Open dataset folder (TUM RGB-D, EuRoC, KITTI, an image folder or PCD files), or drop a folder on this window.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="239"/>
        <source>No dataset open</source>
        <translation>Kein Datensatz geöffnet</translation>
    </message>
</context>
<context>
    <name>OptionEditor</name>
    <message>
        <location filename="../widgets/option_editor.cpp" line="68"/>
        <source>Reset to default (%1)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ParameterPanel</name>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="45"/>
        <source>Filter options</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="49"/>
        <source>Load profile…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="52"/>
        <source>Save profile…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="55"/>
        <source>Reset all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="154"/>
        <source>All options reset to their defaults.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="165"/>
        <source>Loaded profile %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="175"/>
        <source>Saved profile %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="182"/>
        <source>Load profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="182"/>
        <source>YAML profiles (*.yaml *.yml);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="189"/>
        <source>Save profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="190"/>
        <source>YAML profiles (*.yaml *.yml)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>PlaybackBar</name>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="35"/>
        <source>Step one frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="54"/>
        <source>Playback speed relative to the recording&apos;s timestamps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="58"/>
        <source>max</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="64"/>
        <source>Loop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="111"/>
        <source>Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="111"/>
        <source>Play</source>
        <translation type="unfinished"></translation>
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
        <translation>Brett</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="214"/>
        <source>Board found in %1 of %2 %3.</source>
        <translation>Brett in %1 von %2 %3 gefunden.</translation>
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
        <location filename="../app/sightline/calibration_dialog.cpp" line="208"/>
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
        <translation>Quelle und Brett wählen, dann Kalibrieren drücken.</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="171"/>
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
        <location filename="../app/sightline/calibration_dialog.cpp" line="305"/>
        <source>Detected corners: %1 (%2 px)</source>
        <translation>Gefundene Ecken: %1 (%2 px)</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="177"/>
        <source>Detecting the board...</source>
        <translation>Suche das Brett...</translation>
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
        <location filename="../app/sightline/calibration_dialog.cpp" line="253"/>
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
        <location filename="../app/sightline/calibration_dialog.cpp" line="336"/>
        <source>Nothing to save: calibrate first.</source>
        <translation>Nichts zu speichern: zuerst kalibrieren.</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="350"/>
        <source>OpenCV YAML (*.yaml *.yml)</source>
        <translation>OpenCV-YAML (*.yaml *.yml)</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="241"/>
        <source>RMS %1 px; %2 views used, %3 rejected.</source>
        <translation>RMS %1 px; %2 Ansichten verwendet, %3 verworfen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="233"/>
        <source>RMS left %1 px, right %2 px, stereo %3 px; baseline %4 mm; %5 of %6 pairs used.</source>
        <translation>RMS links %1 px, rechts %2 px, Stereo %3 px; Basislinie %4 mm; %5 von %6 Paaren verwendet.</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="117"/>
        <source>Right error (px)</source>
        <translation>Fehler rechts (px)</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="349"/>
        <source>Save calibration</source>
        <translation>Kalibrierung speichern</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="344"/>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="353"/>
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
        <location filename="../app/sightline/calibration_dialog.cpp" line="247"/>
        <source>fx %1 fy %2 cx %3 cy %4; coverage: %5</source>
        <translation>fx %1 fy %2 cx %3 cy %4; Abdeckung: %5</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="217"/>
        <source>images</source>
        <translation>Bildern</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="85"/>
        <source>inner corners, squares of</source>
        <translation>innere Ecken, Felder von</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="217"/>
        <source>pairs</source>
        <translation>Paaren</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="278"/>
        <location filename="../app/sightline/calibration_dialog.cpp" line="292"/>
        <source>rejected</source>
        <translation>verworfen</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="278"/>
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
    <name>sightline::MainWindow</name>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="160"/>
        <source>&amp;Calibrate camera...</source>
        <translation>Kamera &amp;kalibrieren...</translation>
    </message>
</context>
<context>
    <name>sightline::ButtonPickerPresenter</name>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="132"/>
        <source>Button picker (monocular SLAM)</source>
        <translation>Knopfwahl (monokulares SLAM)</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="156"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="188"/>
        <source>Operator panel</source>
        <translation>Bedienfeld</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="177"/>
        <source>Operator panel full screen</source>
        <translation>Bedienfeld im Vollbild</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="190"/>
        <source>View</source>
        <translation>Ansicht</translation>
    </message>
</context>
<context>
    <name>sightline::OperatorPanel</name>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="180"/>
        <source>%1 cm</source>
        <translation>%1 cm</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="185"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="159"/>
        <source>Locating</source>
        <translation>Lokalisiere</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="161"/>
        <source>Lost - hold still</source>
        <translation>Verloren - still halten</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="156"/>
        <source>No button here - tap again</source>
        <translation>Kein Knopf hier - erneut tippen</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="155"/>
        <source>Press this button?</source>
        <translation>Diesen Knopf drücken?</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="186"/>
        <source>STOP</source>
        <translation>STOPP</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="157"/>
        <source>Searching</source>
        <translation>Suche</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="187"/>
        <source>Start again</source>
        <translation>Neu starten</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="162"/>
        <source>Stopped</source>
        <translation>Gestoppt</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="154"/>
        <source>Tap a button</source>
        <translation>Knopf antippen</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="160"/>
        <source>Target sent</source>
        <translation>Ziel gesendet</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="158"/>
        <source>Tracking</source>
        <translation>Verfolge</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="184"/>
        <source>Yes</source>
        <translation>Ja</translation>
    </message>
</context>
</TS>
