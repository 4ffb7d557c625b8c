<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="it_IT">
<context>
    <name>sightline::ButtonPickerPresenter</name>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="42"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="86"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="90"/>
        <source>Stopped</source>
        <translation>Fermato</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="44"/>
        <source>Waiting for Yes</source>
        <translation>In attesa del Sì</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="46"/>
        <source>Button lost</source>
        <translation>Pulsante perso</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="48"/>
        <source>Button unclear</source>
        <translation>Pulsante non chiaro</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="50"/>
        <source>Measuring the button</source>
        <translation>Misura del pulsante in corso</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="52"/>
        <source>Measuring again</source>
        <translation>Nuova misura</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="54"/>
        <source>Measuring the distance</source>
        <translation>Misura della distanza in corso</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="56"/>
        <source>Panel unclear</source>
        <translation>Pannello non chiaro</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="58"/>
        <source>Position not sure yet</source>
        <translation>Posizione non ancora sicura</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="60"/>
        <source>Panel direction not sure yet</source>
        <translation>Direzione del pannello non ancora sicura</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="62"/>
        <source>Button out of reach</source>
        <translation>Pulsante fuori portata</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="72"/>
        <source>The picture changed: tap again</source>
        <translation>L&apos;immagine è cambiata: tocca di nuovo</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="74"/>
        <source>The picture was too old: tap again</source>
        <translation>L&apos;immagine era troppo vecchia: tocca di nuovo</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="76"/>
        <source>Stopped: press Start again first</source>
        <translation>Fermato: premi prima «Riparti»</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="85"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="227"/>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="214"/>
        <source>Paused</source>
        <translation>In pausa</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="88"/>
        <source>Arm link off</source>
        <translation>Collegamento al braccio spento</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="89"/>
        <source>No arm connected</source>
        <translation>Nessun braccio collegato</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="93"/>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="219"/>
        <source>Waiting</source>
        <translation>In attesa</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="114"/>
        <source>Button picker (monocular SLAM)</source>
        <translation>Selettore di pulsanti (SLAM monoculare)</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="122"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="146"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="185"/>
        <source>Operator panel</source>
        <translation>Pannello operatore</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="126"/>
        <source>Operator panel full screen</source>
        <translation>Pannello operatore a schermo intero</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="227"/>
        <source>End of the recording</source>
        <translation>Fine della registrazione</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="245"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="253"/>
        <source>The picture is paused: press Play, then tap</source>
        <translation>L&apos;immagine è in pausa: premi Riproduci, poi tocca</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="252"/>
        <source>The recording has ended: nothing to tap</source>
        <translation>La registrazione è finita: niente da toccare</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="254"/>
        <source>No picture yet: open a camera or a recording</source>
        <translation>Ancora nessuna immagine: apri una telecamera o una registrazione</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="291"/>
        <source>No button at the tap: %1</source>
        <translation>Nessun pulsante nel punto toccato: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="306"/>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="206"/>
        <source>No metric scale (no arm motion)</source>
        <translation>Nessuna scala metrica (nessun movimento del braccio)</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="308"/>
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
    <name>sightline::CoreMessage</name>
    <message>
        <location filename="../widgets/core_message.cpp" line="17"/>
        <source>invalid argument</source>
        <translation>argomento non valido</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="18"/>
        <source>not found</source>
        <translation>non trovato</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="19"/>
        <source>parse error</source>
        <translation>errore di formato</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="20"/>
        <source>unavailable</source>
        <translation>non disponibile</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="21"/>
        <source>out of range</source>
        <translation>fuori intervallo</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="22"/>
        <source>failed precondition</source>
        <translation>precondizione non soddisfatta</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="23"/>
        <source>internal error</source>
        <translation>errore interno</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="28"/>
        <source>%1 line %2</source>
        <translation>%1 riga %2</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="29"/>
        <source>profile %1</source>
        <translation>profilo %1</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="30"/>
        <source>parameter panel</source>
        <translation>pannello dei parametri</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="36"/>
        <source>unknown option &apos;%1&apos;</source>
        <translation>opzione sconosciuta &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="37"/>
        <source>option &apos;%1&apos;: %2 is outside %3</source>
        <translation>opzione &apos;%1&apos;: %2 è fuori da %3</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="38"/>
        <source>option &apos;%1&apos;: &apos;%2&apos; is not one of: %3</source>
        <translation>opzione &apos;%1&apos;: &apos;%2&apos; non è uno dei valori: %3</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="39"/>
        <source>option &apos;%1&apos;: &apos;%2&apos; is not a boolean (true/false)</source>
        <translation>opzione &apos;%1&apos;: &apos;%2&apos; non è un booleano (true/false)</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="40"/>
        <source>option &apos;%1&apos;: &apos;%2&apos; is not an integer</source>
        <translation>opzione &apos;%1&apos;: &apos;%2&apos; non è un numero intero</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="41"/>
        <source>option &apos;%1&apos;: &apos;%2&apos; is not a number</source>
        <translation>opzione &apos;%1&apos;: &apos;%2&apos; non è un numero</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="42"/>
        <source>option &apos;%1&apos;: value is not finite</source>
        <translation>opzione &apos;%1&apos;: il valore non è finito</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="43"/>
        <source>a profile must be a map of option keys</source>
        <translation>un profilo deve essere una mappa di chiavi di opzione</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="44"/>
        <source>option &apos;%1&apos; is given twice (also line %2)</source>
        <translation>l&apos;opzione &apos;%1&apos; è indicata due volte (anche alla riga %2)</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="45"/>
        <source>option &apos;%1&apos; has no value</source>
        <translation>l&apos;opzione &apos;%1&apos; non ha un valore</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="46"/>
        <source>option &apos;%1&apos; must be a single value, not a list</source>
        <translation>l&apos;opzione &apos;%1&apos; deve essere un valore singolo, non una lista</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="47"/>
        <source>an option key must be a word, not a list or map</source>
        <translation>una chiave di opzione deve essere una parola, non una lista o una mappa</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="48"/>
        <source>options nest deeper than %1 levels</source>
        <translation>le opzioni sono annidate oltre %1 livelli</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="49"/>
        <source>lists or maps nest deeper than %1 levels</source>
        <translation>liste o mappe annidate oltre %1 livelli</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="50"/>
        <source>more than %1 values (aliases expanding?); a profile lists each option once</source>
        <translation>più di %1 valori (alias che si espandono?); un profilo elenca ogni opzione una sola volta</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="52"/>
        <source>not a readable YAML profile: %1</source>
        <translation>non è un profilo YAML leggibile: %1</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="53"/>
        <source>cannot write profile %1</source>
        <translation>impossibile scrivere il profilo %1</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="54"/>
        <source>write to %1 failed (disk full?)</source>
        <translation>scrittura su %1 non riuscita (disco pieno?)</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="55"/>
        <source>no such file</source>
        <translation>file inesistente</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="56"/>
        <source>profile %1 is a folder, not a file</source>
        <translation>il profilo %1 è una cartella, non un file</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="57"/>
        <source>profile %1 is not a regular file (a device, pipe or socket)</source>
        <translation>il profilo %1 non è un file regolare (un dispositivo, una pipe o un socket)</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="59"/>
        <source>profile %1 cannot be read: %2</source>
        <translation>impossibile leggere il profilo %1: %2</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="60"/>
        <source>profile %1 is %2 bytes; a profile holds at most %3</source>
        <translation>il profilo %1 è di %2 byte; un profilo contiene al massimo %3</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="62"/>
        <source>cannot read its size: %1</source>
        <translation>impossibile leggerne la dimensione: %1</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="63"/>
        <source>read error (%1 of %2 bytes)</source>
        <translation>errore di lettura (%1 di %2 byte)</translation>
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
    <message>
        <location filename="../app/sightline/core_texts.cpp" line="19"/>
        <source>ROS 1 bag files (.bag): images, RGB-D, stereo and point clouds, with tf ground truth</source>
        <translation>File bag di ROS 1 (.bag): immagini, RGB-D, stereo e nuvole di punti, con riferimento da tf</translation>
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
        <location filename="../app/sightline/evaluation_panel.cpp" line="175"/>
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
        <location filename="../app/sightline/evaluation_panel.cpp" line="185"/>
        <source>Evaluation failed: %1</source>
        <translation>Valutazione non riuscita: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="198"/>
        <source>%1 associated poses, ground-truth path %2 m.</source>
        <translation>%1 pose associate, percorso della ground truth %2 m.</translation>
    </message>
</context>
<context>
    <name>sightline::ImageView</name>
    <message>
        <location filename="../widgets/image_view.cpp" line="49"/>
        <location filename="../widgets/image_view.cpp" line="80"/>
        <location filename="../widgets/image_view.cpp" line="135"/>
        <source>No image</source>
        <translation>Nessuna immagine</translation>
    </message>
    <message>
        <location filename="../widgets/image_view.cpp" line="83"/>
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
        <location filename="../widgets/log_panel.cpp" line="33"/>
        <source>Click a line to read it in full.</source>
        <translation>Fai clic su una riga per leggerla per intero.</translation>
    </message>
    <message>
        <location filename="../widgets/log_panel.cpp" line="51"/>
        <source>Clear messages</source>
        <translation>Cancella i messaggi</translation>
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
        <translation>Colore</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="83"/>
        <location filename="../app/sightline/main_window.cpp" line="406"/>
        <source>Depth</source>
        <translation>Profondità</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="89"/>
        <source>Parameters</source>
        <translation>Parametri</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="91"/>
        <source>Log</source>
        <translation>Registro</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="94"/>
        <source>Evaluation</source>
        <translation>Valutazione</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="107"/>
        <source>Playback</source>
        <translation>Riproduzione</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="117"/>
        <source>&amp;File</source>
        <translation>&amp;File</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="118"/>
        <source>&amp;Open dataset folder...</source>
        <translation>&amp;Apri cartella del dataset...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="121"/>
        <source>Open dataset folder</source>
        <translation>Apri cartella del dataset</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="126"/>
        <source>Open point cloud</source>
        <translation>Apri nuvola di punti</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="124"/>
        <source>Open recording &amp;file (PCD, ONI)...</source>
        <translation>Apri &amp;file di registrazione (PCD, ONI)...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="127"/>
        <source>Recordings (*.pcd *.oni *.bag)</source>
        <translation>Registrazioni (*.pcd *.oni *.bag)</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="130"/>
        <source>Open &amp;recent</source>
        <translation>Apri &amp;recenti</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="137"/>
        <source>&amp;Quit</source>
        <translation>&amp;Esci</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="141"/>
        <source>&amp;View</source>
        <translation>&amp;Visualizza</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="143"/>
        <source>&amp;Reset 3D view</source>
        <translation>&amp;Ripristina la vista 3D</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="146"/>
        <source>&amp;Follow the trajectory</source>
        <translation>&amp;Segui la traiettoria</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="148"/>
        <source>Fit the 3D view again whenever a growing trajectory leaves it.</source>
        <translation>Riadatta la vista 3D ogni volta che una traiettoria in crescita ne esce.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="157"/>
        <source>&amp;Sensors</source>
        <translation>&amp;Sensori</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="164"/>
        <source> (unavailable)</source>
        <translation> (non disponibile)</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="169"/>
        <source>Connect to the first %1 device</source>
        <translation>Collegati al primo dispositivo %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="175"/>
        <source>Replay recording</source>
        <translation>Riproduci una registrazione</translation>
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
        <translation>Nessuna (mostra solo le immagini)</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="190"/>
        <source>&amp;Tools</source>
        <translation>S&amp;trumenti</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="191"/>
        <source>&amp;Evaluate trajectory...</source>
        <translation>&amp;Valuta una traiettoria...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="196"/>
        <source>Evaluate &amp;current run</source>
        <translation>Valuta l&apos;esecuzione &amp;corrente</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="198"/>
        <source>Compares the running pipeline&apos;s trajectory with the dataset&apos;s ground truth.</source>
        <translation>Confronta la traiettoria della pipeline in esecuzione con la ground truth del dataset.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="207"/>
        <source>&amp;Help</source>
        <translation>&amp;Aiuto</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="208"/>
        <source>&amp;About Sightline</source>
        <translation>&amp;Informazioni su Sightline</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="209"/>
        <source>About Sightline</source>
        <translation>Informazioni su Sightline</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="210"/>
        <source>Sightline: robot perception for assistive and mobile robotics.
Indoor mapping, mobility maps, stereo odometry and monocular button localisation on live sensors or recorded data.</source>
        <translation>Sightline: percezione robotica per la robotica assistiva e mobile.
Mappatura di interni, mappe di percorribilità, odometria stereo e localizzazione monoculare dei pulsanti da sensori dal vivo o dati registrati.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="227"/>
        <source>Could not open %1: %2</source>
        <translation>Impossibile aprire %1: %2</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="228"/>
        <source>Could not open %1</source>
        <translation>Impossibile aprire %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="236"/>
        <source>End of recording.</source>
        <translation>Fine della registrazione.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="265"/>
        <source>Demo %p%</source>
        <translation>Demo %p%</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="272"/>
        <source>Generating the demo recordings (only the first time)...</source>
        <translation>Generazione delle registrazioni demo (solo la prima volta)...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="281"/>
        <source>Demo: a robot drives a simulated office corridor (RGB-D, stereo, wheel odometry, exact ground truth). The arm-camera panel approach is in %1.</source>
        <translation>Demo: un robot percorre un corridoio d&apos;ufficio simulato (RGB-D, stereo, odometria delle ruote, ground truth esatta). L&apos;avvicinamento della telecamera del braccio al pannello è in %1.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="288"/>
        <source>The demo could not be made: %1</source>
        <translation>Impossibile creare la demo: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="345"/>
        <source>No pipeline: showing frames only.</source>
        <translation>Nessuna pipeline: mostro solo le immagini.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="356"/>
        <source>Pipeline: %1</source>
        <translation>Pipeline: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="360"/>
        <source>%1 cannot run on %2 frames; open another dataset.</source>
        <translation>%1 non può funzionare su immagini %2; apri un altro dataset.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="389"/>
        <location filename="../app/sightline/main_window.cpp" line="390"/>
        <source>Opening %1 ...</source>
        <translation>Apertura di %1 ...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="405"/>
        <source>Left</source>
        <translation>Sinistra</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="405"/>
        <source>Image</source>
        <translation>Immagine</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="406"/>
        <source>Right</source>
        <translation>Destra</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="412"/>
        <source>%1: %2, %3 frames, %4x%5%6</source>
        <translation>%1: %2, %3 immagini, %4x%5%6</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="417"/>
        <source>, ground truth</source>
        <translation>, ground truth</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="419"/>
        <source>Opened %1</source>
        <translation>Aperto %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="424"/>
        <source>Sightline - %1</source>
        <translation>Sightline - %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="443"/>
        <source>frame %1, read in %2 ms</source>
        <translation>immagine %1, letta in %2 ms</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="492"/>
        <source>No dataset open. Use File &gt; Open dataset folder (TUM RGB-D, EuRoC, KITTI, an image folder or PCD files), or drop a folder on this window.</source>
        <translation>Nessun dataset aperto. Usa File &gt; Apri cartella del dataset (TUM RGB-D, EuRoC, KITTI, una cartella di immagini o file PCD), oppure trascina una cartella su questa finestra.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="494"/>
        <source>No dataset open</source>
        <translation>Nessun dataset aperto</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="200"/>
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
    <message>
        <location filename="../app/sightline/main_window_playback.cpp" line="44"/>
        <source>Reset the map?</source>
        <translation>Azzerare la mappa?</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_playback.cpp" line="45"/>
        <source>%1 has built its map over %2 frames. Seeking starts it over from the frame you seek to: the map and the trajectory so far are lost.</source>
        <translation>%1 ha costruito la sua mappa su %2 fotogrammi. Un salto la ricomincia dal fotogramma scelto: la mappa e la traiettoria finora vanno perse.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_playback.cpp" line="51"/>
        <source>Seek and reset the map</source>
        <translation>Salta e azzera la mappa</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_playback.cpp" line="53"/>
        <source>Keep the map</source>
        <translation>Mantieni la mappa</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_ros.cpp" line="24"/>
        <source>Connect to &amp;ROS master...</source>
        <translation>Connetti al master &amp;ROS...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_ros.cpp" line="25"/>
        <source>&amp;Disconnect from ROS master</source>
        <translation>&amp;Disconnetti dal master ROS</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_ros.cpp" line="32"/>
        <source>Connect to ROS master</source>
        <translation>Connetti al master ROS</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_ros.cpp" line="40"/>
        <source>Disconnected from the ROS master</source>
        <translation>Disconnesso dal master ROS</translation>
    </message>
</context>
<context>
    <name>sightline::MappingPresenter</name>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="112"/>
        <source>Indoor mapping (Manhattan walls)</source>
        <translation>Mappatura di interni (pareti di Manhattan)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="119"/>
        <source>Occupancy, scan and walls</source>
        <translation>Occupazione, scansione e pareti</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="125"/>
        <source>Calibrate floor</source>
        <translation>Calibra il pavimento</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="127"/>
        <source>Fit the floor plane again from the next frames (the robot should see open floor).</source>
        <translation>Stima di nuovo il piano del pavimento dalle prossime immagini (il robot deve vedere pavimento libero).</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="130"/>
        <source>Save floor...</source>
        <translation>Salva il pavimento...</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="132"/>
        <source>Save the floor calibration in use, for mapping.run.floor_file or `sightline-cli run mapping --set mapping.run.floor_file=...`.</source>
        <translation>Salva la calibrazione del pavimento in uso, per mapping.run.floor_file o `sightline-cli run mapping --set mapping.run.floor_file=...`.</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="135"/>
        <source>Save floor calibration</source>
        <translation>Salva la calibrazione del pavimento</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="136"/>
        <source>YAML (*.yaml)</source>
        <translation>YAML (*.yaml)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="148"/>
        <source>Stitched map</source>
        <translation>Mappa unita</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="180"/>
        <location filename="../app/sightline/mapping_presenter.cpp" line="212"/>
        <source>free</source>
        <translation>libero</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="181"/>
        <location filename="../app/sightline/mapping_presenter.cpp" line="214"/>
        <source>occupied</source>
        <translation>occupato</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="182"/>
        <source>person</source>
        <translation>persona</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="183"/>
        <source>scan rays</source>
        <translation>raggi di scansione</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="184"/>
        <location filename="../app/sightline/mapping_presenter.cpp" line="223"/>
        <source>walls, first direction</source>
        <translation>pareti, prima direzione</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="185"/>
        <location filename="../app/sightline/mapping_presenter.cpp" line="224"/>
        <source>walls, perpendicular</source>
        <translation>pareti, perpendicolari</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="186"/>
        <location filename="../app/sightline/mapping_presenter.cpp" line="225"/>
        <source>other lines</source>
        <translation>altre linee</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="187"/>
        <source>robot</source>
        <translation>robot</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="213"/>
        <source>unknown</source>
        <translation>sconosciuto</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="215"/>
        <source>path and robot</source>
        <translation>percorso e robot</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="226"/>
        <source>floor</source>
        <translation>pavimento</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="228"/>
        <source>map: free</source>
        <translation>mappa: libero</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="229"/>
        <source>map: occupied</source>
        <translation>mappa: occupato</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="230"/>
        <source>path</source>
        <translation>percorso</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="235"/>
        <source>Manhattan reference reset: %1</source>
        <translation>Riferimento di Manhattan azzerato: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="276"/>
        <source>Calibrating the floor again from the next frames.</source>
        <translation>Nuova calibrazione del pavimento dalle prossime immagini.</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="289"/>
        <source>Saved the floor calibration to %1</source>
        <translation>Calibrazione del pavimento salvata in %1</translation>
    </message>
</context>
<context>
    <name>sightline::MobilityImagePanel</name>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="73"/>
        <source>Projection</source>
        <translation>Proiezione</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="74"/>
        <source>Top view</source>
        <translation>Vista dall&apos;alto</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="75"/>
        <source>GPR surface</source>
        <translation>Superficie GPR</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="85"/>
        <source>score 0: not passable</source>
        <translation>punteggio 0: non percorribile</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="86"/>
        <source>score 0.5</source>
        <translation>punteggio 0,5</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="87"/>
        <source>score 1: passable</source>
        <translation>punteggio 1: percorribile</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="88"/>
        <source>not scored</source>
        <translation>non valutato</translation>
    </message>
</context>
<context>
    <name>sightline::MobilityPresenter</name>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="27"/>
        <source>Mobility map</source>
        <translation>Mappa di percorribilità</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="37"/>
        <source>Mobility map (red 0, green 1)</source>
        <translation>Mappa di percorribilità (rosso 0, verde 1)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="41"/>
        <source>Mobility stages (Table II)</source>
        <translation>Fasi della mappa di percorribilità (Tabella II)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="77"/>
        <source>colour: one per segment</source>
        <translation>colore: uno per segmento</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="80"/>
        <source>score 0: not passable</source>
        <translation>punteggio 0: non percorribile</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="80"/>
        <source>score 1: passable</source>
        <translation>punteggio 1: percorribile</translation>
    </message>
</context>
<context>
    <name>sightline::MobilityTimingPanel</name>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="22"/>
        <source>3D colour:</source>
        <translation>Colore 3D:</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="24"/>
        <source>Score (rule)</source>
        <translation>Punteggio (regola)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="24"/>
        <source>Score (GPR)</source>
        <translation>Punteggio (GPR)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="24"/>
        <source>Segment</source>
        <translation>Segmento</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="32"/>
        <source>Stage</source>
        <translation>Fase</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="32"/>
        <source>Time (ms)</source>
        <translation>Tempo (ms)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="32"/>
        <source>Points</source>
        <translation>Punti</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="53"/>
        <source>Total</source>
        <translation>Totale</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="56"/>
        <source>%1 mode, %2 segments</source>
        <translation>modalità %1, %2 segmenti</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="60"/>
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
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="194"/>
        <source>inlier</source>
        <translation>inlier</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="195"/>
        <source>outlier</source>
        <translation>outlier</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="196"/>
        <source>keypoint, unmatched</source>
        <translation>punto chiave, non associato</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="197"/>
        <source>frame: tracking quality</source>
        <translation>cornice: qualità del tracciamento</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="212"/>
        <source>%1: %2 inliers of %3 matches, %4 map points, %5 keyframes, %6 ms</source>
        <translation>%1: %2 inlier su %3 corrispondenze, %4 punti mappa, %5 keyframe, %6 ms</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="222"/>
        <source>Metric scale from %1: ML %2, single ratio %3 map units per metre; map and trajectory in metres.</source>
        <translation>Scala metrica da %1: ML %2, rapporto singolo %3 unità di mappa per metro; mappa e traiettoria in metri.</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="228"/>
        <source>Scale unknown (measured motion: %1): the map is in arbitrary units (first baseline = 0.1).</source>
        <translation>Scala sconosciuta (moto misurato: %1): la mappa è in unità arbitrarie (prima baseline = 0,1).</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="268"/>
        <source>camera path</source>
        <translation>percorso della camera</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="269"/>
        <source>keyframes</source>
        <translation>fotogrammi chiave</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="270"/>
        <source>camera: tracking quality</source>
        <translation>camera: qualità del tracciamento</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="271"/>
        <source>map points: colour of their first keyframe</source>
        <translation>punti della mappa: colore del loro primo fotogramma chiave</translation>
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
        <translation>Annulla</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="292"/>
        <source>Locating</source>
        <translation>Localizzazione</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="296"/>
        <source>Lost - hold still</source>
        <translation>Perso - resta fermo</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="286"/>
        <source>No button here - tap again</source>
        <translation>Nessun pulsante qui - tocca di nuovo</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="211"/>
        <source>Robot: live</source>
        <translation>Robot: in diretta</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="214"/>
        <source>Waiting for the robot&apos;s picture</source>
        <translation>In attesa dell&apos;immagine del robot</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="217"/>
        <source>Picture stale: no taps</source>
        <translation>Immagine vecchia: nessun tocco</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="220"/>
        <source>Disconnected: reconnecting</source>
        <translation>Disconnesso: riconnessione</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="284"/>
        <source>Press this button?</source>
        <translation>Premere questo pulsante?</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="300"/>
        <source>Holding: nothing sent</source>
        <translation>In attesa: niente inviato</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="302"/>
        <source>Tap not taken</source>
        <translation>Tocco non accettato</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="304"/>
        <source>Tracking only</source>
        <translation>Solo inseguimento</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="339"/>
        <source>STOP</source>
        <translation>STOP</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="375"/>
        <source>Leave</source>
        <translation>Esci</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="375"/>
        <source>Leave the operator panel?</source>
        <translation>Uscire dal pannello operatore?</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="288"/>
        <source>Searching</source>
        <translation>Ricerca</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="340"/>
        <source>Start again</source>
        <translation>Riparti</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="298"/>
        <source>Stopped</source>
        <translation>Fermato</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="282"/>
        <source>Tap a button</source>
        <translation>Tocca un pulsante</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="294"/>
        <source>Target sent</source>
        <translation>Bersaglio inviato</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="290"/>
        <source>Tracking</source>
        <translation>Pulsante agganciato</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="337"/>
        <location filename="../widgets/operator_panel.cpp" line="379"/>
        <source>Yes</source>
        <translation>Sì</translation>
    </message>
</context>
<context>
    <name>sightline::OptionEditor</name>
    <message>
        <location filename="../widgets/option_editor.cpp" line="54"/>
        <source>Range: %1 … %2%3</source>
        <translation>Intervallo: %1 … %2%3</translation>
    </message>
    <message>
        <location filename="../widgets/option_editor.cpp" line="59"/>
        <source>Choices: %1</source>
        <translation>Scelte: %1</translation>
    </message>
    <message>
        <location filename="../widgets/option_editor.cpp" line="62"/>
        <source>Default: %1%2</source>
        <translation>Predefinito: %1%2</translation>
    </message>
    <message>
        <location filename="../widgets/option_editor.cpp" line="85"/>
        <source>Reset to default (%1)</source>
        <translation>Ripristina il predefinito (%1)</translation>
    </message>
</context>
<context>
    <name>sightline::OptionText</name>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="14"/>
        <source>... and a relative 1-sigma scale error at most this.</source>
        <translation>... e un errore di scala relativo a 1 sigma al massimo pari a questo valore.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="15"/>
        <source>... and at least this fraction of the scan&apos;s rays hit it.</source>
        <translation>... e almeno questa frazione dei raggi della scansione la colpisce.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="16"/>
        <source>... and by this fraction of the angle turned since the last correction.</source>
        <translation>... e di questa frazione dell&apos;angolo ruotato dall&apos;ultima correzione.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="17"/>
        <source>... or the camera centres to lie this far apart (rays crossing).</source>
        <translation>... oppure che i centri della camera distino almeno tanto (raggi che si incrociano).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="19"/>
        <source>... or when it turned at least this much.</source>
        <translation>... oppure quando ha ruotato almeno di tanto.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="20"/>
        <source>... plus this fraction of the tracked radius (a model centre off by a fixed amount on the button grows with its apparent size).</source>
        <translation>... più questa frazione del raggio tracciato (un centro del modello spostato di una quantità fissa sul pulsante cresce con la sua dimensione apparente).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="21"/>
        <source>... plus this times the depth squared (Kinect noise and quantisation).</source>
        <translation>... più questo valore per il quadrato della profondità (rumore e quantizzazione del Kinect).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="22"/>
        <source>... reached within this many frames; otherwise the anchor starts again (tracks followed over many frames drift, and their drift reads as an offset).</source>
        <translation>... raggiunta entro questo numero di fotogrammi; altrimenti l&apos;ancoraggio ricomincia (le tracce seguite per molti fotogrammi derivano, e la loro deriva appare come un offset).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="23"/>
        <source>.oni playback speed: 0 delivers frames as fast as they are read, nothing skipped; 1 paces at the recorded rate.</source>
        <translation>Velocità di riproduzione dei .oni: 0 fornisce i fotogrammi alla velocità con cui vengono letti, senza saltarne; 1 segue la frequenza registrata.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="24"/>
        <source>.oni recordings start again at the first frame instead of ending.</source>
        <translation>Le registrazioni .oni ricominciano dal primo fotogramma invece di terminare.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="25"/>
        <source>1-sigma error of the tracked button centre; moves the point across the viewing ray (the target&apos;s stated uncertainty includes it).</source>
        <translation>Errore a 1 sigma del centro del pulsante tracciato; sposta il punto trasversalmente al raggio visivo (l&apos;incertezza dichiarata del target lo include).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="26"/>
        <source>1-sigma of the tracked centre in the triangulation ...</source>
        <translation>1-sigma del centro tracciato nella triangolazione ...</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="27"/>
        <source>1-sigma relative error of the tracked radius.</source>
        <translation>Errore relativo a 1-sigma del raggio tracciato.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="28"/>
        <source>1-sigma rotation error of the hand-eye calibration; times the distance to the button.</source>
        <translation>Errore di rotazione a 1 sigma della calibrazione mano-occhio; moltiplicato per la distanza dal pulsante.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="29"/>
        <source>1-sigma translation error of the hand-eye calibration (end effector to camera).</source>
        <translation>Errore di traslazione a 1 sigma della calibrazione mano-occhio (dall&apos;end effector alla telecamera).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="30"/>
        <source>A bucket gets new corners only when it holds fewer than this fraction of its share of max_features (1 = whenever it is not full).</source>
        <translation>Una cella (bucket) riceve nuovi corner solo quando ne contiene meno di questa frazione della sua quota di max_features (1 = ogni volta che non è piena).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="31"/>
        <source>A button centre farther than this outside the image is out of view (lost).</source>
        <translation>Un centro del pulsante più lontano di così fuori dall&apos;immagine è fuori vista (perso).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="32"/>
        <source>A camera frame newer than the newest arm pose waits at most this long (host clock) for the pose that covers its stamp; then it has no arm pose.</source>
        <translation>Un fotogramma della telecamera più recente dell&apos;ultima posa del braccio attende al massimo tanto (orologio dell&apos;host) la posa che copre il suo timestamp; poi resta senza posa del braccio.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="34"/>
        <source>A frame has ground truth when a pose lies within this time.</source>
        <translation>Un fotogramma ha la ground truth quando una posa si trova entro questo intervallo di tempo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="35"/>
        <source>A frame sets the reference only when the wall length in a second direction a few degrees off (inside the gate, outside the trim) is at most this fraction of the main direction&apos;s.</source>
        <translation>Un fotogramma fissa il riferimento solo quando la lunghezza dei muri in una seconda direzione, scostata di pochi gradi (dentro il gate, fuori dal taglio), è al massimo questa frazione di quella della direzione principale.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="36"/>
        <source>A frame stays in the window when the camera moved this fraction of its points&apos; median depth since the previous one that stayed (0 = every frame stays); otherwise the next frame replaces it.</source>
        <translation>Un fotogramma resta nella finestra quando la telecamera si è mossa di questa frazione della profondità mediana dei suoi punti rispetto al precedente rimasto (0 = ogni fotogramma resta); altrimenti il fotogramma successivo lo sostituisce.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="38"/>
        <source>A frame this far from every keyframe (relative to the mean depth) becomes one.</source>
        <translation>Un fotogramma così lontano da ogni keyframe (rispetto alla profondità media) diventa un keyframe.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="39"/>
        <source>A frame tracking fewer than this share of the last keyframe&apos;s points becomes one.</source>
        <translation>Un fotogramma che traccia meno di questa quota dei punti dell&apos;ultimo keyframe diventa un keyframe.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="41"/>
        <source>A frame with fewer matches than this with the newest candidate becomes a candidate too (the oldest leaves a full ring); at low frame rates every frame does.</source>
        <translation>Un fotogramma con meno corrispondenze di queste con il candidato più recente diventa anch&apos;esso candidato (ad anello pieno esce il più vecchio); a bassa frequenza lo diventa ogni fotogramma.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="42"/>
        <source>A frame&apos;s normal this many sigmas off the average is skipped.</source>
        <translation>Un fotogramma la cui normale si discosta dalla media di questo numero di sigma viene saltato.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="43"/>
        <source>A frame&apos;s walls count only when their summed vote weight (length x fit quality) reaches this.</source>
        <translation>I muri di un fotogramma contano solo quando il loro peso di voto sommato (lunghezza x qualità del fit) raggiunge questo valore.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="44"/>
        <source>A ground candidate holds at least this fraction of the points.</source>
        <translation>Un candidato pavimento contiene almeno questa frazione dei punti.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="45"/>
        <source>A ground plane&apos;s normal lies at most this far from the expected up direction.</source>
        <translation>La normale di un piano del suolo si discosta al massimo di tanto dalla direzione verso l&apos;alto attesa.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="46"/>
        <source>A ground point&apos;s own normal lies at most this far from the plane&apos;s.</source>
        <translation>La normale propria di un punto del suolo si discosta al massimo di tanto da quella del piano.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="47"/>
        <source>A ground-truth or odometry pose belongs to a frame when this close in time.</source>
        <translation>Una posa di ground truth o di odometria appartiene a un fotogramma quando è così vicina nel tempo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="48"/>
        <source>A ground-truth pose belongs to a frame when this close in time.</source>
        <translation>Una posa di ground truth appartiene a un fotogramma quando è così vicina nel tempo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="50"/>
        <source>A line this close to a Manhattan axis is classed as parallel (0) or perpendicular (1) to the reference.</source>
        <translation>Una linea così vicina a un asse Manhattan è classificata come parallela (0) o perpendicolare (1) al riferimento.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="52"/>
        <source>A pose belongs to a frame when this close in time.</source>
        <translation>Una posa appartiene a un fotogramma quando è così vicina nel tempo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="55"/>
        <source>A segment&apos;s raised height is this quantile of its heights above the ground.</source>
        <translation>L&apos;altezza rialzata di un segmento è questo quantile delle sue altezze sopra il suolo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="56"/>
        <source>A sloped segment whose plane meets the ground within this distance of its lowest points is connected to the ground (a ramp), not raised.</source>
        <translation>Un segmento inclinato il cui piano incontra il suolo entro questa distanza dai suoi punti più bassi è collegato al suolo (una rampa), non rialzato.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="57"/>
        <source>A streaming device that delivers nothing for this long is treated as lost and reopened; 0 never does (e.g. waiting for rare hardware triggers).</source>
        <translation>Un dispositivo in streaming che non fornisce nulla per questo tempo è considerato perso e viene riaperto; 0 non lo fa mai (ad es. in attesa di trigger hardware rari).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="58"/>
        <source>A track must return to its start within this when tracked backwards; 0 = no check.</source>
        <translation>Una traccia, seguita all&apos;indietro, deve tornare al suo inizio entro questo valore; 0 = nessun controllo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="59"/>
        <source>A track seen from a direction differing more than this from its anchor&apos;s is anchored anew: the further aside, the more a wrongly fitted or assumed surface (the road taken as facing the camera) misleads the warp; 3 suits subsampled driving.</source>
        <translation>Una traccia vista da una direzione che differisce più di così da quella del suo ancoraggio viene ancorata di nuovo: più è laterale, più una superficie adattata o assunta in modo errato (la strada presa come rivolta verso la telecamera) inganna la deformazione; 3 è adatto alla guida sottocampionata.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="60"/>
        <source>A track whose patch would be scaled by more than this fraction since its anchor (the camera came close) is anchored anew.</source>
        <translation>Una traccia la cui patch verrebbe scalata di più di questa frazione dal suo ancoraggio (la telecamera si è avvicinata) viene ancorata di nuovo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="61"/>
        <source>A track&apos;s surface is fitted as a plane to the tracks within this radius at a similar depth, so the anchor&apos;s patch is warped as that plane; 0 = every patch is taken as facing the camera.</source>
        <translation>La superficie di una traccia è adattata come piano alle tracce entro questo raggio a profondità simile, così la patch dell&apos;ancoraggio viene deformata come quel piano; 0 = ogni patch è considerata rivolta verso la telecamera.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="63"/>
        <source>Accuracy: a segment is compared with the true region holding this fraction of its points.</source>
        <translation>Accuratezza: un segmento è confrontato con la regione vera che contiene questa frazione dei suoi punti.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="64"/>
        <source>Adaptive termination: stop when an outlier-free sample was drawn with this probability given the best inlier fraction; 1 = always max_iterations.</source>
        <translation>Terminazione adattiva: fermarsi quando è stato estratto un campione senza outlier con questa probabilità, data la migliore frazione di inlier; 1 = sempre max_iterations.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="65"/>
        <source>Add features of confidently tracked frames to the model when the button&apos;s apparent size has changed.</source>
        <translation>Aggiungere al modello le feature dei fotogrammi tracciati con sicurezza quando la dimensione apparente del pulsante è cambiata.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="66"/>
        <source>Added to the triangulation&apos;s stated 1-sigma: biases no residual shows (the tracked centre&apos;s offset on the button, the size&apos;s depth on a relief).</source>
        <translation>Aggiunto all&apos;1-sigma dichiarato della triangolazione: errori sistematici che nessun residuo mostra (lo scostamento del centro tracciato sul pulsante, la profondità della dimensione su un rilievo).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="67"/>
        <source>After a loss, search whole frames and re-acquire the button only on a confident match at a plausible size.</source>
        <translation>Dopo una perdita, cercare in fotogrammi interi e riacquisire il pulsante solo con una corrispondenza sicura e di dimensione plausibile.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="68"/>
        <source>Agreement of the voting lines modulo 90 deg (1 = perfect); below it the frame&apos;s walls are not used.</source>
        <translation>Concordanza delle linee votanti modulo 90 deg (1 = perfetta); al di sotto, i muri del fotogramma non vengono usati.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="69"/>
        <source>Also estimate a constant offset of the tracked centre in the image (a detector&apos;s sub-pixel convention): it would tilt the rays of the approach against the sideways move&apos;s.</source>
        <translation>Stima anche uno scostamento costante del centro tracciato nell&apos;immagine (la convenzione sub-pixel di un rilevatore): inclinerebbe i raggi dell&apos;avvicinamento rispetto a quelli del movimento laterale.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="70"/>
        <source>Also list and open Aravis&apos; in-process simulated camera Fake_1 (demos and tests).</source>
        <translation>Elencare e aprire anche la telecamera simulata interna di Aravis Fake_1 (demo e test).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="71"/>
        <source>Also locate the button from the arm&apos;s metric camera poses alone (the tracked centre&apos;s rays and its apparent size, core/button/arm_triangulation.h) and combine that point with the map&apos;s by their variances. Off by default: on the simulated approach&apos;s seeds 1-5 the mean final error goes 4.77 -&gt; 3.68 mm and the worst 10.1 -&gt; 5.9 mm, but seeds 1 and 4 and the 12 cm sideways approach get worse (docs/button.md).</source>
        <translation>Localizza il pulsante anche dalle sole pose metriche della camera date dal braccio (i raggi del centro tracciato e la sua dimensione apparente, core/button/arm_triangulation.h) e combina quel punto con quello della mappa secondo le loro varianze. Disattivato per default: sui seed 1-5 dell&apos;avvicinamento simulato l&apos;errore finale medio passa da 4.77 -&gt; 3.68 mm e il peggiore da 10.1 -&gt; 5.9 mm, ma i seed 1 e 4 e l&apos;avvicinamento con 12 cm di spostamento laterale peggiorano (docs/button.md).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="72"/>
        <source>Also project current points into the previous images (uses both depths).</source>
        <translation>Proiettare anche i punti attuali nelle immagini precedenti (usa entrambe le profondità).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="74"/>
        <source>An aligned patch whose zero-mean normalised correlation with the warped anchor patch is lower failed (occlusion, reflection).</source>
        <translation>Una patch allineata la cui correlazione normalizzata a media nulla con la patch di ancoraggio deformata è inferiore è fallita (occlusione, riflesso).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="75"/>
        <source>An alignment that moves the tracked position further than this failed (the KLT position is kept and the track anchored anew).</source>
        <translation>Un allineamento che sposta la posizione tracciata più di così è fallito (si mantiene la posizione KLT e la traccia viene ancorata di nuovo).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="76"/>
        <source>An anchor is used for at most this many frames; then the track is anchored anew.</source>
        <translation>Un ancoraggio viene usato al massimo per questo numero di fotogrammi; poi la traccia viene ancorata di nuovo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="77"/>
        <source>An arm_pose message with more joint positions is refused.</source>
        <translation>Un messaggio arm_pose con più posizioni dei giunti viene rifiutato.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="78"/>
        <source>An arm_pose position farther than this from the base is refused.</source>
        <translation>Una posizione arm_pose più lontana di così dalla base viene rifiutata.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="81"/>
        <source>Analog gain; negative keeps the camera&apos;s. Out-of-range values are errors.</source>
        <translation>Guadagno analogico; un valore negativo mantiene quello della telecamera. I valori fuori intervallo sono errori.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="83"/>
        <source>Ask the device to deliver depth and colour frames of the same instant.</source>
        <translation>Chiedere al dispositivo di fornire fotogrammi di profondità e colore dello stesso istante.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="84"/>
        <source>At low rates (mono.tracking.low_rate_interval_s), a frame tracking fewer than this share of the last keyframe&apos;s points becomes a keyframe within min_keyframe_gap too (0 = off).</source>
        <translation>A bassa frequenza (mono.tracking.low_rate_interval_s), un fotogramma che traccia meno di questa frazione dei punti dell&apos;ultimo fotogramma chiave diventa fotogramma chiave anche entro min_keyframe_gap (0 = disattivato).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="85"/>
        <source>At low rates, a frame this far from every keyframe (relative to the mean depth) becomes a keyframe within min_keyframe_gap too.</source>
        <translation>A bassa frequenza, un fotogramma così lontano da ogni fotogramma chiave (rispetto alla profondità media) diventa fotogramma chiave anche entro min_keyframe_gap.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="86"/>
        <source>At low rates, when the constant-velocity prediction tracks fewer inliers, the last pose (zero motion) is tried too and the better kept (0 = off).</source>
        <translation>A bassa frequenza, quando la previsione a velocità costante traccia meno inlier, si prova anche l&apos;ultima posa (moto nullo) e si tiene la migliore (0 = disattivato).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="87"/>
        <source>Authorised clients at most; further ones are closed.</source>
        <translation>Numero massimo di client autorizzati; quelli ulteriori vengono chiusi.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="88"/>
        <source>Band of the refinement (offset histogram bin and refit band): narrower than err_max, so that a door recessed behind the wall face does not tilt the line.</source>
        <translation>Banda del raffinamento (classe dell&apos;istogramma dell&apos;offset e banda del nuovo fit): più stretta di err_max, affinché una porta arretrata rispetto alla faccia del muro non inclini la linea.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="89"/>
        <source>Baseline over the median depth of the first points needed to accept (0.07 is a 4 deg ray angle sideways); a short baseline gives a distorted first map and a drifting scale.</source>
        <translation>Baseline sulla profondità mediana dei primi punti necessaria per accettare (0.07 corrisponde a un angolo dei raggi di 4 deg lateralmente); una baseline corta dà una prima mappa distorta e una scala che deriva.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="90"/>
        <source>Best over second-best descriptor distance in a window; 1 = off.</source>
        <translation>Rapporto tra la migliore e la seconda migliore distanza dei descrittori in una finestra; 1 = disattivato.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="91"/>
        <source>Camera pitched down by this: expected up = camera -y turned by pitch and roll.</source>
        <translation>Telecamera inclinata verso il basso di tanto: alto atteso = -y della telecamera ruotato di beccheggio e rollio.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="92"/>
        <source>Camera roll.</source>
        <translation>Rollio della telecamera.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="93"/>
        <source>Candidate first frames kept (a ring of recent frames); each new frame is tried against every one, oldest first (the largest baseline).</source>
        <translation>Candidati primo fotogramma conservati (un anello di fotogrammi recenti); ogni nuovo fotogramma viene provato con ciascuno, dal più vecchio (la base più lunga).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="94"/>
        <source>Canny lower threshold.</source>
        <translation>Soglia inferiore di Canny.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="95"/>
        <source>Canny upper threshold.</source>
        <translation>Soglia superiore di Canny.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="96"/>
        <source>Cell edge of the global map.</source>
        <translation>Lato della cella della mappa globale.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="97"/>
        <source>Cell of the keypoint grid used by window searches.</source>
        <translation>Cella della griglia dei keypoint usata dalle ricerche a finestra.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="98"/>
        <source>Coarse search window of the zero-motion try.</source>
        <translation>Finestra di ricerca grossolana del tentativo a moto nullo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="99"/>
        <source>Collinear lines (angles this close, one fit within the threshold) are merged.</source>
        <translation>Le linee collineari (angoli così vicini, un fit entro la soglia) vengono unite.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="100"/>
        <source>Compute SIFT only in a window around the predicted centre (fast).</source>
        <translation>Calcolare SIFT solo in una finestra attorno al centro previsto (veloce).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="101"/>
        <source>Connections still owing the token at most; a new one closes the oldest.</source>
        <translation>Numero massimo di connessioni che devono ancora presentare il token; una nuova chiude la più vecchia.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="102"/>
        <source>Consecutive frames of constant-motion fallback before the pose is held.</source>
        <translation>Fotogrammi consecutivi con il ripiego sul moto costante prima che la posa venga mantenuta.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="103"/>
        <source>Consecutive scan points farther apart than this start a new run.</source>
        <translation>Punti di scansione consecutivi distanti più di così iniziano un nuovo tratto.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="104"/>
        <source>Consistent matches needed to re-acquire a lost button.</source>
        <translation>Corrispondenze coerenti necessarie per riacquisire un pulsante perso.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="106"/>
        <source>Correct the heading with the walls&apos; Manhattan directions; off = dead reckoning only.</source>
        <translation>Correggere la direzione di marcia con le direzioni Manhattan dei muri; disattivato = solo navigazione stimata.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="107"/>
        <source>Demosaic Bayer formats to BGR colour; off delivers the raw mosaic as grey.</source>
        <translation>Effettuare il demosaicing dei formati Bayer in colore BGR; disattivato fornisce il mosaico grezzo in scala di grigi.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="108"/>
        <source>Depth beyond this is left out of the 3D cloud.</source>
        <translation>La profondità oltre questo valore resta fuori dalla nuvola 3D.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="49"/>
        <source>A line needs at least this many points (2 = as published; more rejects clutter).</source>
        <translation>Una linea richiede almeno questo numero di punti (2 = come pubblicato; di più scarta il disordine).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="54"/>
        <source>A region whose centroid is farther from the tap and that does not contain it is not the tapped button (published method).</source>
        <translation>Una regione il cui baricentro è più lontano dal tocco e che non lo contiene non è il pulsante toccato (metodo pubblicato).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="82"/>
        <source>Angle between scan rays (published res_scan = 0.2 deg).</source>
        <translation>Angolo tra i raggi della scansione (pubblicato: res_scan = 0.2 deg).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="109"/>
        <source>Depth images are sampled to about this many columns (published: 320 x 240).</source>
        <translation>Le immagini di profondità vengono campionate a circa questo numero di colonne (pubblicato: 320 x 240).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="110"/>
        <source>Depth points a cell needs to count as occupied (1 = as published: any non-floor point).</source>
        <translation>Punti di profondità necessari perché una cella conti come occupata (1 = come pubblicato: qualsiasi punto non del pavimento).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="111"/>
        <source>Depth readings beyond this are treated as invalid downstream.</source>
        <translation>Le letture di profondità oltre questo valore sono considerate non valide a valle.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="112"/>
        <source>Depth readings beyond this count as invalid.</source>
        <translation>Le letture di profondità oltre questo valore sono considerate non valide.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="115"/>
        <source>Depth sigmas (of both points at both times) added to the rigidity tolerance.</source>
        <translation>Sigma di profondità (di entrambi i punti in entrambi gli istanti) aggiunti alla tolleranza di rigidità.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="116"/>
        <source>Descriptor matches with a keyframe needed to try relocalisation.</source>
        <translation>Corrispondenze di descrittori con un keyframe necessarie per tentare la rilocalizzazione.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="117"/>
        <source>Disparity noise giving the depth sigma Z^2 s / (f b).</source>
        <translation>Rumore di disparità che dà il sigma di profondità Z^2 s / (f b).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="118"/>
        <source>Displacement pairs between consecutive keyframes (poses refined by bundle adjustment) or between tracked frames scale_interval_frames apart.</source>
        <translation>Coppie di spostamenti tra keyframe consecutivi (pose raffinate dal bundle adjustment) o tra fotogrammi tracciati distanti scale_interval_frames.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="119"/>
        <source>Distance from the epipolar line allowed for a new-point match.</source>
        <translation>Distanza dalla linea epipolare ammessa per una corrispondenza di un nuovo punto.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="120"/>
        <source>Distance gate: a match farther than this from the predicted centre is dropped.</source>
        <translation>Gate di distanza: una corrispondenza più lontana di così dal centro previsto viene scartata.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="121"/>
        <source>Draws per hypothesis to find a pair within the distance limits.</source>
        <translation>Estrazioni per ipotesi per trovare una coppia entro i limiti di distanza.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="122"/>
        <source>Edge of one occupancy cell; RANSAC&apos;s 5-cell error scales with it.</source>
        <translation>Lato di una cella di occupazione; l&apos;errore di 5 celle di RANSAC scala con esso.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="124"/>
        <source>Epipolar (row) constraint: largest row difference of a match.</source>
        <translation>Vincolo epipolare (di riga): massima differenza di riga di una corrispondenza.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="125"/>
        <source>Estimate a constant disparity offset of the rig (rectification or matcher bias) online from the motion, and add it to every disparity; an offset of a fraction of a pixel moves far points most and makes the translation too long or too short.</source>
        <translation>Stimare online dal moto un offset di disparità costante del rig (bias della rettifica o del matcher) e aggiungerlo a ogni disparità; un offset di una frazione di pixel sposta soprattutto i punti lontani e rende la traslazione troppo lunga o troppo corta.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="126"/>
        <source>Estimate each pose against the last keyframe&apos;s stereo observations of the tracks (after the frame-to-frame estimate), so per-frame errors do not accumulate.</source>
        <translation>Stimare ogni posa rispetto alle osservazioni stereo delle tracce nell&apos;ultimo keyframe (dopo la stima fotogramma per fotogramma), così gli errori dei singoli fotogrammi non si accumulano.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="127"/>
        <source>Exposure time; 0 keeps the camera&apos;s. Out-of-range values are errors.</source>
        <translation>Tempo di esposizione; 0 mantiene quello della telecamera. I valori fuori intervallo sono errori.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="128"/>
        <source>FAST corner threshold.</source>
        <translation>Soglia dei corner FAST.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="129"/>
        <source>FLANN leaf checks per query.</source>
        <translation>Controlli delle foglie FLANN per interrogazione.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="130"/>
        <source>FLANN randomised kd-trees.</source>
        <translation>Alberi kd randomizzati di FLANN.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="131"/>
        <source>Faster estimated rotation is rejected.</source>
        <translation>Una rotazione stimata più veloce viene rifiutata.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="132"/>
        <source>Faster estimated translation is rejected.</source>
        <translation>Una traslazione stimata più veloce viene rifiutata.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="133"/>
        <source>Features kept per frame, tracked plus new.</source>
        <translation>Feature mantenute per fotogramma, tracciate più nuove.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="134"/>
        <source>Features this close to the border are dropped.</source>
        <translation>Le feature così vicine al bordo vengono scartate.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="135"/>
        <source>Features within this many button radii of the centre are added.</source>
        <translation>Vengono aggiunte le feature entro questo numero di raggi del pulsante dal centro.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="136"/>
        <source>Fewer SIFT keypoints on the region: the button cannot be tracked.</source>
        <translation>Meno keypoint SIFT sulla regione: il pulsante non può essere tracciato.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="137"/>
        <source>Fewer consistent matches: the button is lost.</source>
        <translation>Meno corrispondenze coerenti: il pulsante è perso.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="138"/>
        <source>Fewer inliers after refinement is rejected.</source>
        <translation>Un numero inferiore di inlier dopo il raffinamento viene rifiutato.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="139"/>
        <source>Fewer inliers than this fraction of the points: the plane is not sound.</source>
        <translation>Meno inlier di questa frazione dei punti: il piano non è affidabile.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="140"/>
        <source>Fewer inliers than this means the motion could not be estimated.</source>
        <translation>Meno inlier di questo valore significa che il moto non ha potuto essere stimato.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="141"/>
        <source>Fewer map points or plane inliers: no normal in this frame.</source>
        <translation>Meno punti della mappa o inlier del piano: nessuna normale in questo fotogramma.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="142"/>
        <source>Fewer points left after the range cut is reported as an error.</source>
        <translation>Se dopo il taglio di distanza restano meno punti viene segnalato un errore.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="143"/>
        <source>Fewer points than this: the plane is not sound (no target is sent).</source>
        <translation>Meno punti di questo valore: il piano non è affidabile (nessun target viene inviato).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="144"/>
        <source>Fewer points: no 3D position.</source>
        <translation>Meno punti: nessuna posizione 3D.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="145"/>
        <source>Fewer tracked views with an arm pose: no triangulated point.</source>
        <translation>Meno viste tracciate con una posa del braccio: nessun punto triangolato.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="146"/>
        <source>Fewest tracks (the track included) a surface is fitted to.</source>
        <translation>Numero minimo di tracce (inclusa la traccia stessa) a cui viene adattata una superficie.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="147"/>
        <source>Field of view to scan, centred on forward; 0 = the camera&apos;s own (rays outside it can never hit anything).</source>
        <translation>Campo visivo da scansionare, centrato in avanti; 0 = quello della telecamera (i raggi al di fuori non possono mai colpire nulla).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="148"/>
        <source>Floor calibration (sightline-cli floor) giving the expected up direction; empty = mobility.mount_pitch_deg / mount_roll_deg.</source>
        <translation>Calibrazione del pavimento (sightline-cli floor) che fornisce la direzione verso l&apos;alto attesa; vuoto = mobility.mount_pitch_deg / mount_roll_deg.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="149"/>
        <source>Floor calibration file (sightline-cli floor); empty = calibrate from the first frames of the run.</source>
        <translation>File di calibrazione del pavimento (sightline-cli floor); vuoto = calibrare dai primi fotogrammi dell&apos;esecuzione.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="150"/>
        <source>Floor of the residual RMS by which each frame pair&apos;s measurement is weighted.</source>
        <translation>Limite inferiore dell&apos;RMS dei residui con cui è pesata la misura di ogni coppia di fotogrammi.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="151"/>
        <source>Format of trajectory.txt; --format kitti.</source>
        <translation>Formato di trajectory.txt; --format kitti.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="152"/>
        <source>Fraction of a circle&apos;s rim that must lie on an edge.</source>
        <translation>Frazione del bordo di un cerchio che deve trovarsi su uno spigolo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="153"/>
        <source>Fraction of directions around a region&apos;s centre in which its outline lies; a button&apos;s (even broken) outline surrounds its centre.</source>
        <translation>Frazione delle direzioni attorno al centro di una regione in cui si trova il suo contorno; il contorno (anche interrotto) di un pulsante circonda il suo centro.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="154"/>
        <source>Fraction of the correction applied per frame (1 = take the walls&apos; heading).</source>
        <translation>Frazione della correzione applicata per fotogramma (1 = adottare la direzione dei muri).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="156"/>
        <source>Frame rate of overlay.avi.</source>
        <translation>Frequenza dei fotogrammi di overlay.avi.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="157"/>
        <source>Frame results carry a rendered map image every n frames (0 = never).</source>
        <translation>I risultati dei fotogrammi includono un&apos;immagine renderizzata della mappa ogni n fotogrammi (0 = mai).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="158"/>
        <source>Frames between two keyframes at least (see urgent_keyframe_ratio).</source>
        <translation>Fotogrammi minimi tra due fotogrammi chiave (vedi urgent_keyframe_ratio).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="159"/>
        <source>Frames buffered between the capture thread and the consumer; when full the oldest is dropped, so latency stays bounded.</source>
        <translation>Fotogrammi in buffer tra il thread di acquisizione e il consumatore; quando è pieno il più vecchio viene scartato, così la latenza resta limitata.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="161"/>
        <source>Frames in the window; the oldest is held fixed.</source>
        <translation>Fotogrammi nella finestra; il più vecchio è mantenuto fisso.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="162"/>
        <source>Frames read before subsampling; 0 = all.</source>
        <translation>Fotogrammi letti prima del sottocampionamento; 0 = tutti.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="163"/>
        <source>Frames read; 0 = all.</source>
        <translation>Fotogrammi letti; 0 = tutti.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="164"/>
        <source>Frames spanned by one displacement pair of the scale estimators.</source>
        <translation>Fotogrammi coperti da una coppia di spostamenti degli stimatori di scala.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="165"/>
        <source>Frames that left the window keep constraining its points this long, with their poses held fixed, so the window&apos;s drift does not restart at every slide.</source>
        <translation>I fotogrammi usciti dalla finestra continuano a vincolarne i punti per questo tempo, con le pose mantenute fisse, così la deriva della finestra non riparte a ogni scorrimento.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="166"/>
        <source>Frames to process; 0 = all.</source>
        <translation>Fotogrammi da elaborare; 0 = tutti.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="167"/>
        <source>Frames to read; 0 reads the whole recording.</source>
        <translation>Fotogrammi da leggere; 0 legge l&apos;intera registrazione.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="168"/>
        <source>Frames tried against one first frame before it is replaced.</source>
        <translation>Fotogrammi provati contro un primo fotogramma prima che venga sostituito.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="169"/>
        <source>Frames used to calibrate the floor when no floor_file is given.</source>
        <translation>Fotogrammi usati per calibrare il pavimento quando non è indicato alcun floor_file.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="170"/>
        <source>Free scaling of cv::stereoRectify: 0 keeps only valid pixels, 1 keeps all.</source>
        <translation>Scalatura libera di cv::stereoRectify: 0 mantiene solo i pixel validi, 1 li mantiene tutti.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="171"/>
        <source>Free-running frame rate, or the host&apos;s rate with software triggering; 0 keeps the camera&apos;s. Rates the camera cannot reach are errors.</source>
        <translation>Frequenza dei fotogrammi in modalità libera, o la frequenza dell&apos;host con il trigger software; 0 mantiene quella della telecamera. Le frequenze che la telecamera non raggiunge sono errori.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="172"/>
        <source>Gauss-Newton iterations of the alignment.</source>
        <translation>Iterazioni di Gauss-Newton dell&apos;allineamento.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="173"/>
        <source>Gauss-Newton iterations on the reprojection error; 0 keeps the RANSAC motion.</source>
        <translation>Iterazioni di Gauss-Newton sull&apos;errore di riproiezione; 0 mantiene il moto di RANSAC.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="174"/>
        <source>Gauss-Newton steps on the reprojection error of each 3-point sample.</source>
        <translation>Passi di Gauss-Newton sull&apos;errore di riproiezione di ogni campione di 3 punti.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="175"/>
        <source>Gaussian blur before edge detection.</source>
        <translation>Sfocatura gaussiana prima del rilevamento dei bordi.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="176"/>
        <source>GenICam pixel format to select (Mono8, Mono16, BayerRG8, RGB8, ...); empty keeps the camera&apos;s. 16-bit formats are scaled to 8 bits.</source>
        <translation>Formato pixel GenICam da selezionare (Mono8, Mono16, BayerRG8, RGB8, ...); vuoto mantiene quello della telecamera. I formati a 16 bit vengono scalati a 8 bit.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="177"/>
        <source>GigE receive socket buffer; 0 lets Aravis size it to a whole frame (without it most packets of large frames are lost).</source>
        <translation>Buffer del socket di ricezione GigE; 0 lascia che Aravis lo dimensioni per un fotogramma intero (senza di esso la maggior parte dei pacchetti dei fotogrammi grandi va persa).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="178"/>
        <source>GigE stream packet size; 0 negotiates the largest packet that reaches the host.</source>
        <translation>Dimensione dei pacchetti dello stream GigE; 0 negozia il pacchetto più grande che raggiunge l&apos;host.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="179"/>
        <source>Global bundle adjustment of every keyframe and point when the run stops (0 = none).</source>
        <translation>Bundle adjustment globale di tutti i keyframe e punti quando l&apos;esecuzione termina (0 = nessuno).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="180"/>
        <source>Grab() returns the newest frame and skips older queued ones (views); off hands out every queued frame in order (recording).</source>
        <translation>Grab() restituisce il fotogramma più recente e salta quelli più vecchi in coda (viste); disattivato consegna ogni fotogramma in coda nell&apos;ordine (registrazione).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="181"/>
        <source>Ground RANSAC inlier distance at the sensor ...</source>
        <translation>Distanza degli inlier RANSAC del suolo al sensore ...</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="182"/>
        <source>Guided matching: best over second-best descriptor distance along the line.</source>
        <translation>Corrispondenza guidata: distanza del descrittore migliore sulla seconda migliore lungo la retta.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="183"/>
        <source>Guided matching: distance from the epipolar line a match may have.</source>
        <translation>Corrispondenza guidata: distanza ammessa di una corrispondenza dalla retta epipolare.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="184"/>
        <source>Half size of the search window.</source>
        <translation>Metà della dimensione della finestra di ricerca.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="185"/>
        <source>Half-size of the sub-pixel corner refinement at full resolution after detection on a reduced level; 0 = none.</source>
        <translation>Metà della dimensione del raffinamento sub-pixel dei corner a piena risoluzione dopo il rilevamento su un livello ridotto; 0 = nessuno.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="186"/>
        <source>Headless runs write the overlay of the track from the tap on as a PNG sequence (overlay/frame_NNNNNN.png, one per row of button.csv).</source>
        <translation>Le esecuzioni headless scrivono l&apos;overlay della traccia dal tocco in poi come sequenza PNG (overlay/frame_NNNNNN.png, una per riga di button.csv).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="187"/>
        <source>Heartbeat period; 0 = none.</source>
        <translation>Periodo dell&apos;heartbeat; 0 = nessuno.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="188"/>
        <source>Height of the occupancy image (published: 400), i.e. the forward range in cells.</source>
        <translation>Altezza dell&apos;immagine di occupazione (pubblicato: 400), cioè la portata in avanti in celle.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="350"/>
        <source>Region from the tap: outlines at two scales plus Hough circles, the one holding the tap nearest its centre (multiscale), or the published rule (the centroid nearest the tap within max_tap_distance_px).</source>
        <translation>Regione dal tocco: contorni a due scale più cerchi di Hough, quella che contiene il tocco più vicino al suo centro (multiscale), oppure la regola della pubblicazione (il baricentro più vicino al tocco entro max_tap_distance_px).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="377"/>
        <source>Score drawn in the maps: the published Table I rule or the Gaussian process.</source>
        <translation>Punteggio disegnato nelle mappe: la regola della Tabella I della pubblicazione o il processo gaussiano.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="395"/>
        <source>Start a new map when the reset rule fires (as published); off keeps stitching.</source>
        <translation>Iniziare una nuova mappa quando scatta la regola di reset (come pubblicato); disattivato continua a unire.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="400"/>
        <source>Step B6: cut the consensus set at gaps wider than this along the line and keep the longest piece, so that lines are contiguous walls (0 = as published: no cut).</source>
        <translation>Passo B6: tagliare l&apos;insieme di consenso in corrispondenza di interruzioni lungo la linea più larghe di così e mantenere il tratto più lungo, così le linee sono muri continui (0 = come pubblicato: nessun taglio).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="401"/>
        <source>Step B7: keep the hypothesis with the lowest summed error (as published) or mean error.</source>
        <translation>Passo B7: mantenere l&apos;ipotesi con l&apos;errore sommato più basso (come pubblicato) o con l&apos;errore medio più basso.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="402"/>
        <source>Step C: re-find the chosen line&apos;s dominant surface by sweeping its direction this far either way, then refit on it (0 = as published: the line of step B6 as is).</source>
        <translation>Passo C: ritrovare la superficie dominante della linea scelta ruotandone la direzione di tanto da entrambi i lati, poi rifare il fit su di essa (0 = come pubblicato: la linea del passo B6 così com&apos;è).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="470"/>
        <source>Wall-line extractor: the published multi-line RANSAC or split-and-merge.</source>
        <translation>Estrattore delle linee di muro: il RANSAC multi-linea della pubblicazione o split-and-merge.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="472"/>
        <source>Weigh them so once one position states a 1-sigma of at most this (the arm has come close; far positions then carry the newest scale&apos;s error times their distance); 0 = only with weighted (docs/button.md).</source>
        <translation>Pesa le posizioni così appena una posizione dichiara una sigma di al massimo questo valore (il braccio si è avvicinato; le posizioni lontane portano allora l&apos;errore della scala più recente per la loro distanza); 0 = solo con weighted (docs/button.md).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="477"/>
        <source>When even after that fewer tracks survive than this fraction of the share that usually survives (a slow average over the last frames; a sharp turn, or a turn at a low frame rate), the camera&apos;s rotation is searched by comparing the two images and the points are tracked again from where it puts them; the better attempt is kept. 0 = never.</source>
        <translation>Se anche dopo sopravvivono meno tracce di questa frazione della quota che di solito sopravvive (una media lenta sugli ultimi fotogrammi; una curva stretta o una curva a bassa frequenza di fotogrammi), la rotazione della telecamera viene cercata confrontando le due immagini e i punti vengono tracciati di nuovo da dove essa li pone; si tiene il tentativo migliore. 0 = mai.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="480"/>
        <source>Where person boxes come from: the dataset&apos;s ground truth, clusters of a person&apos;s size standing on the floor in the depth image (depth), OpenCV&apos;s HOG detector on the colour image, auto (ground truth when present, else depth) or none.</source>
        <translation>Da dove vengono i riquadri delle persone: la verità di riferimento del dataset, gruppi di punti delle dimensioni di una persona in piedi sul pavimento nell&apos;immagine di profondità (depth), il rilevatore HOG di OpenCV sull&apos;immagine a colori, auto (verità di riferimento se presente, altrimenti depth) o none.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="482"/>
        <source>Width of the occupancy image (published: 400); the robot sits at its bottom centre.</source>
        <translation>Larghezza dell&apos;immagine di occupazione (pubblicato: 400); il robot si trova al centro del bordo inferiore.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="507"/>
        <source>depth: a head is the highest point within this radius; people side by side are split at their heads.</source>
        <translation>depth: una testa è il punto più alto entro questo raggio; le persone affiancate vengono separate in corrispondenza delle teste.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="508"/>
        <source>depth: a person&apos;s footprint is at least this long.</source>
        <translation>depth: l&apos;impronta di una persona è lunga almeno tanto.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="509"/>
        <source>depth: a person&apos;s footprint is at most this long (walls are longer); wider clusters are split at their heads.</source>
        <translation>depth: l&apos;impronta di una persona è lunga al massimo tanto (le pareti sono più lunghe); i gruppi più larghi vengono separati in corrispondenza delle teste.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="510"/>
        <source>depth: a person&apos;s lowest point lies at most this high above the floor.</source>
        <translation>depth: il punto più basso di una persona si trova al massimo a questa altezza dal pavimento.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="511"/>
        <source>depth: a person&apos;s top lies at least this high above the floor.</source>
        <translation>depth: il punto più alto di una persona si trova almeno a questa altezza dal pavimento.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="513"/>
        <source>depth: a person&apos;s top lies at most this high (walls and pillars go higher).</source>
        <translation>depth: il punto più alto di una persona si trova al massimo a questa altezza (pareti e colonne salgono di più).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="514"/>
        <source>depth: between two heads the tops dip at least this much (neck, shoulders); the cut-off top of a wall is flat and is not split.</source>
        <translation>depth: tra due teste le altezze scendono almeno di tanto (collo, spalle); il bordo superiore tagliato di una parete è piatto e non viene separato.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="515"/>
        <source>depth: floor grid cell in which points are clustered.</source>
        <translation>depth: cella della griglia sul pavimento in cui i punti vengono raggruppati.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="516"/>
        <source>depth: points farther away are not looked at.</source>
        <translation>depth: i punti più lontani non vengono considerati.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="517"/>
        <source>depth: sampled points a person needs.</source>
        <translation>depth: punti campionati necessari per una persona.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="520"/>
        <source>depth: the depth image is sampled to about this many columns.</source>
        <translation>depth: l&apos;immagine di profondità viene campionata a circa questo numero di colonne.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="521"/>
        <source>depth: the shorter side of a person&apos;s footprint is at least this (legs, arms and the torso&apos;s curve); the end of a wall seen at the edge of view is one cell thick.</source>
        <translation>depth: il lato più corto dell&apos;impronta di una persona è almeno tanto (gambe, braccia e la curva del busto); l&apos;estremità di una parete vista al bordo dell&apos;immagine è spessa una cella.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="525"/>
        <source>epsilon_floor: a point within this height of the floor plane is floor (published value 3.5, read as 3.5 cm: generous so that no floor pixel is labelled occupied).</source>
        <translation>epsilon_floor: un punto entro questa altezza dal piano del pavimento è pavimento (valore pubblicato 3.5, letto come 3.5 cm: generoso, affinché nessun pixel del pavimento sia marcato come occupato).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="526"/>
        <source>err_max: inlier distance in occupancy cells (published: 5 pixels); metres = cells x mapping.occupancy.cell_size_m.</source>
        <translation>err_max: distanza degli inlier in celle di occupazione (pubblicato: 5 pixel); metri = celle x mapping.occupancy.cell_size_m.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="531"/>
        <source>grid: organized pixel-grid path (fast); pcl: the published voxel grid, outlier removal and k-d tree path.</source>
        <translation>grid: percorso sulla griglia di pixel organizzata (veloce); pcl: il percorso della pubblicazione con griglia di voxel, rimozione degli outlier e albero k-d.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="534"/>
        <source>j_max: hypotheses per line (published: 250); also caps the adaptive count.</source>
        <translation>j_max: ipotesi per linea (pubblicato: 250); limita anche il conteggio adattivo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="551"/>
        <source>rgbd, rgbd_icp: a colour frame whose brightness varies less than this is not tracked (a black or blank frame).</source>
        <translation>rgbd, rgbd_icp: un&apos;immagine a colori la cui luminosità varia meno di questo valore non viene tracciata (un fotogramma nero o vuoto).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="552"/>
        <source>rgbd, rgbd_icp: start the alignment from ORB features matched with PnP RANSAC when they agree (fast turns at low frame rates).</source>
        <translation>rgbd, rgbd_icp: avvia l&apos;allineamento dalle feature ORB associate con PnP RANSAC quando concordano (curve rapide a basso frame rate).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="553"/>
        <source>wheelchair: 5 m range, 3 cm step; icub: 1.75 m, 5 cm (the published humanoid); custom: range_cut_m and max_step_m.</source>
        <translation>wheelchair: portata 5 m, gradino 3 cm; icub: 1.75 m, 5 cm (l&apos;umanoide della pubblicazione); custom: range_cut_m e max_step_m.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="189"/>
        <source>Highest plausible camera height above the floor.</source>
        <translation>Altezza massima plausibile della telecamera sopra il pavimento.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="18"/>
        <source>... or turned this much.</source>
        <translation>... o ha ruotato di tanto.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="33"/>
        <source>A frame becomes the odometry&apos;s reference when it moved this far from the last one (0 with keyframe_rotation_deg 0: every frame).</source>
        <translation>Un fotogramma diventa il riferimento dell&apos;odometria quando si è spostato di tanto dall&apos;ultimo (0 con keyframe_rotation_deg 0: ogni fotogramma).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="37"/>
        <source>A frame this far after the last, or in a sequence whose recent frames are (median of five steps), is low-rate (keyframe-rate): the zero-motion try below and the urgent keyframes of mono.mapping apply.</source>
        <translation>Un fotogramma almeno così distante dal precedente, o in una sequenza i cui fotogrammi recenti lo sono (mediana di cinque passi), è a bassa frequenza (a fotogrammi chiave): valgono il tentativo a moto nullo qui sotto e i fotogrammi chiave urgenti di mono.mapping.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="40"/>
        <source>A frame with a smaller fraction of depth pixels in range is not tracked (the pose is held).</source>
        <translation>Un fotogramma con una frazione minore di pixel di profondità nell&apos;intervallo non viene tracciato (la posa viene mantenuta).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="51"/>
        <source>A new keyframe looks for a revisit among keyframes at least this many keyframes older.</source>
        <translation>Un nuovo fotogramma chiave cerca un ritorno tra i fotogrammi chiave più vecchi di almeno questo numero di fotogrammi chiave.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="53"/>
        <source>A ray of such an outline is on an edge when that edge is also this many times the median edge along the ray in its radius band (texture stands out less).</source>
        <translation>Un raggio di tale contorno è su un bordo quando quel bordo è anche questo numero di volte il bordo mediano lungo il raggio nella sua fascia di raggi (una trama risalta meno).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="62"/>
        <source>A tracked corner within this of where the plane&apos;s homography puts it is on the panel.</source>
        <translation>Un angolo tracciato entro questa distanza dal punto in cui lo pone l&apos;omografia del piano appartiene al pannello.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="73"/>
        <source>Always weigh each position by 1 / its own variance (plane fit, tracked centre and scale, growing with the distance): the near frames of the approach count most.</source>
        <translation>Pesa sempre ogni posizione con 1 / la propria varianza (adattamento del piano, centro tracciato e scala, crescente con la distanza): i fotogrammi vicini dell&apos;avvicinamento contano di più.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="79"/>
        <source>An odometry step faster than this (sensor time) is rejected.</source>
        <translation>Un passo di odometria più veloce di questo (tempo del sensore) viene scartato.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="80"/>
        <source>An odometry step turning faster than this (sensor time) is rejected.</source>
        <translation>Un passo di odometria che ruota più velocemente di questo (tempo del sensore) viene scartato.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="105"/>
        <source>Corners tracked around the button for the plane from the arm&apos;s motion.</source>
        <translation>Angoli tracciati attorno al pulsante per il piano dal movimento del braccio.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="113"/>
        <source>Depth readings farther than this are not used by the odometry.</source>
        <translation>Le letture di profondità più lontane di questo valore non vengono usate dall&apos;odometria.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="114"/>
        <source>Depth readings nearer than this are not used by the odometry.</source>
        <translation>Le letture di profondità più vicine di questo valore non vengono usate dall&apos;odometria.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="123"/>
        <source>Edge strength most rays of such an outline must reach.</source>
        <translation>Intensità del bordo che la maggior parte dei raggi di tale contorno deve raggiungere.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="155"/>
        <source>Fraction of the pixels the odometry uses per pyramid level.</source>
        <translation>Frazione dei pixel che l&apos;odometria usa per ogni livello della piramide.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="160"/>
        <source>Frames farther apart in sensor time are not aligned; tracking starts again from the held pose.</source>
        <translation>I fotogrammi più distanti di così nel tempo del sensore non vengono allineati; il tracciamento riparte dalla posa mantenuta.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="190"/>
        <source>Hough accumulator threshold.</source>
        <translation>Soglia dell&apos;accumulatore di Hough.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="191"/>
        <source>How long Grab() waits for a frame before reporting the device as unavailable.</source>
        <translation>Quanto a lungo Grab() attende un fotogramma prima di segnalare il dispositivo come non disponibile.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="192"/>
        <source>Huber loss threshold of bundle adjustment.</source>
        <translation>Soglia di Huber del bundle adjustment.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="193"/>
        <source>Huber threshold of the robust least squares.</source>
        <translation>Soglia di Huber dei minimi quadrati robusti.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="194"/>
        <source>Huber threshold of the robust pose optimisation.</source>
        <translation>Soglia di Huber dell&apos;ottimizzazione robusta della posa.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="195"/>
        <source>Huber threshold of the robust weight of an observation&apos;s reprojection error.</source>
        <translation>Soglia di Huber del peso robusto dell&apos;errore di riproiezione di un&apos;osservazione.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="196"/>
        <source>Huber threshold of the robust weight.</source>
        <translation>Soglia di Huber del peso robusto.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="197"/>
        <source>Huber threshold of the robust weights of the offset measurement.</source>
        <translation>Soglia di Huber dei pesi robusti della misura dell&apos;offset.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="198"/>
        <source>Hypotheses per line: fixed (max_iterations, seed) or adaptive log(1-p)/log(1-w^2) with w the best inlier ratio so far.</source>
        <translation>Ipotesi per linea: fisse (max_iterations, originale) o adattive log(1-p)/log(1-w^2), con w il miglior rapporto di inlier finora.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="199"/>
        <source>IPv4 address the target server binds; 127.0.0.1 keeps it on this machine.</source>
        <translation>Indirizzo IPv4 a cui si lega il server dei target; 127.0.0.1 lo mantiene su questa macchina.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="200"/>
        <source>Idle-time adjustment slices run at stop on a large map (bounds the stop time).</source>
        <translation>Porzioni della compensazione nei tempi morti eseguite all&apos;arresto su una mappa grande (limita il tempo di arresto).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="201"/>
        <source>Image buffers in the stream&apos;s pool; more ride out longer consumer stalls.</source>
        <translation>Buffer di immagine nel pool dello stream; di più permettono di superare blocchi più lunghi del consumatore.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="202"/>
        <source>Image pyramid levels of the odometry (coarse to fine; more handle larger steps).</source>
        <translation>Livelli della piramide di immagini dell&apos;odometria (dal grossolano al fine; più livelli gestiscono passi maggiori).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="203"/>
        <source>Inlier RMS above this: the plane is not sound.</source>
        <translation>RMS degli inlier sopra questo valore: il piano non è affidabile.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="204"/>
        <source>Inlier distance of the panel plane.</source>
        <translation>Distanza degli inlier del piano del pannello.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="205"/>
        <source>Inliers against the old map that confirm a revisit; the map since then is then bent onto the old one.</source>
        <translation>Inlier rispetto alla vecchia mappa che confermano un ritorno; la mappa costruita da allora viene poi piegata su quella vecchia.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="206"/>
        <source>Inliers needed to accept a relocalisation.</source>
        <translation>Inlier necessari per accettare una rilocalizzazione.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="207"/>
        <source>Input line used with hardware triggering, e.g. Line1.</source>
        <translation>Linea di ingresso usata con il trigger hardware, ad es. Line1.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="208"/>
        <source>Iterations of each local bundle adjustment (0 = none).</source>
        <translation>Iterazioni di ogni bundle adjustment locale (0 = nessuno).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="209"/>
        <source>Iterations of one idle-time adjustment slice (0 = no adjustment in idle time).</source>
        <translation>Iterazioni di una porzione della compensazione nei tempi morti (0 = nessuna compensazione nei tempi morti).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="210"/>
        <source>KLT iterations per level.</source>
        <translation>Iterazioni KLT per livello.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="211"/>
        <source>KLT pyramid levels above full resolution (shared with stereo matching).</source>
        <translation>Livelli della piramide KLT sopra la piena risoluzione (condivisi con il matching stereo).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="212"/>
        <source>KLT pyramid levels used around the disparity guess.</source>
        <translation>Livelli della piramide KLT usati attorno alla stima della disparità.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="213"/>
        <source>KLT stops when its update is smaller than this.</source>
        <translation>KLT si ferma quando il suo aggiornamento è minore di questo valore.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="214"/>
        <source>KLT window side (odd).</source>
        <translation>Lato della finestra KLT (dispari).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="215"/>
        <source>Keyframes whose poses one slice of the idle-time global adjustment optimises.</source>
        <translation>Fotogrammi chiave le cui pose sono ottimizzate da una porzione della compensazione globale nei tempi morti.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="217"/>
        <source>Larger 1-sigma position uncertainty: no target.</source>
        <translation>Incertezza di posizione a 1 sigma maggiore: nessun target.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="218"/>
        <source>Larger 1-sigma uncertainty of the approach direction (the panel normal): no target.</source>
        <translation>Incertezza a 1 sigma maggiore della direzione di avvicinamento (la normale del pannello): nessun target.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="219"/>
        <source>Larger change of velocity from the last accepted motion is rejected; 0 = no check.</source>
        <translation>Una variazione di velocità maggiore rispetto all&apos;ultimo moto accettato viene rifiutata; 0 = nessun controllo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="220"/>
        <source>Larger median offset of the face points from the panel plane is not applied.</source>
        <translation>Uno scostamento mediano maggiore dei punti della faccia dal piano del pannello non viene applicato.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="221"/>
        <source>Largest Hamming distance of a new-point match.</source>
        <translation>Massima distanza di Hamming di una corrispondenza di un nuovo punto.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="222"/>
        <source>Largest Hamming distance of a tracked ORB match.</source>
        <translation>Massima distanza di Hamming di una corrispondenza ORB tracciata.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="223"/>
        <source>Largest Hough circle radius.</source>
        <translation>Raggio massimo dei cerchi di Hough.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="224"/>
        <source>Largest angle between the floor normal and the camera&apos;s up axis (-y).</source>
        <translation>Angolo massimo tra la normale del pavimento e l&apos;asse verso l&apos;alto della telecamera (-y).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="225"/>
        <source>Largest button region as a fraction of the image area.</source>
        <translation>Regione del pulsante più grande, come frazione dell&apos;area dell&apos;immagine.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="226"/>
        <source>Largest depth/colour timestamp difference of an RGB-D pair from a device; frames without a partner are dropped and counted.</source>
        <translation>Massima differenza di timestamp tra profondità e colore di una coppia RGB-D da un dispositivo; i fotogrammi senza partner vengono scartati e contati.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="227"/>
        <source>Largest difference between the left and right timestamps of a pair; frames without a partner are dropped and counted.</source>
        <translation>Massima differenza tra i timestamp sinistro e destro di una coppia; i fotogrammi senza partner vengono scartati e contati.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="228"/>
        <source>Largest disparity searched and accepted.</source>
        <translation>Massima disparità cercata e accettata.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="229"/>
        <source>Largest size change (either way) since the last tracked frame at re-acquisition.</source>
        <translation>Massima variazione di dimensione (in entrambi i sensi) dall&apos;ultimo fotogramma tracciato alla riacquisizione.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="230"/>
        <source>Largest turn between two frames that search looks for.</source>
        <translation>Rotazione massima tra due fotogrammi che la ricerca considera.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="231"/>
        <source>Left-right check: the right point tracked back must land this close; 0 = no check.</source>
        <translation>Controllo sinistra-destra: il punto destro tracciato all&apos;indietro deve tornare così vicino; 0 = nessun controllo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="232"/>
        <source>Length of the first baseline in map units (PTAM: 0.1); metric scale comes later.</source>
        <translation>Lunghezza della prima baseline in unità della mappa (PTAM: 0.1); la scala metrica arriva dopo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="233"/>
        <source>Levenberg-Marquardt iterations per frame.</source>
        <translation>Iterazioni di Levenberg-Marquardt per fotogramma.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="234"/>
        <source>Lines vote with weight length / (1 + (rms / rms_scale_m)^2): scattered consensus sets (a wall merged with a door recess) count less.</source>
        <translation>Le linee votano con peso lunghezza / (1 + (rms / rms_scale_m)^2): gli insiemi di consenso sparsi (un muro fuso con il vano di una porta) contano meno.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="235"/>
        <source>Lines with fewer points are dropped.</source>
        <translation>Le linee con meno punti vengono scartate.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="236"/>
        <source>Log-odds added when a frame sees a cell free.</source>
        <translation>Log-odds aggiunti quando un fotogramma vede una cella libera.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="237"/>
        <source>Log-odds added when a frame sees a cell occupied.</source>
        <translation>Log-odds aggiunti quando un fotogramma vede una cella occupata.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="238"/>
        <source>Longer client lines are discarded; an over-long token line closes the connection.</source>
        <translation>Le righe dei client più lunghe vengono scartate; una riga di token troppo lunga chiude la connessione.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="239"/>
        <source>Longer image side at which contours are searched; larger frames are scaled down.</source>
        <translation>Lato maggiore dell&apos;immagine a cui si cercano i contorni; i fotogrammi più grandi vengono ridotti.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="240"/>
        <source>Longest over shortest side of the region&apos;s rotated box.</source>
        <translation>Rapporto tra il lato più lungo e quello più corto del riquadro ruotato della regione.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="241"/>
        <source>Looming needs the largest and smallest depth to differ by this fraction ...</source>
        <translation>L&apos;ingrandimento apparente (looming) richiede che la profondità massima e minima differiscano di questa frazione ...</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="242"/>
        <source>Lowe&apos;s ratio test: best over second-best descriptor distance must be below this.</source>
        <translation>Test del rapporto di Lowe: la migliore distanza dei descrittori divisa per la seconda migliore deve essere inferiore a questo valore.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="243"/>
        <source>Lower clamp of a cell&apos;s log-odds.</source>
        <translation>Limite inferiore dei log-odds di una cella.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="244"/>
        <source>Lowest plausible camera height above the floor.</source>
        <translation>Altezza minima plausibile della telecamera sopra il pavimento.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="245"/>
        <source>Map points projecting within this distance of the button centre are used.</source>
        <translation>Vengono usati i punti della mappa che si proiettano entro questa distanza dal centro del pulsante.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="246"/>
        <source>Map points within this many tracked button radii (the button&apos;s face) are used first; 0 = always use radius_px.</source>
        <translation>I punti della mappa entro questo numero di raggi del pulsante tracciato (la faccia del pulsante) vengono usati per primi; 0 = usare sempre radius_px.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="247"/>
        <source>Maps with up to this many keyframes get the full global adjustment at stop; larger ones get at most final_ba_max_slices slices of the idle-time adjustment.</source>
        <translation>Le mappe con al massimo questo numero di fotogrammi chiave ricevono all&apos;arresto la compensazione globale completa; quelle più grandi al massimo final_ba_max_slices porzioni della compensazione nei tempi morti.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="248"/>
        <source>Matches with a smaller disparity (too far to triangulate) are rejected.</source>
        <translation>Le corrispondenze con disparità minore (troppo lontane per la triangolazione) vengono rifiutate.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="249"/>
        <source>Matches with the first frame needed before initialisation is tried.</source>
        <translation>Corrispondenze con il primo fotogramma necessarie prima di tentare l&apos;inizializzazione.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="250"/>
        <source>Measured displacements shorter than this are dropped.</source>
        <translation>Gli spostamenti misurati più corti di così vengono scartati.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="251"/>
        <source>Measured motion for the metric scale: the arm&apos;s recorded poses (arm_poses.txt), the arm&apos;s poses streamed live to the button pipeline&apos;s arm-target server (arm_stream), ground-truth displacements, or none. auto: the recorded arm poses when arm_poses.txt is there; else, for the button pipeline while serving, the stream; else (mono-slam) ground truth.</source>
        <translation>Moto misurato per la scala metrica: le pose registrate del braccio (arm_poses.txt), le pose del braccio trasmesse in diretta al server dei target della pipeline del pulsante (arm_stream), gli spostamenti di ground truth, oppure nessuno. auto: le pose registrate del braccio se arm_poses.txt è presente; altrimenti, per la pipeline del pulsante mentre serve i target, lo stream; altrimenti (mono-slam) la ground truth.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="252"/>
        <source>Median angle between the rays of a match needed before trying (move sideways).</source>
        <translation>Angolo mediano tra i raggi di una corrispondenza necessario prima di tentare (spostati lateralmente).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="253"/>
        <source>Minimum distance between corners.</source>
        <translation>Distanza minima tra i corner.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="254"/>
        <source>Mirror images left-right, as OpenNI does by default for people facing the camera.</source>
        <translation>Specchiare le immagini sinistra-destra, come fa OpenNI per impostazione predefinita per le persone rivolte verso la telecamera.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="255"/>
        <source>Morphological closing that joins broken button outlines; 0 = none.</source>
        <translation>Chiusura morfologica che unisce i contorni interrotti dei pulsanti; 0 = nessuna.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="256"/>
        <source>Most recent keyframes whose poses local bundle adjustment optimises.</source>
        <translation>Keyframe più recenti le cui pose vengono ottimizzate dal bundle adjustment locale.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="258"/>
        <source>Niceness of the mapping thread (threaded mode, Linux); 10 lets tracking win a core it shares with mapping, but starves mapping on a loaded machine.</source>
        <translation>Valore nice del thread di mappatura (modalità a thread, Linux); 10 fa prevalere il tracking su un core condiviso con la mappatura, ma affama la mappatura su una macchina carica.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="259"/>
        <source>No pose is interpolated across a larger gap between two arm_pose messages.</source>
        <translation>Nessuna posa viene interpolata attraverso un intervallo maggiore tra due messaggi arm_pose.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="260"/>
        <source>No second reset within this many frames of the last one.</source>
        <translation>Nessun secondo reset entro questo numero di fotogrammi dall&apos;ultimo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="261"/>
        <source>No target until the online hand-eye check has seen the mount&apos;s translation (the arm must rotate between keyframes); without it that translation is taken on trust.</source>
        <translation>Nessun target finché il controllo mano-occhio online non ha visto la traslazione del montaggio (il braccio deve ruotare tra i keyframe); senza di esso quella traslazione è accettata sulla fiducia.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="262"/>
        <source>Noise of a camera displacement measured in the map (sigma_x of the ML estimator).</source>
        <translation>Rumore di uno spostamento della telecamera misurato nella mappa (sigma_x dello stimatore ML).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="263"/>
        <source>Noise of a displacement measured by the arm or robot (sigma_y).</source>
        <translation>Rumore di uno spostamento misurato dal braccio o dal robot (sigma_y).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="264"/>
        <source>ORB features per frame for the feature guess.</source>
        <translation>Feature ORB per fotogramma per la stima iniziale dalle feature.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="265"/>
        <source>ORB keypoints extracted per frame.</source>
        <translation>Keypoint ORB estratti per fotogramma.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="266"/>
        <source>Observations reprojecting worse than this are dropped from the window.</source>
        <translation>Le osservazioni che si riproiettano peggio di così vengono tolte dalla finestra.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="267"/>
        <source>Observations with a smaller disparity (no usable depth) are left out.</source>
        <translation>Le osservazioni con disparità minore (nessuna profondità utilizzabile) vengono escluse.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="268"/>
        <source>Occupied cells closer than this to the robot are ignored (robot body, noise).</source>
        <translation>Le celle occupate più vicine di così al robot vengono ignorate (corpo del robot, rumore).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="270"/>
        <source>Odometry correspondences farther apart than this in depth are rejected.</source>
        <translation>Le corrispondenze dell&apos;odometria più distanti di così in profondità vengono scartate.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="271"/>
        <source>Odometry iterations per pyramid level.</source>
        <translation>Iterazioni dell&apos;odometria per livello della piramide.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="272"/>
        <source>Of the re-acquiring matches, at least this many lie on the button itself.</source>
        <translation>Delle corrispondenze di riacquisizione, almeno questo numero si trova sul pulsante stesso.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="273"/>
        <source>Old keyframes this close to a new keyframe (relative to the mean depth) are tried as a revisit (0 = no revisit search).</source>
        <translation>I vecchi fotogrammi chiave così vicini a un nuovo fotogramma chiave (rispetto alla profondità media) vengono provati come ritorno (0 = nessuna ricerca di ritorni).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="274"/>
        <source>Older estimates are not sent.</source>
        <translation>Le stime più vecchie non vengono inviate.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="275"/>
        <source>Older frames&apos; normals fade with exp(-age / this) in the average (data time); 0 = this frame&apos;s normal only.</source>
        <translation>Le normali dei fotogrammi più vecchi si attenuano nella media con exp(-età / questo valore) (tempo dei dati); 0 = solo la normale di questo fotogramma.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="276"/>
        <source>On close: how long the stop lines may take to go out before the sockets close.</source>
        <translation>Alla chiusura: quanto tempo possono impiegare le righe di stop a partire prima che i socket si chiudano.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="277"/>
        <source>On the button: within this many radii of its centre.</source>
        <translation>Sul pulsante: entro questo numero di raggi dal suo centro.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="278"/>
        <source>Once a revisit links the map to old keyframes, those whose centre is this close to the camera (relative to the mean depth) join the recent ones in the map tracked against, so the place is tracked on its old points (0 = recent keyframes only).</source>
        <translation>Quando un ritorno collega la mappa a vecchi fotogrammi chiave, quelli il cui centro è così vicino alla camera (rispetto alla profondità media) si aggiungono ai recenti nella mappa usata per il tracciamento, così il luogo viene tracciato sui suoi vecchi punti (0 = solo fotogrammi chiave recenti).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="279"/>
        <source>Only frames tracked at least this confidently refresh the model.</source>
        <translation>Solo i fotogrammi tracciati almeno con questa sicurezza aggiornano il modello.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="280"/>
        <source>Otherwise: the camera&apos;s optical centre this far ahead of the odometry base.</source>
        <translation>Altrimenti: il centro ottico della telecamera tanto avanti rispetto alla base dell&apos;odometria.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="281"/>
        <source>Outlier removal: keep points with mean neighbour distance &lt;= mu + alpha sigma.</source>
        <translation>Rimozione degli outlier: mantenere i punti con distanza media dai vicini &lt;= mu + alpha sigma.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="282"/>
        <source>Pairs weigh |measured displacement|^-e in the ML estimate: 1 = the map&apos;s error grows with the distance travelled, 0 = every pair equally noisy.</source>
        <translation>Le coppie pesano |spostamento misurato|^-e nella stima ML: 1 = l&apos;errore della mappa cresce con la distanza percorsa, 0 = ogni coppia ugualmente rumorosa.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="283"/>
        <source>Pairs whose own ratio lies outside a factor of this from the estimate are dropped.</source>
        <translation>Le coppie il cui rapporto proprio si discosta dalla stima oltre un fattore pari a questo valore vengono scartate.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="284"/>
        <source>Pause between attempts to reopen a lost device.</source>
        <translation>Pausa tra i tentativi di riaprire un dispositivo perso.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="285"/>
        <source>Per-client queue length; a slow client loses its oldest messages (counted).</source>
        <translation>Lunghezza della coda per client; un client lento perde i suoi messaggi più vecchi (contati).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="286"/>
        <source>Per-segment plane RANSAC inlier distance.</source>
        <translation>Distanza degli inlier del RANSAC del piano per segmento.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="287"/>
        <source>Per-segment plane RANSAC iterations before the least-squares refit (0 = PCA only).</source>
        <translation>Iterazioni del RANSAC del piano per segmento prima del nuovo fit ai minimi quadrati (0 = solo PCA).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="288"/>
        <source>Pixel format as a FOURCC, e.g. MJPG for high resolutions over USB 2; empty keeps the camera&apos;s.</source>
        <translation>Formato pixel come FOURCC, ad es. MJPG per alte risoluzioni su USB 2; vuoto mantiene quello della telecamera.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="289"/>
        <source>Pixels in a person box within this depth of the box&apos;s median depth are the person.</source>
        <translation>I pixel in un riquadro di persona entro questa profondità dalla profondità mediana del riquadro sono la persona.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="290"/>
        <source>Place every kept position again with the newest metric scale (kept in map units).</source>
        <translation>Ricollocare ogni posizione mantenuta con la scala metrica più recente (mantenute in unità della mappa).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="291"/>
        <source>Plane RANSAC hypotheses of the panel normal.</source>
        <translation>Ipotesi RANSAC del piano per la normale del pannello.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="292"/>
        <source>Plane RANSAC hypotheses.</source>
        <translation>Ipotesi RANSAC del piano.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="293"/>
        <source>Plane inlier distance.</source>
        <translation>Distanza degli inlier del piano.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="294"/>
        <source>PnP inliers the feature guess needs to be used.</source>
        <translation>Inlier PnP necessari perché la stima dalle feature venga usata.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="295"/>
        <source>Point-to-plane distance of an inlier while fitting the floor.</source>
        <translation>Distanza punto-piano di un inlier durante il fit del pavimento.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="296"/>
        <source>Points are subsampled evenly to at most this many.</source>
        <translation>I punti vengono sottocampionati uniformemente fino a questo numero al massimo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="297"/>
        <source>Points each ground hypothesis is scored on.</source>
        <translation>Punti su cui viene valutata ogni ipotesi di suolo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="298"/>
        <source>Points farther than this are not used for the fit.</source>
        <translation>I punti più lontani di così non vengono usati per il fit.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="299"/>
        <source>Points found in fewer of the frames that should see them are culled.</source>
        <translation>I punti trovati in meno fotogrammi di quelli che dovrebbero vederli vengono eliminati.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="300"/>
        <source>Points higher than this above the floor (ceiling, lamps) are ignored.</source>
        <translation>I punti più alti di così sopra il pavimento (soffitto, lampade) vengono ignorati.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="301"/>
        <source>Points on the button&apos;s face that move the panel plane onto the face.</source>
        <translation>Punti sulla faccia del pulsante che spostano il piano del pannello sulla faccia.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="302"/>
        <source>Points whose neighbourhood bends more (surface variation, 0 = flat) get no normal and stay unsegmented: edges between surfaces.</source>
        <translation>I punti il cui intorno si curva di più (variazione di superficie, 0 = piatto) non ricevono normale e restano non segmentati: spigoli tra superfici.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="303"/>
        <source>Prior standard deviation of the offset around zero; smaller trusts the calibration longer.</source>
        <translation>Deviazione standard a priori dell&apos;offset attorno a zero; più piccola si fida più a lungo della calibrazione.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="304"/>
        <source>Probability above which a cell is occupied (map.yaml occupied_thresh).</source>
        <translation>Probabilità sopra la quale una cella è occupata (map.yaml occupied_thresh).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="305"/>
        <source>Probability below which a cell is free (map.yaml free_thresh).</source>
        <translation>Probabilità sotto la quale una cella è libera (map.yaml free_thresh).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="307"/>
        <source>Process every stride-th frame read, from the first (1 = all): a keyframe-rate sequence from a full-rate recording.</source>
        <translation>Elabora un fotogramma letto ogni stride, dal primo (1 = tutti): una sequenza a fotogrammi chiave da una registrazione a piena frequenza.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="308"/>
        <source>Publish the targets through the arm-target server (button.arm.*); --serve HOST:PORT.</source>
        <translation>Pubblicare i target tramite il server dei target del braccio (button.arm.*); --serve HOST:PORT.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="309"/>
        <source>Published eq. 13: depth-to-colour sensor offset along x.</source>
        <translation>Pubblicazione eq. 13: offset tra sensore di profondità e di colore lungo x.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="310"/>
        <source>Published eq. 13: depth-to-colour sensor offset along y.</source>
        <translation>Pubblicazione eq. 13: offset tra sensore di profondità e di colore lungo y.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="311"/>
        <source>Published eq. 6: expected inlier ratio w; iterations = log(1-p) / log(1-w^3).</source>
        <translation>Pubblicazione eq. 6: rapporto di inlier atteso w; iterazioni = log(1-p) / log(1-w^3).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="312"/>
        <source>Published eq. 6: wanted probability p of drawing one all-inlier sample.</source>
        <translation>Pubblicazione eq. 6: probabilità p desiderata di estrarre un campione di soli inlier.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="313"/>
        <source>Pyramid level Shi-Tomasi corners are detected on (0 = full resolution).</source>
        <translation>Livello della piramide su cui vengono rilevati i corner di Shi-Tomasi (0 = piena risoluzione).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="314"/>
        <source>Pyramid level of the row search for features without a disparity guess.</source>
        <translation>Livello della piramide della ricerca per righe per le feature senza stima della disparità.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="315"/>
        <source>Pyramid levels of the second tracking attempt (reaches about 2^levels further).</source>
        <translation>Livelli della piramide del secondo tentativo di tracking (arriva circa 2^levels più lontano).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="316"/>
        <source>Pyramid levels.</source>
        <translation>Livelli della piramide.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="317"/>
        <source>RANSAC inlier distance of the essential matrix and the homography.</source>
        <translation>Distanza degli inlier RANSAC della matrice essenziale e dell&apos;omografia.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="318"/>
        <source>RANSAC plane hypotheses (half of them sampled within one voxel).</source>
        <translation>Ipotesi RANSAC del piano (metà campionate entro un voxel).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="319"/>
        <source>RGB-D odometry: rgbd aligns brightness and depth (needs registered colour), icp aligns depth surfaces only (point-to-plane), rgbd_icp uses both.</source>
        <translation>Odometria RGB-D: rgbd allinea luminosità e profondità (richiede il colore registrato), icp allinea solo le superfici di profondità (punto-piano), rgbd_icp usa entrambi.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="322"/>
        <source>ROS bag: largest time between the two tf samples a pose at a frame&apos;s stamp is interpolated between; frames in a longer gap get no pose.</source>
        <translation>Bag ROS: tempo massimo tra i due campioni tf tra cui si interpola una posa all&apos;istante di un frame; i frame in un intervallo più lungo non hanno posa.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="325"/>
        <source>ROS bag: the arm&apos;s base tf frame; the pose of end_effector_frame in it is the arm&apos;s pose when there is no arm_poses.txt.</source>
        <translation>Bag ROS: il frame tf della base del braccio; la posa di end_effector_frame in esso è la posa del braccio quando manca arm_poses.txt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="326"/>
        <source>ROS bag: the arm&apos;s end-effector tf frame.</source>
        <translation>Bag ROS: il frame tf dell&apos;end effector del braccio.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="331"/>
        <source>ROS bag: the platform&apos;s tf frame whose pose in odom_frame is the odometry.</source>
        <translation>Bag ROS: il frame tf della piattaforma la cui posa in odom_frame è l&apos;odometria.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="334"/>
        <source>ROS bag: the tf frame of the odometry; without an odometry topic, the pose of base_frame in it on /tf is the platform&apos;s odometry.</source>
        <translation>Bag ROS: il frame tf dell&apos;odometria; senza un topic di odometria, la posa di base_frame in esso su /tf è l&apos;odometria della piattaforma.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="335"/>
        <source>Random generator seed.</source>
        <translation>Seme del generatore casuale.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="336"/>
        <source>Random generator seed; each scan starts from it, so results are reproducible.</source>
        <translation>Seme del generatore casuale; ogni scansione parte da esso, così i risultati sono riproducibili.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="337"/>
        <source>Random seed of the plane RANSAC.</source>
        <translation>Seme casuale del RANSAC del piano.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="338"/>
        <source>Rate at which a replayed recording delivers frames; 0 follows its timestamps.</source>
        <translation>Frequenza con cui una registrazione riprodotta fornisce i fotogrammi; 0 segue i suoi timestamp.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="339"/>
        <source>Ray angle a first map point needs.</source>
        <translation>Angolo tra i raggi necessario a un primo punto della mappa.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="340"/>
        <source>Ray angle a new map point needs.</source>
        <translation>Angolo tra i raggi necessario a un nuovo punto della mappa.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="341"/>
        <source>Rays stop at this range; 0 = at the occupancy image border.</source>
        <translation>I raggi si fermano a questa portata; 0 = al bordo dell&apos;immagine di occupazione.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="342"/>
        <source>Re-acquisition is refused when the other matches support a second similarity with this fraction of the inliers (another button of a repeated panel).</source>
        <translation>La riacquisizione viene rifiutata quando le altre corrispondenze sostengono una seconda similitudine con questa frazione degli inlier (un altro pulsante di un pannello con elementi ripetuti).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="343"/>
        <source>Recent keyframes a new keyframe triangulates new points with.</source>
        <translation>Keyframe recenti con cui un nuovo keyframe triangola nuovi punti.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="344"/>
        <source>Rectify even when the rig says its images are rectified.</source>
        <translation>Rettificare anche quando il rig dichiara che le sue immagini sono già rettificate.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="345"/>
        <source>Refine every tracked position against the track&apos;s anchor (where it was first seen), its patch warped by the motion since, so tracks do not drift frame by frame.</source>
        <translation>Raffinare ogni posizione tracciata rispetto all&apos;ancoraggio della traccia (dove è stata vista per la prima volta), con la sua patch deformata dal moto da allora, così le tracce non derivano fotogramma dopo fotogramma.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="346"/>
        <source>Refine the 3D points with the motion (two-frame bundle adjustment); removes the depth bias of triangulation.</source>
        <translation>Raffinare i punti 3D con il moto (bundle adjustment a due fotogrammi); elimina il bias di profondità della triangolazione.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="347"/>
        <source>Refine the last frames&apos; poses and their tracks&apos; points together on the stereo reprojection error (sliding-window bundle adjustment), so per-frame errors do not add up.</source>
        <translation>Raffinare insieme le pose degli ultimi fotogrammi e i punti delle loro tracce sull&apos;errore di riproiezione stereo (bundle adjustment a finestra scorrevole), così gli errori dei singoli fotogrammi non si sommano.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="348"/>
        <source>Refined RMS reprojection error above this is rejected.</source>
        <translation>Un errore di riproiezione RMS raffinato superiore a questo valore viene rifiutato.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="349"/>
        <source>Refinement rounds: refine, re-select inliers by the reprojection threshold, refine.</source>
        <translation>Cicli di raffinamento: raffinare, riselezionare gli inlier con la soglia di riproiezione, raffinare.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="351"/>
        <source>Region growing: largest RGB-N colour distance between neighbours (255 (n+1)/2).</source>
        <translation>Crescita per regioni: massima distanza di colore RGB-N tra vicini (255 (n+1)/2).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="352"/>
        <source>Region-of-interest height; 0 keeps the camera&apos;s.</source>
        <translation>Altezza della regione di interesse; 0 mantiene quella della telecamera.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="353"/>
        <source>Region-of-interest width; 0 keeps the camera&apos;s.</source>
        <translation>Larghezza della regione di interesse; 0 mantiene quella della telecamera.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="354"/>
        <source>Register depth to the colour camera in the device when it supports it, so that depth and colour pixels correspond.</source>
        <translation>Registrare la profondità sulla telecamera a colori nel dispositivo, se lo supporta, così i pixel di profondità e di colore si corrispondono.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="355"/>
        <source>Reprojection error a first map point may have in either view.</source>
        <translation>Errore di riproiezione ammesso per un primo punto della mappa in ciascuna vista.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="356"/>
        <source>Reprojection error a new map point may have in either keyframe.</source>
        <translation>Errore di riproiezione ammesso per un nuovo punto della mappa in ciascun keyframe.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="357"/>
        <source>Requested frame rate; 0 keeps the camera&apos;s.</source>
        <translation>Frequenza dei fotogrammi richiesta; 0 mantiene quella della telecamera.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="358"/>
        <source>Requested image height; 0 keeps the camera&apos;s.</source>
        <translation>Altezza dell&apos;immagine richiesta; 0 mantiene quella della telecamera.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="359"/>
        <source>Requested image width; 0 keeps the camera&apos;s. V4L2 picks the nearest mode.</source>
        <translation>Larghezza dell&apos;immagine richiesta; 0 mantiene quella della telecamera. V4L2 sceglie la modalità più vicina.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="360"/>
        <source>Reset rule: a pose-source move larger than this between two frames resets the reference.</source>
        <translation>Regola di reset: uno spostamento della sorgente di pose maggiore di così tra due fotogrammi azzera il riferimento.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="361"/>
        <source>Reset rule: a pose-source turn larger than this between two frames resets the reference.</source>
        <translation>Regola di reset: una rotazione della sorgente di pose maggiore di così tra due fotogrammi azzera il riferimento.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="362"/>
        <source>Reset rule: this many consecutive frames whose walls disagree by more than max_correction_deg reset the reference.</source>
        <translation>Regola di reset: questo numero di fotogrammi consecutivi i cui muri discordano di più di max_correction_deg azzera il riferimento.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="363"/>
        <source>Residual beyond which a match is an outlier.</source>
        <translation>Residuo oltre il quale una corrispondenza è un outlier.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="364"/>
        <source>Reweighted Gauss-Newton iterations.</source>
        <translation>Iterazioni di Gauss-Newton ripesate.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="365"/>
        <source>Rigid samples tried at least before adaptive termination may stop.</source>
        <translation>Campioni rigidi provati almeno prima che la terminazione adattiva possa fermarsi.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="366"/>
        <source>Roughness triangulation in plane coordinates: the cells&apos; grid or 2D Delaunay.</source>
        <translation>Triangolazione della rugosità in coordinate del piano: la griglia delle celle o Delaunay 2D.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="367"/>
        <source>Roughness uses the segment&apos;s points within this range (all when none is).</source>
        <translation>La rugosità usa i punti del segmento entro questa portata (tutti se non ce n&apos;è nessuno).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="368"/>
        <source>Roughness: points are averaged in plane cells of this size, then triangulated.</source>
        <translation>Rugosità: i punti vengono mediati in celle del piano di questa dimensione, poi triangolati.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="369"/>
        <source>Row search: mean absolute difference above this means no match.</source>
        <translation>Ricerca per righe: una differenza assoluta media superiore a questo valore significa nessuna corrispondenza.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="370"/>
        <source>Run mapping on its own thread (live); off = inline after each keyframe, deterministic.</source>
        <translation>Eseguire la mappatura in un thread proprio (dal vivo); disattivato = in linea dopo ogni keyframe, deterministico.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="371"/>
        <source>SAD window side of the row search, at its level.</source>
        <translation>Lato della finestra SAD della ricerca per righe, al suo livello.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="372"/>
        <source>SIFT contrast threshold.</source>
        <translation>Soglia di contrasto SIFT.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="373"/>
        <source>SIFT contrast threshold; lower finds more keypoints on plain buttons.</source>
        <translation>Soglia di contrasto SIFT; più bassa trova più keypoint su pulsanti uniformi.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="374"/>
        <source>SIFT keypoints up to this far outside the region belong to the button model.</source>
        <translation>I keypoint SIFT fino a questa distanza fuori dalla regione appartengono al modello del pulsante.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="375"/>
        <source>SIFT on a larger region runs on its crop scaled down so the region&apos;s radius is this (fewer, coarser features, much faster on close-up photos); 0 = never.</source>
        <translation>Su una regione più grande SIFT lavora sul ritaglio ridotto in modo che il raggio della regione sia questo valore (meno caratteristiche, più grossolane, molto più veloce su foto ravvicinate); 0 = mai.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="376"/>
        <source>Scale between pyramid levels.</source>
        <translation>Fattore di scala tra i livelli della piramide.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="378"/>
        <source>Scored cloud written per frame.</source>
        <translation>Nuvola valutata scritta per fotogramma.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="379"/>
        <source>Search window around a map point&apos;s predicted position.</source>
        <translation>Finestra di ricerca attorno alla posizione prevista di un punto della mappa.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="380"/>
        <source>Serve the targets to the arm over TCP (button.arm.bind_address, port, token); 127.0.0.1:5757 by default. The same as button.run.serve. Switching it keeps the run (map, button, STOP); switching it off sends the arm a stop line.</source>
        <translation>Servire i target al braccio via TCP (button.arm.bind_address, port, token); 127.0.0.1:5757 per impostazione predefinita. Equivale a button.run.serve. Cambiarlo mantiene l&apos;esecuzione (mappa, pulsante, STOP); disattivarlo invia al braccio una riga di stop.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="381"/>
        <source>Shi-Tomasi gradient window.</source>
        <translation>Finestra del gradiente di Shi-Tomasi.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="382"/>
        <source>Shi-Tomasi: smallest minimum eigenvalue of a corner (cv::cornerMinEigenVal units).</source>
        <translation>Shi-Tomasi: minimo autovalore minimo di un corner (unità di cv::cornerMinEigenVal).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="383"/>
        <source>Shorter lines are dropped.</source>
        <translation>Le linee più corte vengono scartate.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="384"/>
        <source>Side of the aligned patch (odd).</source>
        <translation>Lato della patch allineata (dispari).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="385"/>
        <source>Side of the detection grid&apos;s buckets; each holds at most its share of max_features.</source>
        <translation>Lato delle celle (bucket) della griglia di rilevamento; ognuna contiene al massimo la sua quota di max_features.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="386"/>
        <source>Similarity RANSAC inlier distance.</source>
        <translation>Distanza degli inlier del RANSAC di similitudine.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="387"/>
        <source>Size change since the last refresh that triggers the next.</source>
        <translation>Variazione di dimensione dall&apos;ultimo aggiornamento che fa scattare il successivo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="388"/>
        <source>Smaller estimates are not applied: within the spread the estimate shows on a rig without offset (the simulator: +-0.03 px).</source>
        <translation>Le stime più piccole non vengono applicate: rientrano nella dispersione che la stima mostra su un rig senza offset (il simulatore: +-0.03 px).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="389"/>
        <source>Smaller regions stay unsegmented and unscored.</source>
        <translation>Le regioni più piccole restano non segmentate e non valutate.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="390"/>
        <source>Smallest 1-sigma stated for one frame&apos;s normal (the map points&apos; errors are correlated, so the fit&apos;s own figure is optimistic).</source>
        <translation>Minimo 1 sigma dichiarato per la normale di un fotogramma (gli errori dei punti della mappa sono correlati, quindi il valore proprio del fit è ottimistico).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="391"/>
        <source>Smallest Hough circle radius.</source>
        <translation>Raggio minimo dei cerchi di Hough.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="392"/>
        <source>Smallest approach_sigma_deg a target states: the average of frames that share one map does not beat the map&apos;s own bias (on the simulated approach with the SLAM&apos;s map, up to 4.3 deg against per-frame fits of 0.5 deg).</source>
        <translation>Minimo approach_sigma_deg dichiarato da un target: la media di fotogrammi che condividono una mappa non supera il bias della mappa stessa (nell&apos;avvicinamento simulato con la mappa dello SLAM, fino a 4.3 deg contro fit per fotogramma di 0.5 deg).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="393"/>
        <source>Smallest button region.</source>
        <translation>Regione del pulsante più piccola.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="394"/>
        <source>Split a piece while a point lies farther than this from its chord; merge pieces that fit one line within it (cells, like RANSAC&apos;s err_max).</source>
        <translation>Dividere un tratto finché un punto si trova più lontano di così dalla sua corda; unire i tratti che stanno su una linea entro questo valore (celle, come err_max di RANSAC).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="396"/>
        <source>Start again at the end (timestamps keep increasing) instead of ending the stream.</source>
        <translation>Ricominciare alla fine (i timestamp continuano a crescere) invece di terminare lo stream.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="397"/>
        <source>Start each alignment from the last motion scaled by the time between frames.</source>
        <translation>Avvia ogni allineamento dall&apos;ultimo movimento, scalato per il tempo tra i fotogrammi.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="398"/>
        <source>Step B2: ... and at most this far apart (no lines across the room).</source>
        <translation>Passo B2: ... e al massimo così distanti (nessuna linea attraverso la stanza).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="399"/>
        <source>Step B2: the two sampled points must be at least this far apart (no short lines).</source>
        <translation>Passo B2: i due punti campionati devono distare almeno tanto (nessuna linea corta).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="403"/>
        <source>Stereo calibration (OpenCV stereo YAML as `sightline-cli calibrate stereo` writes) used instead of the source&apos;s; needed for live pairs (aravis://L,R) opened without one.</source>
        <translation>Calibrazione stereo (YAML stereo di OpenCV come lo scrive `sightline-cli calibrate stereo`) usata al posto di quella della sorgente; necessaria per coppie dal vivo (aravis://L,R) aperte senza.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="404"/>
        <source>Stereo calibration of the pair (OpenCV stereo YAML: M1 D1 M2 D2 R T, image_width/height, as `sightline-cli calibrate stereo` writes); the stereo odometry needs it. Also as aravis://LEFT,RIGHT?calibration_file=FILE.</source>
        <translation>Calibrazione stereo della coppia (YAML stereo di OpenCV: M1 D1 M2 D2 R T, image_width/height, come lo scrive `sightline-cli calibrate stereo`); l&apos;odometria stereo ne ha bisogno. Anche come aravis://LEFT,RIGHT?calibration_file=FILE.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="405"/>
        <source>Stop when the update is smaller (radians or metres).</source>
        <translation>Fermarsi quando l&apos;aggiornamento è minore (radianti o metri).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="406"/>
        <source>Stream colour.</source>
        <translation>Trasmettere il colore.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="407"/>
        <source>Stream depth.</source>
        <translation>Trasmettere la profondità.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="408"/>
        <source>Stream height for depth and colour; 0 keeps the device&apos;s default mode.</source>
        <translation>Altezza dello stream per profondità e colore; 0 mantiene la modalità predefinita del dispositivo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="409"/>
        <source>Stream rate; 0 keeps the device&apos;s default mode.</source>
        <translation>Frequenza dello stream; 0 mantiene la modalità predefinita del dispositivo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="410"/>
        <source>Stream width for depth and colour; 0 keeps the device&apos;s default mode.</source>
        <translation>Larghezza dello stream per profondità e colore; 0 mantiene la modalità predefinita del dispositivo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="411"/>
        <source>Synchronous mode: frames without a new keyframe between two idle-time slices.</source>
        <translation>Modalità sincrona: fotogrammi senza un nuovo fotogramma chiave tra due porzioni nei tempi morti.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="412"/>
        <source>TCP port of the target server; 0 = any free port.</source>
        <translation>Porta TCP del server dei target; 0 = una porta libera qualsiasi.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="413"/>
        <source>Take the approach from the plane that the arm&apos;s own motion shows (corners around the button tracked from an anchor frame, the views&apos; poses from the arm) rather than from the SLAM&apos;s map, whenever that plane is found.</source>
        <translation>Prendere la direzione di avvicinamento dal piano che mostra il movimento stesso del braccio (angoli attorno al pulsante tracciati da un fotogramma di ancoraggio, le pose delle viste dal braccio) invece che dalla mappa dello SLAM, quando quel piano è trovato.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="414"/>
        <source>Take the camera&apos;s offset ahead of the odometry base from the recording&apos;s scene.yaml (simulator) when present.</source>
        <translation>Prendere lo scostamento della telecamera davanti alla base dell&apos;odometria dal scene.yaml della registrazione (simulatore), se presente.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="415"/>
        <source>The SIFT margin grows to this many region radii when that is larger.</source>
        <translation>Il margine SIFT cresce fino a questo numero di raggi della regione, se è maggiore.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="416"/>
        <source>The appearance model&apos;s probability that the region at the tap is a button and not a printed label or sign beside one; below it: no button here. 0 = off.</source>
        <translation>La probabilità, secondo il modello di aspetto, che la regione toccata sia un pulsante e non un&apos;etichetta o un cartello stampato accanto; sotto questo valore: nessun pulsante qui. 0 = disattivato.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="417"/>
        <source>The approach direction is the normal of a plane through the map points within this distance of the located button (the panel around it).</source>
        <translation>La direzione di avvicinamento è la normale di un piano passante per i punti della mappa entro questa distanza dal pulsante localizzato (il pannello attorno).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="418"/>
        <source>The arm&apos;s and the SLAM&apos;s displacement directions disagree by more than this (online hand-eye check; a wrong mount rotation): no target.</source>
        <translation>Le direzioni di spostamento del braccio e dello SLAM discordano di più di così (controllo mano-occhio online; una rotazione di montaggio errata): nessun target.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="419"/>
        <source>The arm&apos;s clock minus the camera&apos;s (configured; arm stamp = frame stamp + this).</source>
        <translation>L&apos;orologio del braccio meno quello della telecamera (configurato; timestamp del braccio = timestamp del fotogramma + questo valore).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="420"/>
        <source>The arm&apos;s motion since the anchor frame, as an angle seen from the panel, before its plane is used.</source>
        <translation>Il movimento del braccio dal fotogramma di ancoraggio, come angolo visto dal pannello, prima che il suo piano sia usato.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="421"/>
        <source>The current frame becomes the keyframe when fewer keyframe tracks agree with the motion.</source>
        <translation>Il fotogramma corrente diventa il keyframe quando meno tracce del keyframe concordano con il moto.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="422"/>
        <source>The current frame becomes the keyframe when fewer of the keyframe&apos;s tracks survive.</source>
        <translation>Il fotogramma corrente diventa il keyframe quando sopravvivono meno tracce del keyframe.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="423"/>
        <source>The depth colour map spans zero to this range.</source>
        <translation>La mappa di colori della profondità va da zero a questa distanza.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="424"/>
        <source>The estimated offset is clamped to +- this.</source>
        <translation>L&apos;offset stimato è limitato a +- questo valore.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="425"/>
        <source>The face&apos;s offset from the panel plane is the median of its points within this many robust sigmas of that median, until the set settles (points triangulated with little parallax leave a one-sided tail); 0 = the median of all.</source>
        <translation>Lo scostamento della faccia dal piano del pannello è la mediana dei suoi punti entro questo numero di sigma robuste da quella mediana, finché l&apos;insieme si stabilizza (i punti triangolati con poca parallasse lasciano una coda da un solo lato); 0 = la mediana di tutti.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="426"/>
        <source>The floor is the lowest plane: at most this fraction of points may lie clearly below it (rejects table tops).</source>
        <translation>Il pavimento è il piano più basso: al massimo questa frazione dei punti può trovarsi chiaramente al di sotto (scarta i piani dei tavoli).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="427"/>
        <source>The floor must hold at least this fraction of the valid points.</source>
        <translation>Il pavimento deve contenere almeno questa frazione dei punti validi.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="428"/>
        <source>The gate grows to this many predicted button radii when that is larger.</source>
        <translation>Il gate cresce fino a questo numero di raggi previsti del pulsante, se è maggiore.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="429"/>
        <source>The gate widens by this per metre driven since the last correction (expected heading drift of the pose source).</source>
        <translation>Il gate si allarga di questo valore per metro percorso dall&apos;ultima correzione (deriva di direzione attesa della sorgente di pose).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="430"/>
        <source>The homography is chosen when its share of the inliers exceeds this.</source>
        <translation>L&apos;omografia viene scelta quando la sua quota di inlier supera questo valore.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="431"/>
        <source>The map grows by at least this much each time it must.</source>
        <translation>La mappa cresce almeno di tanto ogni volta che deve.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="432"/>
        <source>The maximum-likelihood estimate is reported from this many pairs on.</source>
        <translation>La stima di massima verosimiglianza viene riportata a partire da questo numero di coppie.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="433"/>
        <source>The metric scale counts as converged with this many displacement pairs in the ML estimate at least ...</source>
        <translation>La scala metrica è considerata convergente con almeno questo numero di coppie di spostamenti nella stima ML ...</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="434"/>
        <source>The model never grows beyond this many keypoints.</source>
        <translation>Il modello non cresce mai oltre questo numero di keypoint.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="435"/>
        <source>The offset is measured between an anchor frame and the first later frame whose translation from it reaches this fraction of the common tracks&apos; median depth: with less parallax, tracking errors dominate the measurement.</source>
        <translation>L&apos;offset viene misurato tra un fotogramma di ancoraggio e il primo fotogramma successivo la cui traslazione da esso raggiunge questa frazione della profondità mediana delle tracce comuni: con meno parallasse gli errori di tracking dominano la misura.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="436"/>
        <source>The online hand-eye check compares keyframes at least this far apart (measured): the directions of shorter displacements drown in the noise.</source>
        <translation>Il controllo mano-occhio online confronta keyframe distanti almeno tanto (misurato): le direzioni degli spostamenti più brevi si perdono nel rumore.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="437"/>
        <source>The online hand-eye check sees the mount&apos;s translation only when the arm rotates at least this much between two keyframes.</source>
        <translation>Il controllo mano-occhio online vede la traslazione del montaggio solo quando il braccio ruota almeno di tanto tra due keyframe.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="438"/>
        <source>The operator&apos;s tap is refused when the frame it was made on is older than this (data time) by the time the pipeline takes it.</source>
        <translation>Il tocco dell&apos;operatore viene rifiutato quando il fotogramma su cui è stato fatto è più vecchio di così (tempo dei dati) nel momento in cui la pipeline lo prende.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="439"/>
        <source>The operator&apos;s tap: X,Y in pixels, optionally @FRAME (frame index, default 0); confirmed at once. sightline-cli run button --tap X,Y[@FRAME] sets it.</source>
        <translation>Il tocco dell&apos;operatore: X,Y in pixel, facoltativamente @FRAME (indice del fotogramma, predefinito 0); confermato subito. sightline-cli run button --tap X,Y[@FRAME] lo imposta.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="440"/>
        <source>The panel plane passes at most this far from the located button: of the surfaces around it (a side wall, a door frame) only the one holding the button gives the push direction.</source>
        <translation>Il piano del pannello passa al massimo a questa distanza dal pulsante localizzato: delle superfici intorno (una parete laterale, uno stipite) solo quella che porta il pulsante dà la direzione di pressione.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="441"/>
        <source>The position&apos;s panel plane is fitted robustly to the map points within this many tracked button radii and moved onto the face by its points&apos; median offset; 0 = the plane within radius_px (or the face&apos;s own).</source>
        <translation>Il piano della posizione è stimato in modo robusto sui punti della mappa entro questo numero di raggi del pulsante tracciato e spostato sulla faccia del pulsante della mediana degli scarti dei suoi punti; 0 = il piano entro radius_px (o quello della faccia stessa).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="442"/>
        <source>The size from the tap&apos;s own keypoints alone (not the refreshed ones, whose scale drifts; the looming in button.triangulate.*) needs this many consistent matches.</source>
        <translation>La dimensione dai soli punti chiave del tocco (non da quelli aggiornati, la cui scala deriva; il looming in button.triangulate.*) richiede almeno tante corrispondenze coerenti.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="443"/>
        <source>The size from the tap&apos;s own keypoints only (ButtonTrack::anchor_scale: the keypoints the tracker&apos;s refresh adds carry each refresh&apos;s scale error on); false: the tracked radius.</source>
        <translation>La dimensione dai soli punti chiave del tocco (ButtonTrack::anchor_scale: i punti chiave aggiunti dall&apos;aggiornamento del tracker portano avanti l&apos;errore di scala di ogni aggiornamento); false: il raggio tracciato.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="444"/>
        <source>The target is the per-axis median of this many recent base-frame positions (sound plane, converged scale); 0 = every one since the tap, 1 = no fusion.</source>
        <translation>Il target è la mediana per asse di questo numero di posizioni recenti nel sistema della base (piano affidabile, scala convergente); 0 = tutte dal tocco, 1 = nessuna fusione.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="445"/>
        <source>The tracking gate never exceeds this: larger corrections are not applied.</source>
        <translation>Il gate di tracking non supera mai questo valore: le correzioni maggiori non vengono applicate.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="446"/>
        <source>The window grows to this many predicted button radii when that is larger.</source>
        <translation>La finestra cresce fino a questo numero di raggi previsti del pulsante, se è maggiore.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="447"/>
        <source>Tolerance of accuracy.map_iou: a map cell within this many cells of a true wall counts as on it.</source>
        <translation>Tolleranza di accuracy.map_iou: una cella della mappa entro questo numero di celle da un muro vero conta come sopra di esso.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="448"/>
        <source>Top-view grid cell.</source>
        <translation>Cella della griglia della vista dall&apos;alto.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="449"/>
        <source>Track points drawn behind the button on the overlay.</source>
        <translation>Punti della traccia disegnati dietro il pulsante nell&apos;overlay.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="450"/>
        <source>Tracking gate right after a correction: lines farther than this from the expected direction neither vote nor correct.</source>
        <translation>Gate di tracking subito dopo una correzione: le linee più lontane di così dalla direzione attesa non votano né correggono.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="451"/>
        <source>Tracking is lost when fewer than this share of the map points predicted in the image are found (PTAM&apos;s test against a wrong pose after a jump).</source>
        <translation>Il tracking è perso quando si trova meno di questa quota dei punti della mappa previsti nell&apos;immagine (il test di PTAM contro una posa errata dopo un salto).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="452"/>
        <source>Tracking quality is good from this many inliers.</source>
        <translation>La qualità del tracking è buona da questo numero di inlier.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="453"/>
        <source>Tracking quality is poor from this many inliers; fewer is lost.</source>
        <translation>La qualità del tracking è scarsa da questo numero di inlier; con meno è perso.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="454"/>
        <source>Triangulated points needed to accept the initialisation.</source>
        <translation>Punti triangolati necessari per accettare l&apos;inizializzazione.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="455"/>
        <source>UMBRAL1: change of a pairwise distance a rigid sample may show, before depth uncertainty is added.</source>
        <translation>UMBRAL1: variazione di una distanza tra coppie di punti che un campione rigido può mostrare, prima di aggiungere l&apos;incertezza di profondità.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="456"/>
        <source>UMBRAL2: rigidity rejections after which RANSAC fails (the last motion is kept).</source>
        <translation>UMBRAL2: rifiuti per rigidità dopo i quali RANSAC fallisce (si mantiene l&apos;ultimo moto).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="457"/>
        <source>UMBRAL3: reprojection error (RMS of both images) of an inlier.</source>
        <translation>UMBRAL3: errore di riproiezione (RMS di entrambe le immagini) di un inlier.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="458"/>
        <source>UMBRAL4: stop sampling once this fraction of the points is inlier.</source>
        <translation>UMBRAL4: smettere di campionare non appena questa frazione dei punti è inlier.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="459"/>
        <source>UMBRAL5: rigid samples tried before the best inlier set is taken.</source>
        <translation>UMBRAL5: campioni rigidi provati prima di adottare il miglior insieme di inlier.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="460"/>
        <source>Up-facing planes searched; the lowest large one is the ground.</source>
        <translation>Piani rivolti verso l&apos;alto cercati; il più basso tra quelli grandi è il suolo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="461"/>
        <source>Upper clamp of a cell&apos;s log-odds.</source>
        <translation>Limite superiore dei log-odds di una cella.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="462"/>
        <source>Use every n-th depth pixel for the 3D cloud; 1 shows all (slower).</source>
        <translation>Usare un pixel di profondità ogni n per la nuvola 3D; 1 li mostra tutti (più lento).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="463"/>
        <source>Use the apparent size (looming: the radius grows as 1 / depth while the arm moves forward by a measured distance) besides the rays.</source>
        <translation>Usa, oltre ai raggi, la dimensione apparente (looming: il raggio cresce come 1 / profondità mentre il braccio avanza di una distanza misurata).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="464"/>
        <source>Viewing ray closer to parallel with the plane than this |cos|: no position.</source>
        <translation>Raggio visivo più vicino al parallelo con il piano di questo |cos|: nessuna posizione.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="465"/>
        <source>Voting lines within this of their length-weighted median are averaged; others (a wall merged with a recessed door, a box) are dropped.</source>
        <translation>Le linee votanti entro questo valore dalla loro mediana pesata per lunghezza vengono mediate; le altre (un muro fuso con una porta arretrata, una scatola) vengono scartate.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="466"/>
        <source>Voting wall length a frame needs before it may set the reference direction.</source>
        <translation>Lunghezza di muri votanti di cui un fotogramma ha bisogno prima di poter fissare la direzione di riferimento.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="467"/>
        <source>Voxel size for locally sampled hypotheses (finds a floor that covers little of the view).</source>
        <translation>Dimensione del voxel per le ipotesi campionate localmente (trova un pavimento che copre poco della vista).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="468"/>
        <source>Wall lines shorter than this do not vote for the direction.</source>
        <translation>Le linee di muro più corte di così non votano per la direzione.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="469"/>
        <source>Wall lines with fewer scan points do not vote.</source>
        <translation>Le linee di muro con meno punti di scansione non votano.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="471"/>
        <source>Weaker tracking confidence: no target.</source>
        <translation>Confidenza di tracking più debole: nessun target.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="473"/>
        <source>Weight observations by 1 / (|u - cx| / cx + 0.05) (libviso2), favouring the centre, as the two-frame refinement does.</source>
        <translation>Pesare le osservazioni per 1 / (|u - cx| / cx + 0.05) (libviso2), favorendo il centro, come fa il raffinamento a due fotogrammi.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="474"/>
        <source>Weight observations by 1 / (|u - cx| / cx + 0.05) (libviso2), favouring the centre.</source>
        <translation>Pesare le osservazioni per 1 / (|u - cx| / cx + 0.05) (libviso2), favorendo il centro.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="475"/>
        <source>Weight of the fused positions&apos; spread (1.4826 x median absolute deviation from the fused target) in the stated uncertainty.</source>
        <translation>Peso della dispersione delle posizioni fuse (1.4826 x deviazione assoluta mediana dal target fuso) nell&apos;incertezza dichiarata.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="476"/>
        <source>What replaces a rejected motion: the last accepted one, or none.</source>
        <translation>Che cosa sostituisce un moto rifiutato: l&apos;ultimo accettato o nessuno.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="478"/>
        <source>When fewer tracks survive than this fraction of the share that survived in the previous frame (poor motion prediction), the lost ones are tracked again with retrack_pyramid_levels; 0 = never.</source>
        <translation>Quando sopravvivono meno tracce di questa frazione della quota sopravvissuta nel fotogramma precedente (cattiva previsione del moto), quelle perse vengono tracciate di nuovo con retrack_pyramid_levels; 0 = mai.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="479"/>
        <source>When set, a client must send {&quot;token&quot;: &quot;...&quot;} before it receives anything; required when bind_address is not a loopback address.</source>
        <translation>Se impostato, un client deve inviare {&quot;token&quot;: &quot;...&quot;} prima di ricevere qualcosa; obbligatorio quando bind_address non è un indirizzo di loopback.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="481"/>
        <source>Where the robot&apos;s translation comes from: the recording&apos;s odometry (odometry.txt, a bag&apos;s odometry or tf, a live source&apos;s), RGB-D odometry on the depth and colour frames, none (heading from the walls only), or auto (the recording&apos;s odometry when it has one, else RGB-D odometry when the frames have colour or the method is icp, else none).</source>
        <translation>Da dove proviene la traslazione del robot: l&apos;odometria della registrazione (odometry.txt, odometria o tf di un bag, quella di una sorgente dal vivo), odometria RGB-D sui fotogrammi di profondità e colore, none (direzione solo dalle pareti) o auto (l&apos;odometria della registrazione quando c&apos;è, altrimenti odometria RGB-D quando i fotogrammi hanno colore o il metodo è icp, altrimenti none).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="483"/>
        <source>Width of the reduced copies of the two images compared in that search.</source>
        <translation>Larghezza delle copie ridotte delle due immagini confrontate in quella ricerca.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="484"/>
        <source>Window of the second pass, after a first pose.</source>
        <translation>Finestra del secondo passaggio, dopo una prima posa.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="485"/>
        <source>Window used when the first search finds too few points.</source>
        <translation>Finestra usata quando la prima ricerca trova troppo pochi punti.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="486"/>
        <source>With a token: a connection that has not presented it after this long is closed.</source>
        <translation>Con un token: una connessione che non lo ha presentato dopo questo tempo viene chiusa.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="487"/>
        <source>With fewer than min_matches but this many matches, an essential matrix from them guides a second matching along epipolar lines (large motion).</source>
        <translation>Con meno di min_matches ma almeno tante corrispondenze, una matrice essenziale stimata da esse guida un secondo abbinamento lungo le rette epipolari (moto ampio).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="488"/>
        <source>With png: also overlay.avi (Motion-JPEG through OpenCV&apos;s built-in writer).</source>
        <translation>Con png: anche overlay.avi (Motion-JPEG tramite il writer integrato di OpenCV).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="489"/>
        <source>With serve: give up waiting for clients after this long.</source>
        <translation>Con serve: smettere di attendere i client dopo questo tempo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="490"/>
        <source>With serve: keep serving this long after the last frame so queued targets go out.</source>
        <translation>Con serve: continuare a servire per questo tempo dopo l&apos;ultimo fotogramma, così i target in coda vengono inviati.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="491"/>
        <source>With serve: wait for this many connected clients before the first frame.</source>
        <translation>Con serve: attendere questo numero di client connessi prima del primo fotogramma.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="492"/>
        <source>Without a reference: lines within this of the best-supported direction (modulo 90 deg) vote.</source>
        <translation>Senza riferimento: votano le linee entro questo valore dalla direzione meglio supportata (modulo 90 deg).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="493"/>
        <source>Workspace box, base x max.</source>
        <translation>Box dello spazio di lavoro, base x max.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="494"/>
        <source>Workspace box, base x min.</source>
        <translation>Box dello spazio di lavoro, base x min.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="495"/>
        <source>Workspace box, base y max.</source>
        <translation>Box dello spazio di lavoro, base y max.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="496"/>
        <source>Workspace box, base y min.</source>
        <translation>Box dello spazio di lavoro, base y min.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="497"/>
        <source>Workspace box, base z max.</source>
        <translation>Box dello spazio di lavoro, base z max.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="498"/>
        <source>Workspace box, base z min.</source>
        <translation>Box dello spazio di lavoro, base z min.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="499"/>
        <source>Write the projection and top-view PNGs per frame.</source>
        <translation>Scrivere per fotogramma i PNG della proiezione e della vista dall&apos;alto.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="500"/>
        <source>accuracy.wall_recall: a true wall is visible in a frame when at least this much of it is in view ...</source>
        <translation>accuracy.wall_recall: un muro vero è visibile in un fotogramma quando almeno questa parte di esso è inquadrata ...</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="501"/>
        <source>arm_pose messages closer than 1/this in the arm&apos;s time are dropped (counted).</source>
        <translation>I messaggi arm_pose più vicini di 1/questo valore nel tempo del braccio vengono scartati (contati).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="502"/>
        <source>arm_pose messages older than this behind the newest are forgotten.</source>
        <translation>I messaggi arm_pose più indietro di così rispetto al più recente vengono dimenticati.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="503"/>
        <source>arm_poses.txt (base_from_end_effector, TUM); empty = beside the sensor folder.</source>
        <translation>arm_poses.txt (base_from_end_effector, TUM); vuoto = accanto alla cartella del sensore.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="504"/>
        <source>custom platform: a segment raised more than this above the ground scores 0.</source>
        <translation>Piattaforma custom: un segmento rialzato più di così sopra il suolo ha punteggio 0.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="505"/>
        <source>custom platform: points farther from the sensor are dropped.</source>
        <translation>Piattaforma custom: i punti più lontani dal sensore vengono scartati.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="506"/>
        <source>delaunay: triangles with an edge longer than this many cells are dropped.</source>
        <translation>delaunay: i triangoli con un lato più lungo di questo numero di celle vengono scartati.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="512"/>
        <source>depth: a person&apos;s top lies at least this many footprint lengths above the floor (a desk, a table or a sofa is wider than it is tall).</source>
        <translation>depth: la sommità di una persona è almeno a questo multiplo della lunghezza dell&apos;impronta sopra il pavimento (una scrivania, un tavolo o un divano è più largo che alto).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="518"/>
        <source>depth: the HOG score a cluster&apos;s box needs when it touches the image&apos;s border (a body cut off scores lower).</source>
        <translation>depth: il punteggio HOG che il riquadro di un cluster deve raggiungere quando tocca il bordo dell&apos;immagine (un corpo tagliato ottiene un punteggio più basso).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="519"/>
        <source>depth: the HOG score a cluster&apos;s box needs when the whole box is in view.</source>
        <translation>depth: il punteggio HOG che il riquadro di un cluster deve raggiungere quando è interamente visibile.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="522"/>
        <source>depth: when on, a cluster reaching the image&apos;s top row (its top out of view) is not a person: fewer false people at the edge of view, but people near enough to have their heads cut off are missed.</source>
        <translation>depth: se attivo, un gruppo che raggiunge la prima riga dell&apos;immagine (con la sommità fuori vista) non è una persona: meno persone false al bordo dell&apos;immagine, ma le persone tanto vicine da avere la testa tagliata vengono perse.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="523"/>
        <source>depth: when the colour image is registered to the depth image, OpenCV&apos;s HOG people detector must also score each cluster&apos;s box (a chair or a desk of a person&apos;s size is dropped).</source>
        <translation>depth: se l&apos;immagine a colori è registrata sull&apos;immagine di profondità, anche il rilevatore di persone HOG di OpenCV deve confermare il riquadro di ogni cluster (una sedia o una scrivania delle dimensioni di una persona viene scartata).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="524"/>
        <source>device: pair by camera timestamps (cameras on a common clock, e.g. PTP or a shared trigger); host: pair by arrival time at the host.</source>
        <translation>device: accoppiare per timestamp delle telecamere (telecamere con un orologio comune, ad es. PTP o un trigger condiviso); host: accoppiare per ora di arrivo all&apos;host.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="527"/>
        <source>free: the camera runs on its own clock; software: the host triggers each frame (both cameras of a pair together); hardware: an external pulse on trigger_line.</source>
        <translation>free: la telecamera funziona con il proprio orologio; software: l&apos;host attiva ogni fotogramma (entrambe le telecamere di una coppia insieme); hardware: un impulso esterno su trigger_line.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="528"/>
        <source>grid: every n-th pixel in both directions (stands in for the voxel grid).</source>
        <translation>grid: un pixel ogni n in entrambe le direzioni (al posto della griglia di voxel).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="529"/>
        <source>grid: grid neighbours whose depths differ by more than this fraction are apart.</source>
        <translation>grid: i vicini nella griglia le cui profondità differiscono di più di questa frazione sono separati.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="530"/>
        <source>grid: half-width of the window of grid points each normal is fitted to.</source>
        <translation>grid: semi-larghezza della finestra di punti della griglia a cui si adatta ogni normale.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="532"/>
        <source>hand_eye.yaml (end_effector_from_camera); empty = beside arm_poses (for arm_stream: beside the images); none = identity.</source>
        <translation>hand_eye.yaml (end_effector_from_camera); vuoto = accanto a arm_poses (per arm_stream: accanto alle immagini); none = identità.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="533"/>
        <source>i_max (step E): at most this many lines.</source>
        <translation>i_max (passo E): al massimo questo numero di linee.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="535"/>
        <source>multiscale: add Hough circles (round buttons, thin rings).</source>
        <translation>multiscale: aggiungere cerchi di Hough (pulsanti rotondi, anelli sottili).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="536"/>
        <source>multiscale: blur of the second scale, times blur_sigma_px.</source>
        <translation>multiscale: sfocatura della seconda scala, moltiplicata per blur_sigma_px.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="537"/>
        <source>multiscale: half size of the window around the tap that is searched.</source>
        <translation>multiscale: metà della dimensione della finestra attorno al tocco in cui si cerca.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="538"/>
        <source>multiscale: longest over shortest side of a region&apos;s rotated box.</source>
        <translation>multiscale: rapporto tra il lato più lungo e quello più corto del riquadro ruotato di una regione.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="539"/>
        <source>multiscale: regions are ranked by (offset + bias) / radius, so the button&apos;s outline wins over a glyph on it.</source>
        <translation>multiscale: le regioni sono ordinate per (offset + bias) / raggio, così il contorno del pulsante prevale su un simbolo sopra di esso.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="540"/>
        <source>multiscale: the region&apos;s centroid lies at most this many radii from the tap.</source>
        <translation>multiscale: il baricentro della regione si trova al massimo a questo numero di raggi dal tocco.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="541"/>
        <source>multiscale: the two Canny pairs are the thresholds times 2/(1+s) and 2s/(1+s).</source>
        <translation>multiscale: le due coppie di Canny sono le soglie moltiplicate per 2/(1+s) e 2s/(1+s).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="542"/>
        <source>multiscale: when no outline holds the tap, look for closed outlines of the strongest radial edges around it (faint or thin-ringed buttons).</source>
        <translation>multiscale: quando nessun contorno contiene il tocco, cerca attorno ad esso contorni chiusi dei bordi radiali più forti (pulsanti tenui o con anello sottile).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="543"/>
        <source>p of the adaptive count: probability of drawing one all-inlier pair.</source>
        <translation>p del conteggio adattivo: probabilità di estrarre una coppia di soli inlier.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="544"/>
        <source>pcl: neighbour radius of the region growing.</source>
        <translation>pcl: raggio dei vicini della crescita per regioni.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="545"/>
        <source>pcl: neighbours of the normal fit.</source>
        <translation>pcl: vicini del fit delle normali.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="546"/>
        <source>pcl: neighbours of the outlier removal.</source>
        <translation>pcl: vicini della rimozione degli outlier.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="547"/>
        <source>pcl: voxel grid leaf size.</source>
        <translation>pcl: dimensione delle foglie della griglia di voxel.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="548"/>
        <source>ratio_max (step B8): a hypothesis with more inliers than this ends the search.</source>
        <translation>ratio_max (passo B8): un&apos;ipotesi con più inlier di così termina la ricerca.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="549"/>
        <source>ratio_min (steps B5, B6): a line needs this fraction of the remaining points.</source>
        <translation>ratio_min (passi B5, B6): una linea richiede questa frazione dei punti rimanenti.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="550"/>
        <source>ratio_scan_max (step E): stop once this fraction of the points lies on lines.</source>
        <translation>ratio_scan_max (passo E): fermarsi quando questa frazione dei punti si trova su linee.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="216"/>
        <source>Kind of frames read from a ROS bag; auto picks RGB-D, then stereo, then mono, then point clouds, as the bag&apos;s topics allow.</source>
        <translation>Tipo di fotogrammi letti da una bag ROS; auto sceglie RGB-D, poi stereo, poi mono, poi nuvole di punti, secondo quanto permettono i topic della bag.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="257"/>
        <source>New centre: the model centre through a RANSAC similarity of the matches, or the matched keypoints&apos; centroid (the published rule).</source>
        <translation>Nuovo centro: il centro del modello tramite una similitudine RANSAC delle corrispondenze, oppure il baricentro dei keypoint corrispondenti (la regola della pubblicazione).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="269"/>
        <source>Occupied evidence: the polar scan&apos;s hits (visible surfaces, thin walls) or every occupied cell of the occupancy image (as published; depth noise behind walls stays).</source>
        <translation>Evidenza di occupazione: i colpi della scansione polare (superfici visibili, muri sottili) oppure ogni cella occupata dell&apos;immagine di occupazione (come pubblicato; il rumore di profondità dietro i muri resta).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="306"/>
        <source>Process every k-th frame (the published subsampling sweep); --subsample K.</source>
        <translation>Elaborare un fotogramma ogni k (la serie di sottocampionamenti della pubblicazione); --subsample K.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="320"/>
        <source>ROS bag: ground truth is the pose of tf_child_frame in this tf frame; empty uses the bag&apos;s only transform chain on /tf.</source>
        <translation>Bag ROS: il riferimento è la posa di tf_child_frame in questo frame tf; vuoto usa l&apos;unica catena di trasformazioni della bag su /tf.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="321"/>
        <source>ROS bag: largest stamp difference of a colour/depth or left/right pair; images without a partner are skipped.</source>
        <translation>Bag ROS: massima differenza di timestamp di una coppia colore/profondità o sinistra/destra; le immagini senza partner vengono saltate.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="323"/>
        <source>ROS bag: the CameraInfo topic of the image topic; empty looks beside the image topic, then takes the bag&apos;s only CameraInfo topic.</source>
        <translation>Bag ROS: il topic CameraInfo del topic dell&apos;immagine; vuoto cerca accanto al topic dell&apos;immagine, poi prende l&apos;unico topic CameraInfo della bag.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="324"/>
        <source>ROS bag: the PointCloud2 topic read as point-cloud frames.</source>
        <translation>Bag ROS: il topic PointCloud2 letto come nuvole di punti.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="327"/>
        <source>ROS bag: the camera&apos;s tf frame whose pose in tf_parent_frame is the ground truth.</source>
        <translation>Bag ROS: il frame tf della telecamera la cui posa in tf_parent_frame è il riferimento.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="328"/>
        <source>ROS bag: the colour, left or mono image topic (Image or CompressedImage); empty picks it when the bag leaves no doubt.</source>
        <translation>Bag ROS: il topic dell&apos;immagine a colori, sinistra o mono (Image o CompressedImage); vuoto lo sceglie quando la bag non lascia dubbi.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="329"/>
        <source>ROS bag: the depth image topic (16UC1 millimetres or 32FC1 metres); empty picks it when the bag leaves no doubt.</source>
        <translation>Bag ROS: il topic dell&apos;immagine di profondità (16UC1 millimetri o 32FC1 metri); vuoto lo sceglie quando la bag non lascia dubbi.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="330"/>
        <source>ROS bag: the nav_msgs/Odometry topic; empty takes the bag&apos;s only one.</source>
        <translation>Bag ROS: il topic nav_msgs/Odometry; vuoto prende l&apos;unico della bag.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="332"/>
        <source>ROS bag: the right camera&apos;s CameraInfo topic; its projection matrix P gives the stereo baseline.</source>
        <translation>Bag ROS: il topic CameraInfo della telecamera destra; la sua matrice di proiezione P dà la base stereo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="333"/>
        <source>ROS bag: the right image topic of a stereo pair; empty picks the topic whose name says right beside one that says left.</source>
        <translation>Bag ROS: il topic dell&apos;immagine destra di una coppia stereo; vuoto sceglie il topic il cui nome dice right accanto a uno che dice left.</translation>
    </message>
</context>
<context>
    <name>sightline::ParameterPanel</name>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="47"/>
        <source>Filter options</source>
        <translation>Filtra le opzioni</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="51"/>
        <source>Load profile…</source>
        <translation>Carica profilo…</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="54"/>
        <source>Save profile…</source>
        <translation>Salva profilo…</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="57"/>
        <source>Reset all</source>
        <translation>Ripristina tutto</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="173"/>
        <source>All options reset to their defaults.</source>
        <translation>Tutte le opzioni riportate ai valori predefiniti.</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="184"/>
        <source>Loaded profile %1</source>
        <translation>Profilo %1 caricato</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="195"/>
        <source>Saved profile %1</source>
        <translation>Profilo %1 salvato</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="202"/>
        <source>Load profile</source>
        <translation>Carica profilo</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="202"/>
        <source>YAML profiles (*.yaml *.yml);;All files (*)</source>
        <translation>Profili YAML (*.yaml *.yml);;Tutti i file (*)</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="209"/>
        <source>Save profile</source>
        <translation>Salva profilo</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="210"/>
        <source>YAML profiles (*.yaml *.yml)</source>
        <translation>Profili YAML (*.yaml *.yml)</translation>
    </message>
</context>
<context>
    <name>sightline::PlaybackBar</name>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="37"/>
        <source>Step one frame</source>
        <translation>Avanza di un&apos;immagine</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="57"/>
        <source>Playback speed relative to the recording&apos;s timestamps</source>
        <translation>Velocità di riproduzione rispetto ai tempi della registrazione</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="61"/>
        <source>max</source>
        <translation>max</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="67"/>
        <source>Loop</source>
        <translation>Ciclo</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="121"/>
        <source>Pause</source>
        <translation>Pausa</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="121"/>
        <source>Play</source>
        <translation>Riproduci</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="155"/>
        <source>frame %1</source>
        <translation>fotogramma %1</translation>
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
    <name>sightline::RemoteOperatorPresenter</name>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="50"/>
        <source>Operator panel (ROS node)</source>
        <translation>Pannello operatore (nodo ROS)</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="86"/>
        <source>Start did not reach the robot: still stopped</source>
        <translation>Il riavvio non ha raggiunto il robot: resta fermo</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="109"/>
        <source>STOP sent: waiting for the robot</source>
        <translation>STOP inviato: in attesa del robot</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="110"/>
        <source>STOP kept: sent as soon as the robot is reachable</source>
        <translation>STOP trattenuto: inviato appena il robot è raggiungibile</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="153"/>
        <source>The robot confirmed STOP</source>
        <translation>Il robot ha confermato lo STOP</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="161"/>
        <source>Target %1, %2, %3 m (%4)</source>
        <translation>Obiettivo %1, %2, %3 m (%4)</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="196"/>
        <source>The robot did not answer the tap: tap again</source>
        <translation>Il robot non ha risposto al tocco: tocca di nuovo</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="253"/>
        <source>The robot did not take the tap: tap again</source>
        <translation>Il robot non ha accettato il tocco: tocca di nuovo</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="262"/>
        <source>The robot&apos;s node is gone</source>
        <translation>Il nodo del robot non c&apos;è più</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="270"/>
        <source>No picture for %1 s</source>
        <translation>Nessuna immagine da %1 s</translation>
    </message>
</context>
<context>
    <name>sightline::RosConnectDialog</name>
    <message>
        <location filename="../app/sightline/ros_connect_dialog.cpp" line="12"/>
        <source>Connect to ROS master</source>
        <translation>Connetti al master ROS</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_connect_dialog.cpp" line="18"/>
        <source>Master URI:</source>
        <translation>URI del master:</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_connect_dialog.cpp" line="19"/>
        <source>Node namespace:</source>
        <translation>Namespace del nodo:</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_connect_dialog.cpp" line="21"/>
        <source>The robot&apos;s master, e.g. http://robot:11311. The robot must reach this computer too: set ROS_IP (or ROS_HOSTNAME) before starting Sightline.</source>
        <translation>Il master del robot, ad es. http://robot:11311. Anche il robot deve raggiungere questo computer: impostare ROS_IP (o ROS_HOSTNAME) prima di avviare Sightline.</translation>
    </message>
</context>
<context>
    <name>sightline::RosNodeView</name>
    <message>
        <location filename="../app/sightline/ros_node_view.cpp" line="65"/>
        <source>ROS node</source>
        <translation>Nodo ROS</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_node_view.cpp" line="69"/>
        <location filename="../app/sightline/ros_node_view.cpp" line="174"/>
        <source>Not connected: File &gt; Connect to ROS master...</source>
        <translation>Non connesso: File &gt; Connetti al master ROS...</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_node_view.cpp" line="100"/>
        <source>ROS: %1</source>
        <translation>ROS: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_node_view.cpp" line="147"/>
        <source>Waiting for the map from %1 ...</source>
        <translation>In attesa della mappa da %1 ...</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_node_view.cpp" line="152"/>
        <source>ROS: not available in this build</source>
        <translation>ROS: non disponibile in questa build</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_node_view.cpp" line="221"/>
        <source>ROS: connected to %1</source>
        <translation>ROS: connesso a %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_node_view.cpp" line="222"/>
        <source>ROS: disconnected — reconnecting to %1</source>
        <translation>ROS: disconnesso — riconnessione a %1</translation>
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
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="210"/>
        <source>tracked %1, new %2, stereo %3, inliers %4, RANSAC %5 it., residual %6 %7, %8 %9%10</source>
        <translation>tracciati %1, nuovi %2, stereo %3, inlier %4, RANSAC %5 it., residuo %6 %7, %8 %9%10</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="220"/>
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
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="175"/>
        <source>estimate and camera</source>
        <translation>stima e camera</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="176"/>
        <source>ground truth</source>
        <translation>ground truth</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="185"/>
        <source>inlier track</source>
        <translation>traccia inlier</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="186"/>
        <source>outlier track</source>
        <translation>traccia outlier</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="187"/>
        <source>new feature</source>
        <translation>nuova caratteristica</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="199"/>
        <source>stereo match</source>
        <translation>corrispondenza stereo</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="229"/>
        <source>residual</source>
        <translation>residuo</translation>
    </message>
</context>
</TS>
