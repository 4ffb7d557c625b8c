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
        <location filename="../widgets/option_editor.cpp" line="47"/>
        <source>Range: %1 … %2%3</source>
        <translation>Rango: %1 … %2%3</translation>
    </message>
    <message>
        <location filename="../widgets/option_editor.cpp" line="52"/>
        <source>Choices: %1</source>
        <translation>Opciones: %1</translation>
    </message>
    <message>
        <location filename="../widgets/option_editor.cpp" line="55"/>
        <source>Default: %1%2</source>
        <translation>Por defecto: %1%2</translation>
    </message>
    <message>
        <location filename="../widgets/option_editor.cpp" line="71"/>
        <source>Reset to default (%1)</source>
        <translation>Volver al valor por defecto (%1)</translation>
    </message>
</context>
<context>
    <name>sightline::ParameterPanel</name>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="45"/>
        <source>Filter options</source>
        <translation>Filtrar opciones</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="49"/>
        <source>Load profile…</source>
        <translation>Cargar perfil…</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="52"/>
        <source>Save profile…</source>
        <translation>Guardar perfil…</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="55"/>
        <source>Reset all</source>
        <translation>Restablecer todo</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="155"/>
        <source>All options reset to their defaults.</source>
        <translation>Todas las opciones vuelven a sus valores por defecto.</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="166"/>
        <source>Loaded profile %1</source>
        <translation>Perfil %1 cargado</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="177"/>
        <source>Saved profile %1</source>
        <translation>Perfil %1 guardado</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="184"/>
        <source>Load profile</source>
        <translation>Cargar perfil</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="184"/>
        <source>YAML profiles (*.yaml *.yml);;All files (*)</source>
        <translation>Perfiles YAML (*.yaml *.yml);;Todos los archivos (*)</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="191"/>
        <source>Save profile</source>
        <translation>Guardar perfil</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="192"/>
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
