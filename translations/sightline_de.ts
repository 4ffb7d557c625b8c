<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>sightline::ButtonPickerPresenter</name>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="42"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="86"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="90"/>
        <source>Stopped</source>
        <translation>Gestoppt</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="44"/>
        <source>Waiting for Yes</source>
        <translation>Warte auf Ja</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="46"/>
        <source>Button lost</source>
        <translation>Knopf verloren</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="48"/>
        <source>Button unclear</source>
        <translation>Knopf unklar</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="50"/>
        <source>Measuring the button</source>
        <translation>Knopf wird vermessen</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="52"/>
        <source>Measuring again</source>
        <translation>Neue Messung</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="54"/>
        <source>Measuring the distance</source>
        <translation>Abstand wird gemessen</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="56"/>
        <source>Panel unclear</source>
        <translation>Tastenfeld unklar</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="58"/>
        <source>Position not sure yet</source>
        <translation>Position noch unsicher</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="60"/>
        <source>Panel direction not sure yet</source>
        <translation>Richtung des Tastenfelds noch unsicher</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="62"/>
        <source>Button out of reach</source>
        <translation>Knopf außer Reichweite</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="72"/>
        <source>The picture changed: tap again</source>
        <translation>Das Bild hat sich geändert: bitte neu antippen</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="74"/>
        <source>The picture was too old: tap again</source>
        <translation>Das Bild war zu alt: bitte neu antippen</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="76"/>
        <source>Stopped: press Start again first</source>
        <translation>Gestoppt: zuerst „Neu starten“ drücken</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="85"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="227"/>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="214"/>
        <source>Paused</source>
        <translation>Angehalten</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="88"/>
        <source>Arm link off</source>
        <translation>Arm-Verbindung aus</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="89"/>
        <source>No arm connected</source>
        <translation>Kein Arm verbunden</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="93"/>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="219"/>
        <source>Waiting</source>
        <translation>Warten</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="114"/>
        <source>Button picker (monocular SLAM)</source>
        <translation>Knopfwahl (monokulares SLAM)</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="122"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="146"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="185"/>
        <source>Operator panel</source>
        <translation>Bedienfeld</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="126"/>
        <source>Operator panel full screen</source>
        <translation>Bedienfeld im Vollbild</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="227"/>
        <source>End of the recording</source>
        <translation>Ende der Aufnahme</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="245"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="253"/>
        <source>The picture is paused: press Play, then tap</source>
        <translation>Das Bild ist angehalten: erst Abspielen drücken, dann antippen</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="252"/>
        <source>The recording has ended: nothing to tap</source>
        <translation>Die Aufnahme ist zu Ende: nichts zum Antippen</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="254"/>
        <source>No picture yet: open a camera or a recording</source>
        <translation>Noch kein Bild: Kamera oder Aufnahme öffnen</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="291"/>
        <source>No button at the tap: %1</source>
        <translation>Kein Knopf an der getippten Stelle: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="306"/>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="206"/>
        <source>No metric scale (no arm motion)</source>
        <translation>Kein metrischer Maßstab (keine Armbewegung)</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="308"/>
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
    <name>sightline::CoreMessage</name>
    <message>
        <location filename="../widgets/core_message.cpp" line="17"/>
        <source>invalid argument</source>
        <translation>ungültiges Argument</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="18"/>
        <source>not found</source>
        <translation>nicht gefunden</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="19"/>
        <source>parse error</source>
        <translation>Formatfehler</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="20"/>
        <source>unavailable</source>
        <translation>nicht verfügbar</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="21"/>
        <source>out of range</source>
        <translation>außerhalb des Bereichs</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="22"/>
        <source>failed precondition</source>
        <translation>Vorbedingung nicht erfüllt</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="23"/>
        <source>internal error</source>
        <translation>interner Fehler</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="28"/>
        <source>%1 line %2</source>
        <translation>%1 Zeile %2</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="29"/>
        <source>profile %1</source>
        <translation>Profil %1</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="30"/>
        <source>parameter panel</source>
        <translation>Parameterleiste</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="36"/>
        <source>unknown option &apos;%1&apos;</source>
        <translation>unbekannte Option &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="37"/>
        <source>option &apos;%1&apos;: %2 is outside %3</source>
        <translation>Option &apos;%1&apos;: %2 liegt außerhalb von %3</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="38"/>
        <source>option &apos;%1&apos;: &apos;%2&apos; is not one of: %3</source>
        <translation>Option &apos;%1&apos;: &apos;%2&apos; ist keiner der Werte: %3</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="39"/>
        <source>option &apos;%1&apos;: &apos;%2&apos; is not a boolean (true/false)</source>
        <translation>Option &apos;%1&apos;: &apos;%2&apos; ist kein Wahrheitswert (true/false)</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="40"/>
        <source>option &apos;%1&apos;: &apos;%2&apos; is not an integer</source>
        <translation>Option &apos;%1&apos;: &apos;%2&apos; ist keine ganze Zahl</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="41"/>
        <source>option &apos;%1&apos;: &apos;%2&apos; is not a number</source>
        <translation>Option &apos;%1&apos;: &apos;%2&apos; ist keine Zahl</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="42"/>
        <source>option &apos;%1&apos;: value is not finite</source>
        <translation>Option &apos;%1&apos;: Wert ist nicht endlich</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="43"/>
        <source>a profile must be a map of option keys</source>
        <translation>ein Profil muss eine Zuordnung von Optionsschlüsseln sein</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="44"/>
        <source>option &apos;%1&apos; is given twice (also line %2)</source>
        <translation>Option &apos;%1&apos; ist doppelt angegeben (auch Zeile %2)</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="45"/>
        <source>option &apos;%1&apos; has no value</source>
        <translation>Option &apos;%1&apos; hat keinen Wert</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="46"/>
        <source>option &apos;%1&apos; must be a single value, not a list</source>
        <translation>Option &apos;%1&apos; muss ein einzelner Wert sein, keine Liste</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="47"/>
        <source>an option key must be a word, not a list or map</source>
        <translation>ein Optionsschlüssel muss ein Wort sein, keine Liste oder Zuordnung</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="48"/>
        <source>options nest deeper than %1 levels</source>
        <translation>Optionen sind tiefer als %1 Ebenen verschachtelt</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="49"/>
        <source>lists or maps nest deeper than %1 levels</source>
        <translation>Listen oder Zuordnungen sind tiefer als %1 Ebenen verschachtelt</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="50"/>
        <source>more than %1 values (aliases expanding?); a profile lists each option once</source>
        <translation>mehr als %1 Werte (expandierende Aliase?); ein Profil nennt jede Option einmal</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="52"/>
        <source>not a readable YAML profile: %1</source>
        <translation>kein lesbares YAML-Profil: %1</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="53"/>
        <source>cannot write profile %1</source>
        <translation>Profil %1 kann nicht geschrieben werden</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="54"/>
        <source>write to %1 failed (disk full?)</source>
        <translation>Schreiben nach %1 fehlgeschlagen (Datenträger voll?)</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="55"/>
        <source>no such file</source>
        <translation>Datei nicht vorhanden</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="56"/>
        <source>profile %1 is a folder, not a file</source>
        <translation>Profil %1 ist ein Ordner, keine Datei</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="57"/>
        <source>profile %1 is not a regular file (a device, pipe or socket)</source>
        <translation>Profil %1 ist keine reguläre Datei (ein Gerät, eine Pipe oder ein Socket)</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="59"/>
        <source>profile %1 cannot be read: %2</source>
        <translation>Profil %1 kann nicht gelesen werden: %2</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="60"/>
        <source>profile %1 is %2 bytes; a profile holds at most %3</source>
        <translation>Profil %1 ist %2 Bytes groß; ein Profil umfasst höchstens %3</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="62"/>
        <source>cannot read its size: %1</source>
        <translation>Größe nicht lesbar: %1</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="63"/>
        <source>read error (%1 of %2 bytes)</source>
        <translation>Lesefehler (%1 von %2 Bytes)</translation>
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
    <message>
        <location filename="../app/sightline/core_texts.cpp" line="19"/>
        <source>ROS 1 bag files (.bag): images, RGB-D, stereo and point clouds, with tf ground truth</source>
        <translation>ROS-1-Bag-Dateien (.bag): Bilder, RGB-D, Stereo und Punktwolken, mit Referenz aus tf</translation>
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
        <location filename="../app/sightline/evaluation_panel.cpp" line="175"/>
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
        <location filename="../app/sightline/evaluation_panel.cpp" line="185"/>
        <source>Evaluation failed: %1</source>
        <translation>Auswertung fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="198"/>
        <source>%1 associated poses, ground-truth path %2 m.</source>
        <translation>%1 zugeordnete Posen, Weglänge der Ground Truth %2 m.</translation>
    </message>
</context>
<context>
    <name>sightline::ImageView</name>
    <message>
        <location filename="../widgets/image_view.cpp" line="49"/>
        <location filename="../widgets/image_view.cpp" line="80"/>
        <location filename="../widgets/image_view.cpp" line="135"/>
        <source>No image</source>
        <translation>Kein Bild</translation>
    </message>
    <message>
        <location filename="../widgets/image_view.cpp" line="83"/>
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
        <location filename="../widgets/log_panel.cpp" line="33"/>
        <source>Click a line to read it in full.</source>
        <translation>Klicken Sie auf eine Zeile, um sie vollständig zu lesen.</translation>
    </message>
    <message>
        <location filename="../widgets/log_panel.cpp" line="51"/>
        <source>Clear messages</source>
        <translation>Meldungen löschen</translation>
    </message>
</context>
<context>
    <name>sightline::MainWindow</name>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="47"/>
        <source>Sightline</source>
        <translation>Sightline</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="82"/>
        <location filename="../app/sightline/main_window.cpp" line="405"/>
        <source>Colour</source>
        <translation>Farbe</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="83"/>
        <location filename="../app/sightline/main_window.cpp" line="406"/>
        <source>Depth</source>
        <translation>Tiefe</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="89"/>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="91"/>
        <source>Log</source>
        <translation>Protokoll</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="94"/>
        <source>Evaluation</source>
        <translation>Auswertung</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="107"/>
        <source>Playback</source>
        <translation>Wiedergabe</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="117"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="118"/>
        <source>&amp;Open dataset folder...</source>
        <translation>Datensatz-Ordner &amp;öffnen...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="121"/>
        <source>Open dataset folder</source>
        <translation>Datensatz-Ordner öffnen</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="126"/>
        <source>Open point cloud</source>
        <translation>Punktwolke öffnen</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="124"/>
        <source>Open recording &amp;file (PCD, ONI)...</source>
        <translation>Aufnahme&amp;datei öffnen (PCD, ONI)...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="127"/>
        <source>Recordings (*.pcd *.oni *.bag)</source>
        <translation>Aufnahmen (*.pcd *.oni *.bag)</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="130"/>
        <source>Open &amp;recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="137"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="141"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="143"/>
        <source>&amp;Reset 3D view</source>
        <translation>3D-Ansicht &amp;zurücksetzen</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="146"/>
        <source>&amp;Follow the trajectory</source>
        <translation>Der Trajektorie &amp;folgen</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="148"/>
        <source>Fit the 3D view again whenever a growing trajectory leaves it.</source>
        <translation>Die 3D-Ansicht neu einpassen, sobald eine wachsende Trajektorie sie verlässt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="157"/>
        <source>&amp;Sensors</source>
        <translation>&amp;Sensoren</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="164"/>
        <source> (unavailable)</source>
        <translation> (nicht verfügbar)</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="169"/>
        <source>Connect to the first %1 device</source>
        <translation>Mit dem ersten %1-Gerät verbinden</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="175"/>
        <source>Replay recording</source>
        <translation>Aufnahme abspielen</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="181"/>
        <source>&amp;Pipeline</source>
        <translation>&amp;Pipeline</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="183"/>
        <location filename="../app/sightline/main_window.cpp" line="327"/>
        <source>None (show frames only)</source>
        <translation>Keine (nur Bilder zeigen)</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="190"/>
        <source>&amp;Tools</source>
        <translation>&amp;Werkzeuge</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="191"/>
        <source>&amp;Evaluate trajectory...</source>
        <translation>Trajektorie &amp;auswerten...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="196"/>
        <source>Evaluate &amp;current run</source>
        <translation>&amp;Aktuellen Lauf auswerten</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="198"/>
        <source>Compares the running pipeline&apos;s trajectory with the dataset&apos;s ground truth.</source>
        <translation>Vergleicht die Trajektorie der laufenden Pipeline mit der Referenz des Datensatzes.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="207"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="208"/>
        <source>&amp;About Sightline</source>
        <translation>Ü&amp;ber Sightline</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="209"/>
        <source>About Sightline</source>
        <translation>Über Sightline</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="210"/>
        <source>Sightline: robot perception for assistive and mobile robotics.
Indoor mapping, mobility maps, stereo odometry and monocular button localisation on live sensors or recorded data.</source>
        <translation>Sightline: Roboterwahrnehmung für assistive und mobile Robotik.
Innenraumkartierung, Befahrbarkeitskarten, Stereo-Odometrie und monokulare Knopflokalisierung auf Live-Sensoren oder aufgezeichneten Daten.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="227"/>
        <source>Could not open %1: %2</source>
        <translation>%1 konnte nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="228"/>
        <source>Could not open %1</source>
        <translation>%1 konnte nicht geöffnet werden</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="236"/>
        <source>End of recording.</source>
        <translation>Ende der Aufnahme.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="265"/>
        <source>Demo %p%</source>
        <translation>Demo %p%</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="272"/>
        <source>Generating the demo recordings (only the first time)...</source>
        <translation>Die Demo-Aufnahmen werden erzeugt (nur beim ersten Mal)...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="281"/>
        <source>Demo: a robot drives a simulated office corridor (RGB-D, stereo, wheel odometry, exact ground truth). The arm-camera panel approach is in %1.</source>
        <translation>Demo: Ein Roboter fährt durch einen simulierten Büroflur (RGB-D, Stereo, Radodometrie, exakte Ground Truth). Die Annäherung der Armkamera an das Tastenfeld liegt in %1.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="288"/>
        <source>The demo could not be made: %1</source>
        <translation>Die Demo konnte nicht erzeugt werden: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="345"/>
        <source>No pipeline: showing frames only.</source>
        <translation>Keine Pipeline: nur die Bilder werden gezeigt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="356"/>
        <source>Pipeline: %1</source>
        <translation>Pipeline: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="360"/>
        <source>%1 cannot run on %2 frames; open another dataset.</source>
        <translation>%1 kann nicht auf %2-Bildern laufen; bitte einen anderen Datensatz öffnen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="389"/>
        <location filename="../app/sightline/main_window.cpp" line="390"/>
        <source>Opening %1 ...</source>
        <translation>Öffne %1 ...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="405"/>
        <source>Left</source>
        <translation>Links</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="405"/>
        <source>Image</source>
        <translation>Bild</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="406"/>
        <source>Right</source>
        <translation>Rechts</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="412"/>
        <source>%1: %2, %3 frames, %4x%5%6</source>
        <translation>%1: %2, %3 Bilder, %4x%5%6</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="417"/>
        <source>, ground truth</source>
        <translation>, Ground Truth</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="419"/>
        <source>Opened %1</source>
        <translation>Geöffnet: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="424"/>
        <source>Sightline - %1</source>
        <translation>Sightline - %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="443"/>
        <source>frame %1, read in %2 ms</source>
        <translation>Bild %1, gelesen in %2 ms</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="492"/>
        <source>No dataset open. Use File &gt; Open dataset folder (TUM RGB-D, EuRoC, KITTI, an image folder or PCD files), or drop a folder on this window.</source>
        <translation>Kein Datensatz geöffnet. Datei &gt; Datensatz-Ordner öffnen wählen (TUM RGB-D, EuRoC, KITTI, ein Bildordner oder PCD-Dateien) oder einen Ordner auf dieses Fenster ziehen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="494"/>
        <source>No dataset open</source>
        <translation>Kein Datensatz geöffnet</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="200"/>
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
    <message>
        <location filename="../app/sightline/main_window_playback.cpp" line="44"/>
        <source>Reset the map?</source>
        <translation>Karte zurücksetzen?</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_playback.cpp" line="45"/>
        <source>%1 has built its map over %2 frames. Seeking starts it over from the frame you seek to: the map and the trajectory so far are lost.</source>
        <translation>%1 hat seine Karte über %2 Bilder aufgebaut. Ein Sprung beginnt sie ab dem angesprungenen Bild neu: Die bisherige Karte und Trajektorie gehen verloren.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_playback.cpp" line="51"/>
        <source>Seek and reset the map</source>
        <translation>Springen und Karte zurücksetzen</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_playback.cpp" line="53"/>
        <source>Keep the map</source>
        <translation>Karte behalten</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_ros.cpp" line="24"/>
        <source>Connect to &amp;ROS master...</source>
        <translation>Mit &amp;ROS-Master verbinden...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_ros.cpp" line="25"/>
        <source>&amp;Disconnect from ROS master</source>
        <translation>Vom ROS-Master &amp;trennen</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_ros.cpp" line="32"/>
        <source>Connect to ROS master</source>
        <translation>Mit ROS-Master verbinden</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_ros.cpp" line="40"/>
        <source>Disconnected from the ROS master</source>
        <translation>Vom ROS-Master getrennt</translation>
    </message>
</context>
<context>
    <name>sightline::MappingPresenter</name>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="112"/>
        <source>Indoor mapping (Manhattan walls)</source>
        <translation>Innenraumkartierung (Manhattan-Wände)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="119"/>
        <source>Occupancy, scan and walls</source>
        <translation>Belegung, Scan und Wände</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="125"/>
        <source>Calibrate floor</source>
        <translation>Boden kalibrieren</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="127"/>
        <source>Fit the floor plane again from the next frames (the robot should see open floor).</source>
        <translation>Die Bodenebene aus den nächsten Bildern neu schätzen (der Roboter sollte freien Boden sehen).</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="130"/>
        <source>Save floor...</source>
        <translation>Boden speichern...</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="132"/>
        <source>Save the floor calibration in use, for mapping.run.floor_file or `sightline-cli run mapping --set mapping.run.floor_file=...`.</source>
        <translation>Die verwendete Bodenkalibrierung speichern, für mapping.run.floor_file oder `sightline-cli run mapping --set mapping.run.floor_file=...`.</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="135"/>
        <source>Save floor calibration</source>
        <translation>Bodenkalibrierung speichern</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="136"/>
        <source>YAML (*.yaml)</source>
        <translation>YAML (*.yaml)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="148"/>
        <source>Stitched map</source>
        <translation>Zusammengesetzte Karte</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="180"/>
        <location filename="../app/sightline/mapping_presenter.cpp" line="212"/>
        <source>free</source>
        <translation>frei</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="181"/>
        <location filename="../app/sightline/mapping_presenter.cpp" line="214"/>
        <source>occupied</source>
        <translation>belegt</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="182"/>
        <source>person</source>
        <translation>Person</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="183"/>
        <source>scan rays</source>
        <translation>Scanstrahlen</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="184"/>
        <location filename="../app/sightline/mapping_presenter.cpp" line="223"/>
        <source>walls, first direction</source>
        <translation>Wände, erste Richtung</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="185"/>
        <location filename="../app/sightline/mapping_presenter.cpp" line="224"/>
        <source>walls, perpendicular</source>
        <translation>Wände, senkrecht dazu</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="186"/>
        <location filename="../app/sightline/mapping_presenter.cpp" line="225"/>
        <source>other lines</source>
        <translation>andere Linien</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="187"/>
        <source>robot</source>
        <translation>Roboter</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="213"/>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="215"/>
        <source>path and robot</source>
        <translation>Pfad und Roboter</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="226"/>
        <source>floor</source>
        <translation>Boden</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="228"/>
        <source>map: free</source>
        <translation>Karte: frei</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="229"/>
        <source>map: occupied</source>
        <translation>Karte: belegt</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="230"/>
        <source>path</source>
        <translation>Pfad</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="235"/>
        <source>Manhattan reference reset: %1</source>
        <translation>Manhattan-Referenz zurückgesetzt: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="276"/>
        <source>Calibrating the floor again from the next frames.</source>
        <translation>Der Boden wird aus den nächsten Bildern neu kalibriert.</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="289"/>
        <source>Saved the floor calibration to %1</source>
        <translation>Bodenkalibrierung in %1 gespeichert</translation>
    </message>
</context>
<context>
    <name>sightline::MobilityImagePanel</name>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="73"/>
        <source>Projection</source>
        <translation>Projektion</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="74"/>
        <source>Top view</source>
        <translation>Draufsicht</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="75"/>
        <source>GPR surface</source>
        <translation>GPR-Fläche</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="85"/>
        <source>score 0: not passable</source>
        <translation>Bewertung 0: nicht befahrbar</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="86"/>
        <source>score 0.5</source>
        <translation>Bewertung 0,5</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="87"/>
        <source>score 1: passable</source>
        <translation>Bewertung 1: befahrbar</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="88"/>
        <source>not scored</source>
        <translation>nicht bewertet</translation>
    </message>
</context>
<context>
    <name>sightline::MobilityPresenter</name>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="27"/>
        <source>Mobility map</source>
        <translation>Befahrbarkeitskarte</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="37"/>
        <source>Mobility map (red 0, green 1)</source>
        <translation>Befahrbarkeitskarte (rot 0, grün 1)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="41"/>
        <source>Mobility stages (Table II)</source>
        <translation>Befahrbarkeitskarte: Stufen (Tabelle II)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="77"/>
        <source>colour: one per segment</source>
        <translation>Farbe: eine je Segment</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="80"/>
        <source>score 0: not passable</source>
        <translation>Bewertung 0: nicht befahrbar</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="80"/>
        <source>score 1: passable</source>
        <translation>Bewertung 1: befahrbar</translation>
    </message>
</context>
<context>
    <name>sightline::MobilityTimingPanel</name>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="22"/>
        <source>3D colour:</source>
        <translation>3D-Farbe:</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="24"/>
        <source>Score (rule)</source>
        <translation>Bewertung (Regel)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="24"/>
        <source>Score (GPR)</source>
        <translation>Bewertung (GPR)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="24"/>
        <source>Segment</source>
        <translation>Segment</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="32"/>
        <source>Stage</source>
        <translation>Stufe</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="32"/>
        <source>Time (ms)</source>
        <translation>Zeit (ms)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="32"/>
        <source>Points</source>
        <translation>Punkte</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="53"/>
        <source>Total</source>
        <translation>Gesamt</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="56"/>
        <source>%1 mode, %2 segments</source>
        <translation>Modus %1, %2 Segmente</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="60"/>
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
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="194"/>
        <source>inlier</source>
        <translation>Inlier</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="195"/>
        <source>outlier</source>
        <translation>Ausreißer</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="196"/>
        <source>keypoint, unmatched</source>
        <translation>Merkmalspunkt, ohne Zuordnung</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="197"/>
        <source>frame: tracking quality</source>
        <translation>Rahmen: Tracking-Qualität</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="212"/>
        <source>%1: %2 inliers of %3 matches, %4 map points, %5 keyframes, %6 ms</source>
        <translation>%1: %2 Inlier von %3 Zuordnungen, %4 Kartenpunkte, %5 Keyframes, %6 ms</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="222"/>
        <source>Metric scale from %1: ML %2, single ratio %3 map units per metre; map and trajectory in metres.</source>
        <translation>Metrischer Maßstab (Quelle: %1): ML %2, Einzelverhältnis %3 Karteneinheiten pro Meter; Karte und Trajektorie in Metern.</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="228"/>
        <source>Scale unknown (measured motion: %1): the map is in arbitrary units (first baseline = 0.1).</source>
        <translation>Maßstab unbekannt (gemessene Bewegung: %1): Die Karte ist in beliebigen Einheiten (erste Basislinie = 0,1).</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="268"/>
        <source>camera path</source>
        <translation>Kamerapfad</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="269"/>
        <source>keyframes</source>
        <translation>Schlüsselbilder</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="270"/>
        <source>camera: tracking quality</source>
        <translation>Kamera: Tracking-Qualität</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="271"/>
        <source>map points: colour of their first keyframe</source>
        <translation>Kartenpunkte: Farbe ihres ersten Schlüsselbilds</translation>
    </message>
</context>
<context>
    <name>sightline::OperatorPanel</name>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="333"/>
        <source>%1 cm</source>
        <translation>%1 cm</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="338"/>
        <location filename="../widgets/operator_panel.cpp" line="380"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="292"/>
        <source>Locating</source>
        <translation>Position wird gemessen</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="296"/>
        <source>Lost - hold still</source>
        <translation>Verloren - still halten</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="286"/>
        <source>No button here - tap again</source>
        <translation>Kein Knopf hier - nochmal tippen</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="211"/>
        <source>Robot: live</source>
        <translation>Roboter: live</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="214"/>
        <source>Waiting for the robot&apos;s picture</source>
        <translation>Warte auf das Bild des Roboters</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="217"/>
        <source>Picture stale: no taps</source>
        <translation>Bild veraltet: kein Tippen</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="220"/>
        <source>Disconnected: reconnecting</source>
        <translation>Getrennt: verbinde neu</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="284"/>
        <source>Press this button?</source>
        <translation>Diesen Knopf drücken?</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="300"/>
        <source>Holding: nothing sent</source>
        <translation>Halt: nichts gesendet</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="302"/>
        <source>Tap not taken</source>
        <translation>Antippen nicht angenommen</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="304"/>
        <source>Tracking only</source>
        <translation>Nur Verfolgung</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="339"/>
        <source>STOP</source>
        <translation>STOPP</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="375"/>
        <source>Leave</source>
        <translation>Verlassen</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="375"/>
        <source>Leave the operator panel?</source>
        <translation>Bedienfeld verlassen?</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="288"/>
        <source>Searching</source>
        <translation>Suche läuft</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="340"/>
        <source>Start again</source>
        <translation>Neu starten</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="298"/>
        <source>Stopped</source>
        <translation>Gestoppt</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="282"/>
        <source>Tap a button</source>
        <translation>Knopf antippen</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="294"/>
        <source>Target sent</source>
        <translation>Ziel gesendet</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="290"/>
        <source>Tracking</source>
        <translation>Knopf im Blick</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="337"/>
        <location filename="../widgets/operator_panel.cpp" line="379"/>
        <source>Yes</source>
        <translation>Ja</translation>
    </message>
</context>
<context>
    <name>sightline::OptionEditor</name>
    <message>
        <location filename="../widgets/option_editor.cpp" line="54"/>
        <source>Range: %1 … %2%3</source>
        <translation>Bereich: %1 … %2%3</translation>
    </message>
    <message>
        <location filename="../widgets/option_editor.cpp" line="59"/>
        <source>Choices: %1</source>
        <translation>Auswahl: %1</translation>
    </message>
    <message>
        <location filename="../widgets/option_editor.cpp" line="62"/>
        <source>Default: %1%2</source>
        <translation>Standard: %1%2</translation>
    </message>
    <message>
        <location filename="../widgets/option_editor.cpp" line="85"/>
        <source>Reset to default (%1)</source>
        <translation>Auf Standard zurücksetzen (%1)</translation>
    </message>
</context>
<context>
    <name>sightline::OptionText</name>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="14"/>
        <source>... and a relative 1-sigma scale error at most this.</source>
        <translation>... und ein relativer 1-Sigma-Skalenfehler von höchstens diesem Wert.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="15"/>
        <source>... and at least this fraction of the scan&apos;s rays hit it.</source>
        <translation>... und mindestens dieser Anteil der Strahlen des Scans trifft sie.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="16"/>
        <source>... and by this fraction of the angle turned since the last correction.</source>
        <translation>... und um diesen Anteil des seit der letzten Korrektur gedrehten Winkels.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="17"/>
        <source>... or the camera centres to lie this far apart (rays crossing).</source>
        <translation>... oder die Kamerazentren so weit auseinander liegen (sich kreuzende Strahlen).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="19"/>
        <source>... or when it turned at least this much.</source>
        <translation>... oder wenn er sich mindestens um so viel gedreht hat.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="20"/>
        <source>... plus this fraction of the tracked radius (a model centre off by a fixed amount on the button grows with its apparent size).</source>
        <translation>... plus dieser Anteil des verfolgten Radius (ein um einen festen Betrag versetztes Modellzentrum auf dem Taster wächst mit seiner scheinbaren Größe).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="21"/>
        <source>... plus this times the depth squared (Kinect noise and quantisation).</source>
        <translation>... plus dieser Wert mal dem Quadrat der Tiefe (Kinect-Rauschen und Quantisierung).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="22"/>
        <source>... reached within this many frames; otherwise the anchor starts again (tracks followed over many frames drift, and their drift reads as an offset).</source>
        <translation>... innerhalb so vieler Bilder erreicht; sonst beginnt der Anker von vorn (über viele Bilder verfolgte Tracks driften, und ihre Drift erscheint als Versatz).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="23"/>
        <source>.oni playback speed: 0 delivers frames as fast as they are read, nothing skipped; 1 paces at the recorded rate.</source>
        <translation>Wiedergabegeschwindigkeit von .oni: 0 liefert Bilder so schnell, wie sie gelesen werden, ohne Auslassungen; 1 hält die aufgezeichnete Rate ein.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="24"/>
        <source>.oni recordings start again at the first frame instead of ending.</source>
        <translation>.oni-Aufzeichnungen beginnen wieder beim ersten Bild, statt zu enden.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="25"/>
        <source>1-sigma error of the tracked button centre; moves the point across the viewing ray (the target&apos;s stated uncertainty includes it).</source>
        <translation>1-Sigma-Fehler der verfolgten Knopfmitte; verschiebt den Punkt quer zum Sehstrahl (die angegebene Unsicherheit des Ziels enthält ihn).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="26"/>
        <source>1-sigma of the tracked centre in the triangulation ...</source>
        <translation>1-Sigma des verfolgten Zentrums in der Triangulation ...</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="27"/>
        <source>1-sigma relative error of the tracked radius.</source>
        <translation>Relativer 1-Sigma-Fehler des verfolgten Radius.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="28"/>
        <source>1-sigma rotation error of the hand-eye calibration; times the distance to the button.</source>
        <translation>1-Sigma-Rotationsfehler der Hand-Auge-Kalibrierung; mal dem Abstand zum Knopf.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="29"/>
        <source>1-sigma translation error of the hand-eye calibration (end effector to camera).</source>
        <translation>1-Sigma-Translationsfehler der Hand-Auge-Kalibrierung (Endeffektor zur Kamera).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="30"/>
        <source>A bucket gets new corners only when it holds fewer than this fraction of its share of max_features (1 = whenever it is not full).</source>
        <translation>Eine Zelle (Bucket) erhält nur dann neue Ecken, wenn sie weniger als diesen Anteil ihres Kontingents an max_features hält (1 = immer, wenn sie nicht voll ist).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="31"/>
        <source>A button centre farther than this outside the image is out of view (lost).</source>
        <translation>Eine Knopfmitte, die weiter als dies außerhalb des Bildes liegt, ist außer Sicht (verloren).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="32"/>
        <source>A camera frame newer than the newest arm pose waits at most this long (host clock) for the pose that covers its stamp; then it has no arm pose.</source>
        <translation>Ein Kamerabild, das neuer als die neueste Armpose ist, wartet höchstens so lange (Host-Uhr) auf die Pose, die seinen Zeitstempel abdeckt; danach hat es keine Armpose.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="34"/>
        <source>A frame has ground truth when a pose lies within this time.</source>
        <translation>Ein Bild hat Ground Truth, wenn eine Pose innerhalb dieser Zeit liegt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="35"/>
        <source>A frame sets the reference only when the wall length in a second direction a few degrees off (inside the gate, outside the trim) is at most this fraction of the main direction&apos;s.</source>
        <translation>Ein Bild setzt die Referenz nur, wenn die Wandlänge in einer zweiten, wenige Grad abweichenden Richtung (innerhalb des Gates, außerhalb des Trimmbereichs) höchstens dieser Anteil der Länge in der Hauptrichtung ist.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="36"/>
        <source>A frame stays in the window when the camera moved this fraction of its points&apos; median depth since the previous one that stayed (0 = every frame stays); otherwise the next frame replaces it.</source>
        <translation>Ein Bild bleibt im Fenster, wenn sich die Kamera seit dem vorigen verbliebenen Bild um diesen Anteil der Mediantiefe seiner Punkte bewegt hat (0 = jedes Bild bleibt); sonst ersetzt es das nächste Bild.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="38"/>
        <source>A frame this far from every keyframe (relative to the mean depth) becomes one.</source>
        <translation>Ein Bild, das so weit von jedem Schlüsselbild entfernt ist (relativ zur mittleren Tiefe), wird zum Schlüsselbild.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="39"/>
        <source>A frame tracking fewer than this share of the last keyframe&apos;s points becomes one.</source>
        <translation>Ein Bild, das weniger als diesen Anteil der Punkte des letzten Schlüsselbilds verfolgt, wird zum Schlüsselbild.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="41"/>
        <source>A frame with fewer matches than this with the newest candidate becomes a candidate too (the oldest leaves a full ring); at low frame rates every frame does.</source>
        <translation>Ein Bild mit weniger Zuordnungen als diesen zum neuesten Kandidaten wird ebenfalls Kandidat (bei vollem Ring fällt der älteste heraus); bei niedriger Bildrate wird es jedes Bild.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="42"/>
        <source>A frame&apos;s normal this many sigmas off the average is skipped.</source>
        <translation>Ein Bild, dessen Normale so viele Sigma vom Mittel abweicht, wird übersprungen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="43"/>
        <source>A frame&apos;s walls count only when their summed vote weight (length x fit quality) reaches this.</source>
        <translation>Die Wände eines Bildes zählen nur, wenn ihr summiertes Stimmgewicht (Länge x Fitqualität) diesen Wert erreicht.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="44"/>
        <source>A ground candidate holds at least this fraction of the points.</source>
        <translation>Ein Bodenkandidat enthält mindestens diesen Anteil der Punkte.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="45"/>
        <source>A ground plane&apos;s normal lies at most this far from the expected up direction.</source>
        <translation>Die Normale einer Bodenebene weicht höchstens so weit von der erwarteten Aufwärtsrichtung ab.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="46"/>
        <source>A ground point&apos;s own normal lies at most this far from the plane&apos;s.</source>
        <translation>Die eigene Normale eines Bodenpunkts weicht höchstens so weit von der der Ebene ab.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="47"/>
        <source>A ground-truth or odometry pose belongs to a frame when this close in time.</source>
        <translation>Eine Ground-Truth- oder Odometriepose gehört zu einem Bild, wenn sie zeitlich so nah liegt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="48"/>
        <source>A ground-truth pose belongs to a frame when this close in time.</source>
        <translation>Eine Ground-Truth-Pose gehört zu einem Bild, wenn sie zeitlich so nah liegt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="50"/>
        <source>A line this close to a Manhattan axis is classed as parallel (0) or perpendicular (1) to the reference.</source>
        <translation>Eine Linie, die so nah an einer Manhattan-Achse liegt, gilt als parallel (0) oder senkrecht (1) zur Referenz.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="52"/>
        <source>A pose belongs to a frame when this close in time.</source>
        <translation>Eine Pose gehört zu einem Bild, wenn sie zeitlich so nah liegt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="55"/>
        <source>A segment&apos;s raised height is this quantile of its heights above the ground.</source>
        <translation>Die erhöhte Höhe eines Segments ist dieses Quantil seiner Höhen über dem Boden.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="56"/>
        <source>A sloped segment whose plane meets the ground within this distance of its lowest points is connected to the ground (a ramp), not raised.</source>
        <translation>Ein geneigtes Segment, dessen Ebene den Boden innerhalb dieses Abstands von seinen tiefsten Punkten trifft, ist mit dem Boden verbunden (eine Rampe), nicht erhöht.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="57"/>
        <source>A streaming device that delivers nothing for this long is treated as lost and reopened; 0 never does (e.g. waiting for rare hardware triggers).</source>
        <translation>Ein streamendes Gerät, das so lange nichts liefert, gilt als verloren und wird neu geöffnet; 0 tut das nie (z. B. beim Warten auf seltene Hardware-Trigger).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="58"/>
        <source>A track must return to its start within this when tracked backwards; 0 = no check.</source>
        <translation>Ein Track muss rückwärts verfolgt innerhalb dieses Werts zu seinem Start zurückkehren; 0 = keine Prüfung.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="59"/>
        <source>A track seen from a direction differing more than this from its anchor&apos;s is anchored anew: the further aside, the more a wrongly fitted or assumed surface (the road taken as facing the camera) misleads the warp; 3 suits subsampled driving.</source>
        <translation>Ein Track, der aus einer Richtung gesehen wird, die mehr als dies von der seines Ankers abweicht, wird neu verankert: je weiter seitlich, desto mehr führt eine falsch angepasste oder angenommene Fläche (die Straße als der Kamera zugewandt) die Verzerrung in die Irre; 3 passt für unterabgetastete Fahrten.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="60"/>
        <source>A track whose patch would be scaled by more than this fraction since its anchor (the camera came close) is anchored anew.</source>
        <translation>Ein Track, dessen Patch seit seinem Anker um mehr als diesen Anteil skaliert würde (die Kamera kam näher), wird neu verankert.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="61"/>
        <source>A track&apos;s surface is fitted as a plane to the tracks within this radius at a similar depth, so the anchor&apos;s patch is warped as that plane; 0 = every patch is taken as facing the camera.</source>
        <translation>Die Fläche eines Tracks wird als Ebene an die Tracks in diesem Radius mit ähnlicher Tiefe angepasst, sodass der Patch des Ankers als diese Ebene verzerrt wird; 0 = jeder Patch gilt als der Kamera zugewandt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="63"/>
        <source>Accuracy: a segment is compared with the true region holding this fraction of its points.</source>
        <translation>Genauigkeit: Ein Segment wird mit der wahren Region verglichen, die diesen Anteil seiner Punkte enthält.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="64"/>
        <source>Adaptive termination: stop when an outlier-free sample was drawn with this probability given the best inlier fraction; 1 = always max_iterations.</source>
        <translation>Adaptiver Abbruch: aufhören, wenn mit dieser Wahrscheinlichkeit (bei der besten Inlier-Quote) eine ausreißerfreie Stichprobe gezogen wurde; 1 = immer max_iterations.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="65"/>
        <source>Add features of confidently tracked frames to the model when the button&apos;s apparent size has changed.</source>
        <translation>Merkmale sicher verfolgter Bilder dem Modell hinzufügen, wenn sich die scheinbare Größe des Knopfs geändert hat.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="66"/>
        <source>Added to the triangulation&apos;s stated 1-sigma: biases no residual shows (the tracked centre&apos;s offset on the button, the size&apos;s depth on a relief).</source>
        <translation>Wird zum angegebenen 1-Sigma der Triangulation addiert: systematische Fehler, die kein Residuum zeigt (Versatz des verfolgten Zentrums auf dem Taster, Tiefe der Größe auf einem Relief).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="67"/>
        <source>After a loss, search whole frames and re-acquire the button only on a confident match at a plausible size.</source>
        <translation>Nach einem Verlust ganze Bilder durchsuchen und den Knopf nur bei einer sicheren Übereinstimmung in plausibler Größe wiederfinden.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="68"/>
        <source>Agreement of the voting lines modulo 90 deg (1 = perfect); below it the frame&apos;s walls are not used.</source>
        <translation>Übereinstimmung der abstimmenden Linien modulo 90 deg (1 = perfekt); darunter werden die Wände des Bildes nicht verwendet.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="69"/>
        <source>Also estimate a constant offset of the tracked centre in the image (a detector&apos;s sub-pixel convention): it would tilt the rays of the approach against the sideways move&apos;s.</source>
        <translation>Zusätzlich einen konstanten Versatz des verfolgten Zentrums im Bild schätzen (Subpixel-Konvention eines Detektors): er würde die Strahlen der Annäherung gegen die der Seitwärtsbewegung neigen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="70"/>
        <source>Also list and open Aravis&apos; in-process simulated camera Fake_1 (demos and tests).</source>
        <translation>Auch Aravis&apos; prozessinterne simulierte Kamera Fake_1 auflisten und öffnen (Demos und Tests).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="71"/>
        <source>Also locate the button from the arm&apos;s metric camera poses alone (the tracked centre&apos;s rays and its apparent size, core/button/arm_triangulation.h) and combine that point with the map&apos;s by their variances. Off by default: on the simulated approach&apos;s seeds 1-5 the mean final error goes 4.77 -&gt; 3.68 mm and the worst 10.1 -&gt; 5.9 mm, but seeds 1 and 4 and the 12 cm sideways approach get worse (docs/button.md).</source>
        <translation>Den Taster zusätzlich allein aus den metrischen Kameraposen des Arms lokalisieren (Strahlen des verfolgten Zentrums und seine scheinbare Größe, core/button/arm_triangulation.h) und diesen Punkt mit dem der Karte nach ihren Varianzen kombinieren. Standardmäßig aus: auf den Seeds 1-5 der simulierten Annäherung sinkt der mittlere Endfehler von 4.77 -&gt; 3.68 mm und der größte von 10.1 -&gt; 5.9 mm, aber die Seeds 1 und 4 und die Annäherung mit 12 cm Seitwärtsbewegung werden schlechter (docs/button.md).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="72"/>
        <source>Also project current points into the previous images (uses both depths).</source>
        <translation>Auch aktuelle Punkte in die vorigen Bilder projizieren (nutzt beide Tiefen).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="74"/>
        <source>An aligned patch whose zero-mean normalised correlation with the warped anchor patch is lower failed (occlusion, reflection).</source>
        <translation>Ein ausgerichteter Patch, dessen mittelwertfreie normierte Korrelation mit dem verzerrten Anker-Patch geringer ist, gilt als gescheitert (Verdeckung, Reflexion).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="75"/>
        <source>An alignment that moves the tracked position further than this failed (the KLT position is kept and the track anchored anew).</source>
        <translation>Eine Ausrichtung, die die verfolgte Position weiter als dies verschiebt, gilt als gescheitert (die KLT-Position bleibt, und der Track wird neu verankert).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="76"/>
        <source>An anchor is used for at most this many frames; then the track is anchored anew.</source>
        <translation>Ein Anker wird höchstens für so viele Bilder verwendet; danach wird der Track neu verankert.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="77"/>
        <source>An arm_pose message with more joint positions is refused.</source>
        <translation>Eine arm_pose-Nachricht mit mehr Gelenkpositionen wird abgelehnt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="78"/>
        <source>An arm_pose position farther than this from the base is refused.</source>
        <translation>Eine arm_pose-Position, die weiter als dies von der Basis entfernt ist, wird abgelehnt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="81"/>
        <source>Analog gain; negative keeps the camera&apos;s. Out-of-range values are errors.</source>
        <translation>Analoge Verstärkung; negativ behält die der Kamera. Werte außerhalb des Bereichs sind Fehler.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="83"/>
        <source>Ask the device to deliver depth and colour frames of the same instant.</source>
        <translation>Das Gerät bitten, Tiefen- und Farbbilder desselben Zeitpunkts zu liefern.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="84"/>
        <source>At low rates (mono.tracking.low_rate_interval_s), a frame tracking fewer than this share of the last keyframe&apos;s points becomes a keyframe within min_keyframe_gap too (0 = off).</source>
        <translation>Bei niedriger Rate (mono.tracking.low_rate_interval_s) wird ein Bild, das weniger als diesen Anteil der Punkte des letzten Schlüsselbilds verfolgt, auch innerhalb von min_keyframe_gap Schlüsselbild (0 = aus).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="85"/>
        <source>At low rates, a frame this far from every keyframe (relative to the mean depth) becomes a keyframe within min_keyframe_gap too.</source>
        <translation>Bei niedriger Rate wird ein Bild, das so weit von jedem Schlüsselbild entfernt ist (relativ zur mittleren Tiefe), auch innerhalb von min_keyframe_gap Schlüsselbild.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="86"/>
        <source>At low rates, when the constant-velocity prediction tracks fewer inliers, the last pose (zero motion) is tried too and the better kept (0 = off).</source>
        <translation>Bei niedriger Rate: verfolgt die Vorhersage mit konstanter Geschwindigkeit weniger Inlier, wird auch die letzte Pose (keine Bewegung) versucht und die bessere behalten (0 = aus).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="87"/>
        <source>Authorised clients at most; further ones are closed.</source>
        <translation>Höchstens so viele autorisierte Clients; weitere werden geschlossen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="88"/>
        <source>Band of the refinement (offset histogram bin and refit band): narrower than err_max, so that a door recessed behind the wall face does not tilt the line.</source>
        <translation>Band der Verfeinerung (Histogrammklasse des Versatzes und Band der Neuanpassung): schmaler als err_max, damit eine hinter die Wandfläche zurückgesetzte Tür die Linie nicht kippt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="89"/>
        <source>Baseline over the median depth of the first points needed to accept (0.07 is a 4 deg ray angle sideways); a short baseline gives a distorted first map and a drifting scale.</source>
        <translation>Basislinie geteilt durch die Mediantiefe der ersten Punkte, die zum Akzeptieren nötig ist (0.07 entspricht einem seitlichen Strahlwinkel von 4 deg); eine kurze Basislinie ergibt eine verzerrte erste Karte und eine driftende Skala.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="90"/>
        <source>Best over second-best descriptor distance in a window; 1 = off.</source>
        <translation>Bester durch zweitbesten Deskriptorabstand in einem Fenster; 1 = aus.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="91"/>
        <source>Camera pitched down by this: expected up = camera -y turned by pitch and roll.</source>
        <translation>Kamera um diesen Wert nach unten geneigt: erwartetes Oben = Kamera -y, um Nick- und Rollwinkel gedreht.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="92"/>
        <source>Camera roll.</source>
        <translation>Rollwinkel der Kamera.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="93"/>
        <source>Candidate first frames kept (a ring of recent frames); each new frame is tried against every one, oldest first (the largest baseline).</source>
        <translation>Vorgehaltene Kandidaten für das erste Bild (ein Ring der letzten Bilder); jedes neue Bild wird gegen jeden versucht, der älteste zuerst (die längste Basislinie).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="94"/>
        <source>Canny lower threshold.</source>
        <translation>Untere Canny-Schwelle.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="95"/>
        <source>Canny upper threshold.</source>
        <translation>Obere Canny-Schwelle.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="96"/>
        <source>Cell edge of the global map.</source>
        <translation>Zellkante der globalen Karte.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="97"/>
        <source>Cell of the keypoint grid used by window searches.</source>
        <translation>Zelle des Keypoint-Rasters, das die Fenstersuchen nutzen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="98"/>
        <source>Coarse search window of the zero-motion try.</source>
        <translation>Grobes Suchfenster des Versuchs ohne Bewegung.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="99"/>
        <source>Collinear lines (angles this close, one fit within the threshold) are merged.</source>
        <translation>Kollineare Linien (Winkel so nah, eine Anpassung innerhalb der Schwelle) werden zusammengeführt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="100"/>
        <source>Compute SIFT only in a window around the predicted centre (fast).</source>
        <translation>SIFT nur in einem Fenster um die vorhergesagte Mitte berechnen (schnell).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="101"/>
        <source>Connections still owing the token at most; a new one closes the oldest.</source>
        <translation>Höchstens so viele Verbindungen, die das Token noch schuldig sind; eine neue schließt die älteste.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="102"/>
        <source>Consecutive frames of constant-motion fallback before the pose is held.</source>
        <translation>Aufeinanderfolgende Bilder mit Rückfall auf konstante Bewegung, bevor die Pose gehalten wird.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="103"/>
        <source>Consecutive scan points farther apart than this start a new run.</source>
        <translation>Aufeinanderfolgende Scanpunkte, die weiter als dies auseinanderliegen, beginnen einen neuen Abschnitt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="104"/>
        <source>Consistent matches needed to re-acquire a lost button.</source>
        <translation>Konsistente Übereinstimmungen, die zum Wiederfinden eines verlorenen Knopfs nötig sind.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="106"/>
        <source>Correct the heading with the walls&apos; Manhattan directions; off = dead reckoning only.</source>
        <translation>Die Fahrtrichtung mit den Manhattan-Richtungen der Wände korrigieren; aus = nur Koppelnavigation.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="107"/>
        <source>Demosaic Bayer formats to BGR colour; off delivers the raw mosaic as grey.</source>
        <translation>Bayer-Formate zu BGR-Farbe demosaikieren; aus liefert das rohe Mosaik als Graubild.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="108"/>
        <source>Depth beyond this is left out of the 3D cloud.</source>
        <translation>Tiefe jenseits dieses Werts bleibt aus der 3D-Wolke heraus.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="49"/>
        <source>A line needs at least this many points (2 = as published; more rejects clutter).</source>
        <translation>Eine Linie braucht mindestens so viele Punkte (2 = wie veröffentlicht; mehr verwirft Störobjekte).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="54"/>
        <source>A region whose centroid is farther from the tap and that does not contain it is not the tapped button (published method).</source>
        <translation>Eine Region, deren Schwerpunkt weiter von der Tippstelle entfernt ist und die sie nicht enthält, ist nicht der angetippte Knopf (veröffentlichte Methode).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="82"/>
        <source>Angle between scan rays (published res_scan = 0.2 deg).</source>
        <translation>Winkel zwischen Scanstrahlen (veröffentlicht: res_scan = 0.2 deg).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="109"/>
        <source>Depth images are sampled to about this many columns (published: 320 x 240).</source>
        <translation>Tiefenbilder werden auf etwa so viele Spalten abgetastet (veröffentlicht: 320 x 240).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="110"/>
        <source>Depth points a cell needs to count as occupied (1 = as published: any non-floor point).</source>
        <translation>Tiefenpunkte, die eine Zelle braucht, um als belegt zu gelten (1 = wie veröffentlicht: jeder Nicht-Bodenpunkt).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="111"/>
        <source>Depth readings beyond this are treated as invalid downstream.</source>
        <translation>Tiefenwerte jenseits dieses Werts gelten nachgelagert als ungültig.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="112"/>
        <source>Depth readings beyond this count as invalid.</source>
        <translation>Tiefenwerte jenseits dieses Werts gelten als ungültig.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="115"/>
        <source>Depth sigmas (of both points at both times) added to the rigidity tolerance.</source>
        <translation>Tiefen-Sigmas (beider Punkte zu beiden Zeitpunkten), die zur Starrheitstoleranz addiert werden.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="116"/>
        <source>Descriptor matches with a keyframe needed to try relocalisation.</source>
        <translation>Deskriptor-Übereinstimmungen mit einem Schlüsselbild, die für einen Relokalisierungsversuch nötig sind.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="117"/>
        <source>Disparity noise giving the depth sigma Z^2 s / (f b).</source>
        <translation>Disparitätsrauschen, das das Tiefen-Sigma Z^2 s / (f b) ergibt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="118"/>
        <source>Displacement pairs between consecutive keyframes (poses refined by bundle adjustment) or between tracked frames scale_interval_frames apart.</source>
        <translation>Verschiebungspaare zwischen aufeinanderfolgenden Schlüsselbildern (Posen durch Bündelausgleichung verfeinert) oder zwischen verfolgten Bildern im Abstand scale_interval_frames.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="119"/>
        <source>Distance from the epipolar line allowed for a new-point match.</source>
        <translation>Zulässiger Abstand von der Epipolarlinie für eine Übereinstimmung neuer Punkte.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="120"/>
        <source>Distance gate: a match farther than this from the predicted centre is dropped.</source>
        <translation>Distanz-Gate: Eine Übereinstimmung, die weiter als dies von der vorhergesagten Mitte liegt, wird verworfen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="121"/>
        <source>Draws per hypothesis to find a pair within the distance limits.</source>
        <translation>Ziehungen pro Hypothese, um ein Paar innerhalb der Abstandsgrenzen zu finden.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="122"/>
        <source>Edge of one occupancy cell; RANSAC&apos;s 5-cell error scales with it.</source>
        <translation>Kante einer Belegungszelle; der 5-Zellen-Fehler von RANSAC skaliert damit.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="124"/>
        <source>Epipolar (row) constraint: largest row difference of a match.</source>
        <translation>Epipolare (Zeilen-)Bedingung: größter Zeilenunterschied einer Übereinstimmung.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="125"/>
        <source>Estimate a constant disparity offset of the rig (rectification or matcher bias) online from the motion, and add it to every disparity; an offset of a fraction of a pixel moves far points most and makes the translation too long or too short.</source>
        <translation>Einen konstanten Disparitätsversatz des Rigs (Verzerrung der Rektifizierung oder des Matchers) online aus der Bewegung schätzen und zu jeder Disparität addieren; ein Versatz von einem Bruchteil eines Pixels verschiebt ferne Punkte am stärksten und macht die Translation zu lang oder zu kurz.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="126"/>
        <source>Estimate each pose against the last keyframe&apos;s stereo observations of the tracks (after the frame-to-frame estimate), so per-frame errors do not accumulate.</source>
        <translation>Jede Pose gegen die Stereobeobachtungen der Tracks im letzten Schlüsselbild schätzen (nach der Bild-zu-Bild-Schätzung), damit sich Fehler einzelner Bilder nicht aufsummieren.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="127"/>
        <source>Exposure time; 0 keeps the camera&apos;s. Out-of-range values are errors.</source>
        <translation>Belichtungszeit; 0 behält die der Kamera. Werte außerhalb des Bereichs sind Fehler.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="128"/>
        <source>FAST corner threshold.</source>
        <translation>FAST-Eckenschwelle.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="129"/>
        <source>FLANN leaf checks per query.</source>
        <translation>FLANN-Blattprüfungen pro Anfrage.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="130"/>
        <source>FLANN randomised kd-trees.</source>
        <translation>Randomisierte FLANN-kd-Bäume.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="131"/>
        <source>Faster estimated rotation is rejected.</source>
        <translation>Eine schneller geschätzte Rotation wird verworfen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="132"/>
        <source>Faster estimated translation is rejected.</source>
        <translation>Eine schneller geschätzte Translation wird verworfen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="133"/>
        <source>Features kept per frame, tracked plus new.</source>
        <translation>Pro Bild behaltene Merkmale, verfolgte plus neue.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="134"/>
        <source>Features this close to the border are dropped.</source>
        <translation>So nah am Rand liegende Merkmale werden verworfen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="135"/>
        <source>Features within this many button radii of the centre are added.</source>
        <translation>Merkmale innerhalb so vieler Knopfradien um die Mitte werden hinzugefügt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="136"/>
        <source>Fewer SIFT keypoints on the region: the button cannot be tracked.</source>
        <translation>Weniger SIFT-Keypoints auf der Region: Der Knopf kann nicht verfolgt werden.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="137"/>
        <source>Fewer consistent matches: the button is lost.</source>
        <translation>Weniger konsistente Übereinstimmungen: Der Knopf ist verloren.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="138"/>
        <source>Fewer inliers after refinement is rejected.</source>
        <translation>Weniger Inlier nach der Verfeinerung werden verworfen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="139"/>
        <source>Fewer inliers than this fraction of the points: the plane is not sound.</source>
        <translation>Weniger Inlier als dieser Anteil der Punkte: Die Ebene ist nicht verlässlich.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="140"/>
        <source>Fewer inliers than this means the motion could not be estimated.</source>
        <translation>Weniger Inlier als dieser Wert bedeuten, dass die Bewegung nicht geschätzt werden konnte.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="141"/>
        <source>Fewer map points or plane inliers: no normal in this frame.</source>
        <translation>Weniger Kartenpunkte oder Ebenen-Inlier: keine Normale in diesem Bild.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="142"/>
        <source>Fewer points left after the range cut is reported as an error.</source>
        <translation>Bleiben nach dem Entfernungsschnitt weniger Punkte, wird ein Fehler gemeldet.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="143"/>
        <source>Fewer points than this: the plane is not sound (no target is sent).</source>
        <translation>Weniger Punkte als dieser Wert: Die Ebene ist nicht verlässlich (es wird kein Ziel gesendet).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="144"/>
        <source>Fewer points: no 3D position.</source>
        <translation>Weniger Punkte: keine 3D-Position.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="145"/>
        <source>Fewer tracked views with an arm pose: no triangulated point.</source>
        <translation>Weniger verfolgte Ansichten mit einer Armpose: kein triangulierter Punkt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="146"/>
        <source>Fewest tracks (the track included) a surface is fitted to.</source>
        <translation>Wenigste Tracks (einschließlich des Tracks selbst), an die eine Fläche angepasst wird.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="147"/>
        <source>Field of view to scan, centred on forward; 0 = the camera&apos;s own (rays outside it can never hit anything).</source>
        <translation>Zu scannendes Sichtfeld, zentriert auf vorwärts; 0 = das der Kamera (Strahlen außerhalb davon können nie etwas treffen).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="148"/>
        <source>Floor calibration (sightline-cli floor) giving the expected up direction; empty = mobility.mount_pitch_deg / mount_roll_deg.</source>
        <translation>Bodenkalibrierung (sightline-cli floor), die die erwartete Aufwärtsrichtung liefert; leer = mobility.mount_pitch_deg / mount_roll_deg.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="149"/>
        <source>Floor calibration file (sightline-cli floor); empty = calibrate from the first frames of the run.</source>
        <translation>Bodenkalibrierungsdatei (sightline-cli floor); leer = aus den ersten Bildern des Laufs kalibrieren.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="150"/>
        <source>Floor of the residual RMS by which each frame pair&apos;s measurement is weighted.</source>
        <translation>Untergrenze des Residuen-RMS, mit dem die Messung jedes Bildpaars gewichtet wird.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="151"/>
        <source>Format of trajectory.txt; --format kitti.</source>
        <translation>Format von trajectory.txt; --format kitti.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="152"/>
        <source>Fraction of a circle&apos;s rim that must lie on an edge.</source>
        <translation>Anteil des Kreisrands, der auf einer Kante liegen muss.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="153"/>
        <source>Fraction of directions around a region&apos;s centre in which its outline lies; a button&apos;s (even broken) outline surrounds its centre.</source>
        <translation>Anteil der Richtungen um die Mitte einer Region, in denen ihr Umriss liegt; der (auch unterbrochene) Umriss eines Knopfs umschließt seine Mitte.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="154"/>
        <source>Fraction of the correction applied per frame (1 = take the walls&apos; heading).</source>
        <translation>Pro Bild angewandter Anteil der Korrektur (1 = die Richtung der Wände übernehmen).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="156"/>
        <source>Frame rate of overlay.avi.</source>
        <translation>Bildrate von overlay.avi.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="157"/>
        <source>Frame results carry a rendered map image every n frames (0 = never).</source>
        <translation>Bildergebnisse enthalten alle n Bilder ein gerendertes Kartenbild (0 = nie).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="158"/>
        <source>Frames between two keyframes at least (see urgent_keyframe_ratio).</source>
        <translation>Mindestabstand zwischen zwei Schlüsselbildern in Bildern (siehe urgent_keyframe_ratio).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="159"/>
        <source>Frames buffered between the capture thread and the consumer; when full the oldest is dropped, so latency stays bounded.</source>
        <translation>Zwischen Aufnahme-Thread und Verbraucher gepufferte Bilder; ist der Puffer voll, wird das älteste verworfen, sodass die Latenz begrenzt bleibt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="161"/>
        <source>Frames in the window; the oldest is held fixed.</source>
        <translation>Bilder im Fenster; das älteste wird festgehalten.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="162"/>
        <source>Frames read before subsampling; 0 = all.</source>
        <translation>Vor der Unterabtastung gelesene Bilder; 0 = alle.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="163"/>
        <source>Frames read; 0 = all.</source>
        <translation>Gelesene Bilder; 0 = alle.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="164"/>
        <source>Frames spanned by one displacement pair of the scale estimators.</source>
        <translation>Bilder, die ein Verschiebungspaar der Skalenschätzer überspannt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="165"/>
        <source>Frames that left the window keep constraining its points this long, with their poses held fixed, so the window&apos;s drift does not restart at every slide.</source>
        <translation>Bilder, die das Fenster verlassen haben, binden seine Punkte noch so lange, mit festgehaltenen Posen, damit die Drift des Fensters nicht bei jedem Verschieben neu beginnt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="166"/>
        <source>Frames to process; 0 = all.</source>
        <translation>Zu verarbeitende Bilder; 0 = alle.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="167"/>
        <source>Frames to read; 0 reads the whole recording.</source>
        <translation>Zu lesende Bilder; 0 liest die ganze Aufzeichnung.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="168"/>
        <source>Frames tried against one first frame before it is replaced.</source>
        <translation>Gegen ein erstes Bild versuchte Bilder, bevor es ersetzt wird.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="169"/>
        <source>Frames used to calibrate the floor when no floor_file is given.</source>
        <translation>Bilder zur Bodenkalibrierung, wenn keine floor_file angegeben ist.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="170"/>
        <source>Free scaling of cv::stereoRectify: 0 keeps only valid pixels, 1 keeps all.</source>
        <translation>Freie Skalierung von cv::stereoRectify: 0 behält nur gültige Pixel, 1 behält alle.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="171"/>
        <source>Free-running frame rate, or the host&apos;s rate with software triggering; 0 keeps the camera&apos;s. Rates the camera cannot reach are errors.</source>
        <translation>Bildrate im Freilauf oder die Rate des Hosts bei Software-Triggerung; 0 behält die der Kamera. Raten, die die Kamera nicht erreicht, sind Fehler.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="172"/>
        <source>Gauss-Newton iterations of the alignment.</source>
        <translation>Gauß-Newton-Iterationen der Ausrichtung.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="173"/>
        <source>Gauss-Newton iterations on the reprojection error; 0 keeps the RANSAC motion.</source>
        <translation>Gauß-Newton-Iterationen auf dem Reprojektionsfehler; 0 behält die RANSAC-Bewegung.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="174"/>
        <source>Gauss-Newton steps on the reprojection error of each 3-point sample.</source>
        <translation>Gauß-Newton-Schritte auf dem Reprojektionsfehler jeder 3-Punkte-Stichprobe.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="175"/>
        <source>Gaussian blur before edge detection.</source>
        <translation>Gaußsche Unschärfe vor der Kantenerkennung.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="176"/>
        <source>GenICam pixel format to select (Mono8, Mono16, BayerRG8, RGB8, ...); empty keeps the camera&apos;s. 16-bit formats are scaled to 8 bits.</source>
        <translation>Zu wählendes GenICam-Pixelformat (Mono8, Mono16, BayerRG8, RGB8, ...); leer behält das der Kamera. 16-Bit-Formate werden auf 8 Bit skaliert.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="177"/>
        <source>GigE receive socket buffer; 0 lets Aravis size it to a whole frame (without it most packets of large frames are lost).</source>
        <translation>GigE-Empfangspuffer des Sockets; 0 lässt Aravis ihn auf ein ganzes Bild bemessen (ohne ihn gehen die meisten Pakete großer Bilder verloren).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="178"/>
        <source>GigE stream packet size; 0 negotiates the largest packet that reaches the host.</source>
        <translation>Paketgröße des GigE-Streams; 0 handelt das größte Paket aus, das den Host erreicht.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="179"/>
        <source>Global bundle adjustment of every keyframe and point when the run stops (0 = none).</source>
        <translation>Globale Bündelausgleichung aller Schlüsselbilder und Punkte, wenn der Lauf endet (0 = keine).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="180"/>
        <source>Grab() returns the newest frame and skips older queued ones (views); off hands out every queued frame in order (recording).</source>
        <translation>Grab() liefert das neueste Bild und überspringt ältere wartende (Ansichten); aus gibt jedes wartende Bild der Reihe nach aus (Aufzeichnung).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="181"/>
        <source>Ground RANSAC inlier distance at the sensor ...</source>
        <translation>RANSAC-Inlier-Abstand des Bodens am Sensor ...</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="182"/>
        <source>Guided matching: best over second-best descriptor distance along the line.</source>
        <translation>Geführte Zuordnung: beste durch zweitbeste Deskriptordistanz entlang der Linie.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="183"/>
        <source>Guided matching: distance from the epipolar line a match may have.</source>
        <translation>Geführte Zuordnung: zulässiger Abstand einer Zuordnung von der Epipolarlinie.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="184"/>
        <source>Half size of the search window.</source>
        <translation>Halbe Größe des Suchfensters.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="185"/>
        <source>Half-size of the sub-pixel corner refinement at full resolution after detection on a reduced level; 0 = none.</source>
        <translation>Halbe Größe der Subpixel-Eckenverfeinerung in voller Auflösung nach der Erkennung auf einer verkleinerten Stufe; 0 = keine.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="186"/>
        <source>Headless runs write the overlay of the track from the tap on as a PNG sequence (overlay/frame_NNNNNN.png, one per row of button.csv).</source>
        <translation>Headless-Läufe schreiben das Overlay des Tracks ab dem Antippen als PNG-Folge (overlay/frame_NNNNNN.png, eins pro Zeile von button.csv).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="187"/>
        <source>Heartbeat period; 0 = none.</source>
        <translation>Heartbeat-Periode; 0 = keiner.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="188"/>
        <source>Height of the occupancy image (published: 400), i.e. the forward range in cells.</source>
        <translation>Höhe des Belegungsbilds (veröffentlicht: 400), d. h. die Reichweite nach vorn in Zellen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="350"/>
        <source>Region from the tap: outlines at two scales plus Hough circles, the one holding the tap nearest its centre (multiscale), or the published rule (the centroid nearest the tap within max_tap_distance_px).</source>
        <translation>Region ab der Tippstelle: Umrisse in zwei Skalen plus Hough-Kreise, diejenige, die die Tippstelle am nächsten an ihrer Mitte enthält (multiscale), oder die Regel der Veröffentlichung (der Schwerpunkt, der der Tippstelle innerhalb max_tap_distance_px am nächsten liegt).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="377"/>
        <source>Score drawn in the maps: the published Table I rule or the Gaussian process.</source>
        <translation>In den Karten gezeichnete Bewertung: die Regel aus Tabelle I der Veröffentlichung oder der Gaußprozess.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="395"/>
        <source>Start a new map when the reset rule fires (as published); off keeps stitching.</source>
        <translation>Eine neue Karte beginnen, wenn die Reset-Regel greift (wie veröffentlicht); aus setzt das Zusammenfügen fort.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="400"/>
        <source>Step B6: cut the consensus set at gaps wider than this along the line and keep the longest piece, so that lines are contiguous walls (0 = as published: no cut).</source>
        <translation>Schritt B6: die Konsensmenge an Lücken entlang der Linie, die breiter als dies sind, schneiden und das längste Stück behalten, damit Linien zusammenhängende Wände sind (0 = wie veröffentlicht: kein Schnitt).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="401"/>
        <source>Step B7: keep the hypothesis with the lowest summed error (as published) or mean error.</source>
        <translation>Schritt B7: die Hypothese mit dem kleinsten summierten Fehler (wie veröffentlicht) oder mittleren Fehler behalten.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="402"/>
        <source>Step C: re-find the chosen line&apos;s dominant surface by sweeping its direction this far either way, then refit on it (0 = as published: the line of step B6 as is).</source>
        <translation>Schritt C: die dominante Fläche der gewählten Linie neu finden, indem ihre Richtung so weit in beide Richtungen geschwenkt wird, dann darauf neu anpassen (0 = wie veröffentlicht: die Linie aus Schritt B6 unverändert).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="470"/>
        <source>Wall-line extractor: the published multi-line RANSAC or split-and-merge.</source>
        <translation>Wandlinien-Extraktor: das Mehrlinien-RANSAC der Veröffentlichung oder Split-and-Merge.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="472"/>
        <source>Weigh them so once one position states a 1-sigma of at most this (the arm has come close; far positions then carry the newest scale&apos;s error times their distance); 0 = only with weighted (docs/button.md).</source>
        <translation>Die Positionen so gewichten, sobald eine Position eine 1-Sigma-Unsicherheit von höchstens diesem Wert angibt (der Arm ist nahe gekommen; ferne Positionen tragen dann den Fehler des neuesten Maßstabs mal ihrer Entfernung); 0 = nur mit weighted (docs/button.md).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="477"/>
        <source>When even after that fewer tracks survive than this fraction of the share that usually survives (a slow average over the last frames; a sharp turn, or a turn at a low frame rate), the camera&apos;s rotation is searched by comparing the two images and the points are tracked again from where it puts them; the better attempt is kept. 0 = never.</source>
        <translation>Wenn selbst danach weniger Spuren überleben als dieser Anteil des üblicherweise überlebenden Anteils (ein langsamer Mittelwert über die letzten Bilder; eine scharfe Kurve oder eine Kurve bei niedriger Bildrate), wird die Drehung der Kamera durch Vergleich der beiden Bilder gesucht und die Punkte werden von dort aus erneut verfolgt; der bessere Versuch wird behalten. 0 = nie.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="480"/>
        <source>Where person boxes come from: the dataset&apos;s ground truth, clusters of a person&apos;s size standing on the floor in the depth image (depth), OpenCV&apos;s HOG detector on the colour image, auto (ground truth when present, else depth) or none.</source>
        <translation>Woher die Personenboxen kommen: die Ground Truth des Datensatzes, Cluster von Personengröße, die im Tiefenbild auf dem Boden stehen (depth), OpenCVs HOG-Detektor im Farbbild, auto (Ground Truth, wenn vorhanden, sonst depth) oder none.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="482"/>
        <source>Width of the occupancy image (published: 400); the robot sits at its bottom centre.</source>
        <translation>Breite des Belegungsbilds (veröffentlicht: 400); der Roboter sitzt unten in der Mitte.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="507"/>
        <source>depth: a head is the highest point within this radius; people side by side are split at their heads.</source>
        <translation>depth: Ein Kopf ist der höchste Punkt innerhalb dieses Radius; nebeneinander stehende Personen werden an ihren Köpfen getrennt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="508"/>
        <source>depth: a person&apos;s footprint is at least this long.</source>
        <translation>depth: Die Grundfläche einer Person ist mindestens so lang.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="509"/>
        <source>depth: a person&apos;s footprint is at most this long (walls are longer); wider clusters are split at their heads.</source>
        <translation>depth: Die Grundfläche einer Person ist höchstens so lang (Wände sind länger); breitere Cluster werden an ihren Köpfen getrennt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="510"/>
        <source>depth: a person&apos;s lowest point lies at most this high above the floor.</source>
        <translation>depth: Der tiefste Punkt einer Person liegt höchstens so hoch über dem Boden.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="511"/>
        <source>depth: a person&apos;s top lies at least this high above the floor.</source>
        <translation>depth: Der höchste Punkt einer Person liegt mindestens so hoch über dem Boden.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="513"/>
        <source>depth: a person&apos;s top lies at most this high (walls and pillars go higher).</source>
        <translation>depth: Der höchste Punkt einer Person liegt höchstens so hoch (Wände und Säulen reichen höher).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="514"/>
        <source>depth: between two heads the tops dip at least this much (neck, shoulders); the cut-off top of a wall is flat and is not split.</source>
        <translation>depth: Zwischen zwei Köpfen sinken die Höhen mindestens um so viel ab (Hals, Schultern); die abgeschnittene Oberkante einer Wand ist flach und wird nicht getrennt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="515"/>
        <source>depth: floor grid cell in which points are clustered.</source>
        <translation>depth: Zelle des Bodenrasters, in dem Punkte zu Clustern zusammengefasst werden.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="516"/>
        <source>depth: points farther away are not looked at.</source>
        <translation>depth: Weiter entfernte Punkte werden nicht betrachtet.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="517"/>
        <source>depth: sampled points a person needs.</source>
        <translation>depth: Abgetastete Punkte, die eine Person braucht.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="520"/>
        <source>depth: the depth image is sampled to about this many columns.</source>
        <translation>depth: Das Tiefenbild wird auf etwa so viele Spalten abgetastet.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="521"/>
        <source>depth: the shorter side of a person&apos;s footprint is at least this (legs, arms and the torso&apos;s curve); the end of a wall seen at the edge of view is one cell thick.</source>
        <translation>depth: Die kürzere Seite der Grundfläche einer Person ist mindestens so lang (Beine, Arme und die Rundung des Rumpfs); das Ende einer Wand am Bildrand ist eine Zelle dick.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="525"/>
        <source>epsilon_floor: a point within this height of the floor plane is floor (published value 3.5, read as 3.5 cm: generous so that no floor pixel is labelled occupied).</source>
        <translation>epsilon_floor: Ein Punkt innerhalb dieser Höhe über der Bodenebene ist Boden (veröffentlichter Wert 3.5, gelesen als 3.5 cm: großzügig, damit kein Bodenpixel als belegt markiert wird).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="526"/>
        <source>err_max: inlier distance in occupancy cells (published: 5 pixels); metres = cells x mapping.occupancy.cell_size_m.</source>
        <translation>err_max: Inlier-Abstand in Belegungszellen (veröffentlicht: 5 Pixel); Meter = Zellen x mapping.occupancy.cell_size_m.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="531"/>
        <source>grid: organized pixel-grid path (fast); pcl: the published voxel grid, outlier removal and k-d tree path.</source>
        <translation>grid: Pfad über das organisierte Pixelraster (schnell); pcl: der Pfad der Veröffentlichung mit Voxelgitter, Ausreißerentfernung und k-d-Baum.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="534"/>
        <source>j_max: hypotheses per line (published: 250); also caps the adaptive count.</source>
        <translation>j_max: Hypothesen pro Linie (veröffentlicht: 250); begrenzt auch die adaptive Anzahl.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="551"/>
        <source>rgbd, rgbd_icp: a colour frame whose brightness varies less than this is not tracked (a black or blank frame).</source>
        <translation>rgbd, rgbd_icp: ein Farbbild, dessen Helligkeit weniger als dies schwankt, wird nicht verfolgt (ein schwarzes oder leeres Bild).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="552"/>
        <source>rgbd, rgbd_icp: start the alignment from ORB features matched with PnP RANSAC when they agree (fast turns at low frame rates).</source>
        <translation>rgbd, rgbd_icp: die Ausrichtung bei ORB-Merkmalen beginnen, die mit PnP-RANSAC zugeordnet sind, wenn diese übereinstimmen (schnelle Drehungen bei niedriger Bildrate).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="553"/>
        <source>wheelchair: 5 m range, 3 cm step; icub: 1.75 m, 5 cm (the published humanoid); custom: range_cut_m and max_step_m.</source>
        <translation>wheelchair: 5 m Reichweite, 3 cm Stufe; icub: 1.75 m, 5 cm (der Humanoide der Veröffentlichung); custom: range_cut_m und max_step_m.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="189"/>
        <source>Highest plausible camera height above the floor.</source>
        <translation>Höchste plausible Kamerahöhe über dem Boden.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="18"/>
        <source>... or turned this much.</source>
        <translation>... oder sich um so viel gedreht hat.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="33"/>
        <source>A frame becomes the odometry&apos;s reference when it moved this far from the last one (0 with keyframe_rotation_deg 0: every frame).</source>
        <translation>Ein Bild wird zur Referenz der Odometrie, wenn es sich so weit von der letzten entfernt hat (0 mit keyframe_rotation_deg 0: jedes Bild).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="37"/>
        <source>A frame this far after the last, or in a sequence whose recent frames are (median of five steps), is low-rate (keyframe-rate): the zero-motion try below and the urgent keyframes of mono.mapping apply.</source>
        <translation>Ein Bild mindestens so weit nach dem letzten, oder in einer Folge, deren letzte Bilder es sind (Median von fünf Schritten), gilt als niedrige Bildrate (Schlüsselbildrate): der Versuch ohne Bewegung unten und die dringenden Schlüsselbilder von mono.mapping gelten.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="40"/>
        <source>A frame with a smaller fraction of depth pixels in range is not tracked (the pose is held).</source>
        <translation>Ein Bild mit einem kleineren Anteil an Tiefenpixeln im Messbereich wird nicht verfolgt (die Pose wird gehalten).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="51"/>
        <source>A new keyframe looks for a revisit among keyframes at least this many keyframes older.</source>
        <translation>Ein neues Schlüsselbild sucht einen erneuten Besuch unter Schlüsselbildern, die mindestens so viele Schlüsselbilder älter sind.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="53"/>
        <source>A ray of such an outline is on an edge when that edge is also this many times the median edge along the ray in its radius band (texture stands out less).</source>
        <translation>Ein Strahl eines solchen Umrisses liegt auf einer Kante, wenn diese Kante auch so viele Male so stark ist wie die mittlere Kante entlang des Strahls in seinem Radiusband (Textur hebt sich weniger ab).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="62"/>
        <source>A tracked corner within this of where the plane&apos;s homography puts it is on the panel.</source>
        <translation>Eine verfolgte Ecke, die höchstens so weit von der durch die Homographie der Ebene vorhergesagten Stelle liegt, gehört zum Tableau.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="73"/>
        <source>Always weigh each position by 1 / its own variance (plane fit, tracked centre and scale, growing with the distance): the near frames of the approach count most.</source>
        <translation>Jede Position immer mit 1 / ihrer eigenen Varianz gewichten (Ebenenanpassung, verfolgtes Zentrum und Maßstab, mit der Entfernung wachsend): die nahen Bilder der Annäherung zählen am meisten.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="79"/>
        <source>An odometry step faster than this (sensor time) is rejected.</source>
        <translation>Ein Odometrieschritt, der schneller ist (Sensorzeit), wird verworfen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="80"/>
        <source>An odometry step turning faster than this (sensor time) is rejected.</source>
        <translation>Ein Odometrieschritt, der sich schneller dreht (Sensorzeit), wird verworfen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="105"/>
        <source>Corners tracked around the button for the plane from the arm&apos;s motion.</source>
        <translation>Um die Taste verfolgte Ecken für die Ebene aus der Bewegung des Arms.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="113"/>
        <source>Depth readings farther than this are not used by the odometry.</source>
        <translation>Weiter entfernte Tiefenwerte verwendet die Odometrie nicht.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="114"/>
        <source>Depth readings nearer than this are not used by the odometry.</source>
        <translation>Nähere Tiefenwerte verwendet die Odometrie nicht.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="123"/>
        <source>Edge strength most rays of such an outline must reach.</source>
        <translation>Kantenstärke, die die meisten Strahlen eines solchen Umrisses erreichen müssen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="155"/>
        <source>Fraction of the pixels the odometry uses per pyramid level.</source>
        <translation>Anteil der Pixel, den die Odometrie je Pyramidenstufe verwendet.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="160"/>
        <source>Frames farther apart in sensor time are not aligned; tracking starts again from the held pose.</source>
        <translation>Bilder, die in Sensorzeit weiter auseinander liegen, werden nicht ausgerichtet; die Verfolgung beginnt neu an der gehaltenen Pose.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="190"/>
        <source>Hough accumulator threshold.</source>
        <translation>Schwelle des Hough-Akkumulators.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="191"/>
        <source>How long Grab() waits for a frame before reporting the device as unavailable.</source>
        <translation>Wie lange Grab() auf ein Bild wartet, bevor das Gerät als nicht verfügbar gemeldet wird.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="192"/>
        <source>Huber loss threshold of bundle adjustment.</source>
        <translation>Huber-Schwelle der Bündelausgleichung.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="193"/>
        <source>Huber threshold of the robust least squares.</source>
        <translation>Huber-Schwelle der robusten kleinsten Quadrate.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="194"/>
        <source>Huber threshold of the robust pose optimisation.</source>
        <translation>Huber-Schwelle der robusten Posenoptimierung.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="195"/>
        <source>Huber threshold of the robust weight of an observation&apos;s reprojection error.</source>
        <translation>Huber-Schwelle des robusten Gewichts des Reprojektionsfehlers einer Beobachtung.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="196"/>
        <source>Huber threshold of the robust weight.</source>
        <translation>Huber-Schwelle des robusten Gewichts.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="197"/>
        <source>Huber threshold of the robust weights of the offset measurement.</source>
        <translation>Huber-Schwelle der robusten Gewichte der Versatzmessung.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="198"/>
        <source>Hypotheses per line: fixed (max_iterations, seed) or adaptive log(1-p)/log(1-w^2) with w the best inlier ratio so far.</source>
        <translation>Hypothesen pro Linie: fest (max_iterations, Vorlage) oder adaptiv log(1-p)/log(1-w^2), mit w der bisher besten Inlier-Quote.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="199"/>
        <source>IPv4 address the target server binds; 127.0.0.1 keeps it on this machine.</source>
        <translation>IPv4-Adresse, an die der Zielserver bindet; 127.0.0.1 hält ihn auf diesem Rechner.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="200"/>
        <source>Idle-time adjustment slices run at stop on a large map (bounds the stop time).</source>
        <translation>Abschnitte der Ausgleichung in Leerlaufzeit, die beim Beenden auf einer großen Karte laufen (begrenzt die Zeit zum Beenden).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="201"/>
        <source>Image buffers in the stream&apos;s pool; more ride out longer consumer stalls.</source>
        <translation>Bildpuffer im Pool des Streams; mehr überbrücken längere Stockungen des Verbrauchers.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="202"/>
        <source>Image pyramid levels of the odometry (coarse to fine; more handle larger steps).</source>
        <translation>Stufen der Bildpyramide der Odometrie (grob nach fein; mehr Stufen bewältigen größere Schritte).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="203"/>
        <source>Inlier RMS above this: the plane is not sound.</source>
        <translation>Inlier-RMS über diesem Wert: Die Ebene ist nicht verlässlich.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="204"/>
        <source>Inlier distance of the panel plane.</source>
        <translation>Inlier-Abstand der Panelebene.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="205"/>
        <source>Inliers against the old map that confirm a revisit; the map since then is then bent onto the old one.</source>
        <translation>Inlier gegen die alte Karte, die einen erneuten Besuch bestätigen; die seither gebaute Karte wird dann auf die alte gebogen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="206"/>
        <source>Inliers needed to accept a relocalisation.</source>
        <translation>Inlier, die zum Akzeptieren einer Relokalisierung nötig sind.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="207"/>
        <source>Input line used with hardware triggering, e.g. Line1.</source>
        <translation>Eingangsleitung bei Hardware-Triggerung, z. B. Line1.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="208"/>
        <source>Iterations of each local bundle adjustment (0 = none).</source>
        <translation>Iterationen jeder lokalen Bündelausgleichung (0 = keine).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="209"/>
        <source>Iterations of one idle-time adjustment slice (0 = no adjustment in idle time).</source>
        <translation>Iterationen eines Abschnitts der Ausgleichung in Leerlaufzeit (0 = keine Ausgleichung im Leerlauf).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="210"/>
        <source>KLT iterations per level.</source>
        <translation>KLT-Iterationen pro Stufe.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="211"/>
        <source>KLT pyramid levels above full resolution (shared with stereo matching).</source>
        <translation>KLT-Pyramidenstufen über der vollen Auflösung (mit dem Stereo-Matching geteilt).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="212"/>
        <source>KLT pyramid levels used around the disparity guess.</source>
        <translation>Um die Disparitätsschätzung verwendete KLT-Pyramidenstufen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="213"/>
        <source>KLT stops when its update is smaller than this.</source>
        <translation>KLT hört auf, wenn seine Aktualisierung kleiner als dieser Wert ist.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="214"/>
        <source>KLT window side (odd).</source>
        <translation>Seitenlänge des KLT-Fensters (ungerade).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="215"/>
        <source>Keyframes whose poses one slice of the idle-time global adjustment optimises.</source>
        <translation>Schlüsselbilder, deren Posen ein Abschnitt der globalen Ausgleichung in Leerlaufzeit optimiert.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="217"/>
        <source>Larger 1-sigma position uncertainty: no target.</source>
        <translation>Größere 1-Sigma-Positionsunsicherheit: kein Ziel.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="218"/>
        <source>Larger 1-sigma uncertainty of the approach direction (the panel normal): no target.</source>
        <translation>Größere 1-Sigma-Unsicherheit der Anfahrrichtung (der Panelnormale): kein Ziel.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="219"/>
        <source>Larger change of velocity from the last accepted motion is rejected; 0 = no check.</source>
        <translation>Eine größere Geschwindigkeitsänderung gegenüber der letzten akzeptierten Bewegung wird verworfen; 0 = keine Prüfung.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="220"/>
        <source>Larger median offset of the face points from the panel plane is not applied.</source>
        <translation>Ein größerer Medianabstand der Flächenpunkte von der Panelebene wird nicht angewandt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="221"/>
        <source>Largest Hamming distance of a new-point match.</source>
        <translation>Größte Hamming-Distanz einer Übereinstimmung neuer Punkte.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="222"/>
        <source>Largest Hamming distance of a tracked ORB match.</source>
        <translation>Größte Hamming-Distanz einer verfolgten ORB-Übereinstimmung.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="223"/>
        <source>Largest Hough circle radius.</source>
        <translation>Größter Radius der Hough-Kreise.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="224"/>
        <source>Largest angle between the floor normal and the camera&apos;s up axis (-y).</source>
        <translation>Größter Winkel zwischen der Bodennormale und der Aufwärtsachse der Kamera (-y).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="225"/>
        <source>Largest button region as a fraction of the image area.</source>
        <translation>Größte Knopfregion als Anteil der Bildfläche.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="226"/>
        <source>Largest depth/colour timestamp difference of an RGB-D pair from a device; frames without a partner are dropped and counted.</source>
        <translation>Größter Zeitstempelunterschied zwischen Tiefe und Farbe eines RGB-D-Paars eines Geräts; Bilder ohne Partner werden verworfen und gezählt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="227"/>
        <source>Largest difference between the left and right timestamps of a pair; frames without a partner are dropped and counted.</source>
        <translation>Größter Unterschied zwischen den Zeitstempeln links und rechts eines Paars; Bilder ohne Partner werden verworfen und gezählt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="228"/>
        <source>Largest disparity searched and accepted.</source>
        <translation>Größte gesuchte und akzeptierte Disparität.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="229"/>
        <source>Largest size change (either way) since the last tracked frame at re-acquisition.</source>
        <translation>Größte Größenänderung (in beide Richtungen) seit dem letzten verfolgten Bild beim Wiederfinden.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="230"/>
        <source>Largest turn between two frames that search looks for.</source>
        <translation>Größte Drehung zwischen zwei Bildern, nach der diese Suche sucht.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="231"/>
        <source>Left-right check: the right point tracked back must land this close; 0 = no check.</source>
        <translation>Links-rechts-Prüfung: Der zurückverfolgte rechte Punkt muss so nah landen; 0 = keine Prüfung.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="232"/>
        <source>Length of the first baseline in map units (PTAM: 0.1); metric scale comes later.</source>
        <translation>Länge der ersten Basislinie in Karteneinheiten (PTAM: 0.1); die metrische Skala kommt später.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="233"/>
        <source>Levenberg-Marquardt iterations per frame.</source>
        <translation>Levenberg-Marquardt-Iterationen pro Bild.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="234"/>
        <source>Lines vote with weight length / (1 + (rms / rms_scale_m)^2): scattered consensus sets (a wall merged with a door recess) count less.</source>
        <translation>Linien stimmen mit dem Gewicht Länge / (1 + (rms / rms_scale_m)^2) ab: verstreute Konsensmengen (eine mit einer Türnische verschmolzene Wand) zählen weniger.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="235"/>
        <source>Lines with fewer points are dropped.</source>
        <translation>Linien mit weniger Punkten werden verworfen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="236"/>
        <source>Log-odds added when a frame sees a cell free.</source>
        <translation>Log-Odds, die addiert werden, wenn ein Bild eine Zelle frei sieht.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="237"/>
        <source>Log-odds added when a frame sees a cell occupied.</source>
        <translation>Log-Odds, die addiert werden, wenn ein Bild eine Zelle belegt sieht.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="238"/>
        <source>Longer client lines are discarded; an over-long token line closes the connection.</source>
        <translation>Längere Client-Zeilen werden verworfen; eine überlange Token-Zeile schließt die Verbindung.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="239"/>
        <source>Longer image side at which contours are searched; larger frames are scaled down.</source>
        <translation>Längere Bildseite, auf der Konturen gesucht werden; größere Bilder werden verkleinert.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="240"/>
        <source>Longest over shortest side of the region&apos;s rotated box.</source>
        <translation>Längste durch kürzeste Seite des gedrehten Rahmens der Region.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="241"/>
        <source>Looming needs the largest and smallest depth to differ by this fraction ...</source>
        <translation>Die Größenzunahme (Looming) verlangt, dass größte und kleinste Tiefe sich um diesen Anteil unterscheiden ...</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="242"/>
        <source>Lowe&apos;s ratio test: best over second-best descriptor distance must be below this.</source>
        <translation>Lowes Verhältnistest: Bester durch zweitbesten Deskriptorabstand muss unter diesem Wert liegen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="243"/>
        <source>Lower clamp of a cell&apos;s log-odds.</source>
        <translation>Untere Begrenzung der Log-Odds einer Zelle.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="244"/>
        <source>Lowest plausible camera height above the floor.</source>
        <translation>Niedrigste plausible Kamerahöhe über dem Boden.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="245"/>
        <source>Map points projecting within this distance of the button centre are used.</source>
        <translation>Kartenpunkte, die innerhalb dieses Abstands von der Knopfmitte projiziert werden, werden verwendet.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="246"/>
        <source>Map points within this many tracked button radii (the button&apos;s face) are used first; 0 = always use radius_px.</source>
        <translation>Kartenpunkte innerhalb so vieler verfolgter Knopfradien (die Knopffläche) werden zuerst verwendet; 0 = immer radius_px verwenden.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="247"/>
        <source>Maps with up to this many keyframes get the full global adjustment at stop; larger ones get at most final_ba_max_slices slices of the idle-time adjustment.</source>
        <translation>Karten mit bis zu so vielen Schlüsselbildern erhalten beim Beenden die vollständige globale Ausgleichung; größere höchstens final_ba_max_slices Abschnitte der Ausgleichung in Leerlaufzeit.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="248"/>
        <source>Matches with a smaller disparity (too far to triangulate) are rejected.</source>
        <translation>Übereinstimmungen mit kleinerer Disparität (zu weit für die Triangulation) werden verworfen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="249"/>
        <source>Matches with the first frame needed before initialisation is tried.</source>
        <translation>Übereinstimmungen mit dem ersten Bild, die vor einem Initialisierungsversuch nötig sind.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="250"/>
        <source>Measured displacements shorter than this are dropped.</source>
        <translation>Gemessene Verschiebungen, die kürzer als dies sind, werden verworfen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="251"/>
        <source>Measured motion for the metric scale: the arm&apos;s recorded poses (arm_poses.txt), the arm&apos;s poses streamed live to the button pipeline&apos;s arm-target server (arm_stream), ground-truth displacements, or none. auto: the recorded arm poses when arm_poses.txt is there; else, for the button pipeline while serving, the stream; else (mono-slam) ground truth.</source>
        <translation>Gemessene Bewegung für die metrische Skala: die aufgezeichneten Posen des Arms (arm_poses.txt), die live an den Armzielserver der Knopf-Pipeline gestreamten Posen des Arms (arm_stream), Ground-Truth-Verschiebungen oder keine. auto: die aufgezeichneten Armposen, wenn arm_poses.txt vorhanden ist; sonst, für die Knopf-Pipeline beim Bereitstellen, der Stream; sonst (mono-slam) die Ground Truth.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="252"/>
        <source>Median angle between the rays of a match needed before trying (move sideways).</source>
        <translation>Medianwinkel zwischen den Strahlen einer Übereinstimmung, der vor einem Versuch nötig ist (seitlich bewegen).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="253"/>
        <source>Minimum distance between corners.</source>
        <translation>Mindestabstand zwischen Ecken.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="254"/>
        <source>Mirror images left-right, as OpenNI does by default for people facing the camera.</source>
        <translation>Bilder links-rechts spiegeln, wie OpenNI es standardmäßig für Personen vor der Kamera tut.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="255"/>
        <source>Morphological closing that joins broken button outlines; 0 = none.</source>
        <translation>Morphologisches Schließen, das unterbrochene Knopfumrisse verbindet; 0 = keins.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="256"/>
        <source>Most recent keyframes whose poses local bundle adjustment optimises.</source>
        <translation>So viele jüngste Schlüsselbilder, deren Posen die lokale Bündelausgleichung optimiert.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="258"/>
        <source>Niceness of the mapping thread (threaded mode, Linux); 10 lets tracking win a core it shares with mapping, but starves mapping on a loaded machine.</source>
        <translation>Nice-Wert des Mapping-Threads (Thread-Modus, Linux); 10 lässt das Tracking einen mit dem Mapping geteilten Kern gewinnen, lässt das Mapping aber auf einem ausgelasteten Rechner verhungern.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="259"/>
        <source>No pose is interpolated across a larger gap between two arm_pose messages.</source>
        <translation>Über eine größere Lücke zwischen zwei arm_pose-Nachrichten wird keine Pose interpoliert.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="260"/>
        <source>No second reset within this many frames of the last one.</source>
        <translation>Kein zweiter Reset innerhalb so vieler Bilder nach dem letzten.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="261"/>
        <source>No target until the online hand-eye check has seen the mount&apos;s translation (the arm must rotate between keyframes); without it that translation is taken on trust.</source>
        <translation>Kein Ziel, bis die Online-Hand-Auge-Prüfung die Translation der Montage gesehen hat (der Arm muss sich zwischen Schlüsselbildern drehen); ohne sie wird diese Translation ungeprüft übernommen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="262"/>
        <source>Noise of a camera displacement measured in the map (sigma_x of the ML estimator).</source>
        <translation>Rauschen einer in der Karte gemessenen Kameraverschiebung (sigma_x des ML-Schätzers).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="263"/>
        <source>Noise of a displacement measured by the arm or robot (sigma_y).</source>
        <translation>Rauschen einer vom Arm oder Roboter gemessenen Verschiebung (sigma_y).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="264"/>
        <source>ORB features per frame for the feature guess.</source>
        <translation>ORB-Merkmale je Bild für die Merkmalsschätzung.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="265"/>
        <source>ORB keypoints extracted per frame.</source>
        <translation>Pro Bild extrahierte ORB-Keypoints.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="266"/>
        <source>Observations reprojecting worse than this are dropped from the window.</source>
        <translation>Beobachtungen, die schlechter als dies reprojizieren, werden aus dem Fenster entfernt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="267"/>
        <source>Observations with a smaller disparity (no usable depth) are left out.</source>
        <translation>Beobachtungen mit kleinerer Disparität (keine nutzbare Tiefe) bleiben unberücksichtigt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="268"/>
        <source>Occupied cells closer than this to the robot are ignored (robot body, noise).</source>
        <translation>Belegte Zellen, die näher als dies am Roboter liegen, werden ignoriert (Roboterkörper, Rauschen).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="270"/>
        <source>Odometry correspondences farther apart than this in depth are rejected.</source>
        <translation>Odometrie-Korrespondenzen, deren Tiefe weiter auseinander liegt, werden verworfen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="271"/>
        <source>Odometry iterations per pyramid level.</source>
        <translation>Odometrie-Iterationen je Pyramidenstufe.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="272"/>
        <source>Of the re-acquiring matches, at least this many lie on the button itself.</source>
        <translation>Von den wiederfindenden Übereinstimmungen liegen mindestens so viele auf dem Knopf selbst.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="273"/>
        <source>Old keyframes this close to a new keyframe (relative to the mean depth) are tried as a revisit (0 = no revisit search).</source>
        <translation>Alte Schlüsselbilder, die so nah an einem neuen Schlüsselbild liegen (relativ zur mittleren Tiefe), werden als erneuter Besuch geprüft (0 = keine Suche nach erneuten Besuchen).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="274"/>
        <source>Older estimates are not sent.</source>
        <translation>Ältere Schätzungen werden nicht gesendet.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="275"/>
        <source>Older frames&apos; normals fade with exp(-age / this) in the average (data time); 0 = this frame&apos;s normal only.</source>
        <translation>Die Normalen älterer Bilder klingen im Mittel mit exp(-Alter / diesem Wert) ab (Datenzeit); 0 = nur die Normale dieses Bildes.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="276"/>
        <source>On close: how long the stop lines may take to go out before the sockets close.</source>
        <translation>Beim Schließen: wie lange das Senden der Stoppzeilen dauern darf, bevor die Sockets schließen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="277"/>
        <source>On the button: within this many radii of its centre.</source>
        <translation>Auf dem Knopf: innerhalb so vieler Radien um seine Mitte.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="278"/>
        <source>Once a revisit links the map to old keyframes, those whose centre is this close to the camera (relative to the mean depth) join the recent ones in the map tracked against, so the place is tracked on its old points (0 = recent keyframes only).</source>
        <translation>Sobald ein erneuter Besuch die Karte mit alten Schlüsselbildern verbindet, kommen diejenigen, deren Zentrum so nah an der Kamera liegt (relativ zur mittleren Tiefe), zu den jüngsten in der Karte hinzu, gegen die verfolgt wird; so wird der Ort auf seinen alten Punkten verfolgt (0 = nur jüngste Schlüsselbilder).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="279"/>
        <source>Only frames tracked at least this confidently refresh the model.</source>
        <translation>Nur Bilder, die mindestens so sicher verfolgt wurden, erneuern das Modell.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="280"/>
        <source>Otherwise: the camera&apos;s optical centre this far ahead of the odometry base.</source>
        <translation>Sonst: das optische Zentrum der Kamera so weit vor der Odometriebasis.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="281"/>
        <source>Outlier removal: keep points with mean neighbour distance &lt;= mu + alpha sigma.</source>
        <translation>Ausreißerentfernung: Punkte mit mittlerem Nachbarabstand &lt;= mu + alpha sigma behalten.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="282"/>
        <source>Pairs weigh |measured displacement|^-e in the ML estimate: 1 = the map&apos;s error grows with the distance travelled, 0 = every pair equally noisy.</source>
        <translation>Paare gehen mit |gemessene Verschiebung|^-e in die ML-Schätzung ein: 1 = der Fehler der Karte wächst mit der zurückgelegten Strecke, 0 = jedes Paar gleich verrauscht.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="283"/>
        <source>Pairs whose own ratio lies outside a factor of this from the estimate are dropped.</source>
        <translation>Paare, deren eigenes Verhältnis außerhalb eines Faktors dieses Werts von der Schätzung liegt, werden verworfen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="284"/>
        <source>Pause between attempts to reopen a lost device.</source>
        <translation>Pause zwischen Versuchen, ein verlorenes Gerät neu zu öffnen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="285"/>
        <source>Per-client queue length; a slow client loses its oldest messages (counted).</source>
        <translation>Warteschlangenlänge pro Client; ein langsamer Client verliert seine ältesten Nachrichten (gezählt).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="286"/>
        <source>Per-segment plane RANSAC inlier distance.</source>
        <translation>RANSAC-Inlier-Abstand der Ebene pro Segment.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="287"/>
        <source>Per-segment plane RANSAC iterations before the least-squares refit (0 = PCA only).</source>
        <translation>RANSAC-Iterationen der Ebene pro Segment vor der Neuanpassung nach kleinsten Quadraten (0 = nur PCA).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="288"/>
        <source>Pixel format as a FOURCC, e.g. MJPG for high resolutions over USB 2; empty keeps the camera&apos;s.</source>
        <translation>Pixelformat als FOURCC, z. B. MJPG für hohe Auflösungen über USB 2; leer behält das der Kamera.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="289"/>
        <source>Pixels in a person box within this depth of the box&apos;s median depth are the person.</source>
        <translation>Pixel in einem Personenrahmen innerhalb dieser Tiefe um die Mediantiefe des Rahmens gehören zur Person.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="290"/>
        <source>Place every kept position again with the newest metric scale (kept in map units).</source>
        <translation>Jede behaltene Position mit der neuesten metrischen Skala neu platzieren (in Karteneinheiten behalten).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="291"/>
        <source>Plane RANSAC hypotheses of the panel normal.</source>
        <translation>RANSAC-Ebenenhypothesen der Panelnormale.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="292"/>
        <source>Plane RANSAC hypotheses.</source>
        <translation>RANSAC-Ebenenhypothesen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="293"/>
        <source>Plane inlier distance.</source>
        <translation>Inlier-Abstand der Ebene.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="294"/>
        <source>PnP inliers the feature guess needs to be used.</source>
        <translation>PnP-Inlier, die die Merkmalsschätzung braucht, um verwendet zu werden.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="295"/>
        <source>Point-to-plane distance of an inlier while fitting the floor.</source>
        <translation>Punkt-Ebene-Abstand eines Inliers bei der Anpassung des Bodens.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="296"/>
        <source>Points are subsampled evenly to at most this many.</source>
        <translation>Punkte werden gleichmäßig auf höchstens so viele unterabgetastet.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="297"/>
        <source>Points each ground hypothesis is scored on.</source>
        <translation>Punkte, an denen jede Bodenhypothese bewertet wird.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="298"/>
        <source>Points farther than this are not used for the fit.</source>
        <translation>Weiter entfernte Punkte werden für die Anpassung nicht verwendet.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="299"/>
        <source>Points found in fewer of the frames that should see them are culled.</source>
        <translation>Punkte, die in weniger der Bilder gefunden werden, die sie sehen sollten, werden entfernt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="300"/>
        <source>Points higher than this above the floor (ceiling, lamps) are ignored.</source>
        <translation>Punkte, die höher als dies über dem Boden liegen (Decke, Lampen), werden ignoriert.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="301"/>
        <source>Points on the button&apos;s face that move the panel plane onto the face.</source>
        <translation>Punkte auf der Knopffläche, die die Panelebene auf die Fläche verschieben.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="302"/>
        <source>Points whose neighbourhood bends more (surface variation, 0 = flat) get no normal and stay unsegmented: edges between surfaces.</source>
        <translation>Punkte, deren Nachbarschaft sich stärker krümmt (Oberflächenvariation, 0 = flach), erhalten keine Normale und bleiben unsegmentiert: Kanten zwischen Flächen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="303"/>
        <source>Prior standard deviation of the offset around zero; smaller trusts the calibration longer.</source>
        <translation>A-priori-Standardabweichung des Versatzes um null; kleiner vertraut der Kalibrierung länger.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="304"/>
        <source>Probability above which a cell is occupied (map.yaml occupied_thresh).</source>
        <translation>Wahrscheinlichkeit, über der eine Zelle belegt ist (map.yaml occupied_thresh).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="305"/>
        <source>Probability below which a cell is free (map.yaml free_thresh).</source>
        <translation>Wahrscheinlichkeit, unter der eine Zelle frei ist (map.yaml free_thresh).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="307"/>
        <source>Process every stride-th frame read, from the first (1 = all): a keyframe-rate sequence from a full-rate recording.</source>
        <translation>Jedes stride-te gelesene Bild verarbeiten, ab dem ersten (1 = alle): eine Sequenz in Schlüsselbildrate aus einer Aufnahme mit voller Rate.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="308"/>
        <source>Publish the targets through the arm-target server (button.arm.*); --serve HOST:PORT.</source>
        <translation>Die Ziele über den Armzielserver veröffentlichen (button.arm.*); --serve HOST:PORT.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="309"/>
        <source>Published eq. 13: depth-to-colour sensor offset along x.</source>
        <translation>Veröffentlichung Gl. 13: Versatz zwischen Tiefen- und Farbsensor entlang x.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="310"/>
        <source>Published eq. 13: depth-to-colour sensor offset along y.</source>
        <translation>Veröffentlichung Gl. 13: Versatz zwischen Tiefen- und Farbsensor entlang y.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="311"/>
        <source>Published eq. 6: expected inlier ratio w; iterations = log(1-p) / log(1-w^3).</source>
        <translation>Veröffentlichung Gl. 6: erwartete Inlier-Quote w; Iterationen = log(1-p) / log(1-w^3).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="312"/>
        <source>Published eq. 6: wanted probability p of drawing one all-inlier sample.</source>
        <translation>Veröffentlichung Gl. 6: gewünschte Wahrscheinlichkeit p, eine Stichprobe nur aus Inliern zu ziehen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="313"/>
        <source>Pyramid level Shi-Tomasi corners are detected on (0 = full resolution).</source>
        <translation>Pyramidenstufe, auf der Shi-Tomasi-Ecken erkannt werden (0 = volle Auflösung).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="314"/>
        <source>Pyramid level of the row search for features without a disparity guess.</source>
        <translation>Pyramidenstufe der Zeilensuche für Merkmale ohne Disparitätsschätzung.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="315"/>
        <source>Pyramid levels of the second tracking attempt (reaches about 2^levels further).</source>
        <translation>Pyramidenstufen des zweiten Tracking-Versuchs (reicht etwa 2^levels weiter).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="316"/>
        <source>Pyramid levels.</source>
        <translation>Pyramidenstufen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="317"/>
        <source>RANSAC inlier distance of the essential matrix and the homography.</source>
        <translation>RANSAC-Inlier-Abstand der essenziellen Matrix und der Homographie.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="318"/>
        <source>RANSAC plane hypotheses (half of them sampled within one voxel).</source>
        <translation>RANSAC-Ebenenhypothesen (die Hälfte davon innerhalb eines Voxels gezogen).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="319"/>
        <source>RGB-D odometry: rgbd aligns brightness and depth (needs registered colour), icp aligns depth surfaces only (point-to-plane), rgbd_icp uses both.</source>
        <translation>RGB-D-Odometrie: rgbd richtet Helligkeit und Tiefe aus (braucht registrierte Farbe), icp richtet nur Tiefenflächen aus (Punkt-zu-Ebene), rgbd_icp nutzt beides.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="322"/>
        <source>ROS bag: largest time between the two tf samples a pose at a frame&apos;s stamp is interpolated between; frames in a longer gap get no pose.</source>
        <translation>ROS-Bag: größter Zeitabstand der beiden tf-Samples, zwischen denen eine Pose zum Zeitstempel eines Frames interpoliert wird; Frames in einer längeren Lücke erhalten keine Pose.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="325"/>
        <source>ROS bag: the arm&apos;s base tf frame; the pose of end_effector_frame in it is the arm&apos;s pose when there is no arm_poses.txt.</source>
        <translation>ROS-Bag: der tf-Frame der Armbasis; die Pose von end_effector_frame darin ist die Pose des Arms, wenn es keine arm_poses.txt gibt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="326"/>
        <source>ROS bag: the arm&apos;s end-effector tf frame.</source>
        <translation>ROS-Bag: der tf-Frame des Endeffektors des Arms.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="331"/>
        <source>ROS bag: the platform&apos;s tf frame whose pose in odom_frame is the odometry.</source>
        <translation>ROS-Bag: der tf-Frame der Plattform, dessen Pose in odom_frame die Odometrie ist.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="334"/>
        <source>ROS bag: the tf frame of the odometry; without an odometry topic, the pose of base_frame in it on /tf is the platform&apos;s odometry.</source>
        <translation>ROS-Bag: der tf-Frame der Odometrie; ohne Odometrie-Topic ist die Pose von base_frame darin auf /tf die Odometrie der Plattform.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="335"/>
        <source>Random generator seed.</source>
        <translation>Startwert des Zufallsgenerators.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="336"/>
        <source>Random generator seed; each scan starts from it, so results are reproducible.</source>
        <translation>Startwert des Zufallsgenerators; jeder Scan beginnt damit, sodass Ergebnisse reproduzierbar sind.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="337"/>
        <source>Random seed of the plane RANSAC.</source>
        <translation>Zufalls-Startwert des Ebenen-RANSAC.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="338"/>
        <source>Rate at which a replayed recording delivers frames; 0 follows its timestamps.</source>
        <translation>Rate, mit der eine wiedergegebene Aufzeichnung Bilder liefert; 0 folgt ihren Zeitstempeln.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="339"/>
        <source>Ray angle a first map point needs.</source>
        <translation>Strahlwinkel, den ein erster Kartenpunkt braucht.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="340"/>
        <source>Ray angle a new map point needs.</source>
        <translation>Strahlwinkel, den ein neuer Kartenpunkt braucht.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="341"/>
        <source>Rays stop at this range; 0 = at the occupancy image border.</source>
        <translation>Strahlen enden bei dieser Reichweite; 0 = am Rand des Belegungsbilds.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="342"/>
        <source>Re-acquisition is refused when the other matches support a second similarity with this fraction of the inliers (another button of a repeated panel).</source>
        <translation>Das Wiederfinden wird abgelehnt, wenn die übrigen Übereinstimmungen eine zweite Ähnlichkeitstransformation mit diesem Anteil der Inlier stützen (ein anderer Knopf eines Panels mit Wiederholungen).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="343"/>
        <source>Recent keyframes a new keyframe triangulates new points with.</source>
        <translation>Jüngste Schlüsselbilder, mit denen ein neues Schlüsselbild neue Punkte trianguliert.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="344"/>
        <source>Rectify even when the rig says its images are rectified.</source>
        <translation>Auch rektifizieren, wenn das Rig angibt, seine Bilder seien rektifiziert.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="345"/>
        <source>Refine every tracked position against the track&apos;s anchor (where it was first seen), its patch warped by the motion since, so tracks do not drift frame by frame.</source>
        <translation>Jede verfolgte Position gegen den Anker des Tracks verfeinern (wo er zuerst gesehen wurde), dessen Patch mit der Bewegung seither verzerrt, damit Tracks nicht von Bild zu Bild driften.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="346"/>
        <source>Refine the 3D points with the motion (two-frame bundle adjustment); removes the depth bias of triangulation.</source>
        <translation>Die 3D-Punkte mit der Bewegung verfeinern (Zwei-Bild-Bündelausgleichung); entfernt die Tiefenverzerrung der Triangulation.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="347"/>
        <source>Refine the last frames&apos; poses and their tracks&apos; points together on the stereo reprojection error (sliding-window bundle adjustment), so per-frame errors do not add up.</source>
        <translation>Die Posen der letzten Bilder und die Punkte ihrer Tracks gemeinsam auf dem Stereo-Reprojektionsfehler verfeinern (Bündelausgleichung im gleitenden Fenster), damit sich Fehler einzelner Bilder nicht aufaddieren.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="348"/>
        <source>Refined RMS reprojection error above this is rejected.</source>
        <translation>Ein verfeinerter RMS-Reprojektionsfehler über diesem Wert wird verworfen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="349"/>
        <source>Refinement rounds: refine, re-select inliers by the reprojection threshold, refine.</source>
        <translation>Verfeinerungsrunden: verfeinern, Inlier anhand der Reprojektionsschwelle neu wählen, verfeinern.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="351"/>
        <source>Region growing: largest RGB-N colour distance between neighbours (255 (n+1)/2).</source>
        <translation>Regionenwachstum: größter RGB-N-Farbabstand zwischen Nachbarn (255 (n+1)/2).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="352"/>
        <source>Region-of-interest height; 0 keeps the camera&apos;s.</source>
        <translation>Höhe des Interessenbereichs (ROI); 0 behält die der Kamera.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="353"/>
        <source>Region-of-interest width; 0 keeps the camera&apos;s.</source>
        <translation>Breite des Interessenbereichs (ROI); 0 behält die der Kamera.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="354"/>
        <source>Register depth to the colour camera in the device when it supports it, so that depth and colour pixels correspond.</source>
        <translation>Tiefe im Gerät auf die Farbkamera registrieren, wenn es das unterstützt, damit sich Tiefen- und Farbpixel entsprechen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="355"/>
        <source>Reprojection error a first map point may have in either view.</source>
        <translation>Reprojektionsfehler, den ein erster Kartenpunkt in jeder Ansicht haben darf.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="356"/>
        <source>Reprojection error a new map point may have in either keyframe.</source>
        <translation>Reprojektionsfehler, den ein neuer Kartenpunkt in jedem Schlüsselbild haben darf.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="357"/>
        <source>Requested frame rate; 0 keeps the camera&apos;s.</source>
        <translation>Gewünschte Bildrate; 0 behält die der Kamera.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="358"/>
        <source>Requested image height; 0 keeps the camera&apos;s.</source>
        <translation>Gewünschte Bildhöhe; 0 behält die der Kamera.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="359"/>
        <source>Requested image width; 0 keeps the camera&apos;s. V4L2 picks the nearest mode.</source>
        <translation>Gewünschte Bildbreite; 0 behält die der Kamera. V4L2 wählt den nächstliegenden Modus.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="360"/>
        <source>Reset rule: a pose-source move larger than this between two frames resets the reference.</source>
        <translation>Reset-Regel: Eine Bewegung der Posenquelle zwischen zwei Bildern, die größer als dies ist, setzt die Referenz zurück.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="361"/>
        <source>Reset rule: a pose-source turn larger than this between two frames resets the reference.</source>
        <translation>Reset-Regel: Eine Drehung der Posenquelle zwischen zwei Bildern, die größer als dies ist, setzt die Referenz zurück.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="362"/>
        <source>Reset rule: this many consecutive frames whose walls disagree by more than max_correction_deg reset the reference.</source>
        <translation>Reset-Regel: So viele aufeinanderfolgende Bilder, deren Wände um mehr als max_correction_deg abweichen, setzen die Referenz zurück.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="363"/>
        <source>Residual beyond which a match is an outlier.</source>
        <translation>Residuum, ab dem eine Übereinstimmung ein Ausreißer ist.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="364"/>
        <source>Reweighted Gauss-Newton iterations.</source>
        <translation>Neu gewichtete Gauß-Newton-Iterationen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="365"/>
        <source>Rigid samples tried at least before adaptive termination may stop.</source>
        <translation>Mindestens so viele versuchte starre Stichproben, bevor der adaptive Abbruch greifen darf.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="366"/>
        <source>Roughness triangulation in plane coordinates: the cells&apos; grid or 2D Delaunay.</source>
        <translation>Triangulation für die Rauheit in Ebenenkoordinaten: das Zellraster oder 2D-Delaunay.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="367"/>
        <source>Roughness uses the segment&apos;s points within this range (all when none is).</source>
        <translation>Die Rauheit verwendet die Punkte des Segments innerhalb dieser Reichweite (alle, wenn keiner darin liegt).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="368"/>
        <source>Roughness: points are averaged in plane cells of this size, then triangulated.</source>
        <translation>Rauheit: Punkte werden in Ebenenzellen dieser Größe gemittelt und dann trianguliert.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="369"/>
        <source>Row search: mean absolute difference above this means no match.</source>
        <translation>Zeilensuche: Eine mittlere absolute Differenz über diesem Wert bedeutet keine Übereinstimmung.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="370"/>
        <source>Run mapping on its own thread (live); off = inline after each keyframe, deterministic.</source>
        <translation>Mapping in einem eigenen Thread ausführen (live); aus = direkt nach jedem Schlüsselbild, deterministisch.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="371"/>
        <source>SAD window side of the row search, at its level.</source>
        <translation>Seitenlänge des SAD-Fensters der Zeilensuche, auf ihrer Stufe.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="372"/>
        <source>SIFT contrast threshold.</source>
        <translation>SIFT-Kontrastschwelle.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="373"/>
        <source>SIFT contrast threshold; lower finds more keypoints on plain buttons.</source>
        <translation>SIFT-Kontrastschwelle; niedriger findet mehr Keypoints auf schlichten Knöpfen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="374"/>
        <source>SIFT keypoints up to this far outside the region belong to the button model.</source>
        <translation>SIFT-Keypoints bis zu so weit außerhalb der Region gehören zum Knopfmodell.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="375"/>
        <source>SIFT on a larger region runs on its crop scaled down so the region&apos;s radius is this (fewer, coarser features, much faster on close-up photos); 0 = never.</source>
        <translation>SIFT läuft bei einer größeren Region auf ihrem Ausschnitt, so verkleinert, dass der Radius der Region diesem Wert entspricht (weniger, gröbere Merkmale, bei Nahaufnahmen viel schneller); 0 = nie.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="376"/>
        <source>Scale between pyramid levels.</source>
        <translation>Skalierung zwischen Pyramidenstufen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="378"/>
        <source>Scored cloud written per frame.</source>
        <translation>Pro Bild geschriebene bewertete Punktwolke.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="379"/>
        <source>Search window around a map point&apos;s predicted position.</source>
        <translation>Suchfenster um die vorhergesagte Position eines Kartenpunkts.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="380"/>
        <source>Serve the targets to the arm over TCP (button.arm.bind_address, port, token); 127.0.0.1:5757 by default. The same as button.run.serve. Switching it keeps the run (map, button, STOP); switching it off sends the arm a stop line.</source>
        <translation>Die Ziele per TCP an den Arm liefern (button.arm.bind_address, port, token); standardmäßig 127.0.0.1:5757. Dasselbe wie button.run.serve. Das Umschalten behält den Lauf (Karte, Knopf, STOPP); das Ausschalten sendet dem Arm eine Stoppzeile.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="381"/>
        <source>Shi-Tomasi gradient window.</source>
        <translation>Shi-Tomasi-Gradientenfenster.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="382"/>
        <source>Shi-Tomasi: smallest minimum eigenvalue of a corner (cv::cornerMinEigenVal units).</source>
        <translation>Shi-Tomasi: kleinster minimaler Eigenwert einer Ecke (Einheiten von cv::cornerMinEigenVal).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="383"/>
        <source>Shorter lines are dropped.</source>
        <translation>Kürzere Linien werden verworfen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="384"/>
        <source>Side of the aligned patch (odd).</source>
        <translation>Seitenlänge des ausgerichteten Patches (ungerade).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="385"/>
        <source>Side of the detection grid&apos;s buckets; each holds at most its share of max_features.</source>
        <translation>Seitenlänge der Zellen (Buckets) des Erkennungsrasters; jede hält höchstens ihr Kontingent an max_features.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="386"/>
        <source>Similarity RANSAC inlier distance.</source>
        <translation>Inlier-Abstand der RANSAC-Ähnlichkeitstransformation.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="387"/>
        <source>Size change since the last refresh that triggers the next.</source>
        <translation>Größenänderung seit der letzten Erneuerung, die die nächste auslöst.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="388"/>
        <source>Smaller estimates are not applied: within the spread the estimate shows on a rig without offset (the simulator: +-0.03 px).</source>
        <translation>Kleinere Schätzungen werden nicht angewandt: Sie liegen innerhalb der Streuung, die die Schätzung auf einem Rig ohne Versatz zeigt (der Simulator: +-0.03 px).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="389"/>
        <source>Smaller regions stay unsegmented and unscored.</source>
        <translation>Kleinere Regionen bleiben unsegmentiert und unbewertet.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="390"/>
        <source>Smallest 1-sigma stated for one frame&apos;s normal (the map points&apos; errors are correlated, so the fit&apos;s own figure is optimistic).</source>
        <translation>Kleinstes für die Normale eines Bildes angegebenes 1-Sigma (die Fehler der Kartenpunkte sind korreliert, daher ist der eigene Wert der Anpassung zu optimistisch).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="391"/>
        <source>Smallest Hough circle radius.</source>
        <translation>Kleinster Radius der Hough-Kreise.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="392"/>
        <source>Smallest approach_sigma_deg a target states: the average of frames that share one map does not beat the map&apos;s own bias (on the simulated approach with the SLAM&apos;s map, up to 4.3 deg against per-frame fits of 0.5 deg).</source>
        <translation>Kleinstes approach_sigma_deg, das ein Ziel angibt: Das Mittel von Bildern, die sich eine Karte teilen, ist nicht besser als die eigene Verzerrung der Karte (bei der simulierten Anfahrt mit der Karte des SLAM bis zu 4.3 deg gegenüber Anpassungen einzelner Bilder von 0.5 deg).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="393"/>
        <source>Smallest button region.</source>
        <translation>Kleinste Knopfregion.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="394"/>
        <source>Split a piece while a point lies farther than this from its chord; merge pieces that fit one line within it (cells, like RANSAC&apos;s err_max).</source>
        <translation>Ein Stück teilen, solange ein Punkt weiter als dies von seiner Sehne entfernt liegt; Stücke zusammenführen, die innerhalb dieses Werts auf eine Linie passen (Zellen, wie err_max von RANSAC).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="396"/>
        <source>Start again at the end (timestamps keep increasing) instead of ending the stream.</source>
        <translation>Am Ende von vorn beginnen (die Zeitstempel steigen weiter), statt den Stream zu beenden.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="397"/>
        <source>Start each alignment from the last motion scaled by the time between frames.</source>
        <translation>Jede Ausrichtung mit der letzten Bewegung beginnen, skaliert mit der Zeit zwischen den Bildern.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="398"/>
        <source>Step B2: ... and at most this far apart (no lines across the room).</source>
        <translation>Schritt B2: ... und höchstens so weit auseinander (keine Linien quer durch den Raum).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="399"/>
        <source>Step B2: the two sampled points must be at least this far apart (no short lines).</source>
        <translation>Schritt B2: Die beiden gezogenen Punkte müssen mindestens so weit auseinanderliegen (keine kurzen Linien).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="403"/>
        <source>Stereo calibration (OpenCV stereo YAML as `sightline-cli calibrate stereo` writes) used instead of the source&apos;s; needed for live pairs (aravis://L,R) opened without one.</source>
        <translation>Stereokalibrierung (OpenCV-Stereo-YAML, wie `sightline-cli calibrate stereo` sie schreibt), die statt der der Quelle verwendet wird; nötig für Live-Paare (aravis://L,R), die ohne eine geöffnet werden.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="404"/>
        <source>Stereo calibration of the pair (OpenCV stereo YAML: M1 D1 M2 D2 R T, image_width/height, as `sightline-cli calibrate stereo` writes); the stereo odometry needs it. Also as aravis://LEFT,RIGHT?calibration_file=FILE.</source>
        <translation>Stereokalibrierung des Paars (OpenCV-Stereo-YAML: M1 D1 M2 D2 R T, image_width/height, wie `sightline-cli calibrate stereo` sie schreibt); die Stereo-Odometrie braucht sie. Auch als aravis://LEFT,RIGHT?calibration_file=FILE.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="405"/>
        <source>Stop when the update is smaller (radians or metres).</source>
        <translation>Aufhören, wenn die Aktualisierung kleiner ist (Radiant oder Meter).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="406"/>
        <source>Stream colour.</source>
        <translation>Farbe streamen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="407"/>
        <source>Stream depth.</source>
        <translation>Tiefe streamen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="408"/>
        <source>Stream height for depth and colour; 0 keeps the device&apos;s default mode.</source>
        <translation>Streamhöhe für Tiefe und Farbe; 0 behält den Standardmodus des Geräts.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="409"/>
        <source>Stream rate; 0 keeps the device&apos;s default mode.</source>
        <translation>Streamrate; 0 behält den Standardmodus des Geräts.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="410"/>
        <source>Stream width for depth and colour; 0 keeps the device&apos;s default mode.</source>
        <translation>Streambreite für Tiefe und Farbe; 0 behält den Standardmodus des Geräts.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="411"/>
        <source>Synchronous mode: frames without a new keyframe between two idle-time slices.</source>
        <translation>Synchroner Modus: Bilder ohne neues Schlüsselbild zwischen zwei Abschnitten in Leerlaufzeit.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="412"/>
        <source>TCP port of the target server; 0 = any free port.</source>
        <translation>TCP-Port des Zielservers; 0 = ein beliebiger freier Port.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="413"/>
        <source>Take the approach from the plane that the arm&apos;s own motion shows (corners around the button tracked from an anchor frame, the views&apos; poses from the arm) rather than from the SLAM&apos;s map, whenever that plane is found.</source>
        <translation>Die Anfahrrichtung aus der Ebene nehmen, die die eigene Bewegung des Arms zeigt (Ecken um die Taste, von einem Ankerbild an verfolgt, die Posen der Ansichten vom Arm), statt aus der Karte des SLAM, sobald diese Ebene gefunden ist.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="414"/>
        <source>Take the camera&apos;s offset ahead of the odometry base from the recording&apos;s scene.yaml (simulator) when present.</source>
        <translation>Den Versatz der Kamera vor der Odometriebasis aus der scene.yaml der Aufzeichnung (Simulator) übernehmen, wenn vorhanden.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="415"/>
        <source>The SIFT margin grows to this many region radii when that is larger.</source>
        <translation>Der SIFT-Rand wächst auf so viele Regionsradien, wenn das größer ist.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="416"/>
        <source>The appearance model&apos;s probability that the region at the tap is a button and not a printed label or sign beside one; below it: no button here. 0 = off.</source>
        <translation>Die Wahrscheinlichkeit des Erscheinungsmodells, dass die Region am Tippunkt eine Taste ist und kein daneben gedrucktes Etikett oder Schild; darunter: hier keine Taste. 0 = aus.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="417"/>
        <source>The approach direction is the normal of a plane through the map points within this distance of the located button (the panel around it).</source>
        <translation>Die Anfahrrichtung ist die Normale einer Ebene durch die Kartenpunkte innerhalb dieses Abstands vom gefundenen Knopf (das Panel um ihn herum).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="418"/>
        <source>The arm&apos;s and the SLAM&apos;s displacement directions disagree by more than this (online hand-eye check; a wrong mount rotation): no target.</source>
        <translation>Die Verschiebungsrichtungen von Arm und SLAM weichen um mehr als dies voneinander ab (Online-Hand-Auge-Prüfung; eine falsche Montagerotation): kein Ziel.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="419"/>
        <source>The arm&apos;s clock minus the camera&apos;s (configured; arm stamp = frame stamp + this).</source>
        <translation>Die Uhr des Arms minus die der Kamera (konfiguriert; Armzeitstempel = Bildzeitstempel + dieser Wert).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="420"/>
        <source>The arm&apos;s motion since the anchor frame, as an angle seen from the panel, before its plane is used.</source>
        <translation>Die Bewegung des Arms seit dem Ankerbild, als Winkel vom Tableau aus gesehen, bevor seine Ebene verwendet wird.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="421"/>
        <source>The current frame becomes the keyframe when fewer keyframe tracks agree with the motion.</source>
        <translation>Das aktuelle Bild wird zum Schlüsselbild, wenn weniger Tracks des Schlüsselbilds mit der Bewegung übereinstimmen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="422"/>
        <source>The current frame becomes the keyframe when fewer of the keyframe&apos;s tracks survive.</source>
        <translation>Das aktuelle Bild wird zum Schlüsselbild, wenn weniger Tracks des Schlüsselbilds überleben.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="423"/>
        <source>The depth colour map spans zero to this range.</source>
        <translation>Die Tiefen-Farbskala reicht von null bis zu diesem Wert.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="424"/>
        <source>The estimated offset is clamped to +- this.</source>
        <translation>Der geschätzte Versatz wird auf +- diesen Wert begrenzt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="425"/>
        <source>The face&apos;s offset from the panel plane is the median of its points within this many robust sigmas of that median, until the set settles (points triangulated with little parallax leave a one-sided tail); 0 = the median of all.</source>
        <translation>Der Versatz der Tastenfläche von der Paneelebene ist der Median ihrer Punkte innerhalb so vieler robuster Sigmas um diesen Median, bis die Menge stabil ist (mit wenig Parallaxe triangulierte Punkte bilden einen einseitigen Ausläufer); 0 = der Median aller.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="426"/>
        <source>The floor is the lowest plane: at most this fraction of points may lie clearly below it (rejects table tops).</source>
        <translation>Der Boden ist die niedrigste Ebene: Höchstens dieser Anteil der Punkte darf deutlich darunter liegen (verwirft Tischplatten).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="427"/>
        <source>The floor must hold at least this fraction of the valid points.</source>
        <translation>Der Boden muss mindestens diesen Anteil der gültigen Punkte enthalten.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="428"/>
        <source>The gate grows to this many predicted button radii when that is larger.</source>
        <translation>Das Gate wächst auf so viele vorhergesagte Knopfradien, wenn das größer ist.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="429"/>
        <source>The gate widens by this per metre driven since the last correction (expected heading drift of the pose source).</source>
        <translation>Das Gate weitet sich um diesen Wert pro seit der letzten Korrektur gefahrenem Meter (erwartete Richtungsdrift der Posenquelle).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="430"/>
        <source>The homography is chosen when its share of the inliers exceeds this.</source>
        <translation>Die Homographie wird gewählt, wenn ihr Anteil an den Inliern diesen Wert übersteigt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="431"/>
        <source>The map grows by at least this much each time it must.</source>
        <translation>Die Karte wächst jedes Mal, wenn sie muss, um mindestens so viel.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="432"/>
        <source>The maximum-likelihood estimate is reported from this many pairs on.</source>
        <translation>Die Maximum-Likelihood-Schätzung wird ab so vielen Paaren gemeldet.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="433"/>
        <source>The metric scale counts as converged with this many displacement pairs in the ML estimate at least ...</source>
        <translation>Die metrische Skala gilt als konvergiert mit mindestens so vielen Verschiebungspaaren in der ML-Schätzung ...</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="434"/>
        <source>The model never grows beyond this many keypoints.</source>
        <translation>Das Modell wächst nie über so viele Keypoints hinaus.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="435"/>
        <source>The offset is measured between an anchor frame and the first later frame whose translation from it reaches this fraction of the common tracks&apos; median depth: with less parallax, tracking errors dominate the measurement.</source>
        <translation>Der Versatz wird zwischen einem Ankerbild und dem ersten späteren Bild gemessen, dessen Translation davon diesen Anteil der Mediantiefe der gemeinsamen Tracks erreicht: Bei weniger Parallaxe dominieren Tracking-Fehler die Messung.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="436"/>
        <source>The online hand-eye check compares keyframes at least this far apart (measured): the directions of shorter displacements drown in the noise.</source>
        <translation>Die Online-Hand-Auge-Prüfung vergleicht Schlüsselbilder, die mindestens so weit auseinanderliegen (gemessen): Die Richtungen kürzerer Verschiebungen gehen im Rauschen unter.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="437"/>
        <source>The online hand-eye check sees the mount&apos;s translation only when the arm rotates at least this much between two keyframes.</source>
        <translation>Die Online-Hand-Auge-Prüfung sieht die Translation der Montage nur, wenn sich der Arm zwischen zwei Schlüsselbildern mindestens so weit dreht.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="438"/>
        <source>The operator&apos;s tap is refused when the frame it was made on is older than this (data time) by the time the pipeline takes it.</source>
        <translation>Das Antippen des Bedieners wird abgelehnt, wenn das Bild, auf dem es erfolgte, älter als dies ist (Datenzeit), sobald die Pipeline es übernimmt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="439"/>
        <source>The operator&apos;s tap: X,Y in pixels, optionally @FRAME (frame index, default 0); confirmed at once. sightline-cli run button --tap X,Y[@FRAME] sets it.</source>
        <translation>Das Antippen des Bedieners: X,Y in Pixeln, optional @FRAME (Bildindex, Standard 0); sofort bestätigt. sightline-cli run button --tap X,Y[@FRAME] setzt es.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="440"/>
        <source>The panel plane passes at most this far from the located button: of the surfaces around it (a side wall, a door frame) only the one holding the button gives the push direction.</source>
        <translation>Die Panelebene verläuft höchstens so weit vom gefundenen Taster entfernt: von den Flächen um ihn herum (eine Seitenwand, ein Türrahmen) gibt nur die, die den Taster trägt, die Drückrichtung.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="441"/>
        <source>The position&apos;s panel plane is fitted robustly to the map points within this many tracked button radii and moved onto the face by its points&apos; median offset; 0 = the plane within radius_px (or the face&apos;s own).</source>
        <translation>Die Ebene der Position wird robust an die Kartenpunkte innerhalb so vieler verfolgter Tastenradien angepasst und um den Median-Abstand ihrer Punkte auf die Tastenfläche verschoben; 0 = die Ebene innerhalb von radius_px (oder die eigene der Fläche).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="442"/>
        <source>The size from the tap&apos;s own keypoints alone (not the refreshed ones, whose scale drifts; the looming in button.triangulate.*) needs this many consistent matches.</source>
        <translation>Die Größe allein aus den eigenen Schlüsselpunkten des Tippens (nicht den aufgefrischten, deren Maßstab driftet; das Looming in button.triangulate.*) braucht so viele konsistente Zuordnungen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="443"/>
        <source>The size from the tap&apos;s own keypoints only (ButtonTrack::anchor_scale: the keypoints the tracker&apos;s refresh adds carry each refresh&apos;s scale error on); false: the tracked radius.</source>
        <translation>Die Größe nur aus den eigenen Schlüsselpunkten des Tippens (ButtonTrack::anchor_scale: die vom Auffrischen des Trackers hinzugefügten Schlüsselpunkte tragen den Maßstabsfehler jedes Auffrischens weiter); false: der verfolgte Radius.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="444"/>
        <source>The target is the per-axis median of this many recent base-frame positions (sound plane, converged scale); 0 = every one since the tap, 1 = no fusion.</source>
        <translation>Das Ziel ist der achsweise Median so vieler jüngster Positionen im Basissystem (verlässliche Ebene, konvergierte Skala); 0 = jede seit dem Antippen, 1 = keine Fusion.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="445"/>
        <source>The tracking gate never exceeds this: larger corrections are not applied.</source>
        <translation>Das Tracking-Gate überschreitet nie diesen Wert: Größere Korrekturen werden nicht angewandt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="446"/>
        <source>The window grows to this many predicted button radii when that is larger.</source>
        <translation>Das Fenster wächst auf so viele vorhergesagte Knopfradien, wenn das größer ist.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="447"/>
        <source>Tolerance of accuracy.map_iou: a map cell within this many cells of a true wall counts as on it.</source>
        <translation>Toleranz von accuracy.map_iou: Eine Kartenzelle innerhalb so vieler Zellen einer wahren Wand zählt als darauf liegend.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="448"/>
        <source>Top-view grid cell.</source>
        <translation>Rasterzelle der Draufsicht.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="449"/>
        <source>Track points drawn behind the button on the overlay.</source>
        <translation>Auf dem Overlay hinter dem Knopf gezeichnete Trackpunkte.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="450"/>
        <source>Tracking gate right after a correction: lines farther than this from the expected direction neither vote nor correct.</source>
        <translation>Tracking-Gate direkt nach einer Korrektur: Linien, die weiter als dies von der erwarteten Richtung abweichen, stimmen weder ab noch korrigieren sie.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="451"/>
        <source>Tracking is lost when fewer than this share of the map points predicted in the image are found (PTAM&apos;s test against a wrong pose after a jump).</source>
        <translation>Das Tracking ist verloren, wenn weniger als dieser Anteil der im Bild vorhergesagten Kartenpunkte gefunden wird (der Test von PTAM gegen eine falsche Pose nach einem Sprung).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="452"/>
        <source>Tracking quality is good from this many inliers.</source>
        <translation>Die Tracking-Qualität ist ab so vielen Inliern gut.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="453"/>
        <source>Tracking quality is poor from this many inliers; fewer is lost.</source>
        <translation>Die Tracking-Qualität ist ab so vielen Inliern schlecht; weniger gilt als verloren.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="454"/>
        <source>Triangulated points needed to accept the initialisation.</source>
        <translation>Triangulierte Punkte, die zum Akzeptieren der Initialisierung nötig sind.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="455"/>
        <source>UMBRAL1: change of a pairwise distance a rigid sample may show, before depth uncertainty is added.</source>
        <translation>UMBRAL1: Änderung eines paarweisen Abstands, die eine starre Stichprobe zeigen darf, bevor die Tiefenunsicherheit addiert wird.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="456"/>
        <source>UMBRAL2: rigidity rejections after which RANSAC fails (the last motion is kept).</source>
        <translation>UMBRAL2: Starrheitsablehnungen, nach denen RANSAC scheitert (die letzte Bewegung bleibt).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="457"/>
        <source>UMBRAL3: reprojection error (RMS of both images) of an inlier.</source>
        <translation>UMBRAL3: Reprojektionsfehler (RMS beider Bilder) eines Inliers.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="458"/>
        <source>UMBRAL4: stop sampling once this fraction of the points is inlier.</source>
        <translation>UMBRAL4: das Ziehen beenden, sobald dieser Anteil der Punkte Inlier ist.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="459"/>
        <source>UMBRAL5: rigid samples tried before the best inlier set is taken.</source>
        <translation>UMBRAL5: versuchte starre Stichproben, bevor die beste Inlier-Menge übernommen wird.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="460"/>
        <source>Up-facing planes searched; the lowest large one is the ground.</source>
        <translation>Gesuchte nach oben gerichtete Ebenen; die niedrigste große ist der Boden.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="461"/>
        <source>Upper clamp of a cell&apos;s log-odds.</source>
        <translation>Obere Begrenzung der Log-Odds einer Zelle.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="462"/>
        <source>Use every n-th depth pixel for the 3D cloud; 1 shows all (slower).</source>
        <translation>Jedes n-te Tiefenpixel für die 3D-Wolke verwenden; 1 zeigt alle (langsamer).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="463"/>
        <source>Use the apparent size (looming: the radius grows as 1 / depth while the arm moves forward by a measured distance) besides the rays.</source>
        <translation>Neben den Strahlen die scheinbare Größe nutzen (Looming: der Radius wächst mit 1 / Tiefe, während der Arm um eine gemessene Strecke vorfährt).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="464"/>
        <source>Viewing ray closer to parallel with the plane than this |cos|: no position.</source>
        <translation>Sehstrahl paralleler zur Ebene als dieses |cos|: keine Position.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="465"/>
        <source>Voting lines within this of their length-weighted median are averaged; others (a wall merged with a recessed door, a box) are dropped.</source>
        <translation>Abstimmende Linien innerhalb dieses Werts um ihren längengewichteten Median werden gemittelt; andere (eine mit einer Türnische verschmolzene Wand, eine Kiste) werden verworfen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="466"/>
        <source>Voting wall length a frame needs before it may set the reference direction.</source>
        <translation>Abstimmende Wandlänge, die ein Bild braucht, bevor es die Referenzrichtung setzen darf.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="467"/>
        <source>Voxel size for locally sampled hypotheses (finds a floor that covers little of the view).</source>
        <translation>Voxelgröße für lokal gezogene Hypothesen (findet einen Boden, der wenig vom Bild bedeckt).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="468"/>
        <source>Wall lines shorter than this do not vote for the direction.</source>
        <translation>Wandlinien, die kürzer als dies sind, stimmen nicht über die Richtung ab.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="469"/>
        <source>Wall lines with fewer scan points do not vote.</source>
        <translation>Wandlinien mit weniger Scanpunkten stimmen nicht ab.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="471"/>
        <source>Weaker tracking confidence: no target.</source>
        <translation>Geringere Tracking-Sicherheit: kein Ziel.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="473"/>
        <source>Weight observations by 1 / (|u - cx| / cx + 0.05) (libviso2), favouring the centre, as the two-frame refinement does.</source>
        <translation>Beobachtungen mit 1 / (|u - cx| / cx + 0.05) gewichten (libviso2), was die Bildmitte bevorzugt, wie es die Zwei-Bild-Verfeinerung tut.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="474"/>
        <source>Weight observations by 1 / (|u - cx| / cx + 0.05) (libviso2), favouring the centre.</source>
        <translation>Beobachtungen mit 1 / (|u - cx| / cx + 0.05) gewichten (libviso2), was die Bildmitte bevorzugt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="475"/>
        <source>Weight of the fused positions&apos; spread (1.4826 x median absolute deviation from the fused target) in the stated uncertainty.</source>
        <translation>Gewicht der Streuung der fusionierten Positionen (1.4826 x mittlere absolute Abweichung vom fusionierten Ziel) in der angegebenen Unsicherheit.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="476"/>
        <source>What replaces a rejected motion: the last accepted one, or none.</source>
        <translation>Was eine verworfene Bewegung ersetzt: die letzte akzeptierte oder keine.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="478"/>
        <source>When fewer tracks survive than this fraction of the share that survived in the previous frame (poor motion prediction), the lost ones are tracked again with retrack_pyramid_levels; 0 = never.</source>
        <translation>Wenn weniger Tracks überleben als dieser Anteil des im vorigen Bild überlebenden Anteils (schlechte Bewegungsvorhersage), werden die verlorenen mit retrack_pyramid_levels erneut verfolgt; 0 = nie.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="479"/>
        <source>When set, a client must send {&quot;token&quot;: &quot;...&quot;} before it receives anything; required when bind_address is not a loopback address.</source>
        <translation>Wenn gesetzt, muss ein Client {&quot;token&quot;: &quot;...&quot;} senden, bevor er etwas erhält; erforderlich, wenn bind_address keine Loopback-Adresse ist.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="481"/>
        <source>Where the robot&apos;s translation comes from: the recording&apos;s odometry (odometry.txt, a bag&apos;s odometry or tf, a live source&apos;s), RGB-D odometry on the depth and colour frames, none (heading from the walls only), or auto (the recording&apos;s odometry when it has one, else RGB-D odometry when the frames have colour or the method is icp, else none).</source>
        <translation>Woher die Translation des Roboters kommt: die Odometrie der Aufnahme (odometry.txt, Odometrie oder tf einer Bag-Datei, die einer Live-Quelle), RGB-D-Odometrie auf den Tiefen- und Farbbildern, none (Kurs nur aus den Wänden) oder auto (die Odometrie der Aufnahme, wenn sie eine hat, sonst RGB-D-Odometrie, wenn die Bilder Farbe haben oder die Methode icp ist, sonst none).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="483"/>
        <source>Width of the reduced copies of the two images compared in that search.</source>
        <translation>Breite der verkleinerten Kopien der beiden Bilder, die bei dieser Suche verglichen werden.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="484"/>
        <source>Window of the second pass, after a first pose.</source>
        <translation>Fenster des zweiten Durchgangs, nach einer ersten Pose.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="485"/>
        <source>Window used when the first search finds too few points.</source>
        <translation>Fenster, das verwendet wird, wenn die erste Suche zu wenige Punkte findet.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="486"/>
        <source>With a token: a connection that has not presented it after this long is closed.</source>
        <translation>Mit einem Token: Eine Verbindung, die es nach dieser Zeit nicht vorgelegt hat, wird geschlossen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="487"/>
        <source>With fewer than min_matches but this many matches, an essential matrix from them guides a second matching along epipolar lines (large motion).</source>
        <translation>Bei weniger als min_matches, aber mindestens so vielen Zuordnungen leitet eine daraus geschätzte Essentielle Matrix eine zweite Zuordnung entlang der Epipolarlinien (große Bewegung).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="488"/>
        <source>With png: also overlay.avi (Motion-JPEG through OpenCV&apos;s built-in writer).</source>
        <translation>Mit png: auch overlay.avi (Motion-JPEG über den eingebauten Writer von OpenCV).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="489"/>
        <source>With serve: give up waiting for clients after this long.</source>
        <translation>Mit serve: das Warten auf Clients nach dieser Zeit aufgeben.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="490"/>
        <source>With serve: keep serving this long after the last frame so queued targets go out.</source>
        <translation>Mit serve: nach dem letzten Bild noch so lange weiter bereitstellen, damit wartende Ziele hinausgehen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="491"/>
        <source>With serve: wait for this many connected clients before the first frame.</source>
        <translation>Mit serve: vor dem ersten Bild auf so viele verbundene Clients warten.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="492"/>
        <source>Without a reference: lines within this of the best-supported direction (modulo 90 deg) vote.</source>
        <translation>Ohne Referenz: Linien innerhalb dieses Werts um die am besten gestützte Richtung (modulo 90 deg) stimmen ab.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="493"/>
        <source>Workspace box, base x max.</source>
        <translation>Arbeitsraumquader, Basis x max.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="494"/>
        <source>Workspace box, base x min.</source>
        <translation>Arbeitsraumquader, Basis x min.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="495"/>
        <source>Workspace box, base y max.</source>
        <translation>Arbeitsraumquader, Basis y max.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="496"/>
        <source>Workspace box, base y min.</source>
        <translation>Arbeitsraumquader, Basis y min.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="497"/>
        <source>Workspace box, base z max.</source>
        <translation>Arbeitsraumquader, Basis z max.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="498"/>
        <source>Workspace box, base z min.</source>
        <translation>Arbeitsraumquader, Basis z min.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="499"/>
        <source>Write the projection and top-view PNGs per frame.</source>
        <translation>Die Projektions- und Draufsicht-PNGs pro Bild schreiben.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="500"/>
        <source>accuracy.wall_recall: a true wall is visible in a frame when at least this much of it is in view ...</source>
        <translation>accuracy.wall_recall: Eine wahre Wand ist in einem Bild sichtbar, wenn mindestens so viel von ihr im Blickfeld liegt ...</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="501"/>
        <source>arm_pose messages closer than 1/this in the arm&apos;s time are dropped (counted).</source>
        <translation>arm_pose-Nachrichten, die in der Zeit des Arms näher als 1/dieser Wert beieinanderliegen, werden verworfen (gezählt).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="502"/>
        <source>arm_pose messages older than this behind the newest are forgotten.</source>
        <translation>arm_pose-Nachrichten, die weiter als dies hinter der neuesten liegen, werden vergessen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="503"/>
        <source>arm_poses.txt (base_from_end_effector, TUM); empty = beside the sensor folder.</source>
        <translation>arm_poses.txt (base_from_end_effector, TUM); leer = neben dem Sensorordner.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="504"/>
        <source>custom platform: a segment raised more than this above the ground scores 0.</source>
        <translation>Plattform custom: Ein Segment, das mehr als dies über den Boden erhöht ist, erhält den Wert 0.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="505"/>
        <source>custom platform: points farther from the sensor are dropped.</source>
        <translation>Plattform custom: Weiter vom Sensor entfernte Punkte werden verworfen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="506"/>
        <source>delaunay: triangles with an edge longer than this many cells are dropped.</source>
        <translation>delaunay: Dreiecke mit einer Kante, die länger als so viele Zellen ist, werden verworfen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="512"/>
        <source>depth: a person&apos;s top lies at least this many footprint lengths above the floor (a desk, a table or a sofa is wider than it is tall).</source>
        <translation>depth: Die Oberkante einer Person liegt mindestens so viele Grundflächenlängen über dem Boden (ein Schreibtisch, ein Tisch oder ein Sofa ist breiter als hoch).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="518"/>
        <source>depth: the HOG score a cluster&apos;s box needs when it touches the image&apos;s border (a body cut off scores lower).</source>
        <translation>depth: die HOG-Bewertung, die der Rahmen eines Clusters braucht, wenn er den Bildrand berührt (ein abgeschnittener Körper wird niedriger bewertet).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="519"/>
        <source>depth: the HOG score a cluster&apos;s box needs when the whole box is in view.</source>
        <translation>depth: die HOG-Bewertung, die der Rahmen eines Clusters braucht, wenn er ganz im Bild liegt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="522"/>
        <source>depth: when on, a cluster reaching the image&apos;s top row (its top out of view) is not a person: fewer false people at the edge of view, but people near enough to have their heads cut off are missed.</source>
        <translation>depth: Wenn an, ist ein Cluster, der die oberste Bildzeile erreicht (seine Oberkante liegt außerhalb des Bildes), keine Person: weniger falsche Personen am Bildrand, aber Personen, die so nah sind, dass ihr Kopf abgeschnitten ist, werden übersehen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="523"/>
        <source>depth: when the colour image is registered to the depth image, OpenCV&apos;s HOG people detector must also score each cluster&apos;s box (a chair or a desk of a person&apos;s size is dropped).</source>
        <translation>depth: Ist das Farbbild zum Tiefenbild registriert, muss auch OpenCVs HOG-Personendetektor den Rahmen jedes Clusters bestätigen (ein Stuhl oder Schreibtisch von Personengröße fällt weg).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="524"/>
        <source>device: pair by camera timestamps (cameras on a common clock, e.g. PTP or a shared trigger); host: pair by arrival time at the host.</source>
        <translation>device: Paare nach Kamerazeitstempeln bilden (Kameras mit gemeinsamer Uhr, z. B. PTP oder gemeinsamer Trigger); host: Paare nach Ankunftszeit am Host bilden.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="527"/>
        <source>free: the camera runs on its own clock; software: the host triggers each frame (both cameras of a pair together); hardware: an external pulse on trigger_line.</source>
        <translation>free: Die Kamera läuft mit eigenem Takt; software: Der Host triggert jedes Bild (beide Kameras eines Paars gemeinsam); hardware: ein externer Impuls auf trigger_line.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="528"/>
        <source>grid: every n-th pixel in both directions (stands in for the voxel grid).</source>
        <translation>grid: jedes n-te Pixel in beiden Richtungen (anstelle des Voxelgitters).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="529"/>
        <source>grid: grid neighbours whose depths differ by more than this fraction are apart.</source>
        <translation>grid: Rasternachbarn, deren Tiefen sich um mehr als diesen Anteil unterscheiden, sind getrennt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="530"/>
        <source>grid: half-width of the window of grid points each normal is fitted to.</source>
        <translation>grid: halbe Breite des Fensters der Rasterpunkte, an die jede Normale angepasst wird.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="532"/>
        <source>hand_eye.yaml (end_effector_from_camera); empty = beside arm_poses (for arm_stream: beside the images); none = identity.</source>
        <translation>hand_eye.yaml (end_effector_from_camera); leer = neben arm_poses (für arm_stream: neben den Bildern); none = Identität.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="533"/>
        <source>i_max (step E): at most this many lines.</source>
        <translation>i_max (Schritt E): höchstens so viele Linien.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="535"/>
        <source>multiscale: add Hough circles (round buttons, thin rings).</source>
        <translation>multiscale: Hough-Kreise hinzufügen (runde Knöpfe, dünne Ringe).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="536"/>
        <source>multiscale: blur of the second scale, times blur_sigma_px.</source>
        <translation>multiscale: Unschärfe der zweiten Skala, mal blur_sigma_px.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="537"/>
        <source>multiscale: half size of the window around the tap that is searched.</source>
        <translation>multiscale: halbe Größe des Fensters um die Tippstelle, das durchsucht wird.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="538"/>
        <source>multiscale: longest over shortest side of a region&apos;s rotated box.</source>
        <translation>multiscale: längste durch kürzeste Seite des gedrehten Rahmens einer Region.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="539"/>
        <source>multiscale: regions are ranked by (offset + bias) / radius, so the button&apos;s outline wins over a glyph on it.</source>
        <translation>multiscale: Regionen werden nach (Versatz + Bias) / Radius gereiht, sodass der Umriss des Knopfs gegen ein Symbol darauf gewinnt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="540"/>
        <source>multiscale: the region&apos;s centroid lies at most this many radii from the tap.</source>
        <translation>multiscale: Der Schwerpunkt der Region liegt höchstens so viele Radien von der Tippstelle entfernt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="541"/>
        <source>multiscale: the two Canny pairs are the thresholds times 2/(1+s) and 2s/(1+s).</source>
        <translation>multiscale: Die beiden Canny-Paare sind die Schwellen mal 2/(1+s) und 2s/(1+s).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="542"/>
        <source>multiscale: when no outline holds the tap, look for closed outlines of the strongest radial edges around it (faint or thin-ringed buttons).</source>
        <translation>multiscale: wenn kein Umriss den Tipp enthält, um ihn herum geschlossene Umrisse der stärksten radialen Kanten suchen (schwache Tasten oder Tasten mit dünnem Ring).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="543"/>
        <source>p of the adaptive count: probability of drawing one all-inlier pair.</source>
        <translation>p der adaptiven Anzahl: Wahrscheinlichkeit, ein Paar nur aus Inliern zu ziehen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="544"/>
        <source>pcl: neighbour radius of the region growing.</source>
        <translation>pcl: Nachbarradius des Regionenwachstums.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="545"/>
        <source>pcl: neighbours of the normal fit.</source>
        <translation>pcl: Nachbarn der Normalenanpassung.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="546"/>
        <source>pcl: neighbours of the outlier removal.</source>
        <translation>pcl: Nachbarn der Ausreißerentfernung.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="547"/>
        <source>pcl: voxel grid leaf size.</source>
        <translation>pcl: Blattgröße des Voxelgitters.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="548"/>
        <source>ratio_max (step B8): a hypothesis with more inliers than this ends the search.</source>
        <translation>ratio_max (Schritt B8): Eine Hypothese mit mehr Inliern als diesem Anteil beendet die Suche.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="549"/>
        <source>ratio_min (steps B5, B6): a line needs this fraction of the remaining points.</source>
        <translation>ratio_min (Schritte B5, B6): Eine Linie braucht diesen Anteil der verbleibenden Punkte.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="550"/>
        <source>ratio_scan_max (step E): stop once this fraction of the points lies on lines.</source>
        <translation>ratio_scan_max (Schritt E): aufhören, sobald dieser Anteil der Punkte auf Linien liegt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="216"/>
        <source>Kind of frames read from a ROS bag; auto picks RGB-D, then stereo, then mono, then point clouds, as the bag&apos;s topics allow.</source>
        <translation>Art der aus einer ROS-Bag gelesenen Bilder; auto wählt RGB-D, dann Stereo, dann Mono, dann Punktwolken, je nachdem, was die Topics der Bag erlauben.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="257"/>
        <source>New centre: the model centre through a RANSAC similarity of the matches, or the matched keypoints&apos; centroid (the published rule).</source>
        <translation>Neue Mitte: die Modellmitte über eine RANSAC-Ähnlichkeitstransformation der Übereinstimmungen oder der Schwerpunkt der übereinstimmenden Keypoints (die Regel der Veröffentlichung).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="269"/>
        <source>Occupied evidence: the polar scan&apos;s hits (visible surfaces, thin walls) or every occupied cell of the occupancy image (as published; depth noise behind walls stays).</source>
        <translation>Belegt-Evidenz: die Treffer des Polarscans (sichtbare Flächen, dünne Wände) oder jede belegte Zelle des Belegungsbilds (wie veröffentlicht; Tiefenrauschen hinter Wänden bleibt).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="306"/>
        <source>Process every k-th frame (the published subsampling sweep); --subsample K.</source>
        <translation>Jedes k-te Bild verarbeiten (der Unterabtastungsdurchlauf der Veröffentlichung); --subsample K.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="320"/>
        <source>ROS bag: ground truth is the pose of tf_child_frame in this tf frame; empty uses the bag&apos;s only transform chain on /tf.</source>
        <translation>ROS-Bag: Die Referenz ist die Pose von tf_child_frame in diesem tf-Frame; leer nimmt die einzige Transformationskette der Bag auf /tf.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="321"/>
        <source>ROS bag: largest stamp difference of a colour/depth or left/right pair; images without a partner are skipped.</source>
        <translation>ROS-Bag: größter Zeitstempelabstand eines Farb-/Tiefen- oder Links-/Rechts-Paars; Bilder ohne Partner werden übersprungen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="323"/>
        <source>ROS bag: the CameraInfo topic of the image topic; empty looks beside the image topic, then takes the bag&apos;s only CameraInfo topic.</source>
        <translation>ROS-Bag: das CameraInfo-Topic des Bild-Topics; leer sucht neben dem Bild-Topic und nimmt dann das einzige CameraInfo-Topic der Bag.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="324"/>
        <source>ROS bag: the PointCloud2 topic read as point-cloud frames.</source>
        <translation>ROS-Bag: das PointCloud2-Topic, das als Punktwolken gelesen wird.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="327"/>
        <source>ROS bag: the camera&apos;s tf frame whose pose in tf_parent_frame is the ground truth.</source>
        <translation>ROS-Bag: der tf-Frame der Kamera, dessen Pose in tf_parent_frame die Referenz ist.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="328"/>
        <source>ROS bag: the colour, left or mono image topic (Image or CompressedImage); empty picks it when the bag leaves no doubt.</source>
        <translation>ROS-Bag: das Farb-, linke oder Mono-Bild-Topic (Image oder CompressedImage); leer wählt es, wenn die Bag keinen Zweifel lässt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="329"/>
        <source>ROS bag: the depth image topic (16UC1 millimetres or 32FC1 metres); empty picks it when the bag leaves no doubt.</source>
        <translation>ROS-Bag: das Tiefenbild-Topic (16UC1 Millimeter oder 32FC1 Meter); leer wählt es, wenn die Bag keinen Zweifel lässt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="330"/>
        <source>ROS bag: the nav_msgs/Odometry topic; empty takes the bag&apos;s only one.</source>
        <translation>ROS-Bag: das nav_msgs/Odometry-Topic; leer nimmt das einzige der Bag.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="332"/>
        <source>ROS bag: the right camera&apos;s CameraInfo topic; its projection matrix P gives the stereo baseline.</source>
        <translation>ROS-Bag: das CameraInfo-Topic der rechten Kamera; seine Projektionsmatrix P ergibt die Stereobasis.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="333"/>
        <source>ROS bag: the right image topic of a stereo pair; empty picks the topic whose name says right beside one that says left.</source>
        <translation>ROS-Bag: das rechte Bild-Topic eines Stereopaars; leer wählt das Topic, dessen Name right sagt, neben einem, dessen Name left sagt.</translation>
    </message>
</context>
<context>
    <name>sightline::ParameterPanel</name>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="47"/>
        <source>Filter options</source>
        <translation>Optionen filtern</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="51"/>
        <source>Load profile…</source>
        <translation>Profil laden…</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="54"/>
        <source>Save profile…</source>
        <translation>Profil speichern…</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="57"/>
        <source>Reset all</source>
        <translation>Alle zurücksetzen</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="173"/>
        <source>All options reset to their defaults.</source>
        <translation>Alle Optionen auf ihre Standardwerte zurückgesetzt.</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="184"/>
        <source>Loaded profile %1</source>
        <translation>Profil %1 geladen</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="195"/>
        <source>Saved profile %1</source>
        <translation>Profil %1 gespeichert</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="202"/>
        <source>Load profile</source>
        <translation>Profil laden</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="202"/>
        <source>YAML profiles (*.yaml *.yml);;All files (*)</source>
        <translation>YAML-Profile (*.yaml *.yml);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="209"/>
        <source>Save profile</source>
        <translation>Profil speichern</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="210"/>
        <source>YAML profiles (*.yaml *.yml)</source>
        <translation>YAML-Profile (*.yaml *.yml)</translation>
    </message>
</context>
<context>
    <name>sightline::PlaybackBar</name>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="37"/>
        <source>Step one frame</source>
        <translation>Ein Bild weiter</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="57"/>
        <source>Playback speed relative to the recording&apos;s timestamps</source>
        <translation>Wiedergabegeschwindigkeit relativ zu den Zeitstempeln der Aufnahme</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="61"/>
        <source>max</source>
        <translation>max</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="67"/>
        <source>Loop</source>
        <translation>Schleife</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="121"/>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="121"/>
        <source>Play</source>
        <translation>Abspielen</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="155"/>
        <source>frame %1</source>
        <translation>Bild %1</translation>
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
    <name>sightline::RemoteOperatorPresenter</name>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="50"/>
        <source>Operator panel (ROS node)</source>
        <translation>Bedienfeld (ROS-Knoten)</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="86"/>
        <source>Start did not reach the robot: still stopped</source>
        <translation>Neu starten hat den Roboter nicht erreicht: er bleibt gestoppt</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="109"/>
        <source>STOP sent: waiting for the robot</source>
        <translation>STOPP gesendet: warte auf den Roboter</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="110"/>
        <source>STOP kept: sent as soon as the robot is reachable</source>
        <translation>STOPP gehalten: wird gesendet, sobald der Roboter erreichbar ist</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="153"/>
        <source>The robot confirmed STOP</source>
        <translation>Der Roboter hat STOPP bestätigt</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="161"/>
        <source>Target %1, %2, %3 m (%4)</source>
        <translation>Ziel %1, %2, %3 m (%4)</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="196"/>
        <source>The robot did not answer the tap: tap again</source>
        <translation>Der Roboter hat auf das Antippen nicht geantwortet: bitte neu antippen</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="253"/>
        <source>The robot did not take the tap: tap again</source>
        <translation>Der Roboter hat das Antippen nicht angenommen: bitte neu antippen</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="262"/>
        <source>The robot&apos;s node is gone</source>
        <translation>Der Knoten des Roboters ist weg</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="270"/>
        <source>No picture for %1 s</source>
        <translation>Seit %1 s kein Bild</translation>
    </message>
</context>
<context>
    <name>sightline::RosConnectDialog</name>
    <message>
        <location filename="../app/sightline/ros_connect_dialog.cpp" line="12"/>
        <source>Connect to ROS master</source>
        <translation>Mit ROS-Master verbinden</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_connect_dialog.cpp" line="18"/>
        <source>Master URI:</source>
        <translation>Master-URI:</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_connect_dialog.cpp" line="19"/>
        <source>Node namespace:</source>
        <translation>Namensraum des Knotens:</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_connect_dialog.cpp" line="21"/>
        <source>The robot&apos;s master, e.g. http://robot:11311. The robot must reach this computer too: set ROS_IP (or ROS_HOSTNAME) before starting Sightline.</source>
        <translation>Der Master des Roboters, z. B. http://robot:11311. Der Roboter muss auch diesen Rechner erreichen: ROS_IP (oder ROS_HOSTNAME) vor dem Start von Sightline setzen.</translation>
    </message>
</context>
<context>
    <name>sightline::RosNodeView</name>
    <message>
        <location filename="../app/sightline/ros_node_view.cpp" line="65"/>
        <source>ROS node</source>
        <translation>ROS-Knoten</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_node_view.cpp" line="69"/>
        <location filename="../app/sightline/ros_node_view.cpp" line="174"/>
        <source>Not connected: File &gt; Connect to ROS master...</source>
        <translation>Nicht verbunden: Datei &gt; Mit ROS-Master verbinden...</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_node_view.cpp" line="100"/>
        <source>ROS: %1</source>
        <translation>ROS: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_node_view.cpp" line="147"/>
        <source>Waiting for the map from %1 ...</source>
        <translation>Warte auf die Karte von %1 ...</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_node_view.cpp" line="152"/>
        <source>ROS: not available in this build</source>
        <translation>ROS: in diesem Build nicht verfügbar</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_node_view.cpp" line="221"/>
        <source>ROS: connected to %1</source>
        <translation>ROS: verbunden mit %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_node_view.cpp" line="222"/>
        <source>ROS: disconnected — reconnecting to %1</source>
        <translation>ROS: getrennt — verbinde erneut mit %1</translation>
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
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="210"/>
        <source>tracked %1, new %2, stereo %3, inliers %4, RANSAC %5 it., residual %6 %7, %8 %9%10</source>
        <translation>verfolgt %1, neu %2, Stereo %3, Inlier %4, RANSAC %5 It., Residuum %6 %7, %8 %9%10</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="220"/>
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
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="175"/>
        <source>estimate and camera</source>
        <translation>Schätzung und Kamera</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="176"/>
        <source>ground truth</source>
        <translation>Ground Truth</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="185"/>
        <source>inlier track</source>
        <translation>Spur, Inlier</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="186"/>
        <source>outlier track</source>
        <translation>Spur, Ausreißer</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="187"/>
        <source>new feature</source>
        <translation>neues Merkmal</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="199"/>
        <source>stereo match</source>
        <translation>Stereo-Zuordnung</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="229"/>
        <source>residual</source>
        <translation>Residuum</translation>
    </message>
</context>
</TS>
