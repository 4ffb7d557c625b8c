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
</TS>
