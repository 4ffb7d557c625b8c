<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="it_IT">
<context>
    <name>sightline::ButtonPickerPresenter</name>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="40"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="83"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="87"/>
        <source>Stopped</source>
        <translation>Fermato</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="42"/>
        <source>Waiting for Yes</source>
        <translation>In attesa del Sì</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="44"/>
        <source>Button lost</source>
        <translation>Pulsante perso</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="46"/>
        <source>Button unclear</source>
        <translation>Pulsante non chiaro</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="48"/>
        <source>Measuring the button</source>
        <translation>Misura del pulsante in corso</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="50"/>
        <source>Measuring again</source>
        <translation>Nuova misura</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="52"/>
        <source>Measuring the distance</source>
        <translation>Misura della distanza in corso</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="54"/>
        <source>Panel unclear</source>
        <translation>Pannello non chiaro</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="56"/>
        <source>Position not sure yet</source>
        <translation>Posizione non ancora sicura</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="58"/>
        <source>Panel direction not sure yet</source>
        <translation>Direzione del pannello non ancora sicura</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="60"/>
        <source>Button out of reach</source>
        <translation>Pulsante fuori portata</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="71"/>
        <source>The picture changed: tap again</source>
        <translation>L&apos;immagine è cambiata: tocca di nuovo</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="73"/>
        <source>The picture was too old: tap again</source>
        <translation>L&apos;immagine era troppo vecchia: tocca di nuovo</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="75"/>
        <source>Stopped: press Start again first</source>
        <translation>Fermato: premi prima «Riparti»</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="82"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="224"/>
        <source>Paused</source>
        <translation>In pausa</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="85"/>
        <source>Arm link off</source>
        <translation>Collegamento al braccio spento</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="86"/>
        <source>No arm connected</source>
        <translation>Nessun braccio collegato</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="90"/>
        <source>Waiting</source>
        <translation>In attesa</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="111"/>
        <source>Button picker (monocular SLAM)</source>
        <translation>Selettore di pulsanti (SLAM monoculare)</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="119"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="143"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="182"/>
        <source>Operator panel</source>
        <translation>Pannello operatore</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="123"/>
        <source>Operator panel full screen</source>
        <translation>Pannello operatore a schermo intero</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="224"/>
        <source>End of the recording</source>
        <translation>Fine della registrazione</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="242"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="250"/>
        <source>The picture is paused: press Play, then tap</source>
        <translation>L&apos;immagine è in pausa: premi Riproduci, poi tocca</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="249"/>
        <source>The recording has ended: nothing to tap</source>
        <translation>La registrazione è finita: niente da toccare</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="251"/>
        <source>No picture yet: open a camera or a recording</source>
        <translation>Ancora nessuna immagine: apri una telecamera o una registrazione</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="288"/>
        <source>No button at the tap: %1</source>
        <translation>Nessun pulsante nel punto toccato: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="303"/>
        <source>No metric scale (no arm motion)</source>
        <translation>Nessuna scala metrica (nessun movimento del braccio)</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="305"/>
        <source>Without the arm&apos;s poses the button is tracked and located in map units only; no target is sent.</source>
        <translation>Senza le pose del braccio il pulsante è seguito e localizzato solo in unità della mappa; nessun obiettivo viene inviato.</translation>
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
        <translation>&amp;Calibra</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="96"/>
        <source>&amp;Save YAML...</source>
        <translation>&amp;Salva YAML...</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="93"/>
        <source>Board</source>
        <translation>Scacchiera</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="224"/>
        <source>Board found in %1 of %2 %3.</source>
        <translation>Scacchiera trovata in %1 di %2 %3.</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="60"/>
        <source>Browse...</source>
        <translation>Sfoglia...</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="42"/>
        <source>Calibrate camera</source>
        <translation>Calibra la telecamera</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="218"/>
        <source>Calibration failed: %1</source>
        <translation>Calibrazione non riuscita: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="62"/>
        <source>Calibration images</source>
        <translation>Immagini di calibrazione</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="108"/>
        <source>Choose a source and the board, then press Calibrate.</source>
        <translation>Scegli una sorgente e la scacchiera, poi premi Calibra.</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="175"/>
        <source>Choose a source first.</source>
        <translation>Scegli prima una sorgente.</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="131"/>
        <source>Coverage (views per cell)</source>
        <translation>Copertura (viste per cella)</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="129"/>
        <source>Detected corners</source>
        <translation>Angoli rilevati</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="317"/>
        <source>Detected corners: %1 (%2 px)</source>
        <translation>Angoli rilevati: %1 (%2 px)</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="181"/>
        <source>Detecting the board...</source>
        <translation>Ricerca della scacchiera...</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="117"/>
        <source>Error (px)</source>
        <translation>Errore (px)</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="69"/>
        <source>File name pattern inside a mono image folder, e.g. left*.jpg</source>
        <translation>Modello del nome dei file in una cartella di immagini mono, ad es. left*.jpg</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="264"/>
        <source>Hint: %1</source>
        <translation>Suggerimento: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="59"/>
        <source>Image folder, stereo folder, recording or camera URI</source>
        <translation>Cartella di immagini, cartella stereo, registrazione o URI della telecamera</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="92"/>
        <source>Image pattern</source>
        <translation>Modello delle immagini</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="90"/>
        <source>Mode</source>
        <translation>Modalità</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="56"/>
        <source>Mono (one camera)</source>
        <translation>Mono (una telecamera)</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="348"/>
        <source>Nothing to save: calibrate first.</source>
        <translation>Niente da salvare: calibra prima.</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="362"/>
        <source>OpenCV YAML (*.yaml *.yml)</source>
        <translation>YAML di OpenCV (*.yaml *.yml)</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="251"/>
        <source>RMS %1 px; %2 views used, %3 rejected.</source>
        <translation>RMS %1 px; %2 viste usate, %3 scartate.</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="243"/>
        <source>RMS left %1 px, right %2 px, stereo %3 px; baseline %4 mm; %5 of %6 pairs used.</source>
        <translation>RMS sinistra %1 px, destra %2 px, stereo %3 px; baseline %4 mm; %5 di %6 coppie usate.</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="117"/>
        <source>Right error (px)</source>
        <translation>Errore destra (px)</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="361"/>
        <source>Save calibration</source>
        <translation>Salva la calibrazione</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="356"/>
        <source>Saved %1</source>
        <translation>Salvato %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="365"/>
        <source>Saving failed: %1</source>
        <translation>Salvataggio non riuscito: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="91"/>
        <source>Source</source>
        <translation>Sorgente</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="117"/>
        <source>Status</source>
        <translation>Stato</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="57"/>
        <source>Stereo (left and right)</source>
        <translation>Stereo (sinistra e destra)</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="117"/>
        <source>View</source>
        <translation>Vista</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="257"/>
        <source>fx %1 fy %2 cx %3 cy %4; coverage: %5</source>
        <translation>fx %1 fy %2 cx %3 cy %4; copertura: %5</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="227"/>
        <source>images</source>
        <translation>immagini</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="85"/>
        <source>inner corners, squares of</source>
        <translation>angoli interni, caselle da</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="227"/>
        <source>pairs</source>
        <translation>coppie</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="289"/>
        <location filename="../app/sightline/calibration_dialog.cpp" line="303"/>
        <source>rejected</source>
        <translation>scartate</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="289"/>
        <source>used</source>
        <translation>usate</translation>
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
        <translation>Telecamere RGB-D OpenNI2 (Kinect, Xtion, Carmine) e registrazioni .oni</translation>
    </message>
    <message>
        <location filename="../app/sightline/core_texts.cpp" line="13"/>
        <source>GigE Vision / USB3 Vision cameras through Aravis: one camera, or a stereo pair as aravis://LEFT_ID,RIGHT_ID</source>
        <translation>Telecamere GigE Vision / USB3 Vision tramite Aravis: una telecamera, o una coppia stereo come aravis://LEFT_ID,RIGHT_ID</translation>
    </message>
    <message>
        <location filename="../app/sightline/core_texts.cpp" line="16"/>
        <source>USB webcams through OpenCV&apos;s V4L2 backend</source>
        <translation>Webcam USB tramite il backend V4L2 di OpenCV</translation>
    </message>
    <message>
        <location filename="../app/sightline/core_texts.cpp" line="17"/>
        <source>A recording played as a live camera (replay://PATH?fps=30&amp;loop=1)</source>
        <translation>Una registrazione riprodotta come telecamera dal vivo (replay://PATH?fps=30&amp;loop=1)</translation>
    </message>
</context>
<context>
    <name>sightline::DemoGenerator</name>
    <message>
        <location filename="../app/sightline/demo_generator.cpp" line="48"/>
        <source>cannot create the demo folder %1</source>
        <translation>impossibile creare la cartella della demo %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/demo_generator.cpp" line="87"/>
        <source>cannot write %1</source>
        <translation>impossibile scrivere %1</translation>
    </message>
</context>
<context>
    <name>sightline::EvaluationPanel</name>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="75"/>
        <source>estimated trajectory (TUM or KITTI file)</source>
        <translation>traiettoria stimata (file TUM o KITTI)</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="77"/>
        <source>ground truth (TUM or KITTI file)</source>
        <translation>ground truth (file TUM o KITTI)</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="81"/>
        <source>Browse...</source>
        <translation>Sfoglia...</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="90"/>
        <source>SE(3): rotation and translation</source>
        <translation>SE(3): rotazione e traslazione</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="91"/>
        <source>Sim(3): also scale (monocular)</source>
        <translation>Sim(3): anche la scala (monoculare)</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="92"/>
        <source>None</source>
        <translation>Nessuno</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="93"/>
        <source>Evaluate</source>
        <translation>Valuta</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="100"/>
        <source>Estimate</source>
        <translation>Stima</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="100"/>
        <source>Estimated trajectory</source>
        <translation>Traiettoria stimata</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="101"/>
        <source>Ground truth</source>
        <translation>Ground truth</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="102"/>
        <source>Alignment</source>
        <translation>Allineamento</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="104"/>
        <source>Choose two trajectory files and press Evaluate.</source>
        <translation>Scegli due file di traiettoria e premi Valuta.</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="107"/>
        <source>Figure</source>
        <translation>Indice</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="107"/>
        <source>Value</source>
        <translation>Valore</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="107"/>
        <source>Unit</source>
        <translation>Unità</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="107"/>
        <source>Meaning</source>
        <translation>Significato</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="117"/>
        <source>Figures</source>
        <translation>Indici</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="118"/>
        <source>Top view</source>
        <translation>Vista dall&apos;alto</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="119"/>
        <source>Error over time</source>
        <translation>Errore nel tempo</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="144"/>
        <source>Trajectories (*.txt *.csv);;All files (*)</source>
        <translation>Traiettorie (*.txt *.csv);;Tutti i file (*)</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="152"/>
        <source>Evaluating...</source>
        <translation>Valutazione in corso...</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="176"/>
        <source>Evaluation failed: %1</source>
        <translation>Valutazione non riuscita: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="189"/>
        <source>%1 associated poses, ground-truth path %2 m.</source>
        <translation>%1 pose associate, percorso della ground truth %2 m.</translation>
    </message>
</context>
<context>
    <name>sightline::ImageView</name>
    <message>
        <location filename="../widgets/image_view.cpp" line="47"/>
        <location filename="../widgets/image_view.cpp" line="78"/>
        <location filename="../widgets/image_view.cpp" line="131"/>
        <source>No image</source>
        <translation>Nessuna immagine</translation>
    </message>
    <message>
        <location filename="../widgets/image_view.cpp" line="81"/>
        <source>Unsupported image type %1</source>
        <translation>Tipo di immagine non supportato %1</translation>
    </message>
</context>
<context>
    <name>sightline::LiveStatusWidget</name>
    <message>
        <location filename="../app/sightline/live_status_widget.cpp" line="25"/>
        <source>closed</source>
        <translation>chiuso</translation>
    </message>
    <message>
        <location filename="../app/sightline/live_status_widget.cpp" line="27"/>
        <source>streaming</source>
        <translation>in streaming</translation>
    </message>
    <message>
        <location filename="../app/sightline/live_status_widget.cpp" line="29"/>
        <source>disconnected</source>
        <translation>scollegato</translation>
    </message>
    <message>
        <location filename="../app/sightline/live_status_widget.cpp" line="40"/>
        <source>&lt;span style=&apos;color:%1&apos;&gt;&amp;#9679;&lt;/span&gt; %2 &amp;nbsp;%3 fps &amp;nbsp;dropped %4 &amp;nbsp;latency %5 ms</source>
        <translation>&lt;span style=&apos;color:%1&apos;&gt;&amp;#9679;&lt;/span&gt; %2 &amp;nbsp;%3 fps &amp;nbsp;scartati %4 &amp;nbsp;latenza %5 ms</translation>
    </message>
</context>
<context>
    <name>sightline::LogPanel</name>
    <message>
        <location filename="../widgets/log_panel.cpp" line="36"/>
        <source>Clear messages</source>
        <translation>Cancella i messaggi</translation>
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
        <translation>Colore</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="82"/>
        <location filename="../app/sightline/main_window.cpp" line="375"/>
        <source>Depth</source>
        <translation>Profondità</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="87"/>
        <source>Parameters</source>
        <translation>Parametri</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="89"/>
        <source>Log</source>
        <translation>Registro</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="92"/>
        <source>Evaluation</source>
        <translation>Valutazione</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="100"/>
        <source>Playback</source>
        <translation>Riproduzione</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="110"/>
        <source>&amp;File</source>
        <translation>&amp;File</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="111"/>
        <source>&amp;Open dataset folder...</source>
        <translation>&amp;Apri cartella del dataset...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="114"/>
        <source>Open dataset folder</source>
        <translation>Apri cartella del dataset</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="119"/>
        <source>Open point cloud</source>
        <translation>Apri nuvola di punti</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="117"/>
        <source>Open recording &amp;file (PCD, ONI)...</source>
        <translation>Apri &amp;file di registrazione (PCD, ONI)...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="120"/>
        <source>Recordings (*.pcd *.oni)</source>
        <translation>Registrazioni (*.pcd *.oni)</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="123"/>
        <source>Open &amp;recent</source>
        <translation>Apri &amp;recenti</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="128"/>
        <source>&amp;Quit</source>
        <translation>&amp;Esci</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="132"/>
        <source>&amp;View</source>
        <translation>&amp;Visualizza</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="134"/>
        <source>&amp;Reset 3D view</source>
        <translation>&amp;Ripristina la vista 3D</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="142"/>
        <source>&amp;Sensors</source>
        <translation>&amp;Sensori</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="148"/>
        <source> (unavailable)</source>
        <translation> (non disponibile)</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="153"/>
        <source>Connect to the first %1 device</source>
        <translation>Collegati al primo dispositivo %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="159"/>
        <source>Replay recording</source>
        <translation>Riproduci una registrazione</translation>
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
        <translation>Nessuna (mostra solo le immagini)</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="174"/>
        <source>&amp;Tools</source>
        <translation>S&amp;trumenti</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="175"/>
        <source>&amp;Evaluate trajectory...</source>
        <translation>&amp;Valuta una traiettoria...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="180"/>
        <source>Evaluate &amp;current run</source>
        <translation>Valuta l&apos;esecuzione &amp;corrente</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="182"/>
        <source>Compares the running pipeline&apos;s trajectory with the dataset&apos;s ground truth.</source>
        <translation>Confronta la traiettoria della pipeline in esecuzione con la ground truth del dataset.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="191"/>
        <source>&amp;Help</source>
        <translation>&amp;Aiuto</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="192"/>
        <source>&amp;About Sightline</source>
        <translation>&amp;Informazioni su Sightline</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="193"/>
        <source>About Sightline</source>
        <translation>Informazioni su Sightline</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="194"/>
        <source>Sightline: robot perception for assistive and mobile robotics.
Indoor mapping, mobility maps, stereo odometry and monocular button localisation on live sensors or recorded data.</source>
        <translation>Sightline: percezione robotica per la robotica assistiva e mobile.
Mappatura di interni, mappe di percorribilità, odometria stereo e localizzazione monoculare dei pulsanti da sensori dal vivo o dati registrati.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="206"/>
        <source>Could not open %1: %2</source>
        <translation>Impossibile aprire %1: %2</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="207"/>
        <source>Could not open %1</source>
        <translation>Impossibile aprire %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="215"/>
        <source>End of recording.</source>
        <translation>Fine della registrazione.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="239"/>
        <source>Demo %p%</source>
        <translation>Demo %p%</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="246"/>
        <source>Generating the demo recordings (only the first time)...</source>
        <translation>Generazione delle registrazioni demo (solo la prima volta)...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="255"/>
        <source>Demo: a robot drives a simulated office corridor (RGB-D, stereo, wheel odometry, exact ground truth). The arm-camera panel approach is in %1.</source>
        <translation>Demo: un robot percorre un corridoio d&apos;ufficio simulato (RGB-D, stereo, odometria delle ruote, ground truth esatta). L&apos;avvicinamento della telecamera del braccio al pannello è in %1.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="262"/>
        <source>The demo could not be made: %1</source>
        <translation>Impossibile creare la demo: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="318"/>
        <source>No pipeline: showing frames only.</source>
        <translation>Nessuna pipeline: mostro solo le immagini.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="329"/>
        <source>Pipeline: %1</source>
        <translation>Pipeline: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="333"/>
        <source>%1 cannot run on %2 frames; open another dataset.</source>
        <translation>%1 non può funzionare su immagini %2; apri un altro dataset.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="362"/>
        <location filename="../app/sightline/main_window.cpp" line="363"/>
        <source>Opening %1 ...</source>
        <translation>Apertura di %1 ...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="374"/>
        <source>Left</source>
        <translation>Sinistra</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="374"/>
        <source>Image</source>
        <translation>Immagine</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="375"/>
        <source>Right</source>
        <translation>Destra</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="381"/>
        <source>%1: %2, %3 frames, %4x%5%6</source>
        <translation>%1: %2, %3 immagini, %4x%5%6</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="386"/>
        <source>, ground truth</source>
        <translation>, ground truth</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="388"/>
        <source>Opened %1</source>
        <translation>Aperto %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="393"/>
        <source>Sightline - %1</source>
        <translation>Sightline - %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="428"/>
        <source>frame %1, read in %2 ms</source>
        <translation>immagine %1, letta in %2 ms</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="450"/>
        <source>No dataset open. Use File &gt; Open dataset folder (TUM RGB-D, EuRoC, KITTI, an image folder or PCD files), or drop a folder on this window.</source>
        <translation>Nessun dataset aperto. Usa File &gt; Apri cartella del dataset (TUM RGB-D, EuRoC, KITTI, una cartella di immagini o file PCD), oppure trascina una cartella su questa finestra.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="452"/>
        <source>No dataset open</source>
        <translation>Nessun dataset aperto</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="184"/>
        <source>&amp;Calibrate camera...</source>
        <translation>&amp;Calibra la telecamera...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_recording.cpp" line="19"/>
        <source>Recording</source>
        <translation>Registrazione</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_recording.cpp" line="37"/>
        <source>Recording: %1</source>
        <translation>Registrazione: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="35"/>
        <source>&amp;Save results...</source>
        <translation>&amp;Salva i risultati...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="38"/>
        <source>Writes the running pipeline&apos;s results as sightline-cli run does: metrics.json, trajectory, maps, clouds and tables.</source>
        <translation>Scrive i risultati della pipeline in esecuzione come sightline-cli run: metrics.json, traiettoria, mappe, nuvole e tabelle.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="44"/>
        <source>Save results into folder</source>
        <translation>Salva i risultati nella cartella</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="55"/>
        <source>Saved %1 in %2</source>
        <translation>Salvato %1 in %2</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="56"/>
        <source>Results saved in %1</source>
        <translation>Risultati salvati in %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="61"/>
        <source>Could not save results: %1</source>
        <translation>Impossibile salvare i risultati: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="75"/>
        <source>Evaluate current run needs a running pipeline on a dataset with ground truth; choose two trajectory files instead.</source>
        <translation>Per valutare l&apos;esecuzione corrente serve una pipeline in esecuzione su un dataset con ground truth; altrimenti scegli due file di traiettoria.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="82"/>
        <source>Could not make a temporary folder for the evaluation.</source>
        <translation>Impossibile creare una cartella temporanea per la valutazione.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="94"/>
        <source>%1 writes no trajectory to evaluate.</source>
        <translation>%1 non scrive alcuna traiettoria da valutare.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_settings.cpp" line="26"/>
        <source>Reset &amp;layout</source>
        <translation>Ripristina il &amp;layout</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_settings.cpp" line="60"/>
        <source>Setti&amp;ngs</source>
        <translation>&amp;Impostazioni</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_settings.cpp" line="62"/>
        <source>&amp;Language</source>
        <translation>&amp;Lingua</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_settings.cpp" line="67"/>
        <source>System language</source>
        <translation>Lingua del sistema</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_settings.cpp" line="96"/>
        <source>Language: %1</source>
        <translation>Lingua: %1</translation>
    </message>
</context>
<context>
    <name>sightline::MappingPresenter</name>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="91"/>
        <source>Indoor mapping (Manhattan walls)</source>
        <translation>Mappatura di interni (pareti di Manhattan)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="98"/>
        <source>Occupancy, scan and walls</source>
        <translation>Occupazione, scansione e pareti</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="104"/>
        <source>Calibrate floor</source>
        <translation>Calibra il pavimento</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="106"/>
        <source>Fit the floor plane again from the next frames (the robot should see open floor).</source>
        <translation>Stima di nuovo il piano del pavimento dalle prossime immagini (il robot deve vedere pavimento libero).</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="109"/>
        <source>Save floor...</source>
        <translation>Salva il pavimento...</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="111"/>
        <source>Save the floor calibration in use, for mapping.run.floor_file or `sightline-cli run mapping --set mapping.run.floor_file=...`.</source>
        <translation>Salva la calibrazione del pavimento in uso, per mapping.run.floor_file o `sightline-cli run mapping --set mapping.run.floor_file=...`.</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="114"/>
        <source>Save floor calibration</source>
        <translation>Salva la calibrazione del pavimento</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="115"/>
        <source>YAML (*.yaml)</source>
        <translation>YAML (*.yaml)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="127"/>
        <source>Stitched map</source>
        <translation>Mappa unita</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="186"/>
        <source>Manhattan reference reset: %1</source>
        <translation>Riferimento di Manhattan azzerato: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="202"/>
        <source>Calibrating the floor again from the next frames.</source>
        <translation>Nuova calibrazione del pavimento dalle prossime immagini.</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="215"/>
        <source>Saved the floor calibration to %1</source>
        <translation>Calibrazione del pavimento salvata in %1</translation>
    </message>
</context>
<context>
    <name>sightline::MobilityImagePanel</name>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="72"/>
        <source>Projection</source>
        <translation>Proiezione</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="73"/>
        <source>Top view</source>
        <translation>Vista dall&apos;alto</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="74"/>
        <source>GPR surface</source>
        <translation>Superficie GPR</translation>
    </message>
</context>
<context>
    <name>sightline::MobilityPresenter</name>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="26"/>
        <source>Mobility map</source>
        <translation>Mappa di percorribilità</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="36"/>
        <source>Mobility map (red 0, green 1)</source>
        <translation>Mappa di percorribilità (rosso 0, verde 1)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="40"/>
        <source>Mobility stages (Table II)</source>
        <translation>Fasi della mappa di percorribilità (Tabella II)</translation>
    </message>
</context>
<context>
    <name>sightline::MobilityTimingPanel</name>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="21"/>
        <source>3D colour:</source>
        <translation>Colore 3D:</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="23"/>
        <source>Score (rule)</source>
        <translation>Punteggio (regola)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="23"/>
        <source>Score (GPR)</source>
        <translation>Punteggio (GPR)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="23"/>
        <source>Segment</source>
        <translation>Segmento</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="31"/>
        <source>Stage</source>
        <translation>Fase</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="31"/>
        <source>Time (ms)</source>
        <translation>Tempo (ms)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="31"/>
        <source>Points</source>
        <translation>Punti</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="52"/>
        <source>Total</source>
        <translation>Totale</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="55"/>
        <source>%1 mode, %2 segments</source>
        <translation>modalità %1, %2 segmenti</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="59"/>
        <source>, camera %1 m above the ground</source>
        <translation>, telecamera a %1 m dal suolo</translation>
    </message>
</context>
<context>
    <name>sightline::MonoSlamPresenter</name>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="85"/>
        <source>the arm&apos;s poses</source>
        <translation>le pose del braccio</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="86"/>
        <source>the ground truth</source>
        <translation>la ground truth</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="87"/>
        <source>none</source>
        <translation>nessuno</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="125"/>
        <source>Monocular SLAM (PTAM point cloud)</source>
        <translation>SLAM monoculare (nuvola di punti PTAM)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="137"/>
        <source>Reset map</source>
        <translation>Azzera la mappa</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="138"/>
        <source>Pause mapping</source>
        <translation>Sospendi la mappatura</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="151"/>
        <source>Tracked features (inliers green, outliers red)</source>
        <translation>Punti tracciati (inlier verdi, outlier rossi)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="162"/>
        <source>Metric scale (ML solid, single ratio dashed)</source>
        <translation>Scala metrica (ML continua, rapporto singolo tratteggiata)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="207"/>
        <source>%1: %2 inliers of %3 matches, %4 map points, %5 keyframes, %6 ms</source>
        <translation>%1: %2 inlier su %3 corrispondenze, %4 punti mappa, %5 keyframe, %6 ms</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="217"/>
        <source>Metric scale from %1: ML %2, single ratio %3 map units per metre; map and trajectory in metres.</source>
        <translation>Scala metrica da %1: ML %2, rapporto singolo %3 unità di mappa per metro; mappa e traiettoria in metri.</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="223"/>
        <source>Scale unknown (measured motion: %1): the map is in arbitrary units (first baseline = 0.1).</source>
        <translation>Scala sconosciuta (moto misurato: %1): la mappa è in unità arbitrarie (prima baseline = 0,1).</translation>
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
        <translation>Annulla</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="242"/>
        <source>Locating</source>
        <translation>Localizzazione</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="246"/>
        <source>Lost - hold still</source>
        <translation>Perso - resta fermo</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="236"/>
        <source>No button here - tap again</source>
        <translation>Nessun pulsante qui - tocca di nuovo</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="234"/>
        <source>Press this button?</source>
        <translation>Premere questo pulsante?</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="250"/>
        <source>Holding: nothing sent</source>
        <translation>In attesa: niente inviato</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="252"/>
        <source>Tap not taken</source>
        <translation>Tocco non accettato</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="254"/>
        <source>Tracking only</source>
        <translation>Solo inseguimento</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="278"/>
        <source>STOP</source>
        <translation>STOP</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="314"/>
        <source>Leave</source>
        <translation>Esci</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="314"/>
        <source>Leave the operator panel?</source>
        <translation>Uscire dal pannello operatore?</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="238"/>
        <source>Searching</source>
        <translation>Ricerca</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="279"/>
        <source>Start again</source>
        <translation>Riparti</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="248"/>
        <source>Stopped</source>
        <translation>Fermato</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="232"/>
        <source>Tap a button</source>
        <translation>Tocca un pulsante</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="244"/>
        <source>Target sent</source>
        <translation>Bersaglio inviato</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="240"/>
        <source>Tracking</source>
        <translation>Pulsante agganciato</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="276"/>
        <location filename="../widgets/operator_panel.cpp" line="318"/>
        <source>Yes</source>
        <translation>Sì</translation>
    </message>
</context>
<context>
    <name>sightline::OptionEditor</name>
    <message>
        <location filename="../widgets/option_editor.cpp" line="47"/>
        <source>Range: %1 … %2%3</source>
        <translation>Intervallo: %1 … %2%3</translation>
    </message>
    <message>
        <location filename="../widgets/option_editor.cpp" line="52"/>
        <source>Choices: %1</source>
        <translation>Scelte: %1</translation>
    </message>
    <message>
        <location filename="../widgets/option_editor.cpp" line="55"/>
        <source>Default: %1%2</source>
        <translation>Predefinito: %1%2</translation>
    </message>
    <message>
        <location filename="../widgets/option_editor.cpp" line="71"/>
        <source>Reset to default (%1)</source>
        <translation>Ripristina il predefinito (%1)</translation>
    </message>
</context>
<context>
    <name>sightline::ParameterPanel</name>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="45"/>
        <source>Filter options</source>
        <translation>Filtra le opzioni</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="49"/>
        <source>Load profile…</source>
        <translation>Carica profilo…</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="52"/>
        <source>Save profile…</source>
        <translation>Salva profilo…</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="55"/>
        <source>Reset all</source>
        <translation>Ripristina tutto</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="155"/>
        <source>All options reset to their defaults.</source>
        <translation>Tutte le opzioni riportate ai valori predefiniti.</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="166"/>
        <source>Loaded profile %1</source>
        <translation>Profilo %1 caricato</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="177"/>
        <source>Saved profile %1</source>
        <translation>Profilo %1 salvato</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="184"/>
        <source>Load profile</source>
        <translation>Carica profilo</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="184"/>
        <source>YAML profiles (*.yaml *.yml);;All files (*)</source>
        <translation>Profili YAML (*.yaml *.yml);;Tutti i file (*)</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="191"/>
        <source>Save profile</source>
        <translation>Salva profilo</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="192"/>
        <source>YAML profiles (*.yaml *.yml)</source>
        <translation>Profili YAML (*.yaml *.yml)</translation>
    </message>
</context>
<context>
    <name>sightline::PlaybackBar</name>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="35"/>
        <source>Step one frame</source>
        <translation>Avanza di un&apos;immagine</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="54"/>
        <source>Playback speed relative to the recording&apos;s timestamps</source>
        <translation>Velocità di riproduzione rispetto ai tempi della registrazione</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="58"/>
        <source>max</source>
        <translation>max</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="64"/>
        <source>Loop</source>
        <translation>Ciclo</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="111"/>
        <source>Pause</source>
        <translation>Pausa</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="111"/>
        <source>Play</source>
        <translation>Riproduci</translation>
    </message>
</context>
<context>
    <name>sightline::RecordingController</name>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="16"/>
        <source>&amp;Record...</source>
        <translation>&amp;Registra...</translation>
    </message>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="20"/>
        <source>Record what is playing (live sensor or recording) into a folder, in the formats Sightline reads</source>
        <translation>Registra ciò che è in riproduzione (sensore dal vivo o registrazione) in una cartella, nei formati che Sightline legge</translation>
    </message>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="22"/>
        <source>&amp;Stop recording</source>
        <translation>&amp;Ferma la registrazione</translation>
    </message>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="41"/>
        <source>Record into folder</source>
        <translation>Registra nella cartella</translation>
    </message>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="60"/>
        <source>Nothing to record: open a sensor or a recording first.</source>
        <translation>Niente da registrare: apri prima un sensore o una registrazione.</translation>
    </message>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="102"/>
        <source>Recorded %1 frames into %2 (%3 dropped by the recorder), %4 MB at %5 MB/s</source>
        <translation>Registrate %1 immagini in %2 (%3 scartate dal registratore), %4 MB a %5 MB/s</translation>
    </message>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="122"/>
        <source>REC %1 written, %2 dropped, %3 MB/s</source>
        <translation>REC %1 scritte, %2 scartate, %3 MB/s</translation>
    </message>
</context>
<context>
    <name>sightline::ScalePlot</name>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="44"/>
        <source>scale: waiting for displacement pairs</source>
        <translation>scala: in attesa di coppie di spostamenti</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="58"/>
        <source>pairs (map units per metre)</source>
        <translation>coppie (unità di mappa per metro)</translation>
    </message>
</context>
<context>
    <name>sightline::StatisticsPresenter</name>
    <message>
        <location filename="../app/sightline/statistics_presenter.cpp" line="24"/>
        <source>Statistic</source>
        <translation>Statistica</translation>
    </message>
    <message>
        <location filename="../app/sightline/statistics_presenter.cpp" line="24"/>
        <source>Value</source>
        <translation>Valore</translation>
    </message>
    <message>
        <location filename="../app/sightline/statistics_presenter.cpp" line="24"/>
        <source>Unit</source>
        <translation>Unità</translation>
    </message>
    <message>
        <location filename="../app/sightline/statistics_presenter.cpp" line="24"/>
        <source>Meaning</source>
        <translation>Significato</translation>
    </message>
    <message>
        <location filename="../app/sightline/statistics_presenter.cpp" line="30"/>
        <source>Statistics: %1</source>
        <translation>Statistiche: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/statistics_presenter.cpp" line="54"/>
        <source>status</source>
        <translation>stato</translation>
    </message>
</context>
<context>
    <name>sightline::StereoVoPresenter</name>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="89"/>
        <source>Stereo visual odometry</source>
        <translation>Odometria visiva stereo</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="99"/>
        <source>Tracks (inliers green, outliers red, new blue)</source>
        <translation>Tracce (inlier verdi, outlier rossi, nuove blu)</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="103"/>
        <source>Stereo matches (right image)</source>
        <translation>Corrispondenze stereo (immagine destra)</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="110"/>
        <source>per frame [%1]</source>
        <translation>per immagine [%1]</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="111"/>
        <source>%1 per stage</source>
        <translation>%1 per fase</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="113"/>
        <source>residual [%1]; red: gated</source>
        <translation>residuo [%1]; rosso: bloccato</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="118"/>
        <source>Statistics over time</source>
        <translation>Statistiche nel tempo</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="202"/>
        <source>tracked %1, new %2, stereo %3, inliers %4, RANSAC %5 it., residual %6 %7, %8 %9%10</source>
        <translation>tracciati %1, nuovi %2, stereo %3, inlier %4, RANSAC %5 it., residuo %6 %7, %8 %9%10</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="212"/>
        <source>, GATED: pose held</source>
        <translation>, BLOCCATO: posa mantenuta</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="42"/>
        <source>tracks</source>
        <translation>tracce</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="44"/>
        <source>anchored</source>
        <translation>ancorati</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="46"/>
        <source>stereo</source>
        <translation>stereo</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="48"/>
        <source>inliers</source>
        <translation>inlier</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="50"/>
        <source>RANSAC it.</source>
        <translation>it. RANSAC</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="54"/>
        <source>rectify</source>
        <translation>rettifica</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="56"/>
        <source>pyramid</source>
        <translation>piramide</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="58"/>
        <source>tracking</source>
        <translation>tracciamento</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="60"/>
        <source>detection</source>
        <translation>rilevamento</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="62"/>
        <source>matching</source>
        <translation>corrispondenze</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="64"/>
        <source>RANSAC</source>
        <translation>RANSAC</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="66"/>
        <source>refine</source>
        <translation>raffinamento</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="68"/>
        <source>window BA</source>
        <translation>BA a finestra</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="70"/>
        <source>total</source>
        <translation>totale</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="221"/>
        <source>residual</source>
        <translation>residuo</translation>
    </message>
</context>
</TS>
