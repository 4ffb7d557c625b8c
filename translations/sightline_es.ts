<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="es_ES">
<context>
    <name>sightline::ButtonPickerPresenter</name>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="40"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="83"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="87"/>
        <source>Stopped</source>
        <translation>Detenido</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="42"/>
        <source>Waiting for Yes</source>
        <translation>Esperando el Sí</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="44"/>
        <source>Button lost</source>
        <translation>Botón perdido</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="46"/>
        <source>Button unclear</source>
        <translation>Botón poco claro</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="48"/>
        <source>Measuring the button</source>
        <translation>Midiendo el botón</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="50"/>
        <source>Measuring again</source>
        <translation>Midiendo de nuevo</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="52"/>
        <source>Measuring the distance</source>
        <translation>Midiendo la distancia</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="54"/>
        <source>Panel unclear</source>
        <translation>Panel poco claro</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="56"/>
        <source>Position not sure yet</source>
        <translation>Posición aún no segura</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="58"/>
        <source>Panel direction not sure yet</source>
        <translation>Dirección del panel aún no segura</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="60"/>
        <source>Button out of reach</source>
        <translation>Botón fuera de alcance</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="71"/>
        <source>The picture changed: tap again</source>
        <translation>La imagen ha cambiado: toque de nuevo</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="73"/>
        <source>The picture was too old: tap again</source>
        <translation>La imagen era demasiado antigua: toque de nuevo</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="75"/>
        <source>Stopped: press Start again first</source>
        <translation>Detenido: pulse primero «Empezar de nuevo»</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="82"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="224"/>
        <source>Paused</source>
        <translation>En pausa</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="85"/>
        <source>Arm link off</source>
        <translation>Enlace con el brazo apagado</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="86"/>
        <source>No arm connected</source>
        <translation>Ningún brazo conectado</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="90"/>
        <source>Waiting</source>
        <translation>Esperando</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="111"/>
        <source>Button picker (monocular SLAM)</source>
        <translation>Selector de botones (SLAM monocular)</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="119"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="143"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="182"/>
        <source>Operator panel</source>
        <translation>Panel del operador</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="123"/>
        <source>Operator panel full screen</source>
        <translation>Panel del operador a pantalla completa</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="224"/>
        <source>End of the recording</source>
        <translation>Fin de la grabación</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="242"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="250"/>
        <source>The picture is paused: press Play, then tap</source>
        <translation>La imagen está en pausa: pulse Reproducir y luego toque</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="249"/>
        <source>The recording has ended: nothing to tap</source>
        <translation>La grabación ha terminado: nada que tocar</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="251"/>
        <source>No picture yet: open a camera or a recording</source>
        <translation>Todavía no hay imagen: abra una cámara o una grabación</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="288"/>
        <source>No button at the tap: %1</source>
        <translation>No hay ningún botón donde tocó: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="303"/>
        <source>No metric scale (no arm motion)</source>
        <translation>Sin escala métrica (sin movimiento del brazo)</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="305"/>
        <source>Without the arm&apos;s poses the button is tracked and located in map units only; no target is sent.</source>
        <translation>Sin las poses del brazo el botón solo se sigue y se localiza en unidades del mapa; no se envía ningún objetivo.</translation>
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
        <translation>&amp;Calibrar</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="96"/>
        <source>&amp;Save YAML...</source>
        <translation>&amp;Guardar YAML...</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="93"/>
        <source>Board</source>
        <translation>Tablero</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="224"/>
        <source>Board found in %1 of %2 %3.</source>
        <translation>Tablero encontrado en %1 de %2 %3.</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="60"/>
        <source>Browse...</source>
        <translation>Examinar...</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="42"/>
        <source>Calibrate camera</source>
        <translation>Calibrar la cámara</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="218"/>
        <source>Calibration failed: %1</source>
        <translation>La calibración ha fallado: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="62"/>
        <source>Calibration images</source>
        <translation>Imágenes de calibración</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="108"/>
        <source>Choose a source and the board, then press Calibrate.</source>
        <translation>Elija una fuente y el tablero, y pulse Calibrar.</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="175"/>
        <source>Choose a source first.</source>
        <translation>Elija primero una fuente.</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="131"/>
        <source>Coverage (views per cell)</source>
        <translation>Cobertura (vistas por celda)</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="129"/>
        <source>Detected corners</source>
        <translation>Esquinas detectadas</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="317"/>
        <source>Detected corners: %1 (%2 px)</source>
        <translation>Esquinas detectadas: %1 (%2 px)</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="181"/>
        <source>Detecting the board...</source>
        <translation>Buscando el tablero...</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="117"/>
        <source>Error (px)</source>
        <translation>Error (px)</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="69"/>
        <source>File name pattern inside a mono image folder, e.g. left*.jpg</source>
        <translation>Patrón de nombres de archivo en una carpeta de imágenes mono, p. ej. left*.jpg</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="264"/>
        <source>Hint: %1</source>
        <translation>Consejo: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="59"/>
        <source>Image folder, stereo folder, recording or camera URI</source>
        <translation>Carpeta de imágenes, carpeta estéreo, grabación o URI de cámara</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="92"/>
        <source>Image pattern</source>
        <translation>Patrón de imágenes</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="90"/>
        <source>Mode</source>
        <translation>Modo</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="56"/>
        <source>Mono (one camera)</source>
        <translation>Mono (una cámara)</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="348"/>
        <source>Nothing to save: calibrate first.</source>
        <translation>Nada que guardar: calibre primero.</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="362"/>
        <source>OpenCV YAML (*.yaml *.yml)</source>
        <translation>YAML de OpenCV (*.yaml *.yml)</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="251"/>
        <source>RMS %1 px; %2 views used, %3 rejected.</source>
        <translation>RMS %1 px; %2 vistas usadas, %3 descartadas.</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="243"/>
        <source>RMS left %1 px, right %2 px, stereo %3 px; baseline %4 mm; %5 of %6 pairs used.</source>
        <translation>RMS izquierda %1 px, derecha %2 px, estéreo %3 px; línea base %4 mm; %5 de %6 pares usados.</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="117"/>
        <source>Right error (px)</source>
        <translation>Error derecha (px)</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="361"/>
        <source>Save calibration</source>
        <translation>Guardar la calibración</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="356"/>
        <source>Saved %1</source>
        <translation>Guardado %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="365"/>
        <source>Saving failed: %1</source>
        <translation>No se pudo guardar: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="91"/>
        <source>Source</source>
        <translation>Fuente</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="117"/>
        <source>Status</source>
        <translation>Estado</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="57"/>
        <source>Stereo (left and right)</source>
        <translation>Estéreo (izquierda y derecha)</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="117"/>
        <source>View</source>
        <translation>Vista</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="257"/>
        <source>fx %1 fy %2 cx %3 cy %4; coverage: %5</source>
        <translation>fx %1 fy %2 cx %3 cy %4; cobertura: %5</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="227"/>
        <source>images</source>
        <translation>imágenes</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="85"/>
        <source>inner corners, squares of</source>
        <translation>esquinas interiores, casillas de</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="227"/>
        <source>pairs</source>
        <translation>pares</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="289"/>
        <location filename="../app/sightline/calibration_dialog.cpp" line="303"/>
        <source>rejected</source>
        <translation>descartadas</translation>
    </message>
    <message>
        <location filename="../app/sightline/calibration_dialog.cpp" line="289"/>
        <source>used</source>
        <translation>usadas</translation>
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
        <translation>Cámaras RGB-D OpenNI2 (Kinect, Xtion, Carmine) y grabaciones .oni</translation>
    </message>
    <message>
        <location filename="../app/sightline/core_texts.cpp" line="13"/>
        <source>GigE Vision / USB3 Vision cameras through Aravis: one camera, or a stereo pair as aravis://LEFT_ID,RIGHT_ID</source>
        <translation>Cámaras GigE Vision / USB3 Vision mediante Aravis: una cámara, o un par estéreo como aravis://LEFT_ID,RIGHT_ID</translation>
    </message>
    <message>
        <location filename="../app/sightline/core_texts.cpp" line="16"/>
        <source>USB webcams through OpenCV&apos;s V4L2 backend</source>
        <translation>Webcams USB mediante el backend V4L2 de OpenCV</translation>
    </message>
    <message>
        <location filename="../app/sightline/core_texts.cpp" line="17"/>
        <source>A recording played as a live camera (replay://PATH?fps=30&amp;loop=1)</source>
        <translation>Una grabación reproducida como cámara en vivo (replay://PATH?fps=30&amp;loop=1)</translation>
    </message>
</context>
<context>
    <name>sightline::DemoGenerator</name>
    <message>
        <location filename="../app/sightline/demo_generator.cpp" line="48"/>
        <source>cannot create the demo folder %1</source>
        <translation>no se puede crear la carpeta de la demo %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/demo_generator.cpp" line="87"/>
        <source>cannot write %1</source>
        <translation>no se puede escribir %1</translation>
    </message>
</context>
<context>
    <name>sightline::EvaluationPanel</name>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="75"/>
        <source>estimated trajectory (TUM or KITTI file)</source>
        <translation>trayectoria estimada (archivo TUM o KITTI)</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="77"/>
        <source>ground truth (TUM or KITTI file)</source>
        <translation>verdad de referencia (archivo TUM o KITTI)</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="81"/>
        <source>Browse...</source>
        <translation>Examinar...</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="90"/>
        <source>SE(3): rotation and translation</source>
        <translation>SE(3): rotación y traslación</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="91"/>
        <source>Sim(3): also scale (monocular)</source>
        <translation>Sim(3): también la escala (monocular)</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="92"/>
        <source>None</source>
        <translation>Ninguna</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="93"/>
        <source>Evaluate</source>
        <translation>Evaluar</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="100"/>
        <source>Estimate</source>
        <translation>Estimación</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="100"/>
        <source>Estimated trajectory</source>
        <translation>Trayectoria estimada</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="101"/>
        <source>Ground truth</source>
        <translation>Verdad de referencia</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="102"/>
        <source>Alignment</source>
        <translation>Alineación</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="104"/>
        <source>Choose two trajectory files and press Evaluate.</source>
        <translation>Elija dos archivos de trayectoria y pulse Evaluar.</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="107"/>
        <source>Figure</source>
        <translation>Indicador</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="107"/>
        <source>Value</source>
        <translation>Valor</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="107"/>
        <source>Unit</source>
        <translation>Unidad</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="107"/>
        <source>Meaning</source>
        <translation>Significado</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="117"/>
        <source>Figures</source>
        <translation>Indicadores</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="118"/>
        <source>Top view</source>
        <translation>Vista cenital</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="119"/>
        <source>Error over time</source>
        <translation>Error en el tiempo</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="144"/>
        <source>Trajectories (*.txt *.csv);;All files (*)</source>
        <translation>Trayectorias (*.txt *.csv);;Todos los archivos (*)</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="152"/>
        <source>Evaluating...</source>
        <translation>Evaluando...</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="176"/>
        <source>Evaluation failed: %1</source>
        <translation>La evaluación ha fallado: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="189"/>
        <source>%1 associated poses, ground-truth path %2 m.</source>
        <translation>%1 poses asociadas, recorrido de la referencia %2 m.</translation>
    </message>
</context>
<context>
    <name>sightline::ImageView</name>
    <message>
        <location filename="../widgets/image_view.cpp" line="47"/>
        <location filename="../widgets/image_view.cpp" line="78"/>
        <location filename="../widgets/image_view.cpp" line="131"/>
        <source>No image</source>
        <translation>Sin imagen</translation>
    </message>
    <message>
        <location filename="../widgets/image_view.cpp" line="81"/>
        <source>Unsupported image type %1</source>
        <translation>Tipo de imagen no admitido %1</translation>
    </message>
</context>
<context>
    <name>sightline::LiveStatusWidget</name>
    <message>
        <location filename="../app/sightline/live_status_widget.cpp" line="25"/>
        <source>closed</source>
        <translation>cerrado</translation>
    </message>
    <message>
        <location filename="../app/sightline/live_status_widget.cpp" line="27"/>
        <source>streaming</source>
        <translation>transmitiendo</translation>
    </message>
    <message>
        <location filename="../app/sightline/live_status_widget.cpp" line="29"/>
        <source>disconnected</source>
        <translation>desconectado</translation>
    </message>
    <message>
        <location filename="../app/sightline/live_status_widget.cpp" line="40"/>
        <source>&lt;span style=&apos;color:%1&apos;&gt;&amp;#9679;&lt;/span&gt; %2 &amp;nbsp;%3 fps &amp;nbsp;dropped %4 &amp;nbsp;latency %5 ms</source>
        <translation>&lt;span style=&apos;color:%1&apos;&gt;&amp;#9679;&lt;/span&gt; %2 &amp;nbsp;%3 fps &amp;nbsp;descartados %4 &amp;nbsp;latencia %5 ms</translation>
    </message>
</context>
<context>
    <name>sightline::LogPanel</name>
    <message>
        <location filename="../widgets/log_panel.cpp" line="36"/>
        <source>Clear messages</source>
        <translation>Borrar los mensajes</translation>
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
        <translation>Color</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="82"/>
        <location filename="../app/sightline/main_window.cpp" line="375"/>
        <source>Depth</source>
        <translation>Profundidad</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="87"/>
        <source>Parameters</source>
        <translation>Parámetros</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="89"/>
        <source>Log</source>
        <translation>Registro</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="92"/>
        <source>Evaluation</source>
        <translation>Evaluación</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="100"/>
        <source>Playback</source>
        <translation>Reproducción</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="110"/>
        <source>&amp;File</source>
        <translation>&amp;Archivo</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="111"/>
        <source>&amp;Open dataset folder...</source>
        <translation>&amp;Abrir carpeta de datos...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="114"/>
        <source>Open dataset folder</source>
        <translation>Abrir carpeta de datos</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="119"/>
        <source>Open point cloud</source>
        <translation>Abrir nube de puntos</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="117"/>
        <source>Open recording &amp;file (PCD, ONI)...</source>
        <translation>Abrir archivo de &amp;grabación (PCD, ONI)...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="120"/>
        <source>Recordings (*.pcd *.oni)</source>
        <translation>Grabaciones (*.pcd *.oni)</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="123"/>
        <source>Open &amp;recent</source>
        <translation>Abrir &amp;recientes</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="128"/>
        <source>&amp;Quit</source>
        <translation>&amp;Salir</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="132"/>
        <source>&amp;View</source>
        <translation>&amp;Ver</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="134"/>
        <source>&amp;Reset 3D view</source>
        <translation>&amp;Restablecer la vista 3D</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="142"/>
        <source>&amp;Sensors</source>
        <translation>Se&amp;nsores</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="148"/>
        <source> (unavailable)</source>
        <translation> (no disponible)</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="153"/>
        <source>Connect to the first %1 device</source>
        <translation>Conectar con el primer dispositivo %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="159"/>
        <source>Replay recording</source>
        <translation>Reproducir una grabación</translation>
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
        <translation>Ninguno (solo mostrar imágenes)</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="174"/>
        <source>&amp;Tools</source>
        <translation>&amp;Herramientas</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="175"/>
        <source>&amp;Evaluate trajectory...</source>
        <translation>&amp;Evaluar una trayectoria...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="180"/>
        <source>Evaluate &amp;current run</source>
        <translation>Evaluar la ejecución a&amp;ctual</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="182"/>
        <source>Compares the running pipeline&apos;s trajectory with the dataset&apos;s ground truth.</source>
        <translation>Compara la trayectoria del pipeline en ejecución con la verdad de referencia del conjunto de datos.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="191"/>
        <source>&amp;Help</source>
        <translation>A&amp;yuda</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="192"/>
        <source>&amp;About Sightline</source>
        <translation>&amp;Acerca de Sightline</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="193"/>
        <source>About Sightline</source>
        <translation>Acerca de Sightline</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="194"/>
        <source>Sightline: robot perception for assistive and mobile robotics.
Indoor mapping, mobility maps, stereo odometry and monocular button localisation on live sensors or recorded data.</source>
        <translation>Sightline: percepción robótica para la robótica asistencial y móvil.
Mapeo de interiores, mapas de transitabilidad, odometría estéreo y localización monocular de botones con sensores en vivo o datos grabados.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="206"/>
        <source>Could not open %1: %2</source>
        <translation>No se pudo abrir %1: %2</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="207"/>
        <source>Could not open %1</source>
        <translation>No se pudo abrir %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="215"/>
        <source>End of recording.</source>
        <translation>Fin de la grabación.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="239"/>
        <source>Demo %p%</source>
        <translation>Demo %p%</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="246"/>
        <source>Generating the demo recordings (only the first time)...</source>
        <translation>Generando las grabaciones de la demo (solo la primera vez)...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="255"/>
        <source>Demo: a robot drives a simulated office corridor (RGB-D, stereo, wheel odometry, exact ground truth). The arm-camera panel approach is in %1.</source>
        <translation>Demo: un robot recorre un pasillo de oficina simulado (RGB-D, estéreo, odometría de ruedas, verdad de referencia exacta). La aproximación de la cámara del brazo al panel está en %1.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="262"/>
        <source>The demo could not be made: %1</source>
        <translation>No se pudo crear la demo: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="318"/>
        <source>No pipeline: showing frames only.</source>
        <translation>Sin pipeline: solo se muestran las imágenes.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="329"/>
        <source>Pipeline: %1</source>
        <translation>Pipeline: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="333"/>
        <source>%1 cannot run on %2 frames; open another dataset.</source>
        <translation>%1 no puede funcionar con imágenes %2; abra otro conjunto de datos.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="362"/>
        <location filename="../app/sightline/main_window.cpp" line="363"/>
        <source>Opening %1 ...</source>
        <translation>Abriendo %1 ...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="374"/>
        <source>Left</source>
        <translation>Izquierda</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="374"/>
        <source>Image</source>
        <translation>Imagen</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="375"/>
        <source>Right</source>
        <translation>Derecha</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="381"/>
        <source>%1: %2, %3 frames, %4x%5%6</source>
        <translation>%1: %2, %3 imágenes, %4x%5%6</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="386"/>
        <source>, ground truth</source>
        <translation>, verdad de referencia</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="388"/>
        <source>Opened %1</source>
        <translation>Abierto %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="393"/>
        <source>Sightline - %1</source>
        <translation>Sightline - %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="428"/>
        <source>frame %1, read in %2 ms</source>
        <translation>imagen %1, leída en %2 ms</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="450"/>
        <source>No dataset open. Use File &gt; Open dataset folder (TUM RGB-D, EuRoC, KITTI, an image folder or PCD files), or drop a folder on this window.</source>
        <translation>Ningún conjunto de datos abierto. Use Archivo &gt; Abrir carpeta de datos (TUM RGB-D, EuRoC, KITTI, una carpeta de imágenes o archivos PCD), o arrastre una carpeta a esta ventana.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="452"/>
        <source>No dataset open</source>
        <translation>Ningún conjunto de datos abierto</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="184"/>
        <source>&amp;Calibrate camera...</source>
        <translation>&amp;Calibrar la cámara...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_recording.cpp" line="19"/>
        <source>Recording</source>
        <translation>Grabación</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_recording.cpp" line="37"/>
        <source>Recording: %1</source>
        <translation>Grabación: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="35"/>
        <source>&amp;Save results...</source>
        <translation>&amp;Guardar los resultados...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="38"/>
        <source>Writes the running pipeline&apos;s results as sightline-cli run does: metrics.json, trajectory, maps, clouds and tables.</source>
        <translation>Escribe los resultados del pipeline en ejecución como sightline-cli run: metrics.json, trayectoria, mapas, nubes y tablas.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="44"/>
        <source>Save results into folder</source>
        <translation>Guardar los resultados en la carpeta</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="55"/>
        <source>Saved %1 in %2</source>
        <translation>Guardado %1 en %2</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="56"/>
        <source>Results saved in %1</source>
        <translation>Resultados guardados en %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="61"/>
        <source>Could not save results: %1</source>
        <translation>No se pudieron guardar los resultados: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="75"/>
        <source>Evaluate current run needs a running pipeline on a dataset with ground truth; choose two trajectory files instead.</source>
        <translation>Evaluar la ejecución actual requiere un pipeline en ejecución sobre un conjunto de datos con verdad de referencia; si no, elija dos archivos de trayectoria.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="82"/>
        <source>Could not make a temporary folder for the evaluation.</source>
        <translation>No se pudo crear una carpeta temporal para la evaluación.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_results.cpp" line="94"/>
        <source>%1 writes no trajectory to evaluate.</source>
        <translation>%1 no escribe ninguna trayectoria que evaluar.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_settings.cpp" line="26"/>
        <source>Reset &amp;layout</source>
        <translation>Restablecer la &amp;disposición</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_settings.cpp" line="60"/>
        <source>Setti&amp;ngs</source>
        <translation>&amp;Configuración</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_settings.cpp" line="62"/>
        <source>&amp;Language</source>
        <translation>&amp;Idioma</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_settings.cpp" line="67"/>
        <source>System language</source>
        <translation>Idioma del sistema</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_settings.cpp" line="96"/>
        <source>Language: %1</source>
        <translation>Idioma: %1</translation>
    </message>
</context>
<context>
    <name>sightline::MappingPresenter</name>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="91"/>
        <source>Indoor mapping (Manhattan walls)</source>
        <translation>Mapeo de interiores (paredes de Manhattan)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="98"/>
        <source>Occupancy, scan and walls</source>
        <translation>Ocupación, barrido y paredes</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="104"/>
        <source>Calibrate floor</source>
        <translation>Calibrar el suelo</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="106"/>
        <source>Fit the floor plane again from the next frames (the robot should see open floor).</source>
        <translation>Ajustar de nuevo el plano del suelo con las próximas imágenes (el robot debe ver suelo libre).</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="109"/>
        <source>Save floor...</source>
        <translation>Guardar el suelo...</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="111"/>
        <source>Save the floor calibration in use, for mapping.run.floor_file or `sightline-cli run mapping --set mapping.run.floor_file=...`.</source>
        <translation>Guardar la calibración del suelo en uso, para mapping.run.floor_file o `sightline-cli run mapping --set mapping.run.floor_file=...`.</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="114"/>
        <source>Save floor calibration</source>
        <translation>Guardar la calibración del suelo</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="115"/>
        <source>YAML (*.yaml)</source>
        <translation>YAML (*.yaml)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="127"/>
        <source>Stitched map</source>
        <translation>Mapa unido</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="186"/>
        <source>Manhattan reference reset: %1</source>
        <translation>Referencia de Manhattan reiniciada: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="202"/>
        <source>Calibrating the floor again from the next frames.</source>
        <translation>Calibrando de nuevo el suelo con las próximas imágenes.</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="215"/>
        <source>Saved the floor calibration to %1</source>
        <translation>Calibración del suelo guardada en %1</translation>
    </message>
</context>
<context>
    <name>sightline::MobilityImagePanel</name>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="72"/>
        <source>Projection</source>
        <translation>Proyección</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="73"/>
        <source>Top view</source>
        <translation>Vista cenital</translation>
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
        <translation>Mapa de transitabilidad</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="36"/>
        <source>Mobility map (red 0, green 1)</source>
        <translation>Mapa de transitabilidad (rojo 0, verde 1)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="40"/>
        <source>Mobility stages (Table II)</source>
        <translation>Etapas del mapa de transitabilidad (Tabla II)</translation>
    </message>
</context>
<context>
    <name>sightline::MobilityTimingPanel</name>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="21"/>
        <source>3D colour:</source>
        <translation>Color 3D:</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="23"/>
        <source>Score (rule)</source>
        <translation>Puntuación (regla)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="23"/>
        <source>Score (GPR)</source>
        <translation>Puntuación (GPR)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="23"/>
        <source>Segment</source>
        <translation>Segmento</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="31"/>
        <source>Stage</source>
        <translation>Etapa</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="31"/>
        <source>Time (ms)</source>
        <translation>Tiempo (ms)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="31"/>
        <source>Points</source>
        <translation>Puntos</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="52"/>
        <source>Total</source>
        <translation>Total</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="55"/>
        <source>%1 mode, %2 segments</source>
        <translation>modo %1, %2 segmentos</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="59"/>
        <source>, camera %1 m above the ground</source>
        <translation>, cámara a %1 m sobre el suelo</translation>
    </message>
</context>
<context>
    <name>sightline::MonoSlamPresenter</name>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="85"/>
        <source>the arm&apos;s poses</source>
        <translation>las poses del brazo</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="86"/>
        <source>the ground truth</source>
        <translation>la verdad de referencia</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="87"/>
        <source>none</source>
        <translation>ninguna</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="125"/>
        <source>Monocular SLAM (PTAM point cloud)</source>
        <translation>SLAM monocular (nube de puntos PTAM)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="137"/>
        <source>Reset map</source>
        <translation>Reiniciar el mapa</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="138"/>
        <source>Pause mapping</source>
        <translation>Pausar el mapeo</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="151"/>
        <source>Tracked features (inliers green, outliers red)</source>
        <translation>Puntos seguidos (inliers en verde, outliers en rojo)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="162"/>
        <source>Metric scale (ML solid, single ratio dashed)</source>
        <translation>Escala métrica (ML continua, razón única discontinua)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="207"/>
        <source>%1: %2 inliers of %3 matches, %4 map points, %5 keyframes, %6 ms</source>
        <translation>%1: %2 inliers de %3 correspondencias, %4 puntos del mapa, %5 keyframes, %6 ms</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="217"/>
        <source>Metric scale from %1: ML %2, single ratio %3 map units per metre; map and trajectory in metres.</source>
        <translation>Escala métrica a partir de %1: ML %2, razón única %3 unidades de mapa por metro; mapa y trayectoria en metros.</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="223"/>
        <source>Scale unknown (measured motion: %1): the map is in arbitrary units (first baseline = 0.1).</source>
        <translation>Escala desconocida (movimiento medido: %1): el mapa está en unidades arbitrarias (primera línea base = 0,1).</translation>
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
        <translation>Cancelar</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="242"/>
        <source>Locating</source>
        <translation>Localizando</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="246"/>
        <source>Lost - hold still</source>
        <translation>Perdido - quieto</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="236"/>
        <source>No button here - tap again</source>
        <translation>Aquí no hay botón - toque otra vez</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="234"/>
        <source>Press this button?</source>
        <translation>¿Pulsar este botón?</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="250"/>
        <source>Holding: nothing sent</source>
        <translation>En espera: nada enviado</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="252"/>
        <source>Tap not taken</source>
        <translation>Toque no aceptado</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="254"/>
        <source>Tracking only</source>
        <translation>Solo seguimiento</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="278"/>
        <source>STOP</source>
        <translation>PARAR</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="314"/>
        <source>Leave</source>
        <translation>Salir</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="314"/>
        <source>Leave the operator panel?</source>
        <translation>¿Salir del panel del operador?</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="238"/>
        <source>Searching</source>
        <translation>Buscando</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="279"/>
        <source>Start again</source>
        <translation>Empezar de nuevo</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="248"/>
        <source>Stopped</source>
        <translation>Detenido</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="232"/>
        <source>Tap a button</source>
        <translation>Toque un botón</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="244"/>
        <source>Target sent</source>
        <translation>Objetivo enviado</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="240"/>
        <source>Tracking</source>
        <translation>Botón a la vista</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="276"/>
        <location filename="../widgets/operator_panel.cpp" line="318"/>
        <source>Yes</source>
        <translation>Sí</translation>
    </message>
</context>
<context>
    <name>sightline::OptionEditor</name>
    <message>
        <location filename="../widgets/option_editor.cpp" line="54"/>
        <source>Range: %1 … %2%3</source>
        <translation>Rango: %1 … %2%3</translation>
    </message>
    <message>
        <location filename="../widgets/option_editor.cpp" line="59"/>
        <source>Choices: %1</source>
        <translation>Opciones: %1</translation>
    </message>
    <message>
        <location filename="../widgets/option_editor.cpp" line="62"/>
        <source>Default: %1%2</source>
        <translation>Por defecto: %1%2</translation>
    </message>
    <message>
        <location filename="../widgets/option_editor.cpp" line="85"/>
        <source>Reset to default (%1)</source>
        <translation>Volver al valor por defecto (%1)</translation>
    </message>
</context>
<context>
    <name>sightline::OptionText</name>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="14"/>
        <source>... and a relative 1-sigma scale error at most this.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="15"/>
        <source>... and at least this fraction of the scan&apos;s rays hit it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="16"/>
        <source>... and by this fraction of the angle turned since the last correction.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="17"/>
        <source>... or when it turned at least this much.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="18"/>
        <source>... plus this times the depth squared (Kinect noise and quantisation).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="19"/>
        <source>... reached within this many frames; otherwise the anchor starts again (tracks followed over many frames drift, and their drift reads as an offset).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="20"/>
        <source>.oni playback speed: 0 delivers frames as fast as they are read, nothing skipped; 1 paces at the recorded rate.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="21"/>
        <source>.oni recordings start again at the first frame instead of ending.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="22"/>
        <source>1-sigma error of the tracked button centre; moves the point across the viewing ray (the target&apos;s stated uncertainty includes it).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="23"/>
        <source>1-sigma rotation error of the hand-eye calibration; times the distance to the button.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="24"/>
        <source>1-sigma translation error of the hand-eye calibration (end effector to camera).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="25"/>
        <source>A bucket gets new corners only when it holds fewer than this fraction of its share of max_features (1 = whenever it is not full).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="26"/>
        <source>A button centre farther than this outside the image is out of view (lost).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="27"/>
        <source>A camera frame newer than the newest arm pose waits at most this long (host clock) for the pose that covers its stamp; then it has no arm pose.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="28"/>
        <source>A frame has ground truth when a pose lies within this time.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="29"/>
        <source>A frame sets the reference only when the wall length in a second direction a few degrees off (inside the gate, outside the trim) is at most this fraction of the main direction&apos;s.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="30"/>
        <source>A frame stays in the window when the camera moved this fraction of its points&apos; median depth since the previous one that stayed (0 = every frame stays); otherwise the next frame replaces it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="31"/>
        <source>A frame this far from every keyframe (relative to the mean depth) becomes one.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="32"/>
        <source>A frame tracking fewer than this share of the last keyframe&apos;s points becomes one.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="33"/>
        <source>A frame&apos;s normal this many sigmas off the average is skipped.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="34"/>
        <source>A frame&apos;s walls count only when their summed vote weight (length x fit quality) reaches this.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="35"/>
        <source>A ground candidate holds at least this fraction of the points.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="36"/>
        <source>A ground plane&apos;s normal lies at most this far from the expected up direction.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="37"/>
        <source>A ground point&apos;s own normal lies at most this far from the plane&apos;s.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="38"/>
        <source>A ground-truth or odometry pose belongs to a frame when this close in time.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="39"/>
        <source>A ground-truth pose belongs to a frame when this close in time.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="40"/>
        <source>A line needs at least this many points (2 = seed; more rejects clutter).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="41"/>
        <source>A line this close to a Manhattan axis is classed as parallel (0) or perpendicular (1) to the reference.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="42"/>
        <source>A pose belongs to a frame when this close in time.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="43"/>
        <source>A region whose centroid is farther from the tap and that does not contain it is not the tapped button (seed method).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="44"/>
        <source>A segment&apos;s raised height is this quantile of its heights above the ground.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="45"/>
        <source>A sloped segment whose plane meets the ground within this distance of its lowest points is connected to the ground (a ramp), not raised.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="46"/>
        <source>A streaming device that delivers nothing for this long is treated as lost and reopened; 0 never does (e.g. waiting for rare hardware triggers).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="47"/>
        <source>A track must return to its start within this when tracked backwards; 0 = no check.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="48"/>
        <source>A track seen from a direction differing more than this from its anchor&apos;s is anchored anew: the further aside, the more a wrongly fitted or assumed surface (the road taken as facing the camera) misleads the warp; 3 suits subsampled driving.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="49"/>
        <source>A track whose patch would be scaled by more than this fraction since its anchor (the camera came close) is anchored anew.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="50"/>
        <source>A track&apos;s surface is fitted as a plane to the tracks within this radius at a similar depth, so the anchor&apos;s patch is warped as that plane; 0 = every patch is taken as facing the camera.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="51"/>
        <source>Accuracy: a segment is compared with the true region holding this fraction of its points.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="52"/>
        <source>Adaptive termination: stop when an outlier-free sample was drawn with this probability given the best inlier fraction; 1 = always max_iterations.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="53"/>
        <source>Add features of confidently tracked frames to the model when the button&apos;s apparent size has changed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="54"/>
        <source>After a loss, search whole frames and re-acquire the button only on a confident match at a plausible size.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="55"/>
        <source>Agreement of the voting lines modulo 90 deg (1 = perfect); below it the frame&apos;s walls are not used.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="56"/>
        <source>Also list and open Aravis&apos; in-process simulated camera Fake_1 (demos and tests).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="57"/>
        <source>Also project current points into the previous images (uses both depths).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="58"/>
        <source>An aligned patch whose zero-mean normalised correlation with the warped anchor patch is lower failed (occlusion, reflection).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="59"/>
        <source>An alignment that moves the tracked position further than this failed (the KLT position is kept and the track anchored anew).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="60"/>
        <source>An anchor is used for at most this many frames; then the track is anchored anew.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="61"/>
        <source>An arm_pose message with more joint positions is refused.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="62"/>
        <source>An arm_pose position farther than this from the base is refused.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="63"/>
        <source>Analog gain; negative keeps the camera&apos;s. Out-of-range values are errors.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="64"/>
        <source>Angle between scan rays (seed res_scan = 0.2 deg).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="65"/>
        <source>Ask the device to deliver depth and colour frames of the same instant.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="66"/>
        <source>Authorised clients at most; further ones are closed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="67"/>
        <source>Band of the refinement (offset histogram bin and refit band): narrower than err_max, so that a door recessed behind the wall face does not tilt the line.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="68"/>
        <source>Baseline over the median depth of the first points needed to accept (0.07 is a 4 deg ray angle sideways); a short baseline gives a distorted first map and a drifting scale.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="69"/>
        <source>Best over second-best descriptor distance in a window; 1 = off.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="70"/>
        <source>Camera pitched down by this: expected up = camera -y turned by pitch and roll.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="71"/>
        <source>Camera roll.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="72"/>
        <source>Canny lower threshold.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="73"/>
        <source>Canny upper threshold.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="74"/>
        <source>Cell edge of the global map.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="75"/>
        <source>Cell of the keypoint grid used by window searches.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="76"/>
        <source>Collinear lines (angles this close, one fit within the threshold) are merged.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="77"/>
        <source>Compute SIFT only in a window around the predicted centre (fast).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="78"/>
        <source>Connections still owing the token at most; a new one closes the oldest.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="79"/>
        <source>Consecutive frames of constant-motion fallback before the pose is held.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="80"/>
        <source>Consecutive scan points farther apart than this start a new run.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="81"/>
        <source>Consistent matches needed to re-acquire a lost button.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="82"/>
        <source>Correct the heading with the walls&apos; Manhattan directions; off = dead reckoning only.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="83"/>
        <source>Demosaic Bayer formats to BGR colour; off delivers the raw mosaic as grey.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="84"/>
        <source>Depth beyond this is left out of the 3D cloud.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="85"/>
        <source>Depth images are sampled to about this many columns (seed: 320 x 240).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="86"/>
        <source>Depth points a cell needs to count as occupied (1 = seed: any non-floor point).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="87"/>
        <source>Depth readings beyond this are treated as invalid downstream.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="88"/>
        <source>Depth readings beyond this count as invalid.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="89"/>
        <source>Depth sigmas (of both points at both times) added to the rigidity tolerance.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="90"/>
        <source>Descriptor matches with a keyframe needed to try relocalisation.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="91"/>
        <source>Disparity noise giving the depth sigma Z^2 s / (f b).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="92"/>
        <source>Displacement pairs between consecutive keyframes (poses refined by bundle adjustment) or between tracked frames scale_interval_frames apart.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="93"/>
        <source>Distance from the epipolar line allowed for a new-point match.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="94"/>
        <source>Distance gate: a match farther than this from the predicted centre is dropped.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="95"/>
        <source>Draws per hypothesis to find a pair within the distance limits.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="96"/>
        <source>Edge of one occupancy cell; RANSAC&apos;s 5-cell error scales with it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="97"/>
        <source>Epipolar (row) constraint: largest row difference of a match.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="98"/>
        <source>Estimate a constant disparity offset of the rig (rectification or matcher bias) online from the motion, and add it to every disparity; an offset of a fraction of a pixel moves far points most and makes the translation too long or too short.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="99"/>
        <source>Estimate each pose against the last keyframe&apos;s stereo observations of the tracks (after the frame-to-frame estimate), so per-frame errors do not accumulate.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="100"/>
        <source>Exposure time; 0 keeps the camera&apos;s. Out-of-range values are errors.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="101"/>
        <source>FAST corner threshold.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="102"/>
        <source>FLANN leaf checks per query.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="103"/>
        <source>FLANN randomised kd-trees.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="104"/>
        <source>Faster estimated rotation is rejected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="105"/>
        <source>Faster estimated translation is rejected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="106"/>
        <source>Features kept per frame, tracked plus new.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="107"/>
        <source>Features this close to the border are dropped.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="108"/>
        <source>Features within this many button radii of the centre are added.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="109"/>
        <source>Fewer SIFT keypoints on the region: the button cannot be tracked.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="110"/>
        <source>Fewer consistent matches: the button is lost.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="111"/>
        <source>Fewer inliers after refinement is rejected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="112"/>
        <source>Fewer inliers than this fraction of the points: the plane is not sound.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="113"/>
        <source>Fewer inliers than this means the motion could not be estimated.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="114"/>
        <source>Fewer map points or plane inliers: no normal in this frame.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="115"/>
        <source>Fewer points left after the range cut is reported as an error.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="116"/>
        <source>Fewer points than this: the plane is not sound (no target is sent).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="117"/>
        <source>Fewer points: no 3D position.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="118"/>
        <source>Fewest tracks (the track included) a surface is fitted to.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="119"/>
        <source>Field of view to scan, centred on forward; 0 = the camera&apos;s own (rays outside it can never hit anything).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="120"/>
        <source>Floor calibration (sightline-cli floor) giving the expected up direction; empty = mobility.mount_pitch_deg / mount_roll_deg.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="121"/>
        <source>Floor calibration file (sightline-cli floor); empty = calibrate from the first frames of the run.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="122"/>
        <source>Floor of the residual RMS by which each frame pair&apos;s measurement is weighted.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="123"/>
        <source>Format of trajectory.txt; --format kitti.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="124"/>
        <source>Fraction of a circle&apos;s rim that must lie on an edge.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="125"/>
        <source>Fraction of directions around a region&apos;s centre in which its outline lies; a button&apos;s (even broken) outline surrounds its centre.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="126"/>
        <source>Fraction of the correction applied per frame (1 = take the walls&apos; heading).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="127"/>
        <source>Frame rate of overlay.avi.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="128"/>
        <source>Frame results carry a rendered map image every n frames (0 = never).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="129"/>
        <source>Frames between two keyframes at least.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="130"/>
        <source>Frames buffered between the capture thread and the consumer; when full the oldest is dropped, so latency stays bounded.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="131"/>
        <source>Frames in the window; the oldest is held fixed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="132"/>
        <source>Frames read before subsampling; 0 = all.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="133"/>
        <source>Frames read; 0 = all.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="134"/>
        <source>Frames spanned by one displacement pair of the scale estimators.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="135"/>
        <source>Frames that left the window keep constraining its points this long, with their poses held fixed, so the window&apos;s drift does not restart at every slide.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="136"/>
        <source>Frames to process; 0 = all.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="137"/>
        <source>Frames to read; 0 reads the whole recording.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="138"/>
        <source>Frames tried against one first frame before it is replaced.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="139"/>
        <source>Frames used to calibrate the floor when no floor_file is given.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="140"/>
        <source>Free scaling of cv::stereoRectify: 0 keeps only valid pixels, 1 keeps all.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="141"/>
        <source>Free-running frame rate, or the host&apos;s rate with software triggering; 0 keeps the camera&apos;s. Rates the camera cannot reach are errors.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="142"/>
        <source>Gauss-Newton iterations of the alignment.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="143"/>
        <source>Gauss-Newton iterations on the reprojection error; 0 keeps the RANSAC motion.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="144"/>
        <source>Gauss-Newton steps on the reprojection error of each 3-point sample.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="145"/>
        <source>Gaussian blur before edge detection.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="146"/>
        <source>GenICam pixel format to select (Mono8, Mono16, BayerRG8, RGB8, ...); empty keeps the camera&apos;s. 16-bit formats are scaled to 8 bits.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="147"/>
        <source>GigE receive socket buffer; 0 lets Aravis size it to a whole frame (without it most packets of large frames are lost).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="148"/>
        <source>GigE stream packet size; 0 negotiates the largest packet that reaches the host.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="149"/>
        <source>Global bundle adjustment of every keyframe and point when the run stops (0 = none).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="150"/>
        <source>Grab() returns the newest frame and skips older queued ones (views); off hands out every queued frame in order (recording).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="151"/>
        <source>Ground RANSAC inlier distance at the sensor ...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="152"/>
        <source>HOG boxes include padding; each side is shrunk by this fraction of the box.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="153"/>
        <source>Half size of the search window.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="154"/>
        <source>Half-size of the sub-pixel corner refinement at full resolution after detection on a reduced level; 0 = none.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="155"/>
        <source>Headless runs write the overlay of the track from the tap on as a PNG sequence (overlay/frame_NNNNNN.png, one per row of button.csv).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="156"/>
        <source>Heartbeat period; 0 = none.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="157"/>
        <source>Height of the occupancy image (seed: 400), i.e. the forward range in cells.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="158"/>
        <source>Highest plausible camera height above the floor.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="159"/>
        <source>Hough accumulator threshold.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="160"/>
        <source>How long Grab() waits for a frame before reporting the device as unavailable.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="161"/>
        <source>Huber loss threshold of bundle adjustment.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="162"/>
        <source>Huber threshold of the robust pose optimisation.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="163"/>
        <source>Huber threshold of the robust weight of an observation&apos;s reprojection error.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="164"/>
        <source>Huber threshold of the robust weight.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="165"/>
        <source>Huber threshold of the robust weights of the offset measurement.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="166"/>
        <source>Hypotheses per line: fixed (max_iterations, seed) or adaptive log(1-p)/log(1-w^2) with w the best inlier ratio so far.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="167"/>
        <source>IPv4 address the target server binds; 127.0.0.1 keeps it on this machine.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="168"/>
        <source>Image buffers in the stream&apos;s pool; more ride out longer consumer stalls.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="169"/>
        <source>Image pyramid step of the HOG detector (smaller is slower and finds more).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="170"/>
        <source>Inlier RMS above this: the plane is not sound.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="171"/>
        <source>Inlier distance of the panel plane.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="172"/>
        <source>Inliers needed to accept a relocalisation.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="173"/>
        <source>Input line used with hardware triggering, e.g. Line1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="174"/>
        <source>Iterations of each local bundle adjustment (0 = none).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="175"/>
        <source>KLT iterations per level.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="176"/>
        <source>KLT pyramid levels above full resolution (shared with stereo matching).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="177"/>
        <source>KLT pyramid levels used around the disparity guess.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="178"/>
        <source>KLT stops when its update is smaller than this.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="179"/>
        <source>KLT window side (odd).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="180"/>
        <source>Larger 1-sigma position uncertainty: no target.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="181"/>
        <source>Larger 1-sigma uncertainty of the approach direction (the panel normal): no target.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="182"/>
        <source>Larger change of velocity from the last accepted motion is rejected; 0 = no check.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="183"/>
        <source>Larger median offset of the face points from the panel plane is not applied.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="184"/>
        <source>Largest Hamming distance of a new-point match.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="185"/>
        <source>Largest Hamming distance of a tracked ORB match.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="186"/>
        <source>Largest Hough circle radius.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="187"/>
        <source>Largest angle between the floor normal and the camera&apos;s up axis (-y).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="188"/>
        <source>Largest button region as a fraction of the image area.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="189"/>
        <source>Largest depth/colour timestamp difference of an RGB-D pair from a device; frames without a partner are dropped and counted.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="190"/>
        <source>Largest difference between the left and right timestamps of a pair; frames without a partner are dropped and counted.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="191"/>
        <source>Largest disparity searched and accepted.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="192"/>
        <source>Largest size change (either way) since the last tracked frame at re-acquisition.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="193"/>
        <source>Left-right check: the right point tracked back must land this close; 0 = no check.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="194"/>
        <source>Length of the first baseline in map units (PTAM: 0.1); metric scale comes later.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="195"/>
        <source>Levenberg-Marquardt iterations per frame.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="196"/>
        <source>Lines vote with weight length / (1 + (rms / rms_scale_m)^2): scattered consensus sets (a wall merged with a door recess) count less.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="197"/>
        <source>Lines with fewer points are dropped.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="198"/>
        <source>Log-odds added when a frame sees a cell free.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="199"/>
        <source>Log-odds added when a frame sees a cell occupied.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="200"/>
        <source>Longer client lines are discarded; an over-long token line closes the connection.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="201"/>
        <source>Longer image side at which contours are searched; larger frames are scaled down.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="202"/>
        <source>Longest over shortest side of the region&apos;s rotated box.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="203"/>
        <source>Lowe&apos;s ratio test: best over second-best descriptor distance must be below this.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="204"/>
        <source>Lower clamp of a cell&apos;s log-odds.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="205"/>
        <source>Lowest plausible camera height above the floor.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="206"/>
        <source>Map points projecting within this distance of the button centre are used.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="207"/>
        <source>Map points within this many tracked button radii (the button&apos;s face) are used first; 0 = always use radius_px.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="208"/>
        <source>Matches with a smaller disparity (too far to triangulate) are rejected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="209"/>
        <source>Matches with the first frame needed before initialisation is tried.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="210"/>
        <source>Measured displacements shorter than this are dropped.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="211"/>
        <source>Measured motion for the metric scale: the arm&apos;s recorded poses (arm_poses.txt), the arm&apos;s poses streamed live to the button pipeline&apos;s arm-target server (arm_stream), ground-truth displacements, or none. auto: the recorded arm poses when arm_poses.txt is there; else, for the button pipeline while serving, the stream; else (mono-slam) ground truth.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="212"/>
        <source>Median angle between the rays of a match needed before trying (move sideways).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="213"/>
        <source>Minimum distance between corners.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="214"/>
        <source>Mirror images left-right, as OpenNI does by default for people facing the camera.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="215"/>
        <source>Morphological closing that joins broken button outlines; 0 = none.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="216"/>
        <source>Most recent keyframes whose poses local bundle adjustment optimises.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="217"/>
        <source>New centre: the model centre through a RANSAC similarity of the matches, or the matched keypoints&apos; centroid (the seed&apos;s rule).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="218"/>
        <source>Niceness of the mapping thread (threaded mode, Linux); 10 lets tracking win a core it shares with mapping, but starves mapping on a loaded machine.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="219"/>
        <source>No pose is interpolated across a larger gap between two arm_pose messages.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="220"/>
        <source>No second reset within this many frames of the last one.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="221"/>
        <source>No target until the online hand-eye check has seen the mount&apos;s translation (the arm must rotate between keyframes); without it that translation is taken on trust.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="222"/>
        <source>Noise of a camera displacement measured in the map (sigma_x of the ML estimator).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="223"/>
        <source>Noise of a displacement measured by the arm or robot (sigma_y).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="224"/>
        <source>ORB keypoints extracted per frame.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="225"/>
        <source>Observations reprojecting worse than this are dropped from the window.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="226"/>
        <source>Observations with a smaller disparity (no usable depth) are left out.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="227"/>
        <source>Occupied cells closer than this to the robot are ignored (robot body, noise).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="228"/>
        <source>Occupied evidence: the polar scan&apos;s hits (visible surfaces, thin walls) or every occupied cell of the occupancy image (as the seed; depth noise behind walls stays).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="229"/>
        <source>Of the re-acquiring matches, at least this many lie on the button itself.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="230"/>
        <source>Older estimates are not sent.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="231"/>
        <source>Older frames&apos; normals fade with exp(-age / this) in the average (data time); 0 = this frame&apos;s normal only.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="232"/>
        <source>On close: how long the stop lines may take to go out before the sockets close.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="233"/>
        <source>On the button: within this many radii of its centre.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="234"/>
        <source>Only frames tracked at least this confidently refresh the model.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="235"/>
        <source>Otherwise: the camera&apos;s optical centre this far ahead of the odometry base.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="236"/>
        <source>Outlier removal: keep points with mean neighbour distance &lt;= mu + alpha sigma.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="237"/>
        <source>Pairs weigh |measured displacement|^-e in the ML estimate: 1 = the map&apos;s error grows with the distance travelled, 0 = every pair equally noisy.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="238"/>
        <source>Pairs whose own ratio lies outside a factor of this from the estimate are dropped.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="239"/>
        <source>Pause between attempts to reopen a lost device.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="240"/>
        <source>Per-client queue length; a slow client loses its oldest messages (counted).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="241"/>
        <source>Per-segment plane RANSAC inlier distance.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="242"/>
        <source>Per-segment plane RANSAC iterations before the least-squares refit (0 = PCA only).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="243"/>
        <source>Pixel format as a FOURCC, e.g. MJPG for high resolutions over USB 2; empty keeps the camera&apos;s.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="244"/>
        <source>Pixels in a person box within this depth of the box&apos;s median depth are the person.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="245"/>
        <source>Place every kept position again with the newest metric scale (kept in map units).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="246"/>
        <source>Plane RANSAC hypotheses of the panel normal.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="247"/>
        <source>Plane RANSAC hypotheses.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="248"/>
        <source>Plane inlier distance.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="249"/>
        <source>Point-to-plane distance of an inlier while fitting the floor.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="250"/>
        <source>Points are subsampled evenly to at most this many.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="251"/>
        <source>Points each ground hypothesis is scored on.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="252"/>
        <source>Points farther than this are not used for the fit.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="253"/>
        <source>Points found in fewer of the frames that should see them are culled.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="254"/>
        <source>Points higher than this above the floor (ceiling, lamps) are ignored.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="255"/>
        <source>Points on the button&apos;s face that move the panel plane onto the face.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="256"/>
        <source>Points whose neighbourhood bends more (surface variation, 0 = flat) get no normal and stay unsegmented: edges between surfaces.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="257"/>
        <source>Prior standard deviation of the offset around zero; smaller trusts the calibration longer.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="258"/>
        <source>Probability above which a cell is occupied (map.yaml occupied_thresh).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="259"/>
        <source>Probability below which a cell is free (map.yaml free_thresh).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="260"/>
        <source>Process every k-th frame (the seed&apos;s subsampling sweep); --subsample K.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="261"/>
        <source>Publish the targets through the arm-target server (button.arm.*); --serve HOST:PORT.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="262"/>
        <source>Pyramid level Shi-Tomasi corners are detected on (0 = full resolution).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="263"/>
        <source>Pyramid level of the row search for features without a disparity guess.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="264"/>
        <source>Pyramid levels of the second tracking attempt (reaches about 2^levels further).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="265"/>
        <source>Pyramid levels.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="266"/>
        <source>RANSAC inlier distance of the essential matrix and the homography.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="267"/>
        <source>RANSAC plane hypotheses (half of them sampled within one voxel).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="268"/>
        <source>Random generator seed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="269"/>
        <source>Random generator seed; each scan starts from it, so results are reproducible.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="270"/>
        <source>Random seed of the plane RANSAC.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="271"/>
        <source>Rate at which a replayed recording delivers frames; 0 follows its timestamps.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="272"/>
        <source>Ray angle a first map point needs.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="273"/>
        <source>Ray angle a new map point needs.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="274"/>
        <source>Rays stop at this range; 0 = at the occupancy image border.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="275"/>
        <source>Re-acquisition is refused when the other matches support a second similarity with this fraction of the inliers (another button of a repeated panel).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="276"/>
        <source>Recent keyframes a new keyframe triangulates new points with.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="277"/>
        <source>Rectify even when the rig says its images are rectified.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="278"/>
        <source>Refine every tracked position against the track&apos;s anchor (where it was first seen), its patch warped by the motion since, so tracks do not drift frame by frame.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="279"/>
        <source>Refine the 3D points with the motion (two-frame bundle adjustment); removes the depth bias of triangulation.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="280"/>
        <source>Refine the last frames&apos; poses and their tracks&apos; points together on the stereo reprojection error (sliding-window bundle adjustment), so per-frame errors do not add up.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="281"/>
        <source>Refined RMS reprojection error above this is rejected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="282"/>
        <source>Refinement rounds: refine, re-select inliers by the reprojection threshold, refine.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="283"/>
        <source>Region from the tap: outlines at two scales plus Hough circles, the one holding the tap nearest its centre (multiscale), or the seed&apos;s rule (the centroid nearest the tap within max_tap_distance_px).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="284"/>
        <source>Region growing: largest RGB-N colour distance between neighbours (255 (n+1)/2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="285"/>
        <source>Region-of-interest height; 0 keeps the camera&apos;s.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="286"/>
        <source>Region-of-interest width; 0 keeps the camera&apos;s.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="287"/>
        <source>Register depth to the colour camera in the device when it supports it, so that depth and colour pixels correspond.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="288"/>
        <source>Reprojection error a first map point may have in either view.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="289"/>
        <source>Reprojection error a new map point may have in either keyframe.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="290"/>
        <source>Requested frame rate; 0 keeps the camera&apos;s.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="291"/>
        <source>Requested image height; 0 keeps the camera&apos;s.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="292"/>
        <source>Requested image width; 0 keeps the camera&apos;s. V4L2 picks the nearest mode.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="293"/>
        <source>Reset rule: a pose-source move larger than this between two frames resets the reference.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="294"/>
        <source>Reset rule: a pose-source turn larger than this between two frames resets the reference.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="295"/>
        <source>Reset rule: this many consecutive frames whose walls disagree by more than max_correction_deg reset the reference.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="296"/>
        <source>Residual beyond which a match is an outlier.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="297"/>
        <source>Rigid samples tried at least before adaptive termination may stop.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="298"/>
        <source>Roughness triangulation in plane coordinates: the cells&apos; grid or 2D Delaunay.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="299"/>
        <source>Roughness uses the segment&apos;s points within this range (all when none is).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="300"/>
        <source>Roughness: points are averaged in plane cells of this size, then triangulated.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="301"/>
        <source>Row search: mean absolute difference above this means no match.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="302"/>
        <source>Run mapping on its own thread (live); off = inline after each keyframe, deterministic.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="303"/>
        <source>SAD window side of the row search, at its level.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="304"/>
        <source>SIFT contrast threshold.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="305"/>
        <source>SIFT contrast threshold; lower finds more keypoints on plain buttons.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="306"/>
        <source>SIFT keypoints up to this far outside the region belong to the button model.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="307"/>
        <source>SVM score a HOG window needs to count as a person.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="308"/>
        <source>Scale between pyramid levels.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="309"/>
        <source>Score drawn in the maps: the seed&apos;s Table I rule or the Gaussian process.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="310"/>
        <source>Scored cloud written per frame.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="311"/>
        <source>Search window around a map point&apos;s predicted position.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="312"/>
        <source>Seed eq. 13: depth-to-colour sensor offset along x.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="313"/>
        <source>Seed eq. 13: depth-to-colour sensor offset along y.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="314"/>
        <source>Seed eq. 6: expected inlier ratio w; iterations = log(1-p) / log(1-w^3).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="315"/>
        <source>Seed eq. 6: wanted probability p of drawing one all-inlier sample.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="316"/>
        <source>Serve the targets to the arm over TCP (button.arm.bind_address, port, token); 127.0.0.1:5757 by default. The same as button.run.serve. Switching it keeps the run (map, button, STOP); switching it off sends the arm a stop line.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="317"/>
        <source>Shi-Tomasi gradient window.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="318"/>
        <source>Shi-Tomasi: smallest minimum eigenvalue of a corner (cv::cornerMinEigenVal units).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="319"/>
        <source>Shorter lines are dropped.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="320"/>
        <source>Side of the aligned patch (odd).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="321"/>
        <source>Side of the detection grid&apos;s buckets; each holds at most its share of max_features.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="322"/>
        <source>Similarity RANSAC inlier distance.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="323"/>
        <source>Size change since the last refresh that triggers the next.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="324"/>
        <source>Smaller estimates are not applied: within the spread the estimate shows on a rig without offset (the simulator: +-0.03 px).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="325"/>
        <source>Smaller regions stay unsegmented and unscored.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="326"/>
        <source>Smallest 1-sigma stated for one frame&apos;s normal (the map points&apos; errors are correlated, so the fit&apos;s own figure is optimistic).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="327"/>
        <source>Smallest Hough circle radius.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="328"/>
        <source>Smallest approach_sigma_deg a target states: the average of frames that share one map does not beat the map&apos;s own bias (on the simulated approach with the SLAM&apos;s map, up to 4.3 deg against per-frame fits of 0.5 deg).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="329"/>
        <source>Smallest button region.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="330"/>
        <source>Split a piece while a point lies farther than this from its chord; merge pieces that fit one line within it (cells, like RANSAC&apos;s err_max).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="331"/>
        <source>Start a new map when the reset rule fires (seed); off keeps stitching.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="332"/>
        <source>Start again at the end (timestamps keep increasing) instead of ending the stream.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="333"/>
        <source>Step B2: ... and at most this far apart (no lines across the room).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="334"/>
        <source>Step B2: the two sampled points must be at least this far apart (no short lines).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="335"/>
        <source>Step B6: cut the consensus set at gaps wider than this along the line and keep the longest piece, so that lines are contiguous walls (0 = seed: no cut).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="336"/>
        <source>Step B7: keep the hypothesis with the lowest summed error (seed) or mean error.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="337"/>
        <source>Step C: re-find the chosen line&apos;s dominant surface by sweeping its direction this far either way, then refit on it (0 = seed: the line of step B6 as is).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="338"/>
        <source>Stereo calibration (OpenCV stereo YAML as `sightline-cli calibrate stereo` writes) used instead of the source&apos;s; needed for live pairs (aravis://L,R) opened without one.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="339"/>
        <source>Stereo calibration of the pair (OpenCV stereo YAML: M1 D1 M2 D2 R T, image_width/height, as `sightline-cli calibrate stereo` writes); the stereo odometry needs it. Also as aravis://LEFT,RIGHT?calibration_file=FILE.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="340"/>
        <source>Stop when the update is smaller (radians or metres).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="341"/>
        <source>Stream colour.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="342"/>
        <source>Stream depth.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="343"/>
        <source>Stream height for depth and colour; 0 keeps the device&apos;s default mode.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="344"/>
        <source>Stream rate; 0 keeps the device&apos;s default mode.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="345"/>
        <source>Stream width for depth and colour; 0 keeps the device&apos;s default mode.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="346"/>
        <source>TCP port of the target server; 0 = any free port.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="347"/>
        <source>Take the camera&apos;s offset ahead of the odometry base from the recording&apos;s scene.yaml (simulator) when present.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="348"/>
        <source>The SIFT margin grows to this many region radii when that is larger.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="349"/>
        <source>The approach direction is the normal of a plane through the map points within this distance of the located button (the panel around it).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="350"/>
        <source>The arm&apos;s and the SLAM&apos;s displacement directions disagree by more than this (online hand-eye check; a wrong mount rotation): no target.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="351"/>
        <source>The arm&apos;s clock minus the camera&apos;s (configured; arm stamp = frame stamp + this).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="352"/>
        <source>The colour image is downscaled to at most this width before detection.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="353"/>
        <source>The current frame becomes the keyframe when fewer keyframe tracks agree with the motion.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="354"/>
        <source>The current frame becomes the keyframe when fewer of the keyframe&apos;s tracks survive.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="355"/>
        <source>The depth colour map spans zero to this range.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="356"/>
        <source>The estimated offset is clamped to +- this.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="357"/>
        <source>The floor is the lowest plane: at most this fraction of points may lie clearly below it (rejects table tops).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="358"/>
        <source>The floor must hold at least this fraction of the valid points.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="359"/>
        <source>The gate grows to this many predicted button radii when that is larger.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="360"/>
        <source>The gate widens by this per metre driven since the last correction (expected heading drift of the pose source).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="361"/>
        <source>The homography is chosen when its share of the inliers exceeds this.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="362"/>
        <source>The map grows by at least this much each time it must.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="363"/>
        <source>The maximum-likelihood estimate is reported from this many pairs on.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="364"/>
        <source>The metric scale counts as converged with this many displacement pairs in the ML estimate at least ...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="365"/>
        <source>The model never grows beyond this many keypoints.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="366"/>
        <source>The offset is measured between an anchor frame and the first later frame whose translation from it reaches this fraction of the common tracks&apos; median depth: with less parallax, tracking errors dominate the measurement.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="367"/>
        <source>The online hand-eye check compares keyframes at least this far apart (measured): the directions of shorter displacements drown in the noise.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="368"/>
        <source>The online hand-eye check sees the mount&apos;s translation only when the arm rotates at least this much between two keyframes.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="369"/>
        <source>The operator&apos;s tap is refused when the frame it was made on is older than this (data time) by the time the pipeline takes it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="370"/>
        <source>The operator&apos;s tap: X,Y in pixels, optionally @FRAME (frame index, default 0); confirmed at once. sightline-cli run button --tap X,Y[@FRAME] sets it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="371"/>
        <source>The target is the per-axis median of this many recent base-frame positions (sound plane, converged scale); 0 = every one since the tap, 1 = no fusion.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="372"/>
        <source>The tracking gate never exceeds this: larger corrections are not applied.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="373"/>
        <source>The window grows to this many predicted button radii when that is larger.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="374"/>
        <source>Tolerance of accuracy.map_iou: a map cell within this many cells of a true wall counts as on it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="375"/>
        <source>Top-view grid cell.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="376"/>
        <source>Track points drawn behind the button on the overlay.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="377"/>
        <source>Tracking gate right after a correction: lines farther than this from the expected direction neither vote nor correct.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="378"/>
        <source>Tracking is lost when fewer than this share of the map points predicted in the image are found (PTAM&apos;s test against a wrong pose after a jump).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="379"/>
        <source>Tracking quality is good from this many inliers.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="380"/>
        <source>Tracking quality is poor from this many inliers; fewer is lost.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="381"/>
        <source>Triangulated points needed to accept the initialisation.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="382"/>
        <source>UMBRAL1: change of a pairwise distance a rigid sample may show, before depth uncertainty is added.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="383"/>
        <source>UMBRAL2: rigidity rejections after which RANSAC fails (the last motion is kept).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="384"/>
        <source>UMBRAL3: reprojection error (RMS of both images) of an inlier.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="385"/>
        <source>UMBRAL4: stop sampling once this fraction of the points is inlier.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="386"/>
        <source>UMBRAL5: rigid samples tried before the best inlier set is taken.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="387"/>
        <source>Up-facing planes searched; the lowest large one is the ground.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="388"/>
        <source>Upper clamp of a cell&apos;s log-odds.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="389"/>
        <source>Use every n-th depth pixel for the 3D cloud; 1 shows all (slower).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="390"/>
        <source>Viewing ray closer to parallel with the plane than this |cos|: no position.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="391"/>
        <source>Voting lines within this of their length-weighted median are averaged; others (a wall merged with a recessed door, a box) are dropped.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="392"/>
        <source>Voting wall length a frame needs before it may set the reference direction.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="393"/>
        <source>Voxel size for locally sampled hypotheses (finds a floor that covers little of the view).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="394"/>
        <source>Wall lines shorter than this do not vote for the direction.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="395"/>
        <source>Wall lines with fewer scan points do not vote.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="396"/>
        <source>Wall-line extractor: the seed&apos;s multi-line RANSAC or split-and-merge.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="397"/>
        <source>Weaker tracking confidence: no target.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="398"/>
        <source>Weigh each position by 1 / its own variance (plane fit and tracked centre, growing with the distance): the near frames of the approach count most. Off by default: measured worse on the simulated approaches (docs/button.md).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="399"/>
        <source>Weight observations by 1 / (|u - cx| / cx + 0.05) (libviso2), favouring the centre, as the two-frame refinement does.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="400"/>
        <source>Weight observations by 1 / (|u - cx| / cx + 0.05) (libviso2), favouring the centre.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="401"/>
        <source>Weight of the fused positions&apos; spread (1.4826 x median absolute deviation from the fused target) in the stated uncertainty.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="402"/>
        <source>What replaces a rejected motion: the last accepted one, or none.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="403"/>
        <source>When fewer tracks survive than this fraction of the share that survived in the previous frame (poor motion prediction), the lost ones are tracked again with retrack_pyramid_levels; 0 = never.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="404"/>
        <source>When set, a client must send {&quot;token&quot;: &quot;...&quot;} before it receives anything; required when bind_address is not a loopback address.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="405"/>
        <source>Where person boxes come from: the dataset&apos;s ground truth, OpenCV&apos;s HOG detector, auto (ground truth when present, else HOG) or none.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="406"/>
        <source>Width of the occupancy image (seed: 400); the robot sits at its bottom centre.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="407"/>
        <source>Window of the second pass, after a first pose.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="408"/>
        <source>Window used when the first search finds too few points.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="409"/>
        <source>With a token: a connection that has not presented it after this long is closed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="410"/>
        <source>With png: also overlay.avi (Motion-JPEG through OpenCV&apos;s built-in writer).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="411"/>
        <source>With serve: give up waiting for clients after this long.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="412"/>
        <source>With serve: keep serving this long after the last frame so queued targets go out.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="413"/>
        <source>With serve: wait for this many connected clients before the first frame.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="414"/>
        <source>Without a reference: lines within this of the best-supported direction (modulo 90 deg) vote.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="415"/>
        <source>Workspace box, base x max.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="416"/>
        <source>Workspace box, base x min.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="417"/>
        <source>Workspace box, base y max.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="418"/>
        <source>Workspace box, base y min.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="419"/>
        <source>Workspace box, base z max.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="420"/>
        <source>Workspace box, base z min.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="421"/>
        <source>Write the projection and top-view PNGs per frame.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="422"/>
        <source>accuracy.wall_recall: a true wall is visible in a frame when at least this much of it is in view ...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="423"/>
        <source>arm_pose messages closer than 1/this in the arm&apos;s time are dropped (counted).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="424"/>
        <source>arm_pose messages older than this behind the newest are forgotten.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="425"/>
        <source>arm_poses.txt (base_from_end_effector, TUM); empty = beside the sensor folder.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="426"/>
        <source>custom platform: a segment raised more than this above the ground scores 0.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="427"/>
        <source>custom platform: points farther from the sensor are dropped.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="428"/>
        <source>delaunay: triangles with an edge longer than this many cells are dropped.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="429"/>
        <source>device: pair by camera timestamps (cameras on a common clock, e.g. PTP or a shared trigger); host: pair by arrival time at the host.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="430"/>
        <source>epsilon_floor: a point within this height of the floor plane is floor (seed 3.5, read as 3.5 cm: generous so that no floor pixel is labelled occupied).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="431"/>
        <source>err_max: inlier distance in occupancy cells (seed: 5 pixels); metres = cells x mapping.occupancy.cell_size_m.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="432"/>
        <source>free: the camera runs on its own clock; software: the host triggers each frame (both cameras of a pair together); hardware: an external pulse on trigger_line.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="433"/>
        <source>grid: every n-th pixel in both directions (stands in for the voxel grid).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="434"/>
        <source>grid: grid neighbours whose depths differ by more than this fraction are apart.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="435"/>
        <source>grid: half-width of the integral-image normal window.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="436"/>
        <source>grid: organized pixel-grid path (fast); pcl: the seed&apos;s voxel grid, outlier removal and k-d tree path.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="437"/>
        <source>hand_eye.yaml (end_effector_from_camera); empty = beside arm_poses (for arm_stream: beside the images); none = identity.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="438"/>
        <source>i_max (step E): at most this many lines.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="439"/>
        <source>j_max: hypotheses per line (seed: 250); also caps the adaptive count.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="440"/>
        <source>multiscale: add Hough circles (round buttons, thin rings).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="441"/>
        <source>multiscale: blur of the second scale, times blur_sigma_px.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="442"/>
        <source>multiscale: half size of the window around the tap that is searched.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="443"/>
        <source>multiscale: longest over shortest side of a region&apos;s rotated box.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="444"/>
        <source>multiscale: regions are ranked by (offset + bias) / radius, so the button&apos;s outline wins over a glyph on it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="445"/>
        <source>multiscale: the region&apos;s centroid lies at most this many radii from the tap.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="446"/>
        <source>multiscale: the two Canny pairs are the thresholds times 2/(1+s) and 2s/(1+s).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="447"/>
        <source>p of the adaptive count: probability of drawing one all-inlier pair.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="448"/>
        <source>pcl: neighbour radius of the region growing.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="449"/>
        <source>pcl: neighbours of the normal fit.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="450"/>
        <source>pcl: neighbours of the outlier removal.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="451"/>
        <source>pcl: voxel grid leaf size.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="452"/>
        <source>ratio_max (step B8): a hypothesis with more inliers than this ends the search.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="453"/>
        <source>ratio_min (steps B5, B6): a line needs this fraction of the remaining points.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="454"/>
        <source>ratio_scan_max (step E): stop once this fraction of the points lies on lines.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="455"/>
        <source>wheelchair: 5 m range, 3 cm step; icub: 1.75 m, 5 cm (the seed&apos;s humanoid); custom: range_cut_m and max_step_m.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>sightline::ParameterPanel</name>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="46"/>
        <source>Filter options</source>
        <translation>Filtrar opciones</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="50"/>
        <source>Load profile…</source>
        <translation>Cargar perfil…</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="53"/>
        <source>Save profile…</source>
        <translation>Guardar perfil…</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="56"/>
        <source>Reset all</source>
        <translation>Restablecer todo</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="165"/>
        <source>All options reset to their defaults.</source>
        <translation>Todas las opciones vuelven a sus valores por defecto.</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="176"/>
        <source>Loaded profile %1</source>
        <translation>Perfil %1 cargado</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="187"/>
        <source>Saved profile %1</source>
        <translation>Perfil %1 guardado</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="194"/>
        <source>Load profile</source>
        <translation>Cargar perfil</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="194"/>
        <source>YAML profiles (*.yaml *.yml);;All files (*)</source>
        <translation>Perfiles YAML (*.yaml *.yml);;Todos los archivos (*)</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="201"/>
        <source>Save profile</source>
        <translation>Guardar perfil</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="202"/>
        <source>YAML profiles (*.yaml *.yml)</source>
        <translation>Perfiles YAML (*.yaml *.yml)</translation>
    </message>
</context>
<context>
    <name>sightline::PlaybackBar</name>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="35"/>
        <source>Step one frame</source>
        <translation>Avanzar una imagen</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="54"/>
        <source>Playback speed relative to the recording&apos;s timestamps</source>
        <translation>Velocidad de reproducción respecto a las marcas de tiempo de la grabación</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="58"/>
        <source>max</source>
        <translation>máx</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="64"/>
        <source>Loop</source>
        <translation>Bucle</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="111"/>
        <source>Pause</source>
        <translation>Pausa</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="111"/>
        <source>Play</source>
        <translation>Reproducir</translation>
    </message>
</context>
<context>
    <name>sightline::RecordingController</name>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="16"/>
        <source>&amp;Record...</source>
        <translation>&amp;Grabar...</translation>
    </message>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="20"/>
        <source>Record what is playing (live sensor or recording) into a folder, in the formats Sightline reads</source>
        <translation>Grabar lo que se está reproduciendo (sensor en vivo o grabación) en una carpeta, en los formatos que Sightline lee</translation>
    </message>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="22"/>
        <source>&amp;Stop recording</source>
        <translation>&amp;Detener la grabación</translation>
    </message>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="41"/>
        <source>Record into folder</source>
        <translation>Grabar en la carpeta</translation>
    </message>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="60"/>
        <source>Nothing to record: open a sensor or a recording first.</source>
        <translation>Nada que grabar: abra primero un sensor o una grabación.</translation>
    </message>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="102"/>
        <source>Recorded %1 frames into %2 (%3 dropped by the recorder), %4 MB at %5 MB/s</source>
        <translation>Grabadas %1 imágenes en %2 (%3 descartadas por el grabador), %4 MB a %5 MB/s</translation>
    </message>
    <message>
        <location filename="../app/sightline/recording_controller.cpp" line="122"/>
        <source>REC %1 written, %2 dropped, %3 MB/s</source>
        <translation>REC %1 escritas, %2 descartadas, %3 MB/s</translation>
    </message>
</context>
<context>
    <name>sightline::ScalePlot</name>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="44"/>
        <source>scale: waiting for displacement pairs</source>
        <translation>escala: esperando pares de desplazamiento</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="58"/>
        <source>pairs (map units per metre)</source>
        <translation>pares (unidades de mapa por metro)</translation>
    </message>
</context>
<context>
    <name>sightline::StatisticsPresenter</name>
    <message>
        <location filename="../app/sightline/statistics_presenter.cpp" line="24"/>
        <source>Statistic</source>
        <translation>Estadística</translation>
    </message>
    <message>
        <location filename="../app/sightline/statistics_presenter.cpp" line="24"/>
        <source>Value</source>
        <translation>Valor</translation>
    </message>
    <message>
        <location filename="../app/sightline/statistics_presenter.cpp" line="24"/>
        <source>Unit</source>
        <translation>Unidad</translation>
    </message>
    <message>
        <location filename="../app/sightline/statistics_presenter.cpp" line="24"/>
        <source>Meaning</source>
        <translation>Significado</translation>
    </message>
    <message>
        <location filename="../app/sightline/statistics_presenter.cpp" line="30"/>
        <source>Statistics: %1</source>
        <translation>Estadísticas: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/statistics_presenter.cpp" line="54"/>
        <source>status</source>
        <translation>estado</translation>
    </message>
</context>
<context>
    <name>sightline::StereoVoPresenter</name>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="89"/>
        <source>Stereo visual odometry</source>
        <translation>Odometría visual estéreo</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="99"/>
        <source>Tracks (inliers green, outliers red, new blue)</source>
        <translation>Trazas (inliers en verde, outliers en rojo, nuevas en azul)</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="103"/>
        <source>Stereo matches (right image)</source>
        <translation>Correspondencias estéreo (imagen derecha)</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="110"/>
        <source>per frame [%1]</source>
        <translation>por imagen [%1]</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="111"/>
        <source>%1 per stage</source>
        <translation>%1 por etapa</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="113"/>
        <source>residual [%1]; red: gated</source>
        <translation>residuo [%1]; rojo: bloqueado</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="118"/>
        <source>Statistics over time</source>
        <translation>Estadísticas en el tiempo</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="202"/>
        <source>tracked %1, new %2, stereo %3, inliers %4, RANSAC %5 it., residual %6 %7, %8 %9%10</source>
        <translation>seguidas %1, nuevas %2, estéreo %3, inliers %4, RANSAC %5 it., residuo %6 %7, %8 %9%10</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="212"/>
        <source>, GATED: pose held</source>
        <translation>, BLOQUEADO: pose mantenida</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="42"/>
        <source>tracks</source>
        <translation>trazas</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="44"/>
        <source>anchored</source>
        <translation>ancladas</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="46"/>
        <source>stereo</source>
        <translation>estéreo</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="48"/>
        <source>inliers</source>
        <translation>inliers</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="50"/>
        <source>RANSAC it.</source>
        <translation>it. RANSAC</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="54"/>
        <source>rectify</source>
        <translation>rectificación</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="56"/>
        <source>pyramid</source>
        <translation>pirámide</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="58"/>
        <source>tracking</source>
        <translation>seguimiento</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="60"/>
        <source>detection</source>
        <translation>detección</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="62"/>
        <source>matching</source>
        <translation>correspondencia</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="64"/>
        <source>RANSAC</source>
        <translation>RANSAC</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="66"/>
        <source>refine</source>
        <translation>refinado</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="68"/>
        <source>window BA</source>
        <translation>BA de ventana</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="70"/>
        <source>total</source>
        <translation>total</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="221"/>
        <source>residual</source>
        <translation>residuo</translation>
    </message>
</context>
</TS>
