<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
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
        <location filename="../app/sightline/calibration_dialog.cpp" line="224"/>
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
        <translation>Quelle und Brett wählen, dann Kalibrieren drücken.</translation>
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
    <name>sightline::DemoGenerator</name>
    <message>
        <location filename="../app/sightline/demo_generator.cpp" line="46"/>
        <source>cannot create the demo folder %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/demo_generator.cpp" line="84"/>
        <source>cannot write %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sightline::EvaluationPanel</name>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="73"/>
        <source>estimated trajectory (TUM or KITTI file)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="75"/>
        <source>ground truth (TUM or KITTI file)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="79"/>
        <source>Browse...</source>
        <translation type="unfinished">Durchsuchen...</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="88"/>
        <source>SE(3): rotation and translation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="89"/>
        <source>Sim(3): also scale (monocular)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="90"/>
        <source>None</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="91"/>
        <source>Evaluate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="98"/>
        <source>Estimate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="98"/>
        <source>Estimated trajectory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="99"/>
        <source>Ground truth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="100"/>
        <source>Alignment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="102"/>
        <source>Choose two trajectory files and press Evaluate.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="105"/>
        <source>Figure</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="105"/>
        <source>Value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="115"/>
        <source>Figures</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="116"/>
        <source>Top view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="117"/>
        <source>Error over time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="130"/>
        <source>Trajectories (*.txt *.csv);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="138"/>
        <source>Evaluating...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="162"/>
        <source>Evaluation failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="172"/>
        <source>%1 associated poses, ground-truth path %2 m.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sightline::ImageView</name>
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
    <name>sightline::LiveStatusWidget</name>
    <message>
        <location filename="../app/sightline/live_status_widget.cpp" line="23"/>
        <source>&lt;span style=&apos;color:%1&apos;&gt;&amp;#9679;&lt;/span&gt; %2 &amp;nbsp;%3 fps &amp;nbsp;dropped %4 &amp;nbsp;latency %5 ms</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sightline::LogPanel</name>
    <message>
        <location filename="../widgets/log_panel.cpp" line="36"/>
        <source>Clear messages</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sightline::MainWindow</name>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="43"/>
        <source>Sightline</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="73"/>
        <location filename="../app/sightline/main_window.cpp" line="337"/>
        <source>Colour</source>
        <translation>Farbe</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="74"/>
        <location filename="../app/sightline/main_window.cpp" line="338"/>
        <source>Depth</source>
        <translation>Tiefe</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="78"/>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="80"/>
        <source>Log</source>
        <translation>Protokoll</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="82"/>
        <source>Evaluation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="91"/>
        <source>Playback</source>
        <translation>Wiedergabe</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="101"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="102"/>
        <source>&amp;Open dataset folder...</source>
        <translation>Datensatz-Ordner &amp;öffnen...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="105"/>
        <source>Open dataset folder</source>
        <translation>Datensatz-Ordner öffnen</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="110"/>
        <source>Open point cloud</source>
        <translation>Punktwolke öffnen</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="108"/>
        <source>Open recording &amp;file (PCD, ONI)...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="111"/>
        <source>Recordings (*.pcd *.oni)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="114"/>
        <source>Open &amp;recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="117"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="121"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="122"/>
        <source>&amp;Reset 3D view</source>
        <translation>3D-Ansicht &amp;zurücksetzen</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="129"/>
        <source>&amp;Sensors</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="134"/>
        <source> (unavailable)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="138"/>
        <source>Connect to the first %1 device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="145"/>
        <source>Replay recording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="151"/>
        <source>&amp;Pipeline</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="153"/>
        <location filename="../app/sightline/main_window.cpp" line="278"/>
        <source>None (show frames only)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="160"/>
        <source>&amp;Tools</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="161"/>
        <source>&amp;Evaluate trajectory...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="171"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="172"/>
        <source>&amp;About Sightline</source>
        <translation>Ü&amp;ber Sightline</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="173"/>
        <source>About Sightline</source>
        <translation>Über Sightline</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="174"/>
        <source>Sightline: robot perception for assistive and mobile robotics.
Indoor mapping, mobility maps, stereo odometry and monocular button localisation on live sensors or recorded data.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="186"/>
        <source>Could not open %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="187"/>
        <source>Could not open %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="195"/>
        <source>End of recording.</source>
        <translation>Ende der Aufnahme.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="219"/>
        <source>Demo %p%</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="226"/>
        <source>Generating the demo recordings (only the first time)...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="235"/>
        <source>Demo: a robot drives a simulated office corridor (RGB-D, stereo, wheel odometry, exact ground truth). The arm-camera panel approach is in %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="241"/>
        <source>The demo could not be made: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="296"/>
        <source>No pipeline: showing frames only.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="307"/>
        <source>Pipeline: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="311"/>
        <source>%1 cannot run on %2 frames; open another dataset.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="325"/>
        <location filename="../app/sightline/main_window.cpp" line="326"/>
        <source>Opening %1 ...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="337"/>
        <source>Left</source>
        <translation>Links</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="337"/>
        <source>Image</source>
        <translation>Bild</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="338"/>
        <source>Right</source>
        <translation>Rechts</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="344"/>
        <source>%1: %2, %3 frames, %4x%5%6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="349"/>
        <source>, ground truth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="351"/>
        <source>Opened %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="356"/>
        <source>Sightline - %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="391"/>
        <source>frame %1, read in %2 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="413"/>
        <source>No dataset open. Use File &gt; Open dataset folder (TUM RGB-D, EuRoC, KITTI, an image folder or PCD files), or drop a folder on this window.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="415"/>
        <source>No dataset open</source>
        <translation>Kein Datensatz geöffnet</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="166"/>
        <source>&amp;Calibrate camera...</source>
        <translation>Kamera &amp;kalibrieren...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_recording.cpp" line="19"/>
        <source>Recording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_recording.cpp" line="37"/>
        <source>Recording: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sightline::MappingPresenter</name>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="193"/>
        <source>Indoor mapping (Manhattan walls)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="213"/>
        <source>Occupancy, scan and walls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="219"/>
        <source>Calibrate floor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="220"/>
        <source>Fit the floor plane again from the next frames (the robot should see open floor).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="223"/>
        <source>Save floor...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="224"/>
        <source>Save the floor calibration in use, for mapping.run.floor_file or `sightline-cli run mapping --set mapping.run.floor_file=...`.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="227"/>
        <source>Save floor calibration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="228"/>
        <source>YAML (*.yaml)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="237"/>
        <source>Stitched map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="295"/>
        <source>Manhattan reference reset: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="311"/>
        <source>Calibrating the floor again from the next frames.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="323"/>
        <source>Saved the floor calibration to %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sightline::MobilityImagePanel</name>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="65"/>
        <source>Projection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="66"/>
        <source>Top view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="67"/>
        <source>GPR surface</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sightline::MobilityPresenter</name>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="108"/>
        <source>Mobility map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="130"/>
        <source>Mobility map (red 0, green 1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="134"/>
        <source>Mobility stages (Table II)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sightline::MobilityTimingPanel</name>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="21"/>
        <source>3D colour:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="23"/>
        <source>Score (rule)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="23"/>
        <source>Score (GPR)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="23"/>
        <source>Segment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="31"/>
        <source>Stage</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="31"/>
        <source>Time (ms)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="31"/>
        <source>Points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="47"/>
        <source>Total</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="50"/>
        <source>%1 mode, %2 segments</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="52"/>
        <source>, camera %1 m above the ground</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sightline::MonoSlamPresenter</name>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="195"/>
        <source>Monocular SLAM (PTAM point cloud)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="213"/>
        <source>Monocular SLAM needs a camera calibration (camera.yaml)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="229"/>
        <source>Reset map</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="230"/>
        <source>Pause mapping</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="243"/>
        <source>Tracked features (inliers green, outliers red)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="254"/>
        <source>Metric scale (ML solid, single ratio dashed)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="298"/>
        <source>%1: %2 inliers of %3 matches, %4 map points, %5 keyframes, %6 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="308"/>
        <source>Metric scale from %1: ML %2, single ratio %3 map units per metre; map and trajectory in metres.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="314"/>
        <source>Scale unknown (measured motion: %1): the map is in arbitrary units (first baseline = 0.1).</source>
        <translation type="unfinished"></translation>
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
<context>
    <name>sightline::OptionEditor</name>
    <message>
        <location filename="../widgets/option_editor.cpp" line="68"/>
        <source>Reset to default (%1)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sightline::ParameterPanel</name>
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
    <name>sightline::PlaybackBar</name>
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
    <name>sightline::RecordingController</name>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="15"/>
        <source>&amp;Record...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="19"/>
        <source>Record what is playing (live sensor or recording) into a folder, in the formats Sightline reads</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="21"/>
        <source>&amp;Stop recording</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="40"/>
        <source>Record into folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="47"/>
        <source>Nothing to record: open a sensor or a recording first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="90"/>
        <source>Recorded %1 frames into %2 (%3 dropped by the recorder), %4 MB at %5 MB/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="110"/>
        <source>REC %1 written, %2 dropped, %3 MB/s</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sightline::ScalePlot</name>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="43"/>
        <source>scale: waiting for displacement pairs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="57"/>
        <source>pairs (map units per metre)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sightline::StereoVoPresenter</name>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="109"/>
        <source>Stereo visual odometry</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="138"/>
        <source>Tracks (inliers green, outliers red, new blue)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="142"/>
        <source>Stereo matches (right image)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="148"/>
        <source>per frame: counts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="149"/>
        <source>ms per stage</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="150"/>
        <source>residual [px]; red: gated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="155"/>
        <source>Statistics over time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="216"/>
        <source>tracked %1, new %2, stereo %3, inliers %4, RANSAC %5 it., residual %6 px, %7 ms%8</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="225"/>
        <source>, GATED: pose held</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="242"/>
        <source>tracks</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="243"/>
        <source>stereo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="244"/>
        <source>inliers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="245"/>
        <source>RANSAC it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="247"/>
        <source>rectify</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="247"/>
        <source>pyramid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="248"/>
        <source>tracking</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="248"/>
        <source>detection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="249"/>
        <source>matching</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="249"/>
        <source>RANSAC</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="250"/>
        <source>refine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="250"/>
        <source>total</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="257"/>
        <source>residual</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
