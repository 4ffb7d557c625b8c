<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="es_ES">
<context>
    <name>sightline::ButtonPickerPresenter</name>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="42"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="86"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="90"/>
        <source>Stopped</source>
        <translation>Detenido</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="44"/>
        <source>Waiting for Yes</source>
        <translation>Esperando el Sí</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="46"/>
        <source>Button lost</source>
        <translation>Botón perdido</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="48"/>
        <source>Button unclear</source>
        <translation>Botón poco claro</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="50"/>
        <source>Measuring the button</source>
        <translation>Midiendo el botón</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="52"/>
        <source>Measuring again</source>
        <translation>Midiendo de nuevo</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="54"/>
        <source>Measuring the distance</source>
        <translation>Midiendo la distancia</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="56"/>
        <source>Panel unclear</source>
        <translation>Panel poco claro</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="58"/>
        <source>Position not sure yet</source>
        <translation>Posición aún no segura</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="60"/>
        <source>Panel direction not sure yet</source>
        <translation>Dirección del panel aún no segura</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="62"/>
        <source>Button out of reach</source>
        <translation>Botón fuera de alcance</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="72"/>
        <source>The picture changed: tap again</source>
        <translation>La imagen ha cambiado: toque de nuevo</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="74"/>
        <source>The picture was too old: tap again</source>
        <translation>La imagen era demasiado antigua: toque de nuevo</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="76"/>
        <source>Stopped: press Start again first</source>
        <translation>Detenido: pulse primero «Empezar de nuevo»</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="85"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="227"/>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="214"/>
        <source>Paused</source>
        <translation>En pausa</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="88"/>
        <source>Arm link off</source>
        <translation>Enlace con el brazo apagado</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="89"/>
        <source>No arm connected</source>
        <translation>Ningún brazo conectado</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="93"/>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="219"/>
        <source>Waiting</source>
        <translation>Esperando</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="114"/>
        <source>Button picker (monocular SLAM)</source>
        <translation>Selector de botones (SLAM monocular)</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="122"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="146"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="185"/>
        <source>Operator panel</source>
        <translation>Panel del operador</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="126"/>
        <source>Operator panel full screen</source>
        <translation>Panel del operador a pantalla completa</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="227"/>
        <source>End of the recording</source>
        <translation>Fin de la grabación</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="245"/>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="253"/>
        <source>The picture is paused: press Play, then tap</source>
        <translation>La imagen está en pausa: pulse Reproducir y luego toque</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="252"/>
        <source>The recording has ended: nothing to tap</source>
        <translation>La grabación ha terminado: nada que tocar</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="254"/>
        <source>No picture yet: open a camera or a recording</source>
        <translation>Todavía no hay imagen: abra una cámara o una grabación</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="291"/>
        <source>No button at the tap: %1</source>
        <translation>No hay ningún botón donde tocó: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="306"/>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="206"/>
        <source>No metric scale (no arm motion)</source>
        <translation>Sin escala métrica (sin movimiento del brazo)</translation>
    </message>
    <message>
        <location filename="../app/sightline/button_picker_presenter.cpp" line="308"/>
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
    <name>sightline::CoreMessage</name>
    <message>
        <location filename="../widgets/core_message.cpp" line="17"/>
        <source>invalid argument</source>
        <translation>argumento no válido</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="18"/>
        <source>not found</source>
        <translation>no encontrado</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="19"/>
        <source>parse error</source>
        <translation>error de formato</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="20"/>
        <source>unavailable</source>
        <translation>no disponible</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="21"/>
        <source>out of range</source>
        <translation>fuera de rango</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="22"/>
        <source>failed precondition</source>
        <translation>condición previa no cumplida</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="23"/>
        <source>internal error</source>
        <translation>error interno</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="28"/>
        <source>%1 line %2</source>
        <translation>%1 línea %2</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="29"/>
        <source>profile %1</source>
        <translation>perfil %1</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="30"/>
        <source>parameter panel</source>
        <translation>panel de parámetros</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="36"/>
        <source>unknown option &apos;%1&apos;</source>
        <translation>opción desconocida &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="37"/>
        <source>option &apos;%1&apos;: %2 is outside %3</source>
        <translation>opción &apos;%1&apos;: %2 está fuera de %3</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="38"/>
        <source>option &apos;%1&apos;: &apos;%2&apos; is not one of: %3</source>
        <translation>opción &apos;%1&apos;: &apos;%2&apos; no es uno de los valores: %3</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="39"/>
        <source>option &apos;%1&apos;: &apos;%2&apos; is not a boolean (true/false)</source>
        <translation>opción &apos;%1&apos;: &apos;%2&apos; no es un booleano (true/false)</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="40"/>
        <source>option &apos;%1&apos;: &apos;%2&apos; is not an integer</source>
        <translation>opción &apos;%1&apos;: &apos;%2&apos; no es un número entero</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="41"/>
        <source>option &apos;%1&apos;: &apos;%2&apos; is not a number</source>
        <translation>opción &apos;%1&apos;: &apos;%2&apos; no es un número</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="42"/>
        <source>option &apos;%1&apos;: value is not finite</source>
        <translation>opción &apos;%1&apos;: el valor no es finito</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="43"/>
        <source>a profile must be a map of option keys</source>
        <translation>un perfil debe ser un mapa de claves de opción</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="44"/>
        <source>option &apos;%1&apos; is given twice (also line %2)</source>
        <translation>la opción &apos;%1&apos; aparece dos veces (también en la línea %2)</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="45"/>
        <source>option &apos;%1&apos; has no value</source>
        <translation>la opción &apos;%1&apos; no tiene valor</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="46"/>
        <source>option &apos;%1&apos; must be a single value, not a list</source>
        <translation>la opción &apos;%1&apos; debe ser un valor único, no una lista</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="47"/>
        <source>an option key must be a word, not a list or map</source>
        <translation>una clave de opción debe ser una palabra, no una lista ni un mapa</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="48"/>
        <source>options nest deeper than %1 levels</source>
        <translation>las opciones se anidan en más de %1 niveles</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="49"/>
        <source>lists or maps nest deeper than %1 levels</source>
        <translation>listas o mapas anidados en más de %1 niveles</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="50"/>
        <source>more than %1 values (aliases expanding?); a profile lists each option once</source>
        <translation>más de %1 valores (¿alias que se expanden?); un perfil enumera cada opción una sola vez</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="52"/>
        <source>not a readable YAML profile: %1</source>
        <translation>no es un perfil YAML legible: %1</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="53"/>
        <source>cannot write profile %1</source>
        <translation>no se puede escribir el perfil %1</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="54"/>
        <source>write to %1 failed (disk full?)</source>
        <translation>falló la escritura en %1 (¿disco lleno?)</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="55"/>
        <source>no such file</source>
        <translation>el archivo no existe</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="56"/>
        <source>profile %1 is a folder, not a file</source>
        <translation>el perfil %1 es una carpeta, no un archivo</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="57"/>
        <source>profile %1 is not a regular file (a device, pipe or socket)</source>
        <translation>el perfil %1 no es un archivo normal (un dispositivo, una tubería o un socket)</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="59"/>
        <source>profile %1 cannot be read: %2</source>
        <translation>no se puede leer el perfil %1: %2</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="60"/>
        <source>profile %1 is %2 bytes; a profile holds at most %3</source>
        <translation>el perfil %1 ocupa %2 bytes; un perfil contiene como máximo %3</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="62"/>
        <source>cannot read its size: %1</source>
        <translation>no se puede leer su tamaño: %1</translation>
    </message>
    <message>
        <location filename="../widgets/core_message.cpp" line="63"/>
        <source>read error (%1 of %2 bytes)</source>
        <translation>error de lectura (%1 de %2 bytes)</translation>
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
    <message>
        <location filename="../app/sightline/core_texts.cpp" line="19"/>
        <source>ROS 1 bag files (.bag): images, RGB-D, stereo and point clouds, with tf ground truth</source>
        <translation>Archivos bag de ROS 1 (.bag): imágenes, RGB-D, estéreo y nubes de puntos, con referencia de tf</translation>
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
        <location filename="../app/sightline/evaluation_panel.cpp" line="175"/>
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
        <location filename="../app/sightline/evaluation_panel.cpp" line="185"/>
        <source>Evaluation failed: %1</source>
        <translation>La evaluación ha fallado: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/evaluation_panel.cpp" line="198"/>
        <source>%1 associated poses, ground-truth path %2 m.</source>
        <translation>%1 poses asociadas, recorrido de la referencia %2 m.</translation>
    </message>
</context>
<context>
    <name>sightline::ImageView</name>
    <message>
        <location filename="../widgets/image_view.cpp" line="49"/>
        <location filename="../widgets/image_view.cpp" line="80"/>
        <location filename="../widgets/image_view.cpp" line="135"/>
        <source>No image</source>
        <translation>Sin imagen</translation>
    </message>
    <message>
        <location filename="../widgets/image_view.cpp" line="83"/>
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
        <location filename="../widgets/log_panel.cpp" line="33"/>
        <source>Click a line to read it in full.</source>
        <translation>Haga clic en una línea para leerla completa.</translation>
    </message>
    <message>
        <location filename="../widgets/log_panel.cpp" line="51"/>
        <source>Clear messages</source>
        <translation>Borrar los mensajes</translation>
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
        <translation>Color</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="83"/>
        <location filename="../app/sightline/main_window.cpp" line="406"/>
        <source>Depth</source>
        <translation>Profundidad</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="89"/>
        <source>Parameters</source>
        <translation>Parámetros</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="91"/>
        <source>Log</source>
        <translation>Registro</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="94"/>
        <source>Evaluation</source>
        <translation>Evaluación</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="107"/>
        <source>Playback</source>
        <translation>Reproducción</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="117"/>
        <source>&amp;File</source>
        <translation>&amp;Archivo</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="118"/>
        <source>&amp;Open dataset folder...</source>
        <translation>&amp;Abrir carpeta de datos...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="121"/>
        <source>Open dataset folder</source>
        <translation>Abrir carpeta de datos</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="126"/>
        <source>Open point cloud</source>
        <translation>Abrir nube de puntos</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="124"/>
        <source>Open recording &amp;file (PCD, ONI)...</source>
        <translation>Abrir archivo de &amp;grabación (PCD, ONI)...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="127"/>
        <source>Recordings (*.pcd *.oni *.bag)</source>
        <translation>Grabaciones (*.pcd *.oni *.bag)</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="130"/>
        <source>Open &amp;recent</source>
        <translation>Abrir &amp;recientes</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="137"/>
        <source>&amp;Quit</source>
        <translation>&amp;Salir</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="141"/>
        <source>&amp;View</source>
        <translation>&amp;Ver</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="143"/>
        <source>&amp;Reset 3D view</source>
        <translation>&amp;Restablecer la vista 3D</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="146"/>
        <source>&amp;Follow the trajectory</source>
        <translation>&amp;Seguir la trayectoria</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="148"/>
        <source>Fit the 3D view again whenever a growing trajectory leaves it.</source>
        <translation>Ajustar de nuevo la vista 3D cada vez que una trayectoria creciente sale de ella.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="157"/>
        <source>&amp;Sensors</source>
        <translation>Se&amp;nsores</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="164"/>
        <source> (unavailable)</source>
        <translation> (no disponible)</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="169"/>
        <source>Connect to the first %1 device</source>
        <translation>Conectar con el primer dispositivo %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="175"/>
        <source>Replay recording</source>
        <translation>Reproducir una grabación</translation>
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
        <translation>Ninguno (solo mostrar imágenes)</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="190"/>
        <source>&amp;Tools</source>
        <translation>&amp;Herramientas</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="191"/>
        <source>&amp;Evaluate trajectory...</source>
        <translation>&amp;Evaluar una trayectoria...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="196"/>
        <source>Evaluate &amp;current run</source>
        <translation>Evaluar la ejecución a&amp;ctual</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="198"/>
        <source>Compares the running pipeline&apos;s trajectory with the dataset&apos;s ground truth.</source>
        <translation>Compara la trayectoria del pipeline en ejecución con la verdad de referencia del conjunto de datos.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="207"/>
        <source>&amp;Help</source>
        <translation>A&amp;yuda</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="208"/>
        <source>&amp;About Sightline</source>
        <translation>&amp;Acerca de Sightline</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="209"/>
        <source>About Sightline</source>
        <translation>Acerca de Sightline</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="210"/>
        <source>Sightline: robot perception for assistive and mobile robotics.
Indoor mapping, mobility maps, stereo odometry and monocular button localisation on live sensors or recorded data.</source>
        <translation>Sightline: percepción robótica para la robótica asistencial y móvil.
Mapeo de interiores, mapas de transitabilidad, odometría estéreo y localización monocular de botones con sensores en vivo o datos grabados.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="227"/>
        <source>Could not open %1: %2</source>
        <translation>No se pudo abrir %1: %2</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="228"/>
        <source>Could not open %1</source>
        <translation>No se pudo abrir %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="236"/>
        <source>End of recording.</source>
        <translation>Fin de la grabación.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="265"/>
        <source>Demo %p%</source>
        <translation>Demo %p%</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="272"/>
        <source>Generating the demo recordings (only the first time)...</source>
        <translation>Generando las grabaciones de la demo (solo la primera vez)...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="281"/>
        <source>Demo: a robot drives a simulated office corridor (RGB-D, stereo, wheel odometry, exact ground truth). The arm-camera panel approach is in %1.</source>
        <translation>Demo: un robot recorre un pasillo de oficina simulado (RGB-D, estéreo, odometría de ruedas, verdad de referencia exacta). La aproximación de la cámara del brazo al panel está en %1.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="288"/>
        <source>The demo could not be made: %1</source>
        <translation>No se pudo crear la demo: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="345"/>
        <source>No pipeline: showing frames only.</source>
        <translation>Sin pipeline: solo se muestran las imágenes.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="356"/>
        <source>Pipeline: %1</source>
        <translation>Pipeline: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="360"/>
        <source>%1 cannot run on %2 frames; open another dataset.</source>
        <translation>%1 no puede funcionar con imágenes %2; abra otro conjunto de datos.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="389"/>
        <location filename="../app/sightline/main_window.cpp" line="390"/>
        <source>Opening %1 ...</source>
        <translation>Abriendo %1 ...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="405"/>
        <source>Left</source>
        <translation>Izquierda</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="405"/>
        <source>Image</source>
        <translation>Imagen</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="406"/>
        <source>Right</source>
        <translation>Derecha</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="412"/>
        <source>%1: %2, %3 frames, %4x%5%6</source>
        <translation>%1: %2, %3 imágenes, %4x%5%6</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="417"/>
        <source>, ground truth</source>
        <translation>, verdad de referencia</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="419"/>
        <source>Opened %1</source>
        <translation>Abierto %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="424"/>
        <source>Sightline - %1</source>
        <translation>Sightline - %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="443"/>
        <source>frame %1, read in %2 ms</source>
        <translation>imagen %1, leída en %2 ms</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="492"/>
        <source>No dataset open. Use File &gt; Open dataset folder (TUM RGB-D, EuRoC, KITTI, an image folder or PCD files), or drop a folder on this window.</source>
        <translation>Ningún conjunto de datos abierto. Use Archivo &gt; Abrir carpeta de datos (TUM RGB-D, EuRoC, KITTI, una carpeta de imágenes o archivos PCD), o arrastre una carpeta a esta ventana.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="494"/>
        <source>No dataset open</source>
        <translation>Ningún conjunto de datos abierto</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window.cpp" line="200"/>
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
    <message>
        <location filename="../app/sightline/main_window_playback.cpp" line="44"/>
        <source>Reset the map?</source>
        <translation>¿Reiniciar el mapa?</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_playback.cpp" line="45"/>
        <source>%1 has built its map over %2 frames. Seeking starts it over from the frame you seek to: the map and the trajectory so far are lost.</source>
        <translation>%1 ha construido su mapa a lo largo de %2 fotogramas. Saltar lo reinicia desde el fotograma elegido: se pierden el mapa y la trayectoria hasta ahora.</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_playback.cpp" line="51"/>
        <source>Seek and reset the map</source>
        <translation>Saltar y reiniciar el mapa</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_playback.cpp" line="53"/>
        <source>Keep the map</source>
        <translation>Conservar el mapa</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_ros.cpp" line="24"/>
        <source>Connect to &amp;ROS master...</source>
        <translation>Conectar al máster &amp;ROS...</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_ros.cpp" line="25"/>
        <source>&amp;Disconnect from ROS master</source>
        <translation>&amp;Desconectar del máster ROS</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_ros.cpp" line="32"/>
        <source>Connect to ROS master</source>
        <translation>Conectar al máster ROS</translation>
    </message>
    <message>
        <location filename="../app/sightline/main_window_ros.cpp" line="40"/>
        <source>Disconnected from the ROS master</source>
        <translation>Desconectado del máster ROS</translation>
    </message>
</context>
<context>
    <name>sightline::MappingPresenter</name>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="112"/>
        <source>Indoor mapping (Manhattan walls)</source>
        <translation>Mapeo de interiores (paredes de Manhattan)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="119"/>
        <source>Occupancy, scan and walls</source>
        <translation>Ocupación, barrido y paredes</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="125"/>
        <source>Calibrate floor</source>
        <translation>Calibrar el suelo</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="127"/>
        <source>Fit the floor plane again from the next frames (the robot should see open floor).</source>
        <translation>Ajustar de nuevo el plano del suelo con las próximas imágenes (el robot debe ver suelo libre).</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="130"/>
        <source>Save floor...</source>
        <translation>Guardar el suelo...</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="132"/>
        <source>Save the floor calibration in use, for mapping.run.floor_file or `sightline-cli run mapping --set mapping.run.floor_file=...`.</source>
        <translation>Guardar la calibración del suelo en uso, para mapping.run.floor_file o `sightline-cli run mapping --set mapping.run.floor_file=...`.</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="135"/>
        <source>Save floor calibration</source>
        <translation>Guardar la calibración del suelo</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="136"/>
        <source>YAML (*.yaml)</source>
        <translation>YAML (*.yaml)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="148"/>
        <source>Stitched map</source>
        <translation>Mapa unido</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="180"/>
        <location filename="../app/sightline/mapping_presenter.cpp" line="212"/>
        <source>free</source>
        <translation>libre</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="181"/>
        <location filename="../app/sightline/mapping_presenter.cpp" line="214"/>
        <source>occupied</source>
        <translation>ocupado</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="182"/>
        <source>person</source>
        <translation>persona</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="183"/>
        <source>scan rays</source>
        <translation>rayos del escaneo</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="184"/>
        <location filename="../app/sightline/mapping_presenter.cpp" line="223"/>
        <source>walls, first direction</source>
        <translation>paredes, primera dirección</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="185"/>
        <location filename="../app/sightline/mapping_presenter.cpp" line="224"/>
        <source>walls, perpendicular</source>
        <translation>paredes, perpendiculares</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="186"/>
        <location filename="../app/sightline/mapping_presenter.cpp" line="225"/>
        <source>other lines</source>
        <translation>otras líneas</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="187"/>
        <source>robot</source>
        <translation>robot</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="213"/>
        <source>unknown</source>
        <translation>desconocido</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="215"/>
        <source>path and robot</source>
        <translation>trayectoria y robot</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="226"/>
        <source>floor</source>
        <translation>suelo</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="228"/>
        <source>map: free</source>
        <translation>mapa: libre</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="229"/>
        <source>map: occupied</source>
        <translation>mapa: ocupado</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="230"/>
        <source>path</source>
        <translation>trayectoria</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="235"/>
        <source>Manhattan reference reset: %1</source>
        <translation>Referencia de Manhattan reiniciada: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="276"/>
        <source>Calibrating the floor again from the next frames.</source>
        <translation>Calibrando de nuevo el suelo con las próximas imágenes.</translation>
    </message>
    <message>
        <location filename="../app/sightline/mapping_presenter.cpp" line="289"/>
        <source>Saved the floor calibration to %1</source>
        <translation>Calibración del suelo guardada en %1</translation>
    </message>
</context>
<context>
    <name>sightline::MobilityImagePanel</name>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="73"/>
        <source>Projection</source>
        <translation>Proyección</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="74"/>
        <source>Top view</source>
        <translation>Vista cenital</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="75"/>
        <source>GPR surface</source>
        <translation>Superficie GPR</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="85"/>
        <source>score 0: not passable</source>
        <translation>puntuación 0: no transitable</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="86"/>
        <source>score 0.5</source>
        <translation>puntuación 0,5</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="87"/>
        <source>score 1: passable</source>
        <translation>puntuación 1: transitable</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="88"/>
        <source>not scored</source>
        <translation>sin puntuar</translation>
    </message>
</context>
<context>
    <name>sightline::MobilityPresenter</name>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="27"/>
        <source>Mobility map</source>
        <translation>Mapa de transitabilidad</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="37"/>
        <source>Mobility map (red 0, green 1)</source>
        <translation>Mapa de transitabilidad (rojo 0, verde 1)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="41"/>
        <source>Mobility stages (Table II)</source>
        <translation>Etapas del mapa de transitabilidad (Tabla II)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="77"/>
        <source>colour: one per segment</source>
        <translation>color: uno por segmento</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="80"/>
        <source>score 0: not passable</source>
        <translation>puntuación 0: no transitable</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_presenter.cpp" line="80"/>
        <source>score 1: passable</source>
        <translation>puntuación 1: transitable</translation>
    </message>
</context>
<context>
    <name>sightline::MobilityTimingPanel</name>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="22"/>
        <source>3D colour:</source>
        <translation>Color 3D:</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="24"/>
        <source>Score (rule)</source>
        <translation>Puntuación (regla)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="24"/>
        <source>Score (GPR)</source>
        <translation>Puntuación (GPR)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="24"/>
        <source>Segment</source>
        <translation>Segmento</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="32"/>
        <source>Stage</source>
        <translation>Etapa</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="32"/>
        <source>Time (ms)</source>
        <translation>Tiempo (ms)</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="32"/>
        <source>Points</source>
        <translation>Puntos</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="53"/>
        <source>Total</source>
        <translation>Total</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="56"/>
        <source>%1 mode, %2 segments</source>
        <translation>modo %1, %2 segmentos</translation>
    </message>
    <message>
        <location filename="../app/sightline/mobility_views.cpp" line="60"/>
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
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="194"/>
        <source>inlier</source>
        <translation>inlier</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="195"/>
        <source>outlier</source>
        <translation>atípico</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="196"/>
        <source>keypoint, unmatched</source>
        <translation>punto clave, sin emparejar</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="197"/>
        <source>frame: tracking quality</source>
        <translation>marco: calidad del seguimiento</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="212"/>
        <source>%1: %2 inliers of %3 matches, %4 map points, %5 keyframes, %6 ms</source>
        <translation>%1: %2 inliers de %3 correspondencias, %4 puntos del mapa, %5 keyframes, %6 ms</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="222"/>
        <source>Metric scale from %1: ML %2, single ratio %3 map units per metre; map and trajectory in metres.</source>
        <translation>Escala métrica a partir de %1: ML %2, razón única %3 unidades de mapa por metro; mapa y trayectoria en metros.</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="228"/>
        <source>Scale unknown (measured motion: %1): the map is in arbitrary units (first baseline = 0.1).</source>
        <translation>Escala desconocida (movimiento medido: %1): el mapa está en unidades arbitrarias (primera línea base = 0,1).</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="268"/>
        <source>camera path</source>
        <translation>trayectoria de la cámara</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="269"/>
        <source>keyframes</source>
        <translation>fotogramas clave</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="270"/>
        <source>camera: tracking quality</source>
        <translation>cámara: calidad del seguimiento</translation>
    </message>
    <message>
        <location filename="../app/sightline/mono_slam_presenter.cpp" line="271"/>
        <source>map points: colour of their first keyframe</source>
        <translation>puntos del mapa: color de su primer fotograma clave</translation>
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
        <translation>Cancelar</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="292"/>
        <source>Locating</source>
        <translation>Localizando</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="296"/>
        <source>Lost - hold still</source>
        <translation>Perdido - quieto</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="286"/>
        <source>No button here - tap again</source>
        <translation>Aquí no hay botón - toque otra vez</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="211"/>
        <source>Robot: live</source>
        <translation>Robot: en directo</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="214"/>
        <source>Waiting for the robot&apos;s picture</source>
        <translation>Esperando la imagen del robot</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="217"/>
        <source>Picture stale: no taps</source>
        <translation>Imagen antigua: sin toques</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="220"/>
        <source>Disconnected: reconnecting</source>
        <translation>Desconectado: reconectando</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="284"/>
        <source>Press this button?</source>
        <translation>¿Pulsar este botón?</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="300"/>
        <source>Holding: nothing sent</source>
        <translation>En espera: nada enviado</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="302"/>
        <source>Tap not taken</source>
        <translation>Toque no aceptado</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="304"/>
        <source>Tracking only</source>
        <translation>Solo seguimiento</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="339"/>
        <source>STOP</source>
        <translation>PARAR</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="375"/>
        <source>Leave</source>
        <translation>Salir</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="375"/>
        <source>Leave the operator panel?</source>
        <translation>¿Salir del panel del operador?</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="288"/>
        <source>Searching</source>
        <translation>Buscando</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="340"/>
        <source>Start again</source>
        <translation>Empezar de nuevo</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="298"/>
        <source>Stopped</source>
        <translation>Detenido</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="282"/>
        <source>Tap a button</source>
        <translation>Toque un botón</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="294"/>
        <source>Target sent</source>
        <translation>Objetivo enviado</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="290"/>
        <source>Tracking</source>
        <translation>Botón a la vista</translation>
    </message>
    <message>
        <location filename="../widgets/operator_panel.cpp" line="337"/>
        <location filename="../widgets/operator_panel.cpp" line="379"/>
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
        <translation>... y un error de escala relativo a 1 sigma como máximo igual a este valor.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="15"/>
        <source>... and at least this fraction of the scan&apos;s rays hit it.</source>
        <translation>... y al menos esta fracción de los rayos del barrido lo alcanza.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="16"/>
        <source>... and by this fraction of the angle turned since the last correction.</source>
        <translation>... y en esta fracción del ángulo girado desde la última corrección.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="17"/>
        <source>... or the camera centres to lie this far apart (rays crossing).</source>
        <translation>... o que los centros de la cámara disten al menos esto (rayos que se cruzan).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="19"/>
        <source>... or when it turned at least this much.</source>
        <translation>... o cuando ha girado al menos esto.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="20"/>
        <source>... plus this fraction of the tracked radius (a model centre off by a fixed amount on the button grows with its apparent size).</source>
        <translation>... más esta fracción del radio seguido (un centro del modelo desplazado una cantidad fija sobre el botón crece con su tamaño aparente).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="21"/>
        <source>... plus this times the depth squared (Kinect noise and quantisation).</source>
        <translation>... más este valor por el cuadrado de la profundidad (ruido y cuantización del Kinect).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="22"/>
        <source>... reached within this many frames; otherwise the anchor starts again (tracks followed over many frames drift, and their drift reads as an offset).</source>
        <translation>... alcanzada en este número de fotogramas; si no, el anclaje vuelve a empezar (las pistas seguidas durante muchos fotogramas derivan, y su deriva aparece como un desplazamiento).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="23"/>
        <source>.oni playback speed: 0 delivers frames as fast as they are read, nothing skipped; 1 paces at the recorded rate.</source>
        <translation>Velocidad de reproducción de .oni: 0 entrega los fotogramas tan rápido como se leen, sin saltar ninguno; 1 sigue la frecuencia grabada.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="24"/>
        <source>.oni recordings start again at the first frame instead of ending.</source>
        <translation>Las grabaciones .oni vuelven a empezar en el primer fotograma en lugar de terminar.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="25"/>
        <source>1-sigma error of the tracked button centre; moves the point across the viewing ray (the target&apos;s stated uncertainty includes it).</source>
        <translation>Error a 1 sigma del centro del botón seguido; desplaza el punto transversalmente al rayo de visión (la incertidumbre declarada del objetivo lo incluye).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="26"/>
        <source>1-sigma of the tracked centre in the triangulation ...</source>
        <translation>1-sigma del centro seguido en la triangulación ...</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="27"/>
        <source>1-sigma relative error of the tracked radius.</source>
        <translation>Error relativo a 1-sigma del radio seguido.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="28"/>
        <source>1-sigma rotation error of the hand-eye calibration; times the distance to the button.</source>
        <translation>Error de rotación a 1 sigma de la calibración mano-ojo; multiplicado por la distancia al botón.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="29"/>
        <source>1-sigma translation error of the hand-eye calibration (end effector to camera).</source>
        <translation>Error de traslación a 1 sigma de la calibración mano-ojo (del efector final a la cámara).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="30"/>
        <source>A bucket gets new corners only when it holds fewer than this fraction of its share of max_features (1 = whenever it is not full).</source>
        <translation>Una celda (bucket) recibe esquinas nuevas solo cuando contiene menos de esta fracción de su cuota de max_features (1 = siempre que no esté llena).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="31"/>
        <source>A button centre farther than this outside the image is out of view (lost).</source>
        <translation>Un centro del botón más allá de esto fuera de la imagen está fuera de la vista (perdido).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="32"/>
        <source>A camera frame newer than the newest arm pose waits at most this long (host clock) for the pose that covers its stamp; then it has no arm pose.</source>
        <translation>Un fotograma de la cámara más reciente que la última pose del brazo espera como máximo este tiempo (reloj del host) la pose que cubre su marca de tiempo; después se queda sin pose del brazo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="34"/>
        <source>A frame has ground truth when a pose lies within this time.</source>
        <translation>Un fotograma tiene ground truth cuando hay una pose dentro de este tiempo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="35"/>
        <source>A frame sets the reference only when the wall length in a second direction a few degrees off (inside the gate, outside the trim) is at most this fraction of the main direction&apos;s.</source>
        <translation>Un fotograma fija la referencia solo cuando la longitud de pared en una segunda dirección desviada unos pocos grados (dentro del gate, fuera del recorte) es como máximo esta fracción de la de la dirección principal.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="36"/>
        <source>A frame stays in the window when the camera moved this fraction of its points&apos; median depth since the previous one that stayed (0 = every frame stays); otherwise the next frame replaces it.</source>
        <translation>Un fotograma permanece en la ventana cuando la cámara se ha movido esta fracción de la profundidad mediana de sus puntos desde el anterior que permaneció (0 = todos permanecen); si no, el siguiente fotograma lo sustituye.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="38"/>
        <source>A frame this far from every keyframe (relative to the mean depth) becomes one.</source>
        <translation>Un fotograma a esta distancia de todos los fotogramas clave (relativa a la profundidad media) se convierte en uno.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="39"/>
        <source>A frame tracking fewer than this share of the last keyframe&apos;s points becomes one.</source>
        <translation>Un fotograma que sigue menos de esta proporción de los puntos del último fotograma clave se convierte en uno.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="41"/>
        <source>A frame with fewer matches than this with the newest candidate becomes a candidate too (the oldest leaves a full ring); at low frame rates every frame does.</source>
        <translation>Un fotograma con menos correspondencias que estas con el candidato más reciente pasa también a ser candidato (con el anillo lleno sale el más antiguo); a baja frecuencia lo es cada fotograma.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="42"/>
        <source>A frame&apos;s normal this many sigmas off the average is skipped.</source>
        <translation>Se omite un fotograma cuya normal se aparta esta cantidad de sigmas de la media.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="43"/>
        <source>A frame&apos;s walls count only when their summed vote weight (length x fit quality) reaches this.</source>
        <translation>Las paredes de un fotograma solo cuentan cuando su peso de voto sumado (longitud x calidad del ajuste) alcanza este valor.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="44"/>
        <source>A ground candidate holds at least this fraction of the points.</source>
        <translation>Un candidato a suelo contiene al menos esta fracción de los puntos.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="45"/>
        <source>A ground plane&apos;s normal lies at most this far from the expected up direction.</source>
        <translation>La normal de un plano del suelo se aparta como máximo esto de la dirección hacia arriba esperada.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="46"/>
        <source>A ground point&apos;s own normal lies at most this far from the plane&apos;s.</source>
        <translation>La normal propia de un punto del suelo se aparta como máximo esto de la del plano.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="47"/>
        <source>A ground-truth or odometry pose belongs to a frame when this close in time.</source>
        <translation>Una pose de ground truth o de odometría pertenece a un fotograma cuando está así de cerca en el tiempo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="48"/>
        <source>A ground-truth pose belongs to a frame when this close in time.</source>
        <translation>Una pose de ground truth pertenece a un fotograma cuando está así de cerca en el tiempo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="50"/>
        <source>A line this close to a Manhattan axis is classed as parallel (0) or perpendicular (1) to the reference.</source>
        <translation>Una línea así de cerca de un eje Manhattan se clasifica como paralela (0) o perpendicular (1) a la referencia.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="52"/>
        <source>A pose belongs to a frame when this close in time.</source>
        <translation>Una pose pertenece a un fotograma cuando está así de cerca en el tiempo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="55"/>
        <source>A segment&apos;s raised height is this quantile of its heights above the ground.</source>
        <translation>La altura elevada de un segmento es este cuantil de sus alturas sobre el suelo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="56"/>
        <source>A sloped segment whose plane meets the ground within this distance of its lowest points is connected to the ground (a ramp), not raised.</source>
        <translation>Un segmento inclinado cuyo plano corta el suelo a menos de esta distancia de sus puntos más bajos está conectado al suelo (una rampa), no elevado.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="57"/>
        <source>A streaming device that delivers nothing for this long is treated as lost and reopened; 0 never does (e.g. waiting for rare hardware triggers).</source>
        <translation>Un dispositivo en streaming que no entrega nada durante este tiempo se considera perdido y se vuelve a abrir; 0 no lo hace nunca (p. ej. esperando disparos de hardware poco frecuentes).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="58"/>
        <source>A track must return to its start within this when tracked backwards; 0 = no check.</source>
        <translation>Una pista, seguida hacia atrás, debe volver a su inicio dentro de este valor; 0 = sin comprobación.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="59"/>
        <source>A track seen from a direction differing more than this from its anchor&apos;s is anchored anew: the further aside, the more a wrongly fitted or assumed surface (the road taken as facing the camera) misleads the warp; 3 suits subsampled driving.</source>
        <translation>Una pista vista desde una dirección que difiere más que esto de la de su anclaje se ancla de nuevo: cuanto más lateral, más engaña a la deformación una superficie mal ajustada o supuesta (la carretera tomada como orientada hacia la cámara); 3 conviene a la conducción submuestreada.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="60"/>
        <source>A track whose patch would be scaled by more than this fraction since its anchor (the camera came close) is anchored anew.</source>
        <translation>Una pista cuyo parche se escalaría más de esta fracción desde su anclaje (la cámara se acercó) se ancla de nuevo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="61"/>
        <source>A track&apos;s surface is fitted as a plane to the tracks within this radius at a similar depth, so the anchor&apos;s patch is warped as that plane; 0 = every patch is taken as facing the camera.</source>
        <translation>La superficie de una pista se ajusta como un plano a las pistas dentro de este radio a una profundidad similar, de modo que el parche del anclaje se deforma como ese plano; 0 = cada parche se toma como orientado hacia la cámara.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="63"/>
        <source>Accuracy: a segment is compared with the true region holding this fraction of its points.</source>
        <translation>Precisión: un segmento se compara con la región real que contiene esta fracción de sus puntos.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="64"/>
        <source>Adaptive termination: stop when an outlier-free sample was drawn with this probability given the best inlier fraction; 1 = always max_iterations.</source>
        <translation>Terminación adaptativa: parar cuando se ha extraído una muestra sin outliers con esta probabilidad dada la mejor fracción de inliers; 1 = siempre max_iterations.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="65"/>
        <source>Add features of confidently tracked frames to the model when the button&apos;s apparent size has changed.</source>
        <translation>Añadir al modelo las características de los fotogramas seguidos con confianza cuando el tamaño aparente del botón ha cambiado.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="66"/>
        <source>Added to the triangulation&apos;s stated 1-sigma: biases no residual shows (the tracked centre&apos;s offset on the button, the size&apos;s depth on a relief).</source>
        <translation>Se suma al 1-sigma declarado de la triangulación: sesgos que ningún residuo muestra (el desplazamiento del centro seguido sobre el botón, la profundidad del tamaño sobre un relieve).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="67"/>
        <source>After a loss, search whole frames and re-acquire the button only on a confident match at a plausible size.</source>
        <translation>Tras una pérdida, buscar en fotogramas completos y volver a adquirir el botón solo con una coincidencia fiable y de tamaño plausible.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="68"/>
        <source>Agreement of the voting lines modulo 90 deg (1 = perfect); below it the frame&apos;s walls are not used.</source>
        <translation>Concordancia de las líneas que votan módulo 90 deg (1 = perfecta); por debajo, no se usan las paredes del fotograma.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="69"/>
        <source>Also estimate a constant offset of the tracked centre in the image (a detector&apos;s sub-pixel convention): it would tilt the rays of the approach against the sideways move&apos;s.</source>
        <translation>Estima también un desplazamiento constante del centro seguido en la imagen (la convención subpíxel de un detector): inclinaría los rayos de la aproximación frente a los del movimiento lateral.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="70"/>
        <source>Also list and open Aravis&apos; in-process simulated camera Fake_1 (demos and tests).</source>
        <translation>Listar y abrir también la cámara simulada interna de Aravis Fake_1 (demos y pruebas).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="71"/>
        <source>Also locate the button from the arm&apos;s metric camera poses alone (the tracked centre&apos;s rays and its apparent size, core/button/arm_triangulation.h) and combine that point with the map&apos;s by their variances. Off by default: on the simulated approach&apos;s seeds 1-5 the mean final error goes 4.77 -&gt; 3.68 mm and the worst 10.1 -&gt; 5.9 mm, but seeds 1 and 4 and the 12 cm sideways approach get worse (docs/button.md).</source>
        <translation>Localiza también el botón solo a partir de las poses métricas de la cámara dadas por el brazo (los rayos del centro seguido y su tamaño aparente, core/button/arm_triangulation.h) y combina ese punto con el del mapa según sus varianzas. Desactivado por defecto: en las semillas 1-5 de la aproximación simulada el error final medio pasa de 4.77 -&gt; 3.68 mm y el peor de 10.1 -&gt; 5.9 mm, pero las semillas 1 y 4 y la aproximación con 12 cm de desplazamiento lateral empeoran (docs/button.md).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="72"/>
        <source>Also project current points into the previous images (uses both depths).</source>
        <translation>Proyectar también los puntos actuales en las imágenes anteriores (usa ambas profundidades).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="74"/>
        <source>An aligned patch whose zero-mean normalised correlation with the warped anchor patch is lower failed (occlusion, reflection).</source>
        <translation>Un parche alineado cuya correlación normalizada de media cero con el parche de anclaje deformado es menor ha fallado (oclusión, reflejo).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="75"/>
        <source>An alignment that moves the tracked position further than this failed (the KLT position is kept and the track anchored anew).</source>
        <translation>Una alineación que desplaza la posición seguida más que esto ha fallado (se conserva la posición de KLT y la pista se ancla de nuevo).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="76"/>
        <source>An anchor is used for at most this many frames; then the track is anchored anew.</source>
        <translation>Un anclaje se usa como máximo durante este número de fotogramas; después la pista se ancla de nuevo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="77"/>
        <source>An arm_pose message with more joint positions is refused.</source>
        <translation>Se rechaza un mensaje arm_pose con más posiciones articulares.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="78"/>
        <source>An arm_pose position farther than this from the base is refused.</source>
        <translation>Se rechaza una posición de arm_pose más alejada que esto de la base.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="81"/>
        <source>Analog gain; negative keeps the camera&apos;s. Out-of-range values are errors.</source>
        <translation>Ganancia analógica; un valor negativo conserva la de la cámara. Los valores fuera de rango son errores.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="83"/>
        <source>Ask the device to deliver depth and colour frames of the same instant.</source>
        <translation>Pedir al dispositivo que entregue fotogramas de profundidad y color del mismo instante.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="84"/>
        <source>At low rates (mono.tracking.low_rate_interval_s), a frame tracking fewer than this share of the last keyframe&apos;s points becomes a keyframe within min_keyframe_gap too (0 = off).</source>
        <translation>A baja frecuencia (mono.tracking.low_rate_interval_s), un fotograma que sigue menos de esta fracción de los puntos del último fotograma clave pasa a ser fotograma clave también dentro de min_keyframe_gap (0 = desactivado).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="85"/>
        <source>At low rates, a frame this far from every keyframe (relative to the mean depth) becomes a keyframe within min_keyframe_gap too.</source>
        <translation>A baja frecuencia, un fotograma así de lejos de todo fotograma clave (respecto a la profundidad media) pasa a ser fotograma clave también dentro de min_keyframe_gap.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="86"/>
        <source>At low rates, when the constant-velocity prediction tracks fewer inliers, the last pose (zero motion) is tried too and the better kept (0 = off).</source>
        <translation>A baja frecuencia, cuando la predicción de velocidad constante sigue menos inliers, se prueba también la última pose (movimiento nulo) y se conserva la mejor (0 = desactivado).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="87"/>
        <source>Authorised clients at most; further ones are closed.</source>
        <translation>Número máximo de clientes autorizados; los siguientes se cierran.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="88"/>
        <source>Band of the refinement (offset histogram bin and refit band): narrower than err_max, so that a door recessed behind the wall face does not tilt the line.</source>
        <translation>Banda del refinamiento (clase del histograma del desplazamiento y banda del reajuste): más estrecha que err_max, para que una puerta retranqueada respecto a la cara de la pared no incline la línea.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="89"/>
        <source>Baseline over the median depth of the first points needed to accept (0.07 is a 4 deg ray angle sideways); a short baseline gives a distorted first map and a drifting scale.</source>
        <translation>Línea base dividida por la profundidad mediana de los primeros puntos necesaria para aceptar (0.07 equivale a un ángulo de rayos de 4 deg lateralmente); una línea base corta da un primer mapa distorsionado y una escala que deriva.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="90"/>
        <source>Best over second-best descriptor distance in a window; 1 = off.</source>
        <translation>Cociente entre la mejor y la segunda mejor distancia de descriptores en una ventana; 1 = desactivado.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="91"/>
        <source>Camera pitched down by this: expected up = camera -y turned by pitch and roll.</source>
        <translation>Cámara inclinada hacia abajo este ángulo: arriba esperado = -y de la cámara girado por cabeceo y alabeo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="92"/>
        <source>Camera roll.</source>
        <translation>Alabeo de la cámara.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="93"/>
        <source>Candidate first frames kept (a ring of recent frames); each new frame is tried against every one, oldest first (the largest baseline).</source>
        <translation>Candidatos a primer fotograma que se guardan (un anillo de fotogramas recientes); cada fotograma nuevo se prueba contra todos, el más antiguo primero (la línea base más larga).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="94"/>
        <source>Canny lower threshold.</source>
        <translation>Umbral inferior de Canny.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="95"/>
        <source>Canny upper threshold.</source>
        <translation>Umbral superior de Canny.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="96"/>
        <source>Cell edge of the global map.</source>
        <translation>Lado de celda del mapa global.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="97"/>
        <source>Cell of the keypoint grid used by window searches.</source>
        <translation>Celda de la rejilla de puntos clave que usan las búsquedas en ventana.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="98"/>
        <source>Coarse search window of the zero-motion try.</source>
        <translation>Ventana de búsqueda gruesa del intento con movimiento nulo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="99"/>
        <source>Collinear lines (angles this close, one fit within the threshold) are merged.</source>
        <translation>Las líneas colineales (ángulos así de cercanos, un ajuste dentro del umbral) se fusionan.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="100"/>
        <source>Compute SIFT only in a window around the predicted centre (fast).</source>
        <translation>Calcular SIFT solo en una ventana alrededor del centro predicho (rápido).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="101"/>
        <source>Connections still owing the token at most; a new one closes the oldest.</source>
        <translation>Número máximo de conexiones que aún deben el token; una nueva cierra la más antigua.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="102"/>
        <source>Consecutive frames of constant-motion fallback before the pose is held.</source>
        <translation>Fotogramas consecutivos con recurso al movimiento constante antes de mantener la pose.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="103"/>
        <source>Consecutive scan points farther apart than this start a new run.</source>
        <translation>Los puntos de barrido consecutivos separados más que esto inician un tramo nuevo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="104"/>
        <source>Consistent matches needed to re-acquire a lost button.</source>
        <translation>Coincidencias coherentes necesarias para volver a adquirir un botón perdido.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="106"/>
        <source>Correct the heading with the walls&apos; Manhattan directions; off = dead reckoning only.</source>
        <translation>Corregir el rumbo con las direcciones Manhattan de las paredes; desactivado = solo navegación a estima.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="107"/>
        <source>Demosaic Bayer formats to BGR colour; off delivers the raw mosaic as grey.</source>
        <translation>Convertir por demosaico los formatos Bayer a color BGR; desactivado entrega el mosaico en bruto en gris.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="108"/>
        <source>Depth beyond this is left out of the 3D cloud.</source>
        <translation>La profundidad más allá de este valor queda fuera de la nube 3D.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="49"/>
        <source>A line needs at least this many points (2 = as published; more rejects clutter).</source>
        <translation>Una línea necesita al menos esta cantidad de puntos (2 = como se publicó; más descarta el desorden).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="54"/>
        <source>A region whose centroid is farther from the tap and that does not contain it is not the tapped button (published method).</source>
        <translation>Una región cuyo centroide está más lejos del toque y que no lo contiene no es el botón tocado (método publicado).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="82"/>
        <source>Angle between scan rays (published res_scan = 0.2 deg).</source>
        <translation>Ángulo entre los rayos del barrido (publicado: res_scan = 0.2 deg).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="109"/>
        <source>Depth images are sampled to about this many columns (published: 320 x 240).</source>
        <translation>Las imágenes de profundidad se muestrean a unas tantas columnas (publicado: 320 x 240).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="110"/>
        <source>Depth points a cell needs to count as occupied (1 = as published: any non-floor point).</source>
        <translation>Puntos de profundidad que necesita una celda para contar como ocupada (1 = como se publicó: cualquier punto que no sea del suelo).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="111"/>
        <source>Depth readings beyond this are treated as invalid downstream.</source>
        <translation>Las lecturas de profundidad más allá de este valor se consideran no válidas en las etapas siguientes.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="112"/>
        <source>Depth readings beyond this count as invalid.</source>
        <translation>Las lecturas de profundidad más allá de este valor se consideran no válidas.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="115"/>
        <source>Depth sigmas (of both points at both times) added to the rigidity tolerance.</source>
        <translation>Sigmas de profundidad (de ambos puntos en ambos instantes) que se suman a la tolerancia de rigidez.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="116"/>
        <source>Descriptor matches with a keyframe needed to try relocalisation.</source>
        <translation>Coincidencias de descriptores con un fotograma clave necesarias para intentar la relocalización.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="117"/>
        <source>Disparity noise giving the depth sigma Z^2 s / (f b).</source>
        <translation>Ruido de disparidad que da la sigma de profundidad Z^2 s / (f b).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="118"/>
        <source>Displacement pairs between consecutive keyframes (poses refined by bundle adjustment) or between tracked frames scale_interval_frames apart.</source>
        <translation>Pares de desplazamientos entre fotogramas clave consecutivos (poses refinadas por ajuste de haces) o entre fotogramas seguidos separados scale_interval_frames.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="119"/>
        <source>Distance from the epipolar line allowed for a new-point match.</source>
        <translation>Distancia a la línea epipolar permitida para una coincidencia de un punto nuevo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="120"/>
        <source>Distance gate: a match farther than this from the predicted centre is dropped.</source>
        <translation>Gate de distancia: se descarta una coincidencia más alejada que esto del centro predicho.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="121"/>
        <source>Draws per hypothesis to find a pair within the distance limits.</source>
        <translation>Extracciones por hipótesis para encontrar un par dentro de los límites de distancia.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="122"/>
        <source>Edge of one occupancy cell; RANSAC&apos;s 5-cell error scales with it.</source>
        <translation>Lado de una celda de ocupación; el error de 5 celdas de RANSAC escala con él.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="124"/>
        <source>Epipolar (row) constraint: largest row difference of a match.</source>
        <translation>Restricción epipolar (de fila): mayor diferencia de fila de una coincidencia.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="125"/>
        <source>Estimate a constant disparity offset of the rig (rectification or matcher bias) online from the motion, and add it to every disparity; an offset of a fraction of a pixel moves far points most and makes the translation too long or too short.</source>
        <translation>Estimar en línea a partir del movimiento un desplazamiento de disparidad constante del rig (sesgo de la rectificación o del emparejador) y sumarlo a cada disparidad; un desplazamiento de una fracción de píxel mueve sobre todo los puntos lejanos y hace la traslación demasiado larga o demasiado corta.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="126"/>
        <source>Estimate each pose against the last keyframe&apos;s stereo observations of the tracks (after the frame-to-frame estimate), so per-frame errors do not accumulate.</source>
        <translation>Estimar cada pose frente a las observaciones estéreo de las pistas en el último fotograma clave (tras la estimación fotograma a fotograma), para que los errores de cada fotograma no se acumulen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="127"/>
        <source>Exposure time; 0 keeps the camera&apos;s. Out-of-range values are errors.</source>
        <translation>Tiempo de exposición; 0 conserva el de la cámara. Los valores fuera de rango son errores.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="128"/>
        <source>FAST corner threshold.</source>
        <translation>Umbral de esquinas FAST.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="129"/>
        <source>FLANN leaf checks per query.</source>
        <translation>Comprobaciones de hojas de FLANN por consulta.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="130"/>
        <source>FLANN randomised kd-trees.</source>
        <translation>Árboles kd aleatorizados de FLANN.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="131"/>
        <source>Faster estimated rotation is rejected.</source>
        <translation>Se rechaza una rotación estimada más rápida.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="132"/>
        <source>Faster estimated translation is rejected.</source>
        <translation>Se rechaza una traslación estimada más rápida.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="133"/>
        <source>Features kept per frame, tracked plus new.</source>
        <translation>Características conservadas por fotograma, seguidas más nuevas.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="134"/>
        <source>Features this close to the border are dropped.</source>
        <translation>Se descartan las características así de cerca del borde.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="135"/>
        <source>Features within this many button radii of the centre are added.</source>
        <translation>Se añaden las características dentro de este número de radios del botón alrededor del centro.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="136"/>
        <source>Fewer SIFT keypoints on the region: the button cannot be tracked.</source>
        <translation>Menos puntos clave SIFT en la región: el botón no se puede seguir.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="137"/>
        <source>Fewer consistent matches: the button is lost.</source>
        <translation>Menos coincidencias coherentes: el botón se ha perdido.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="138"/>
        <source>Fewer inliers after refinement is rejected.</source>
        <translation>Se rechaza un número menor de inliers tras el refinamiento.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="139"/>
        <source>Fewer inliers than this fraction of the points: the plane is not sound.</source>
        <translation>Menos inliers que esta fracción de los puntos: el plano no es fiable.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="140"/>
        <source>Fewer inliers than this means the motion could not be estimated.</source>
        <translation>Menos inliers que este valor significa que no se pudo estimar el movimiento.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="141"/>
        <source>Fewer map points or plane inliers: no normal in this frame.</source>
        <translation>Menos puntos del mapa o inliers del plano: ninguna normal en este fotograma.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="142"/>
        <source>Fewer points left after the range cut is reported as an error.</source>
        <translation>Si quedan menos puntos tras el corte de distancia, se informa de un error.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="143"/>
        <source>Fewer points than this: the plane is not sound (no target is sent).</source>
        <translation>Menos puntos que este valor: el plano no es fiable (no se envía ningún objetivo).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="144"/>
        <source>Fewer points: no 3D position.</source>
        <translation>Menos puntos: ninguna posición 3D.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="145"/>
        <source>Fewer tracked views with an arm pose: no triangulated point.</source>
        <translation>Menos vistas seguidas con una pose del brazo: ningún punto triangulado.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="146"/>
        <source>Fewest tracks (the track included) a surface is fitted to.</source>
        <translation>Número mínimo de pistas (incluida la propia pista) a las que se ajusta una superficie.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="147"/>
        <source>Field of view to scan, centred on forward; 0 = the camera&apos;s own (rays outside it can never hit anything).</source>
        <translation>Campo de visión que se barre, centrado hacia delante; 0 = el de la cámara (los rayos fuera de él nunca pueden alcanzar nada).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="148"/>
        <source>Floor calibration (sightline-cli floor) giving the expected up direction; empty = mobility.mount_pitch_deg / mount_roll_deg.</source>
        <translation>Calibración del suelo (sightline-cli floor) que da la dirección hacia arriba esperada; vacío = mobility.mount_pitch_deg / mount_roll_deg.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="149"/>
        <source>Floor calibration file (sightline-cli floor); empty = calibrate from the first frames of the run.</source>
        <translation>Archivo de calibración del suelo (sightline-cli floor); vacío = calibrar con los primeros fotogramas de la ejecución.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="150"/>
        <source>Floor of the residual RMS by which each frame pair&apos;s measurement is weighted.</source>
        <translation>Límite inferior del RMS de los residuos con el que se pondera la medida de cada par de fotogramas.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="151"/>
        <source>Format of trajectory.txt; --format kitti.</source>
        <translation>Formato de trajectory.txt; --format kitti.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="152"/>
        <source>Fraction of a circle&apos;s rim that must lie on an edge.</source>
        <translation>Fracción del borde de un círculo que debe estar sobre un contorno.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="153"/>
        <source>Fraction of directions around a region&apos;s centre in which its outline lies; a button&apos;s (even broken) outline surrounds its centre.</source>
        <translation>Fracción de las direcciones alrededor del centro de una región en las que está su contorno; el contorno (aunque esté roto) de un botón rodea su centro.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="154"/>
        <source>Fraction of the correction applied per frame (1 = take the walls&apos; heading).</source>
        <translation>Fracción de la corrección aplicada por fotograma (1 = adoptar el rumbo de las paredes).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="156"/>
        <source>Frame rate of overlay.avi.</source>
        <translation>Frecuencia de fotogramas de overlay.avi.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="157"/>
        <source>Frame results carry a rendered map image every n frames (0 = never).</source>
        <translation>Los resultados de los fotogramas llevan una imagen renderizada del mapa cada n fotogramas (0 = nunca).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="158"/>
        <source>Frames between two keyframes at least (see urgent_keyframe_ratio).</source>
        <translation>Fotogramas mínimos entre dos fotogramas clave (véase urgent_keyframe_ratio).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="159"/>
        <source>Frames buffered between the capture thread and the consumer; when full the oldest is dropped, so latency stays bounded.</source>
        <translation>Fotogramas en búfer entre el hilo de captura y el consumidor; cuando está lleno se descarta el más antiguo, de modo que la latencia queda acotada.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="161"/>
        <source>Frames in the window; the oldest is held fixed.</source>
        <translation>Fotogramas en la ventana; el más antiguo se mantiene fijo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="162"/>
        <source>Frames read before subsampling; 0 = all.</source>
        <translation>Fotogramas leídos antes del submuestreo; 0 = todos.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="163"/>
        <source>Frames read; 0 = all.</source>
        <translation>Fotogramas leídos; 0 = todos.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="164"/>
        <source>Frames spanned by one displacement pair of the scale estimators.</source>
        <translation>Fotogramas que abarca un par de desplazamientos de los estimadores de escala.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="165"/>
        <source>Frames that left the window keep constraining its points this long, with their poses held fixed, so the window&apos;s drift does not restart at every slide.</source>
        <translation>Los fotogramas que salieron de la ventana siguen restringiendo sus puntos durante este tiempo, con sus poses fijas, para que la deriva de la ventana no se reinicie en cada desplazamiento.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="166"/>
        <source>Frames to process; 0 = all.</source>
        <translation>Fotogramas que procesar; 0 = todos.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="167"/>
        <source>Frames to read; 0 reads the whole recording.</source>
        <translation>Fotogramas que leer; 0 lee toda la grabación.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="168"/>
        <source>Frames tried against one first frame before it is replaced.</source>
        <translation>Fotogramas probados frente a un primer fotograma antes de sustituirlo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="169"/>
        <source>Frames used to calibrate the floor when no floor_file is given.</source>
        <translation>Fotogramas usados para calibrar el suelo cuando no se indica floor_file.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="170"/>
        <source>Free scaling of cv::stereoRectify: 0 keeps only valid pixels, 1 keeps all.</source>
        <translation>Escalado libre de cv::stereoRectify: 0 conserva solo los píxeles válidos, 1 los conserva todos.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="171"/>
        <source>Free-running frame rate, or the host&apos;s rate with software triggering; 0 keeps the camera&apos;s. Rates the camera cannot reach are errors.</source>
        <translation>Frecuencia de fotogramas en modo libre, o la frecuencia del host con disparo por software; 0 conserva la de la cámara. Las frecuencias que la cámara no alcanza son errores.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="172"/>
        <source>Gauss-Newton iterations of the alignment.</source>
        <translation>Iteraciones de Gauss-Newton de la alineación.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="173"/>
        <source>Gauss-Newton iterations on the reprojection error; 0 keeps the RANSAC motion.</source>
        <translation>Iteraciones de Gauss-Newton sobre el error de reproyección; 0 conserva el movimiento de RANSAC.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="174"/>
        <source>Gauss-Newton steps on the reprojection error of each 3-point sample.</source>
        <translation>Pasos de Gauss-Newton sobre el error de reproyección de cada muestra de 3 puntos.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="175"/>
        <source>Gaussian blur before edge detection.</source>
        <translation>Desenfoque gaussiano antes de la detección de bordes.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="176"/>
        <source>GenICam pixel format to select (Mono8, Mono16, BayerRG8, RGB8, ...); empty keeps the camera&apos;s. 16-bit formats are scaled to 8 bits.</source>
        <translation>Formato de píxel GenICam que seleccionar (Mono8, Mono16, BayerRG8, RGB8, ...); vacío conserva el de la cámara. Los formatos de 16 bits se escalan a 8 bits.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="177"/>
        <source>GigE receive socket buffer; 0 lets Aravis size it to a whole frame (without it most packets of large frames are lost).</source>
        <translation>Búfer del socket de recepción GigE; 0 deja que Aravis lo dimensione para un fotograma completo (sin él se pierde la mayoría de los paquetes de los fotogramas grandes).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="178"/>
        <source>GigE stream packet size; 0 negotiates the largest packet that reaches the host.</source>
        <translation>Tamaño de paquete del stream GigE; 0 negocia el paquete más grande que llega al host.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="179"/>
        <source>Global bundle adjustment of every keyframe and point when the run stops (0 = none).</source>
        <translation>Ajuste de haces global de todos los fotogramas clave y puntos cuando termina la ejecución (0 = ninguno).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="180"/>
        <source>Grab() returns the newest frame and skips older queued ones (views); off hands out every queued frame in order (recording).</source>
        <translation>Grab() devuelve el fotograma más reciente y omite los más antiguos en cola (vistas); desactivado entrega todos los fotogramas en cola en orden (grabación).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="181"/>
        <source>Ground RANSAC inlier distance at the sensor ...</source>
        <translation>Distancia de inliers del RANSAC del suelo en el sensor ...</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="182"/>
        <source>Guided matching: best over second-best descriptor distance along the line.</source>
        <translation>Emparejamiento guiado: distancia del mejor descriptor sobre la del segundo mejor a lo largo de la línea.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="183"/>
        <source>Guided matching: distance from the epipolar line a match may have.</source>
        <translation>Emparejamiento guiado: distancia admitida de una correspondencia a la línea epipolar.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="184"/>
        <source>Half size of the search window.</source>
        <translation>Mitad del tamaño de la ventana de búsqueda.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="185"/>
        <source>Half-size of the sub-pixel corner refinement at full resolution after detection on a reduced level; 0 = none.</source>
        <translation>Mitad del tamaño del refinamiento subpíxel de esquinas a resolución completa tras la detección en un nivel reducido; 0 = ninguno.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="186"/>
        <source>Headless runs write the overlay of the track from the tap on as a PNG sequence (overlay/frame_NNNNNN.png, one per row of button.csv).</source>
        <translation>Las ejecuciones sin interfaz escriben la superposición de la pista desde el toque como secuencia PNG (overlay/frame_NNNNNN.png, una por fila de button.csv).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="187"/>
        <source>Heartbeat period; 0 = none.</source>
        <translation>Periodo del heartbeat; 0 = ninguno.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="188"/>
        <source>Height of the occupancy image (published: 400), i.e. the forward range in cells.</source>
        <translation>Altura de la imagen de ocupación (publicado: 400), es decir, el alcance hacia delante en celdas.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="350"/>
        <source>Region from the tap: outlines at two scales plus Hough circles, the one holding the tap nearest its centre (multiscale), or the published rule (the centroid nearest the tap within max_tap_distance_px).</source>
        <translation>Región desde el toque: contornos a dos escalas más círculos de Hough, la que contiene el toque más cerca de su centro (multiscale), o la regla de la publicación (el centroide más cercano al toque dentro de max_tap_distance_px).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="377"/>
        <source>Score drawn in the maps: the published Table I rule or the Gaussian process.</source>
        <translation>Puntuación dibujada en los mapas: la regla de la Tabla I de la publicación o el proceso gaussiano.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="395"/>
        <source>Start a new map when the reset rule fires (as published); off keeps stitching.</source>
        <translation>Empezar un mapa nuevo cuando se dispara la regla de reinicio (como se publicó); desactivado sigue uniendo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="400"/>
        <source>Step B6: cut the consensus set at gaps wider than this along the line and keep the longest piece, so that lines are contiguous walls (0 = as published: no cut).</source>
        <translation>Paso B6: cortar el conjunto de consenso en los huecos a lo largo de la línea más anchos que esto y conservar el tramo más largo, para que las líneas sean paredes continuas (0 = como se publicó: sin corte).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="401"/>
        <source>Step B7: keep the hypothesis with the lowest summed error (as published) or mean error.</source>
        <translation>Paso B7: conservar la hipótesis con el menor error sumado (como se publicó) o con el menor error medio.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="402"/>
        <source>Step C: re-find the chosen line&apos;s dominant surface by sweeping its direction this far either way, then refit on it (0 = as published: the line of step B6 as is).</source>
        <translation>Paso C: volver a encontrar la superficie dominante de la línea elegida girando su dirección esto hacia cada lado, y luego reajustar sobre ella (0 = como se publicó: la línea del paso B6 tal cual).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="470"/>
        <source>Wall-line extractor: the published multi-line RANSAC or split-and-merge.</source>
        <translation>Extractor de líneas de pared: el RANSAC multilínea de la publicación o split-and-merge.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="472"/>
        <source>Weigh them so once one position states a 1-sigma of at most this (the arm has come close; far positions then carry the newest scale&apos;s error times their distance); 0 = only with weighted (docs/button.md).</source>
        <translation>Pondera las posiciones así en cuanto una posición declara una sigma de como mucho este valor (el brazo se ha acercado; las posiciones lejanas llevan entonces el error de la escala más reciente por su distancia); 0 = solo con weighted (docs/button.md).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="477"/>
        <source>When even after that fewer tracks survive than this fraction of the share that usually survives (a slow average over the last frames; a sharp turn, or a turn at a low frame rate), the camera&apos;s rotation is searched by comparing the two images and the points are tracked again from where it puts them; the better attempt is kept. 0 = never.</source>
        <translation>Si aun después sobreviven menos pistas que esta fracción de la parte que suele sobrevivir (un promedio lento de los últimos fotogramas; un giro cerrado o un giro a baja frecuencia de imagen), se busca la rotación de la cámara comparando las dos imágenes y los puntos se siguen de nuevo desde donde ella los coloca; se conserva el mejor intento. 0 = nunca.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="480"/>
        <source>Where person boxes come from: the dataset&apos;s ground truth, clusters of a person&apos;s size standing on the floor in the depth image (depth), OpenCV&apos;s HOG detector on the colour image, auto (ground truth when present, else depth) or none.</source>
        <translation>De dónde vienen los recuadros de personas: la verdad de referencia del conjunto de datos, grupos de puntos del tamaño de una persona de pie sobre el suelo en la imagen de profundidad (depth), el detector HOG de OpenCV en la imagen en color, auto (verdad de referencia si existe, si no depth) o none.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="482"/>
        <source>Width of the occupancy image (published: 400); the robot sits at its bottom centre.</source>
        <translation>Anchura de la imagen de ocupación (publicado: 400); el robot está en el centro del borde inferior.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="507"/>
        <source>depth: a head is the highest point within this radius; people side by side are split at their heads.</source>
        <translation>depth: una cabeza es el punto más alto dentro de este radio; las personas una al lado de otra se separan por sus cabezas.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="508"/>
        <source>depth: a person&apos;s footprint is at least this long.</source>
        <translation>depth: la huella de una persona mide al menos esto.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="509"/>
        <source>depth: a person&apos;s footprint is at most this long (walls are longer); wider clusters are split at their heads.</source>
        <translation>depth: la huella de una persona mide como mucho esto (las paredes son más largas); los grupos más anchos se separan por sus cabezas.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="510"/>
        <source>depth: a person&apos;s lowest point lies at most this high above the floor.</source>
        <translation>depth: el punto más bajo de una persona está como mucho a esta altura sobre el suelo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="511"/>
        <source>depth: a person&apos;s top lies at least this high above the floor.</source>
        <translation>depth: el punto más alto de una persona está al menos a esta altura sobre el suelo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="513"/>
        <source>depth: a person&apos;s top lies at most this high (walls and pillars go higher).</source>
        <translation>depth: el punto más alto de una persona está como mucho a esta altura (las paredes y columnas suben más).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="514"/>
        <source>depth: between two heads the tops dip at least this much (neck, shoulders); the cut-off top of a wall is flat and is not split.</source>
        <translation>depth: entre dos cabezas las alturas bajan al menos esto (cuello, hombros); el borde superior cortado de una pared es plano y no se separa.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="515"/>
        <source>depth: floor grid cell in which points are clustered.</source>
        <translation>depth: celda de la rejilla del suelo en la que se agrupan los puntos.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="516"/>
        <source>depth: points farther away are not looked at.</source>
        <translation>depth: los puntos más lejanos no se consideran.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="517"/>
        <source>depth: sampled points a person needs.</source>
        <translation>depth: puntos muestreados que necesita una persona.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="520"/>
        <source>depth: the depth image is sampled to about this many columns.</source>
        <translation>depth: la imagen de profundidad se muestrea a unas tantas columnas.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="521"/>
        <source>depth: the shorter side of a person&apos;s footprint is at least this (legs, arms and the torso&apos;s curve); the end of a wall seen at the edge of view is one cell thick.</source>
        <translation>depth: el lado más corto de la huella de una persona mide al menos esto (piernas, brazos y la curva del torso); el extremo de una pared visto en el borde de la imagen tiene una celda de grosor.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="525"/>
        <source>epsilon_floor: a point within this height of the floor plane is floor (published value 3.5, read as 3.5 cm: generous so that no floor pixel is labelled occupied).</source>
        <translation>epsilon_floor: un punto dentro de esta altura respecto al plano del suelo es suelo (valor publicado 3.5, leído como 3.5 cm: generoso para que ningún píxel del suelo se marque como ocupado).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="526"/>
        <source>err_max: inlier distance in occupancy cells (published: 5 pixels); metres = cells x mapping.occupancy.cell_size_m.</source>
        <translation>err_max: distancia de inliers en celdas de ocupación (publicado: 5 píxeles); metros = celdas x mapping.occupancy.cell_size_m.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="531"/>
        <source>grid: organized pixel-grid path (fast); pcl: the published voxel grid, outlier removal and k-d tree path.</source>
        <translation>grid: camino por la rejilla de píxeles organizada (rápido); pcl: el camino de la publicación con rejilla de vóxeles, eliminación de outliers y árbol k-d.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="534"/>
        <source>j_max: hypotheses per line (published: 250); also caps the adaptive count.</source>
        <translation>j_max: hipótesis por línea (publicado: 250); también limita el recuento adaptativo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="551"/>
        <source>rgbd, rgbd_icp: a colour frame whose brightness varies less than this is not tracked (a black or blank frame).</source>
        <translation>rgbd, rgbd_icp: una imagen en color cuyo brillo varía menos que esto no se sigue (un fotograma negro o vacío).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="552"/>
        <source>rgbd, rgbd_icp: start the alignment from ORB features matched with PnP RANSAC when they agree (fast turns at low frame rates).</source>
        <translation>rgbd, rgbd_icp: iniciar la alineación desde características ORB emparejadas con PnP RANSAC cuando concuerdan (giros rápidos a baja frecuencia de imagen).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="553"/>
        <source>wheelchair: 5 m range, 3 cm step; icub: 1.75 m, 5 cm (the published humanoid); custom: range_cut_m and max_step_m.</source>
        <translation>wheelchair: alcance de 5 m, escalón de 3 cm; icub: 1.75 m, 5 cm (el humanoide de la publicación); custom: range_cut_m y max_step_m.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="189"/>
        <source>Highest plausible camera height above the floor.</source>
        <translation>Altura máxima plausible de la cámara sobre el suelo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="18"/>
        <source>... or turned this much.</source>
        <translation>... o ha girado tanto.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="33"/>
        <source>A frame becomes the odometry&apos;s reference when it moved this far from the last one (0 with keyframe_rotation_deg 0: every frame).</source>
        <translation>Un fotograma pasa a ser la referencia de la odometría cuando se ha movido esta distancia desde la última (0 con keyframe_rotation_deg 0: cada fotograma).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="37"/>
        <source>A frame this far after the last, or in a sequence whose recent frames are (median of five steps), is low-rate (keyframe-rate): the zero-motion try below and the urgent keyframes of mono.mapping apply.</source>
        <translation>Un fotograma al menos así de separado del anterior, o en una secuencia cuyos fotogramas recientes lo están (mediana de cinco pasos), es de baja frecuencia (de fotogramas clave): se aplican el intento de movimiento nulo de abajo y los fotogramas clave urgentes de mono.mapping.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="40"/>
        <source>A frame with a smaller fraction of depth pixels in range is not tracked (the pose is held).</source>
        <translation>Un fotograma con una fracción menor de píxeles de profundidad dentro del rango no se sigue (la pose se mantiene).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="51"/>
        <source>A new keyframe looks for a revisit among keyframes at least this many keyframes older.</source>
        <translation>Un fotograma clave nuevo busca una revisita entre los fotogramas clave al menos este número de fotogramas clave más antiguos.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="53"/>
        <source>A ray of such an outline is on an edge when that edge is also this many times the median edge along the ray in its radius band (texture stands out less).</source>
        <translation>Un rayo de ese contorno está sobre un borde cuando ese borde es además tantas veces el borde mediano a lo largo del rayo en su banda de radios (una textura destaca menos).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="62"/>
        <source>A tracked corner within this of where the plane&apos;s homography puts it is on the panel.</source>
        <translation>Una esquina seguida a esta distancia como máximo de donde la pone la homografía del plano pertenece al panel.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="73"/>
        <source>Always weigh each position by 1 / its own variance (plane fit, tracked centre and scale, growing with the distance): the near frames of the approach count most.</source>
        <translation>Pondera siempre cada posición por 1 / su propia varianza (ajuste del plano, centro seguido y escala, que crece con la distancia): los fotogramas cercanos de la aproximación cuentan más.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="79"/>
        <source>An odometry step faster than this (sensor time) is rejected.</source>
        <translation>Un paso de odometría más rápido que esto (tiempo del sensor) se rechaza.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="80"/>
        <source>An odometry step turning faster than this (sensor time) is rejected.</source>
        <translation>Un paso de odometría que gira más rápido que esto (tiempo del sensor) se rechaza.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="105"/>
        <source>Corners tracked around the button for the plane from the arm&apos;s motion.</source>
        <translation>Esquinas seguidas alrededor del botón para el plano a partir del movimiento del brazo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="113"/>
        <source>Depth readings farther than this are not used by the odometry.</source>
        <translation>La odometría no usa las lecturas de profundidad más lejanas que esto.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="114"/>
        <source>Depth readings nearer than this are not used by the odometry.</source>
        <translation>La odometría no usa las lecturas de profundidad más cercanas que esto.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="123"/>
        <source>Edge strength most rays of such an outline must reach.</source>
        <translation>Intensidad de borde que la mayoría de los rayos de ese contorno debe alcanzar.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="155"/>
        <source>Fraction of the pixels the odometry uses per pyramid level.</source>
        <translation>Fracción de los píxeles que la odometría usa en cada nivel de la pirámide.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="160"/>
        <source>Frames farther apart in sensor time are not aligned; tracking starts again from the held pose.</source>
        <translation>Los fotogramas más separados que esto en tiempo del sensor no se alinean; el seguimiento comienza de nuevo desde la pose mantenida.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="190"/>
        <source>Hough accumulator threshold.</source>
        <translation>Umbral del acumulador de Hough.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="191"/>
        <source>How long Grab() waits for a frame before reporting the device as unavailable.</source>
        <translation>Cuánto espera Grab() un fotograma antes de informar de que el dispositivo no está disponible.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="192"/>
        <source>Huber loss threshold of bundle adjustment.</source>
        <translation>Umbral de Huber del ajuste de haces.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="193"/>
        <source>Huber threshold of the robust least squares.</source>
        <translation>Umbral de Huber de los mínimos cuadrados robustos.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="194"/>
        <source>Huber threshold of the robust pose optimisation.</source>
        <translation>Umbral de Huber de la optimización robusta de la pose.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="195"/>
        <source>Huber threshold of the robust weight of an observation&apos;s reprojection error.</source>
        <translation>Umbral de Huber del peso robusto del error de reproyección de una observación.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="196"/>
        <source>Huber threshold of the robust weight.</source>
        <translation>Umbral de Huber del peso robusto.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="197"/>
        <source>Huber threshold of the robust weights of the offset measurement.</source>
        <translation>Umbral de Huber de los pesos robustos de la medida del desplazamiento.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="198"/>
        <source>Hypotheses per line: fixed (max_iterations, seed) or adaptive log(1-p)/log(1-w^2) with w the best inlier ratio so far.</source>
        <translation>Hipótesis por línea: fijas (max_iterations, original) o adaptativas log(1-p)/log(1-w^2), con w la mejor proporción de inliers hasta el momento.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="199"/>
        <source>IPv4 address the target server binds; 127.0.0.1 keeps it on this machine.</source>
        <translation>Dirección IPv4 a la que se vincula el servidor de objetivos; 127.0.0.1 lo mantiene en esta máquina.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="200"/>
        <source>Idle-time adjustment slices run at stop on a large map (bounds the stop time).</source>
        <translation>Tramos del ajuste en tiempo ocioso que se ejecutan al detener sobre un mapa grande (acota el tiempo de parada).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="201"/>
        <source>Image buffers in the stream&apos;s pool; more ride out longer consumer stalls.</source>
        <translation>Búferes de imagen en el pool del stream; más permiten aguantar bloqueos más largos del consumidor.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="202"/>
        <source>Image pyramid levels of the odometry (coarse to fine; more handle larger steps).</source>
        <translation>Niveles de la pirámide de imágenes de la odometría (de grueso a fino; más niveles admiten pasos mayores).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="203"/>
        <source>Inlier RMS above this: the plane is not sound.</source>
        <translation>RMS de los inliers por encima de este valor: el plano no es fiable.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="204"/>
        <source>Inlier distance of the panel plane.</source>
        <translation>Distancia de inliers del plano del panel.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="205"/>
        <source>Inliers against the old map that confirm a revisit; the map since then is then bent onto the old one.</source>
        <translation>Inliers frente al mapa antiguo que confirman una revisita; el mapa construido desde entonces se dobla entonces sobre el antiguo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="206"/>
        <source>Inliers needed to accept a relocalisation.</source>
        <translation>Inliers necesarios para aceptar una relocalización.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="207"/>
        <source>Input line used with hardware triggering, e.g. Line1.</source>
        <translation>Línea de entrada usada con disparo por hardware, p. ej. Line1.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="208"/>
        <source>Iterations of each local bundle adjustment (0 = none).</source>
        <translation>Iteraciones de cada ajuste de haces local (0 = ninguno).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="209"/>
        <source>Iterations of one idle-time adjustment slice (0 = no adjustment in idle time).</source>
        <translation>Iteraciones de un tramo del ajuste en tiempo ocioso (0 = ningún ajuste en tiempo ocioso).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="210"/>
        <source>KLT iterations per level.</source>
        <translation>Iteraciones de KLT por nivel.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="211"/>
        <source>KLT pyramid levels above full resolution (shared with stereo matching).</source>
        <translation>Niveles de la pirámide de KLT por encima de la resolución completa (compartidos con el emparejamiento estéreo).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="212"/>
        <source>KLT pyramid levels used around the disparity guess.</source>
        <translation>Niveles de la pirámide de KLT usados alrededor de la estimación de disparidad.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="213"/>
        <source>KLT stops when its update is smaller than this.</source>
        <translation>KLT se detiene cuando su actualización es menor que este valor.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="214"/>
        <source>KLT window side (odd).</source>
        <translation>Lado de la ventana de KLT (impar).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="215"/>
        <source>Keyframes whose poses one slice of the idle-time global adjustment optimises.</source>
        <translation>Fotogramas clave cuyas poses optimiza un tramo del ajuste global en tiempo ocioso.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="217"/>
        <source>Larger 1-sigma position uncertainty: no target.</source>
        <translation>Incertidumbre de posición a 1 sigma mayor: ningún objetivo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="218"/>
        <source>Larger 1-sigma uncertainty of the approach direction (the panel normal): no target.</source>
        <translation>Incertidumbre a 1 sigma mayor de la dirección de aproximación (la normal del panel): ningún objetivo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="219"/>
        <source>Larger change of velocity from the last accepted motion is rejected; 0 = no check.</source>
        <translation>Se rechaza un cambio de velocidad mayor respecto al último movimiento aceptado; 0 = sin comprobación.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="220"/>
        <source>Larger median offset of the face points from the panel plane is not applied.</source>
        <translation>No se aplica un desplazamiento mediano mayor de los puntos de la cara respecto al plano del panel.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="221"/>
        <source>Largest Hamming distance of a new-point match.</source>
        <translation>Mayor distancia de Hamming de una coincidencia de un punto nuevo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="222"/>
        <source>Largest Hamming distance of a tracked ORB match.</source>
        <translation>Mayor distancia de Hamming de una coincidencia ORB seguida.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="223"/>
        <source>Largest Hough circle radius.</source>
        <translation>Radio máximo de los círculos de Hough.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="224"/>
        <source>Largest angle between the floor normal and the camera&apos;s up axis (-y).</source>
        <translation>Ángulo máximo entre la normal del suelo y el eje hacia arriba de la cámara (-y).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="225"/>
        <source>Largest button region as a fraction of the image area.</source>
        <translation>Región del botón más grande, como fracción del área de la imagen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="226"/>
        <source>Largest depth/colour timestamp difference of an RGB-D pair from a device; frames without a partner are dropped and counted.</source>
        <translation>Mayor diferencia de marcas de tiempo entre profundidad y color de un par RGB-D de un dispositivo; los fotogramas sin pareja se descartan y se cuentan.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="227"/>
        <source>Largest difference between the left and right timestamps of a pair; frames without a partner are dropped and counted.</source>
        <translation>Mayor diferencia entre las marcas de tiempo izquierda y derecha de un par; los fotogramas sin pareja se descartan y se cuentan.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="228"/>
        <source>Largest disparity searched and accepted.</source>
        <translation>Mayor disparidad buscada y aceptada.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="229"/>
        <source>Largest size change (either way) since the last tracked frame at re-acquisition.</source>
        <translation>Mayor cambio de tamaño (en ambos sentidos) desde el último fotograma seguido al volver a adquirir.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="230"/>
        <source>Largest turn between two frames that search looks for.</source>
        <translation>Giro máximo entre dos fotogramas que busca esa búsqueda.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="231"/>
        <source>Left-right check: the right point tracked back must land this close; 0 = no check.</source>
        <translation>Comprobación izquierda-derecha: el punto derecho seguido hacia atrás debe caer así de cerca; 0 = sin comprobación.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="232"/>
        <source>Length of the first baseline in map units (PTAM: 0.1); metric scale comes later.</source>
        <translation>Longitud de la primera línea base en unidades del mapa (PTAM: 0.1); la escala métrica llega después.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="233"/>
        <source>Levenberg-Marquardt iterations per frame.</source>
        <translation>Iteraciones de Levenberg-Marquardt por fotograma.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="234"/>
        <source>Lines vote with weight length / (1 + (rms / rms_scale_m)^2): scattered consensus sets (a wall merged with a door recess) count less.</source>
        <translation>Las líneas votan con peso longitud / (1 + (rms / rms_scale_m)^2): los conjuntos de consenso dispersos (una pared fusionada con el hueco de una puerta) cuentan menos.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="235"/>
        <source>Lines with fewer points are dropped.</source>
        <translation>Se descartan las líneas con menos puntos.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="236"/>
        <source>Log-odds added when a frame sees a cell free.</source>
        <translation>Log-odds que se suman cuando un fotograma ve una celda libre.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="237"/>
        <source>Log-odds added when a frame sees a cell occupied.</source>
        <translation>Log-odds que se suman cuando un fotograma ve una celda ocupada.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="238"/>
        <source>Longer client lines are discarded; an over-long token line closes the connection.</source>
        <translation>Las líneas de cliente más largas se descartan; una línea de token demasiado larga cierra la conexión.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="239"/>
        <source>Longer image side at which contours are searched; larger frames are scaled down.</source>
        <translation>Lado mayor de la imagen con el que se buscan contornos; los fotogramas más grandes se reducen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="240"/>
        <source>Longest over shortest side of the region&apos;s rotated box.</source>
        <translation>Cociente entre el lado más largo y el más corto del recuadro girado de la región.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="241"/>
        <source>Looming needs the largest and smallest depth to differ by this fraction ...</source>
        <translation>El crecimiento aparente (looming) requiere que la profundidad mayor y la menor difieran en esta fracción ...</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="242"/>
        <source>Lowe&apos;s ratio test: best over second-best descriptor distance must be below this.</source>
        <translation>Test del cociente de Lowe: la mejor distancia de descriptores dividida por la segunda mejor debe quedar por debajo de este valor.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="243"/>
        <source>Lower clamp of a cell&apos;s log-odds.</source>
        <translation>Límite inferior de los log-odds de una celda.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="244"/>
        <source>Lowest plausible camera height above the floor.</source>
        <translation>Altura mínima plausible de la cámara sobre el suelo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="245"/>
        <source>Map points projecting within this distance of the button centre are used.</source>
        <translation>Se usan los puntos del mapa que se proyectan a menos de esta distancia del centro del botón.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="246"/>
        <source>Map points within this many tracked button radii (the button&apos;s face) are used first; 0 = always use radius_px.</source>
        <translation>Los puntos del mapa dentro de este número de radios del botón seguido (la cara del botón) se usan primero; 0 = usar siempre radius_px.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="247"/>
        <source>Maps with up to this many keyframes get the full global adjustment at stop; larger ones get at most final_ba_max_slices slices of the idle-time adjustment.</source>
        <translation>Los mapas con hasta este número de fotogramas clave reciben al detener el ajuste global completo; los mayores, como mucho final_ba_max_slices tramos del ajuste en tiempo ocioso.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="248"/>
        <source>Matches with a smaller disparity (too far to triangulate) are rejected.</source>
        <translation>Se rechazan las coincidencias con una disparidad menor (demasiado lejos para triangular).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="249"/>
        <source>Matches with the first frame needed before initialisation is tried.</source>
        <translation>Coincidencias con el primer fotograma necesarias antes de intentar la inicialización.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="250"/>
        <source>Measured displacements shorter than this are dropped.</source>
        <translation>Se descartan los desplazamientos medidos más cortos que esto.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="251"/>
        <source>Measured motion for the metric scale: the arm&apos;s recorded poses (arm_poses.txt), the arm&apos;s poses streamed live to the button pipeline&apos;s arm-target server (arm_stream), ground-truth displacements, or none. auto: the recorded arm poses when arm_poses.txt is there; else, for the button pipeline while serving, the stream; else (mono-slam) ground truth.</source>
        <translation>Movimiento medido para la escala métrica: las poses grabadas del brazo (arm_poses.txt), las poses del brazo transmitidas en vivo al servidor de objetivos del pipeline del botón (arm_stream), los desplazamientos de ground truth, o ninguno. auto: las poses grabadas del brazo si existe arm_poses.txt; si no, para el pipeline del botón mientras sirve objetivos, el stream; si no (mono-slam), el ground truth.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="252"/>
        <source>Median angle between the rays of a match needed before trying (move sideways).</source>
        <translation>Ángulo mediano entre los rayos de una coincidencia necesario antes de intentarlo (muévase lateralmente).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="253"/>
        <source>Minimum distance between corners.</source>
        <translation>Distancia mínima entre esquinas.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="254"/>
        <source>Mirror images left-right, as OpenNI does by default for people facing the camera.</source>
        <translation>Reflejar las imágenes de izquierda a derecha, como hace OpenNI por defecto para personas de cara a la cámara.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="255"/>
        <source>Morphological closing that joins broken button outlines; 0 = none.</source>
        <translation>Cierre morfológico que une los contornos rotos de los botones; 0 = ninguno.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="256"/>
        <source>Most recent keyframes whose poses local bundle adjustment optimises.</source>
        <translation>Fotogramas clave más recientes cuyas poses optimiza el ajuste de haces local.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="258"/>
        <source>Niceness of the mapping thread (threaded mode, Linux); 10 lets tracking win a core it shares with mapping, but starves mapping on a loaded machine.</source>
        <translation>Valor nice del hilo de mapeo (modo con hilos, Linux); 10 hace que el seguimiento gane un núcleo que comparte con el mapeo, pero deja sin recursos al mapeo en una máquina cargada.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="259"/>
        <source>No pose is interpolated across a larger gap between two arm_pose messages.</source>
        <translation>No se interpola ninguna pose a través de un hueco mayor entre dos mensajes arm_pose.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="260"/>
        <source>No second reset within this many frames of the last one.</source>
        <translation>Ningún segundo reinicio en este número de fotogramas desde el último.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="261"/>
        <source>No target until the online hand-eye check has seen the mount&apos;s translation (the arm must rotate between keyframes); without it that translation is taken on trust.</source>
        <translation>Ningún objetivo hasta que la comprobación mano-ojo en línea haya visto la traslación del montaje (el brazo debe girar entre fotogramas clave); sin ella esa traslación se acepta sin verificar.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="262"/>
        <source>Noise of a camera displacement measured in the map (sigma_x of the ML estimator).</source>
        <translation>Ruido de un desplazamiento de la cámara medido en el mapa (sigma_x del estimador ML).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="263"/>
        <source>Noise of a displacement measured by the arm or robot (sigma_y).</source>
        <translation>Ruido de un desplazamiento medido por el brazo o el robot (sigma_y).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="264"/>
        <source>ORB features per frame for the feature guess.</source>
        <translation>Características ORB por fotograma para la estimación inicial por características.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="265"/>
        <source>ORB keypoints extracted per frame.</source>
        <translation>Puntos clave ORB extraídos por fotograma.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="266"/>
        <source>Observations reprojecting worse than this are dropped from the window.</source>
        <translation>Las observaciones que reproyectan peor que esto se eliminan de la ventana.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="267"/>
        <source>Observations with a smaller disparity (no usable depth) are left out.</source>
        <translation>Las observaciones con menor disparidad (sin profundidad utilizable) se dejan fuera.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="268"/>
        <source>Occupied cells closer than this to the robot are ignored (robot body, noise).</source>
        <translation>Se ignoran las celdas ocupadas más cerca del robot que esto (cuerpo del robot, ruido).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="270"/>
        <source>Odometry correspondences farther apart than this in depth are rejected.</source>
        <translation>Las correspondencias de la odometría más separadas que esto en profundidad se rechazan.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="271"/>
        <source>Odometry iterations per pyramid level.</source>
        <translation>Iteraciones de la odometría por nivel de la pirámide.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="272"/>
        <source>Of the re-acquiring matches, at least this many lie on the button itself.</source>
        <translation>De las coincidencias de readquisición, al menos este número está sobre el propio botón.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="273"/>
        <source>Old keyframes this close to a new keyframe (relative to the mean depth) are tried as a revisit (0 = no revisit search).</source>
        <translation>Los fotogramas clave antiguos así de cerca de un fotograma clave nuevo (respecto a la profundidad media) se prueban como revisita (0 = sin búsqueda de revisitas).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="274"/>
        <source>Older estimates are not sent.</source>
        <translation>Las estimaciones más antiguas no se envían.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="275"/>
        <source>Older frames&apos; normals fade with exp(-age / this) in the average (data time); 0 = this frame&apos;s normal only.</source>
        <translation>Las normales de los fotogramas más antiguos se atenúan en la media con exp(-edad / este valor) (tiempo de los datos); 0 = solo la normal de este fotograma.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="276"/>
        <source>On close: how long the stop lines may take to go out before the sockets close.</source>
        <translation>Al cerrar: cuánto pueden tardar en salir las líneas de parada antes de que se cierren los sockets.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="277"/>
        <source>On the button: within this many radii of its centre.</source>
        <translation>Sobre el botón: dentro de este número de radios desde su centro.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="278"/>
        <source>Once a revisit links the map to old keyframes, those whose centre is this close to the camera (relative to the mean depth) join the recent ones in the map tracked against, so the place is tracked on its old points (0 = recent keyframes only).</source>
        <translation>Cuando una revisita enlaza el mapa con fotogramas clave antiguos, aquellos cuyo centro está así de cerca de la cámara (respecto a la profundidad media) se suman a los recientes en el mapa contra el que se sigue, de modo que el lugar se sigue sobre sus puntos antiguos (0 = solo fotogramas clave recientes).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="279"/>
        <source>Only frames tracked at least this confidently refresh the model.</source>
        <translation>Solo los fotogramas seguidos al menos con esta confianza renuevan el modelo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="280"/>
        <source>Otherwise: the camera&apos;s optical centre this far ahead of the odometry base.</source>
        <translation>Si no: el centro óptico de la cámara esta distancia por delante de la base de la odometría.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="281"/>
        <source>Outlier removal: keep points with mean neighbour distance &lt;= mu + alpha sigma.</source>
        <translation>Eliminación de outliers: conservar los puntos con distancia media a los vecinos &lt;= mu + alpha sigma.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="282"/>
        <source>Pairs weigh |measured displacement|^-e in the ML estimate: 1 = the map&apos;s error grows with the distance travelled, 0 = every pair equally noisy.</source>
        <translation>Los pares pesan |desplazamiento medido|^-e en la estimación ML: 1 = el error del mapa crece con la distancia recorrida, 0 = todos los pares igual de ruidosos.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="283"/>
        <source>Pairs whose own ratio lies outside a factor of this from the estimate are dropped.</source>
        <translation>Se descartan los pares cuyo cociente propio se aparta de la estimación más de un factor igual a este valor.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="284"/>
        <source>Pause between attempts to reopen a lost device.</source>
        <translation>Pausa entre intentos de volver a abrir un dispositivo perdido.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="285"/>
        <source>Per-client queue length; a slow client loses its oldest messages (counted).</source>
        <translation>Longitud de la cola por cliente; un cliente lento pierde sus mensajes más antiguos (contados).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="286"/>
        <source>Per-segment plane RANSAC inlier distance.</source>
        <translation>Distancia de inliers del RANSAC de plano por segmento.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="287"/>
        <source>Per-segment plane RANSAC iterations before the least-squares refit (0 = PCA only).</source>
        <translation>Iteraciones del RANSAC de plano por segmento antes del reajuste por mínimos cuadrados (0 = solo PCA).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="288"/>
        <source>Pixel format as a FOURCC, e.g. MJPG for high resolutions over USB 2; empty keeps the camera&apos;s.</source>
        <translation>Formato de píxel como FOURCC, p. ej. MJPG para resoluciones altas por USB 2; vacío conserva el de la cámara.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="289"/>
        <source>Pixels in a person box within this depth of the box&apos;s median depth are the person.</source>
        <translation>Los píxeles de un recuadro de persona dentro de esta profundidad respecto a la profundidad mediana del recuadro son la persona.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="290"/>
        <source>Place every kept position again with the newest metric scale (kept in map units).</source>
        <translation>Volver a situar cada posición conservada con la escala métrica más reciente (conservadas en unidades del mapa).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="291"/>
        <source>Plane RANSAC hypotheses of the panel normal.</source>
        <translation>Hipótesis RANSAC de plano para la normal del panel.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="292"/>
        <source>Plane RANSAC hypotheses.</source>
        <translation>Hipótesis RANSAC de plano.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="293"/>
        <source>Plane inlier distance.</source>
        <translation>Distancia de inliers del plano.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="294"/>
        <source>PnP inliers the feature guess needs to be used.</source>
        <translation>Inliers de PnP que necesita la estimación por características para usarse.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="295"/>
        <source>Point-to-plane distance of an inlier while fitting the floor.</source>
        <translation>Distancia punto-plano de un inlier al ajustar el suelo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="296"/>
        <source>Points are subsampled evenly to at most this many.</source>
        <translation>Los puntos se submuestrean uniformemente hasta este número como máximo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="297"/>
        <source>Points each ground hypothesis is scored on.</source>
        <translation>Puntos con los que se puntúa cada hipótesis de suelo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="298"/>
        <source>Points farther than this are not used for the fit.</source>
        <translation>Los puntos más lejanos que esto no se usan para el ajuste.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="299"/>
        <source>Points found in fewer of the frames that should see them are culled.</source>
        <translation>Se eliminan los puntos encontrados en menos fotogramas de los que deberían verlos.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="300"/>
        <source>Points higher than this above the floor (ceiling, lamps) are ignored.</source>
        <translation>Se ignoran los puntos a más altura que esto sobre el suelo (techo, lámparas).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="301"/>
        <source>Points on the button&apos;s face that move the panel plane onto the face.</source>
        <translation>Puntos de la cara del botón que llevan el plano del panel a la cara.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="302"/>
        <source>Points whose neighbourhood bends more (surface variation, 0 = flat) get no normal and stay unsegmented: edges between surfaces.</source>
        <translation>Los puntos cuyo entorno se curva más (variación de superficie, 0 = plano) no reciben normal y quedan sin segmentar: bordes entre superficies.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="303"/>
        <source>Prior standard deviation of the offset around zero; smaller trusts the calibration longer.</source>
        <translation>Desviación típica a priori del desplazamiento alrededor de cero; más pequeña confía más tiempo en la calibración.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="304"/>
        <source>Probability above which a cell is occupied (map.yaml occupied_thresh).</source>
        <translation>Probabilidad por encima de la cual una celda está ocupada (map.yaml occupied_thresh).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="305"/>
        <source>Probability below which a cell is free (map.yaml free_thresh).</source>
        <translation>Probabilidad por debajo de la cual una celda está libre (map.yaml free_thresh).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="307"/>
        <source>Process every stride-th frame read, from the first (1 = all): a keyframe-rate sequence from a full-rate recording.</source>
        <translation>Procesa uno de cada stride fotogramas leídos, desde el primero (1 = todos): una secuencia a ritmo de fotogramas clave a partir de una grabación a frecuencia completa.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="308"/>
        <source>Publish the targets through the arm-target server (button.arm.*); --serve HOST:PORT.</source>
        <translation>Publicar los objetivos mediante el servidor de objetivos del brazo (button.arm.*); --serve HOST:PORT.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="309"/>
        <source>Published eq. 13: depth-to-colour sensor offset along x.</source>
        <translation>Publicación ec. 13: desplazamiento entre los sensores de profundidad y de color a lo largo de x.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="310"/>
        <source>Published eq. 13: depth-to-colour sensor offset along y.</source>
        <translation>Publicación ec. 13: desplazamiento entre los sensores de profundidad y de color a lo largo de y.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="311"/>
        <source>Published eq. 6: expected inlier ratio w; iterations = log(1-p) / log(1-w^3).</source>
        <translation>Publicación ec. 6: proporción de inliers esperada w; iteraciones = log(1-p) / log(1-w^3).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="312"/>
        <source>Published eq. 6: wanted probability p of drawing one all-inlier sample.</source>
        <translation>Publicación ec. 6: probabilidad p deseada de extraer una muestra solo de inliers.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="313"/>
        <source>Pyramid level Shi-Tomasi corners are detected on (0 = full resolution).</source>
        <translation>Nivel de la pirámide en el que se detectan las esquinas de Shi-Tomasi (0 = resolución completa).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="314"/>
        <source>Pyramid level of the row search for features without a disparity guess.</source>
        <translation>Nivel de la pirámide de la búsqueda por filas para características sin estimación de disparidad.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="315"/>
        <source>Pyramid levels of the second tracking attempt (reaches about 2^levels further).</source>
        <translation>Niveles de la pirámide del segundo intento de seguimiento (llega unas 2^levels veces más lejos).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="316"/>
        <source>Pyramid levels.</source>
        <translation>Niveles de la pirámide.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="317"/>
        <source>RANSAC inlier distance of the essential matrix and the homography.</source>
        <translation>Distancia de inliers de RANSAC de la matriz esencial y de la homografía.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="318"/>
        <source>RANSAC plane hypotheses (half of them sampled within one voxel).</source>
        <translation>Hipótesis RANSAC de plano (la mitad muestreadas dentro de un vóxel).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="319"/>
        <source>RGB-D odometry: rgbd aligns brightness and depth (needs registered colour), icp aligns depth surfaces only (point-to-plane), rgbd_icp uses both.</source>
        <translation>Odometría RGB-D: rgbd alinea brillo y profundidad (necesita color registrado), icp alinea solo superficies de profundidad (punto a plano), rgbd_icp usa ambos.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="322"/>
        <source>ROS bag: largest time between the two tf samples a pose at a frame&apos;s stamp is interpolated between; frames in a longer gap get no pose.</source>
        <translation>Bag de ROS: tiempo máximo entre las dos muestras tf entre las que se interpola una pose en la marca de tiempo de un frame; los frames en un hueco más largo no tienen pose.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="325"/>
        <source>ROS bag: the arm&apos;s base tf frame; the pose of end_effector_frame in it is the arm&apos;s pose when there is no arm_poses.txt.</source>
        <translation>Bag de ROS: el frame tf de la base del brazo; la pose de end_effector_frame en él es la pose del brazo cuando no hay arm_poses.txt.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="326"/>
        <source>ROS bag: the arm&apos;s end-effector tf frame.</source>
        <translation>Bag de ROS: el frame tf del efector final del brazo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="331"/>
        <source>ROS bag: the platform&apos;s tf frame whose pose in odom_frame is the odometry.</source>
        <translation>Bag de ROS: el frame tf de la plataforma cuya pose en odom_frame es la odometría.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="334"/>
        <source>ROS bag: the tf frame of the odometry; without an odometry topic, the pose of base_frame in it on /tf is the platform&apos;s odometry.</source>
        <translation>Bag de ROS: el frame tf de la odometría; sin topic de odometría, la pose de base_frame en él en /tf es la odometría de la plataforma.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="335"/>
        <source>Random generator seed.</source>
        <translation>Semilla del generador aleatorio.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="336"/>
        <source>Random generator seed; each scan starts from it, so results are reproducible.</source>
        <translation>Semilla del generador aleatorio; cada barrido parte de ella, de modo que los resultados son reproducibles.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="337"/>
        <source>Random seed of the plane RANSAC.</source>
        <translation>Semilla aleatoria del RANSAC de plano.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="338"/>
        <source>Rate at which a replayed recording delivers frames; 0 follows its timestamps.</source>
        <translation>Frecuencia con la que una grabación reproducida entrega fotogramas; 0 sigue sus marcas de tiempo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="339"/>
        <source>Ray angle a first map point needs.</source>
        <translation>Ángulo entre rayos que necesita un primer punto del mapa.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="340"/>
        <source>Ray angle a new map point needs.</source>
        <translation>Ángulo entre rayos que necesita un punto nuevo del mapa.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="341"/>
        <source>Rays stop at this range; 0 = at the occupancy image border.</source>
        <translation>Los rayos se detienen a este alcance; 0 = en el borde de la imagen de ocupación.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="342"/>
        <source>Re-acquisition is refused when the other matches support a second similarity with this fraction of the inliers (another button of a repeated panel).</source>
        <translation>Se rechaza la readquisición cuando las demás coincidencias respaldan una segunda similitud con esta fracción de los inliers (otro botón de un panel con elementos repetidos).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="343"/>
        <source>Recent keyframes a new keyframe triangulates new points with.</source>
        <translation>Fotogramas clave recientes con los que un fotograma clave nuevo triangula puntos nuevos.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="344"/>
        <source>Rectify even when the rig says its images are rectified.</source>
        <translation>Rectificar incluso cuando el rig indica que sus imágenes ya están rectificadas.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="345"/>
        <source>Refine every tracked position against the track&apos;s anchor (where it was first seen), its patch warped by the motion since, so tracks do not drift frame by frame.</source>
        <translation>Refinar cada posición seguida frente al anclaje de la pista (donde se vio por primera vez), con su parche deformado por el movimiento desde entonces, para que las pistas no deriven fotograma a fotograma.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="346"/>
        <source>Refine the 3D points with the motion (two-frame bundle adjustment); removes the depth bias of triangulation.</source>
        <translation>Refinar los puntos 3D con el movimiento (ajuste de haces de dos fotogramas); elimina el sesgo de profundidad de la triangulación.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="347"/>
        <source>Refine the last frames&apos; poses and their tracks&apos; points together on the stereo reprojection error (sliding-window bundle adjustment), so per-frame errors do not add up.</source>
        <translation>Refinar juntas las poses de los últimos fotogramas y los puntos de sus pistas sobre el error de reproyección estéreo (ajuste de haces en ventana deslizante), para que los errores de cada fotograma no se sumen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="348"/>
        <source>Refined RMS reprojection error above this is rejected.</source>
        <translation>Se rechaza un error de reproyección RMS refinado por encima de este valor.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="349"/>
        <source>Refinement rounds: refine, re-select inliers by the reprojection threshold, refine.</source>
        <translation>Rondas de refinamiento: refinar, volver a seleccionar los inliers con el umbral de reproyección, refinar.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="351"/>
        <source>Region growing: largest RGB-N colour distance between neighbours (255 (n+1)/2).</source>
        <translation>Crecimiento de regiones: mayor distancia de color RGB-N entre vecinos (255 (n+1)/2).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="352"/>
        <source>Region-of-interest height; 0 keeps the camera&apos;s.</source>
        <translation>Altura de la región de interés; 0 conserva la de la cámara.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="353"/>
        <source>Region-of-interest width; 0 keeps the camera&apos;s.</source>
        <translation>Anchura de la región de interés; 0 conserva la de la cámara.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="354"/>
        <source>Register depth to the colour camera in the device when it supports it, so that depth and colour pixels correspond.</source>
        <translation>Registrar la profundidad en la cámara de color dentro del dispositivo cuando lo admite, para que los píxeles de profundidad y de color se correspondan.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="355"/>
        <source>Reprojection error a first map point may have in either view.</source>
        <translation>Error de reproyección que puede tener un primer punto del mapa en cada vista.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="356"/>
        <source>Reprojection error a new map point may have in either keyframe.</source>
        <translation>Error de reproyección que puede tener un punto nuevo del mapa en cada fotograma clave.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="357"/>
        <source>Requested frame rate; 0 keeps the camera&apos;s.</source>
        <translation>Frecuencia de fotogramas solicitada; 0 conserva la de la cámara.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="358"/>
        <source>Requested image height; 0 keeps the camera&apos;s.</source>
        <translation>Altura de imagen solicitada; 0 conserva la de la cámara.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="359"/>
        <source>Requested image width; 0 keeps the camera&apos;s. V4L2 picks the nearest mode.</source>
        <translation>Anchura de imagen solicitada; 0 conserva la de la cámara. V4L2 elige el modo más cercano.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="360"/>
        <source>Reset rule: a pose-source move larger than this between two frames resets the reference.</source>
        <translation>Regla de reinicio: un movimiento de la fuente de poses mayor que esto entre dos fotogramas reinicia la referencia.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="361"/>
        <source>Reset rule: a pose-source turn larger than this between two frames resets the reference.</source>
        <translation>Regla de reinicio: un giro de la fuente de poses mayor que esto entre dos fotogramas reinicia la referencia.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="362"/>
        <source>Reset rule: this many consecutive frames whose walls disagree by more than max_correction_deg reset the reference.</source>
        <translation>Regla de reinicio: este número de fotogramas consecutivos cuyas paredes discrepan más de max_correction_deg reinicia la referencia.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="363"/>
        <source>Residual beyond which a match is an outlier.</source>
        <translation>Residuo a partir del cual una coincidencia es un outlier.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="364"/>
        <source>Reweighted Gauss-Newton iterations.</source>
        <translation>Iteraciones de Gauss-Newton reponderadas.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="365"/>
        <source>Rigid samples tried at least before adaptive termination may stop.</source>
        <translation>Muestras rígidas que se prueban como mínimo antes de que la terminación adaptativa pueda parar.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="366"/>
        <source>Roughness triangulation in plane coordinates: the cells&apos; grid or 2D Delaunay.</source>
        <translation>Triangulación de la rugosidad en coordenadas del plano: la rejilla de celdas o Delaunay 2D.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="367"/>
        <source>Roughness uses the segment&apos;s points within this range (all when none is).</source>
        <translation>La rugosidad usa los puntos del segmento dentro de este alcance (todos si no hay ninguno).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="368"/>
        <source>Roughness: points are averaged in plane cells of this size, then triangulated.</source>
        <translation>Rugosidad: los puntos se promedian en celdas del plano de este tamaño y luego se triangulan.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="369"/>
        <source>Row search: mean absolute difference above this means no match.</source>
        <translation>Búsqueda por filas: una diferencia absoluta media por encima de este valor significa que no hay coincidencia.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="370"/>
        <source>Run mapping on its own thread (live); off = inline after each keyframe, deterministic.</source>
        <translation>Ejecutar el mapeo en su propio hilo (en vivo); desactivado = en línea tras cada fotograma clave, determinista.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="371"/>
        <source>SAD window side of the row search, at its level.</source>
        <translation>Lado de la ventana SAD de la búsqueda por filas, en su nivel.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="372"/>
        <source>SIFT contrast threshold.</source>
        <translation>Umbral de contraste de SIFT.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="373"/>
        <source>SIFT contrast threshold; lower finds more keypoints on plain buttons.</source>
        <translation>Umbral de contraste de SIFT; más bajo encuentra más puntos clave en botones lisos.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="374"/>
        <source>SIFT keypoints up to this far outside the region belong to the button model.</source>
        <translation>Los puntos clave SIFT hasta esta distancia fuera de la región pertenecen al modelo del botón.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="375"/>
        <source>SIFT on a larger region runs on its crop scaled down so the region&apos;s radius is this (fewer, coarser features, much faster on close-up photos); 0 = never.</source>
        <translation>En una región mayor, SIFT trabaja sobre el recorte reducido para que el radio de la región sea este valor (menos características y más gruesas, mucho más rápido en fotos de cerca); 0 = nunca.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="376"/>
        <source>Scale between pyramid levels.</source>
        <translation>Escala entre niveles de la pirámide.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="378"/>
        <source>Scored cloud written per frame.</source>
        <translation>Nube puntuada escrita por fotograma.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="379"/>
        <source>Search window around a map point&apos;s predicted position.</source>
        <translation>Ventana de búsqueda alrededor de la posición predicha de un punto del mapa.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="380"/>
        <source>Serve the targets to the arm over TCP (button.arm.bind_address, port, token); 127.0.0.1:5757 by default. The same as button.run.serve. Switching it keeps the run (map, button, STOP); switching it off sends the arm a stop line.</source>
        <translation>Servir los objetivos al brazo por TCP (button.arm.bind_address, port, token); 127.0.0.1:5757 por defecto. Equivale a button.run.serve. Cambiarlo conserva la ejecución (mapa, botón, PARAR); desactivarlo envía al brazo una línea de parada.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="381"/>
        <source>Shi-Tomasi gradient window.</source>
        <translation>Ventana del gradiente de Shi-Tomasi.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="382"/>
        <source>Shi-Tomasi: smallest minimum eigenvalue of a corner (cv::cornerMinEigenVal units).</source>
        <translation>Shi-Tomasi: menor valor propio mínimo de una esquina (unidades de cv::cornerMinEigenVal).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="383"/>
        <source>Shorter lines are dropped.</source>
        <translation>Se descartan las líneas más cortas.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="384"/>
        <source>Side of the aligned patch (odd).</source>
        <translation>Lado del parche alineado (impar).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="385"/>
        <source>Side of the detection grid&apos;s buckets; each holds at most its share of max_features.</source>
        <translation>Lado de las celdas (buckets) de la rejilla de detección; cada una contiene como máximo su cuota de max_features.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="386"/>
        <source>Similarity RANSAC inlier distance.</source>
        <translation>Distancia de inliers del RANSAC de similitud.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="387"/>
        <source>Size change since the last refresh that triggers the next.</source>
        <translation>Cambio de tamaño desde la última renovación que desencadena la siguiente.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="388"/>
        <source>Smaller estimates are not applied: within the spread the estimate shows on a rig without offset (the simulator: +-0.03 px).</source>
        <translation>No se aplican estimaciones menores: quedan dentro de la dispersión que muestra la estimación en un rig sin desplazamiento (el simulador: +-0.03 px).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="389"/>
        <source>Smaller regions stay unsegmented and unscored.</source>
        <translation>Las regiones más pequeñas quedan sin segmentar y sin puntuar.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="390"/>
        <source>Smallest 1-sigma stated for one frame&apos;s normal (the map points&apos; errors are correlated, so the fit&apos;s own figure is optimistic).</source>
        <translation>Menor 1 sigma declarado para la normal de un fotograma (los errores de los puntos del mapa están correlacionados, así que el valor propio del ajuste es optimista).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="391"/>
        <source>Smallest Hough circle radius.</source>
        <translation>Radio mínimo de los círculos de Hough.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="392"/>
        <source>Smallest approach_sigma_deg a target states: the average of frames that share one map does not beat the map&apos;s own bias (on the simulated approach with the SLAM&apos;s map, up to 4.3 deg against per-frame fits of 0.5 deg).</source>
        <translation>Menor approach_sigma_deg que declara un objetivo: la media de fotogramas que comparten un mapa no supera el sesgo del propio mapa (en la aproximación simulada con el mapa del SLAM, hasta 4.3 deg frente a ajustes por fotograma de 0.5 deg).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="393"/>
        <source>Smallest button region.</source>
        <translation>Región del botón más pequeña.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="394"/>
        <source>Split a piece while a point lies farther than this from its chord; merge pieces that fit one line within it (cells, like RANSAC&apos;s err_max).</source>
        <translation>Dividir un tramo mientras un punto esté más lejos que esto de su cuerda; fusionar los tramos que encajan en una línea dentro de este valor (celdas, como err_max de RANSAC).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="396"/>
        <source>Start again at the end (timestamps keep increasing) instead of ending the stream.</source>
        <translation>Volver a empezar al final (las marcas de tiempo siguen creciendo) en lugar de terminar el stream.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="397"/>
        <source>Start each alignment from the last motion scaled by the time between frames.</source>
        <translation>Iniciar cada alineación desde el último movimiento, escalado por el tiempo entre fotogramas.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="398"/>
        <source>Step B2: ... and at most this far apart (no lines across the room).</source>
        <translation>Paso B2: ... y como máximo así de separados (sin líneas que crucen la habitación).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="399"/>
        <source>Step B2: the two sampled points must be at least this far apart (no short lines).</source>
        <translation>Paso B2: los dos puntos muestreados deben estar al menos así de separados (sin líneas cortas).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="403"/>
        <source>Stereo calibration (OpenCV stereo YAML as `sightline-cli calibrate stereo` writes) used instead of the source&apos;s; needed for live pairs (aravis://L,R) opened without one.</source>
        <translation>Calibración estéreo (YAML estéreo de OpenCV tal como la escribe `sightline-cli calibrate stereo`) usada en lugar de la de la fuente; necesaria para pares en vivo (aravis://L,R) abiertos sin ella.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="404"/>
        <source>Stereo calibration of the pair (OpenCV stereo YAML: M1 D1 M2 D2 R T, image_width/height, as `sightline-cli calibrate stereo` writes); the stereo odometry needs it. Also as aravis://LEFT,RIGHT?calibration_file=FILE.</source>
        <translation>Calibración estéreo del par (YAML estéreo de OpenCV: M1 D1 M2 D2 R T, image_width/height, tal como la escribe `sightline-cli calibrate stereo`); la odometría estéreo la necesita. También como aravis://LEFT,RIGHT?calibration_file=FILE.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="405"/>
        <source>Stop when the update is smaller (radians or metres).</source>
        <translation>Parar cuando la actualización es menor (radianes o metros).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="406"/>
        <source>Stream colour.</source>
        <translation>Transmitir color.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="407"/>
        <source>Stream depth.</source>
        <translation>Transmitir profundidad.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="408"/>
        <source>Stream height for depth and colour; 0 keeps the device&apos;s default mode.</source>
        <translation>Altura del stream de profundidad y color; 0 conserva el modo predeterminado del dispositivo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="409"/>
        <source>Stream rate; 0 keeps the device&apos;s default mode.</source>
        <translation>Frecuencia del stream; 0 conserva el modo predeterminado del dispositivo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="410"/>
        <source>Stream width for depth and colour; 0 keeps the device&apos;s default mode.</source>
        <translation>Anchura del stream de profundidad y color; 0 conserva el modo predeterminado del dispositivo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="411"/>
        <source>Synchronous mode: frames without a new keyframe between two idle-time slices.</source>
        <translation>Modo síncrono: fotogramas sin fotograma clave nuevo entre dos tramos en tiempo ocioso.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="412"/>
        <source>TCP port of the target server; 0 = any free port.</source>
        <translation>Puerto TCP del servidor de objetivos; 0 = cualquier puerto libre.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="413"/>
        <source>Take the approach from the plane that the arm&apos;s own motion shows (corners around the button tracked from an anchor frame, the views&apos; poses from the arm) rather than from the SLAM&apos;s map, whenever that plane is found.</source>
        <translation>Tomar la dirección de aproximación del plano que muestra el propio movimiento del brazo (esquinas alrededor del botón seguidas desde un fotograma de anclaje, las poses de las vistas dadas por el brazo) en lugar del mapa del SLAM, siempre que se encuentre ese plano.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="414"/>
        <source>Take the camera&apos;s offset ahead of the odometry base from the recording&apos;s scene.yaml (simulator) when present.</source>
        <translation>Tomar el desplazamiento de la cámara por delante de la base de la odometría del scene.yaml de la grabación (simulador) cuando existe.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="415"/>
        <source>The SIFT margin grows to this many region radii when that is larger.</source>
        <translation>El margen de SIFT crece hasta este número de radios de la región cuando es mayor.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="416"/>
        <source>The appearance model&apos;s probability that the region at the tap is a button and not a printed label or sign beside one; below it: no button here. 0 = off.</source>
        <translation>La probabilidad, según el modelo de apariencia, de que la región tocada sea un botón y no una etiqueta o un letrero impreso junto a uno; por debajo: aquí no hay botón. 0 = desactivado.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="417"/>
        <source>The approach direction is the normal of a plane through the map points within this distance of the located button (the panel around it).</source>
        <translation>La dirección de aproximación es la normal de un plano por los puntos del mapa a menos de esta distancia del botón localizado (el panel que lo rodea).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="418"/>
        <source>The arm&apos;s and the SLAM&apos;s displacement directions disagree by more than this (online hand-eye check; a wrong mount rotation): no target.</source>
        <translation>Las direcciones de desplazamiento del brazo y del SLAM discrepan más que esto (comprobación mano-ojo en línea; una rotación de montaje errónea): ningún objetivo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="419"/>
        <source>The arm&apos;s clock minus the camera&apos;s (configured; arm stamp = frame stamp + this).</source>
        <translation>El reloj del brazo menos el de la cámara (configurado; marca del brazo = marca del fotograma + este valor).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="420"/>
        <source>The arm&apos;s motion since the anchor frame, as an angle seen from the panel, before its plane is used.</source>
        <translation>El movimiento del brazo desde el fotograma de anclaje, como ángulo visto desde el panel, antes de usar su plano.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="421"/>
        <source>The current frame becomes the keyframe when fewer keyframe tracks agree with the motion.</source>
        <translation>El fotograma actual se convierte en fotograma clave cuando menos pistas del fotograma clave concuerdan con el movimiento.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="422"/>
        <source>The current frame becomes the keyframe when fewer of the keyframe&apos;s tracks survive.</source>
        <translation>El fotograma actual se convierte en fotograma clave cuando sobreviven menos pistas del fotograma clave.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="423"/>
        <source>The depth colour map spans zero to this range.</source>
        <translation>El mapa de colores de profundidad abarca de cero a esta distancia.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="424"/>
        <source>The estimated offset is clamped to +- this.</source>
        <translation>El desplazamiento estimado se limita a +- este valor.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="425"/>
        <source>The face&apos;s offset from the panel plane is the median of its points within this many robust sigmas of that median, until the set settles (points triangulated with little parallax leave a one-sided tail); 0 = the median of all.</source>
        <translation>El desplazamiento de la cara respecto al plano del panel es la mediana de sus puntos dentro de este número de sigmas robustas de esa mediana, hasta que el conjunto se estabiliza (los puntos triangulados con poco paralaje dejan una cola de un solo lado); 0 = la mediana de todos.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="426"/>
        <source>The floor is the lowest plane: at most this fraction of points may lie clearly below it (rejects table tops).</source>
        <translation>El suelo es el plano más bajo: como máximo esta fracción de los puntos puede quedar claramente por debajo (descarta tableros de mesa).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="427"/>
        <source>The floor must hold at least this fraction of the valid points.</source>
        <translation>El suelo debe contener al menos esta fracción de los puntos válidos.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="428"/>
        <source>The gate grows to this many predicted button radii when that is larger.</source>
        <translation>El gate crece hasta este número de radios predichos del botón cuando es mayor.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="429"/>
        <source>The gate widens by this per metre driven since the last correction (expected heading drift of the pose source).</source>
        <translation>El gate se ensancha este valor por cada metro recorrido desde la última corrección (deriva de rumbo esperada de la fuente de poses).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="430"/>
        <source>The homography is chosen when its share of the inliers exceeds this.</source>
        <translation>Se elige la homografía cuando su proporción de inliers supera este valor.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="431"/>
        <source>The map grows by at least this much each time it must.</source>
        <translation>El mapa crece al menos esto cada vez que lo necesita.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="432"/>
        <source>The maximum-likelihood estimate is reported from this many pairs on.</source>
        <translation>La estimación de máxima verosimilitud se informa a partir de este número de pares.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="433"/>
        <source>The metric scale counts as converged with this many displacement pairs in the ML estimate at least ...</source>
        <translation>La escala métrica se considera convergida con al menos este número de pares de desplazamientos en la estimación ML ...</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="434"/>
        <source>The model never grows beyond this many keypoints.</source>
        <translation>El modelo nunca crece más allá de este número de puntos clave.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="435"/>
        <source>The offset is measured between an anchor frame and the first later frame whose translation from it reaches this fraction of the common tracks&apos; median depth: with less parallax, tracking errors dominate the measurement.</source>
        <translation>El desplazamiento se mide entre un fotograma de anclaje y el primer fotograma posterior cuya traslación desde él alcanza esta fracción de la profundidad mediana de las pistas comunes: con menos paralaje, los errores de seguimiento dominan la medida.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="436"/>
        <source>The online hand-eye check compares keyframes at least this far apart (measured): the directions of shorter displacements drown in the noise.</source>
        <translation>La comprobación mano-ojo en línea compara fotogramas clave separados al menos esto (medido): las direcciones de desplazamientos más cortos se pierden en el ruido.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="437"/>
        <source>The online hand-eye check sees the mount&apos;s translation only when the arm rotates at least this much between two keyframes.</source>
        <translation>La comprobación mano-ojo en línea solo ve la traslación del montaje cuando el brazo gira al menos esto entre dos fotogramas clave.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="438"/>
        <source>The operator&apos;s tap is refused when the frame it was made on is older than this (data time) by the time the pipeline takes it.</source>
        <translation>Se rechaza el toque del operador cuando el fotograma en que se hizo es más antiguo que esto (tiempo de los datos) en el momento en que el pipeline lo toma.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="439"/>
        <source>The operator&apos;s tap: X,Y in pixels, optionally @FRAME (frame index, default 0); confirmed at once. sightline-cli run button --tap X,Y[@FRAME] sets it.</source>
        <translation>El toque del operador: X,Y en píxeles, opcionalmente @FRAME (índice de fotograma, por defecto 0); confirmado de inmediato. sightline-cli run button --tap X,Y[@FRAME] lo establece.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="440"/>
        <source>The panel plane passes at most this far from the located button: of the surfaces around it (a side wall, a door frame) only the one holding the button gives the push direction.</source>
        <translation>El plano del panel pasa como mucho a esta distancia del botón localizado: de las superficies a su alrededor (una pared lateral, un marco de puerta) solo la que lleva el botón da la dirección de pulsación.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="441"/>
        <source>The position&apos;s panel plane is fitted robustly to the map points within this many tracked button radii and moved onto the face by its points&apos; median offset; 0 = the plane within radius_px (or the face&apos;s own).</source>
        <translation>El plano de la posición se ajusta de forma robusta a los puntos del mapa dentro de este número de radios del botón seguido y se desplaza a la cara del botón según la mediana de los desvíos de sus puntos; 0 = el plano dentro de radius_px (o el de la propia cara).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="442"/>
        <source>The size from the tap&apos;s own keypoints alone (not the refreshed ones, whose scale drifts; the looming in button.triangulate.*) needs this many consistent matches.</source>
        <translation>El tamaño solo a partir de los puntos clave propios del toque (no de los renovados, cuya escala deriva; el looming en button.triangulate.*) necesita al menos estas correspondencias coherentes.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="443"/>
        <source>The size from the tap&apos;s own keypoints only (ButtonTrack::anchor_scale: the keypoints the tracker&apos;s refresh adds carry each refresh&apos;s scale error on); false: the tracked radius.</source>
        <translation>El tamaño solo a partir de los puntos clave propios del toque (ButtonTrack::anchor_scale: los puntos clave que añade la renovación del seguidor arrastran el error de escala de cada renovación); false: el radio seguido.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="444"/>
        <source>The target is the per-axis median of this many recent base-frame positions (sound plane, converged scale); 0 = every one since the tap, 1 = no fusion.</source>
        <translation>El objetivo es la mediana por eje de este número de posiciones recientes en el sistema de la base (plano fiable, escala convergida); 0 = todas desde el toque, 1 = sin fusión.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="445"/>
        <source>The tracking gate never exceeds this: larger corrections are not applied.</source>
        <translation>El gate de seguimiento nunca supera este valor: las correcciones mayores no se aplican.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="446"/>
        <source>The window grows to this many predicted button radii when that is larger.</source>
        <translation>La ventana crece hasta este número de radios predichos del botón cuando es mayor.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="447"/>
        <source>Tolerance of accuracy.map_iou: a map cell within this many cells of a true wall counts as on it.</source>
        <translation>Tolerancia de accuracy.map_iou: una celda del mapa a menos de este número de celdas de una pared real cuenta como sobre ella.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="448"/>
        <source>Top-view grid cell.</source>
        <translation>Celda de la rejilla de la vista cenital.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="449"/>
        <source>Track points drawn behind the button on the overlay.</source>
        <translation>Puntos de la pista dibujados detrás del botón en la superposición.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="450"/>
        <source>Tracking gate right after a correction: lines farther than this from the expected direction neither vote nor correct.</source>
        <translation>Gate de seguimiento justo después de una corrección: las líneas más alejadas que esto de la dirección esperada ni votan ni corrigen.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="451"/>
        <source>Tracking is lost when fewer than this share of the map points predicted in the image are found (PTAM&apos;s test against a wrong pose after a jump).</source>
        <translation>El seguimiento se pierde cuando se encuentra menos de esta proporción de los puntos del mapa predichos en la imagen (la prueba de PTAM contra una pose errónea tras un salto).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="452"/>
        <source>Tracking quality is good from this many inliers.</source>
        <translation>La calidad del seguimiento es buena a partir de este número de inliers.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="453"/>
        <source>Tracking quality is poor from this many inliers; fewer is lost.</source>
        <translation>La calidad del seguimiento es mala a partir de este número de inliers; con menos se pierde.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="454"/>
        <source>Triangulated points needed to accept the initialisation.</source>
        <translation>Puntos triangulados necesarios para aceptar la inicialización.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="455"/>
        <source>UMBRAL1: change of a pairwise distance a rigid sample may show, before depth uncertainty is added.</source>
        <translation>UMBRAL1: cambio de una distancia entre pares que puede mostrar una muestra rígida, antes de sumar la incertidumbre de profundidad.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="456"/>
        <source>UMBRAL2: rigidity rejections after which RANSAC fails (the last motion is kept).</source>
        <translation>UMBRAL2: rechazos por rigidez tras los cuales RANSAC falla (se conserva el último movimiento).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="457"/>
        <source>UMBRAL3: reprojection error (RMS of both images) of an inlier.</source>
        <translation>UMBRAL3: error de reproyección (RMS de ambas imágenes) de un inlier.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="458"/>
        <source>UMBRAL4: stop sampling once this fraction of the points is inlier.</source>
        <translation>UMBRAL4: dejar de muestrear en cuanto esta fracción de los puntos es inlier.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="459"/>
        <source>UMBRAL5: rigid samples tried before the best inlier set is taken.</source>
        <translation>UMBRAL5: muestras rígidas probadas antes de tomar el mejor conjunto de inliers.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="460"/>
        <source>Up-facing planes searched; the lowest large one is the ground.</source>
        <translation>Planos orientados hacia arriba que se buscan; el más bajo de los grandes es el suelo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="461"/>
        <source>Upper clamp of a cell&apos;s log-odds.</source>
        <translation>Límite superior de los log-odds de una celda.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="462"/>
        <source>Use every n-th depth pixel for the 3D cloud; 1 shows all (slower).</source>
        <translation>Usar uno de cada n píxeles de profundidad para la nube 3D; 1 los muestra todos (más lento).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="463"/>
        <source>Use the apparent size (looming: the radius grows as 1 / depth while the arm moves forward by a measured distance) besides the rays.</source>
        <translation>Usa, además de los rayos, el tamaño aparente (looming: el radio crece como 1 / profundidad mientras el brazo avanza una distancia medida).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="464"/>
        <source>Viewing ray closer to parallel with the plane than this |cos|: no position.</source>
        <translation>Rayo de visión más próximo a ser paralelo al plano que este |cos|: ninguna posición.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="465"/>
        <source>Voting lines within this of their length-weighted median are averaged; others (a wall merged with a recessed door, a box) are dropped.</source>
        <translation>Las líneas que votan dentro de este valor respecto a su mediana ponderada por longitud se promedian; las demás (una pared fusionada con una puerta retranqueada, una caja) se descartan.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="466"/>
        <source>Voting wall length a frame needs before it may set the reference direction.</source>
        <translation>Longitud de pared votante que necesita un fotograma antes de poder fijar la dirección de referencia.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="467"/>
        <source>Voxel size for locally sampled hypotheses (finds a floor that covers little of the view).</source>
        <translation>Tamaño del vóxel para las hipótesis muestreadas localmente (encuentra un suelo que cubre poco de la vista).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="468"/>
        <source>Wall lines shorter than this do not vote for the direction.</source>
        <translation>Las líneas de pared más cortas que esto no votan la dirección.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="469"/>
        <source>Wall lines with fewer scan points do not vote.</source>
        <translation>Las líneas de pared con menos puntos de barrido no votan.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="471"/>
        <source>Weaker tracking confidence: no target.</source>
        <translation>Confianza de seguimiento más débil: ningún objetivo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="473"/>
        <source>Weight observations by 1 / (|u - cx| / cx + 0.05) (libviso2), favouring the centre, as the two-frame refinement does.</source>
        <translation>Ponderar las observaciones por 1 / (|u - cx| / cx + 0.05) (libviso2), favoreciendo el centro, como hace el refinamiento de dos fotogramas.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="474"/>
        <source>Weight observations by 1 / (|u - cx| / cx + 0.05) (libviso2), favouring the centre.</source>
        <translation>Ponderar las observaciones por 1 / (|u - cx| / cx + 0.05) (libviso2), favoreciendo el centro.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="475"/>
        <source>Weight of the fused positions&apos; spread (1.4826 x median absolute deviation from the fused target) in the stated uncertainty.</source>
        <translation>Peso de la dispersión de las posiciones fusionadas (1.4826 x desviación absoluta mediana respecto al objetivo fusionado) en la incertidumbre declarada.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="476"/>
        <source>What replaces a rejected motion: the last accepted one, or none.</source>
        <translation>Qué sustituye a un movimiento rechazado: el último aceptado, o ninguno.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="478"/>
        <source>When fewer tracks survive than this fraction of the share that survived in the previous frame (poor motion prediction), the lost ones are tracked again with retrack_pyramid_levels; 0 = never.</source>
        <translation>Cuando sobreviven menos pistas que esta fracción de la proporción que sobrevivió en el fotograma anterior (mala predicción del movimiento), las perdidas se vuelven a seguir con retrack_pyramid_levels; 0 = nunca.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="479"/>
        <source>When set, a client must send {&quot;token&quot;: &quot;...&quot;} before it receives anything; required when bind_address is not a loopback address.</source>
        <translation>Si se establece, un cliente debe enviar {&quot;token&quot;: &quot;...&quot;} antes de recibir nada; obligatorio cuando bind_address no es una dirección de loopback.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="481"/>
        <source>Where the robot&apos;s translation comes from: the recording&apos;s odometry (odometry.txt, a bag&apos;s odometry or tf, a live source&apos;s), RGB-D odometry on the depth and colour frames, none (heading from the walls only), or auto (the recording&apos;s odometry when it has one, else RGB-D odometry when the frames have colour or the method is icp, else none).</source>
        <translation>De dónde procede la traslación del robot: la odometría de la grabación (odometry.txt, la odometría o tf de un bag, la de una fuente en vivo), odometría RGB-D sobre los fotogramas de profundidad y color, none (rumbo solo a partir de las paredes) o auto (la odometría de la grabación cuando la tiene, si no odometría RGB-D cuando los fotogramas tienen color o el método es icp, si no none).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="483"/>
        <source>Width of the reduced copies of the two images compared in that search.</source>
        <translation>Ancho de las copias reducidas de las dos imágenes que se comparan en esa búsqueda.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="484"/>
        <source>Window of the second pass, after a first pose.</source>
        <translation>Ventana de la segunda pasada, tras una primera pose.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="485"/>
        <source>Window used when the first search finds too few points.</source>
        <translation>Ventana usada cuando la primera búsqueda encuentra demasiado pocos puntos.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="486"/>
        <source>With a token: a connection that has not presented it after this long is closed.</source>
        <translation>Con un token: se cierra una conexión que no lo ha presentado tras este tiempo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="487"/>
        <source>With fewer than min_matches but this many matches, an essential matrix from them guides a second matching along epipolar lines (large motion).</source>
        <translation>Con menos de min_matches pero al menos estas correspondencias, una matriz esencial estimada con ellas guía un segundo emparejamiento a lo largo de las líneas epipolares (movimiento grande).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="488"/>
        <source>With png: also overlay.avi (Motion-JPEG through OpenCV&apos;s built-in writer).</source>
        <translation>Con png: también overlay.avi (Motion-JPEG mediante el escritor integrado de OpenCV).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="489"/>
        <source>With serve: give up waiting for clients after this long.</source>
        <translation>Con serve: dejar de esperar clientes tras este tiempo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="490"/>
        <source>With serve: keep serving this long after the last frame so queued targets go out.</source>
        <translation>Con serve: seguir sirviendo este tiempo tras el último fotograma para que salgan los objetivos en cola.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="491"/>
        <source>With serve: wait for this many connected clients before the first frame.</source>
        <translation>Con serve: esperar a este número de clientes conectados antes del primer fotograma.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="492"/>
        <source>Without a reference: lines within this of the best-supported direction (modulo 90 deg) vote.</source>
        <translation>Sin referencia: votan las líneas dentro de este valor respecto a la dirección mejor respaldada (módulo 90 deg).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="493"/>
        <source>Workspace box, base x max.</source>
        <translation>Caja del espacio de trabajo, base x máx.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="494"/>
        <source>Workspace box, base x min.</source>
        <translation>Caja del espacio de trabajo, base x mín.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="495"/>
        <source>Workspace box, base y max.</source>
        <translation>Caja del espacio de trabajo, base y máx.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="496"/>
        <source>Workspace box, base y min.</source>
        <translation>Caja del espacio de trabajo, base y mín.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="497"/>
        <source>Workspace box, base z max.</source>
        <translation>Caja del espacio de trabajo, base z máx.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="498"/>
        <source>Workspace box, base z min.</source>
        <translation>Caja del espacio de trabajo, base z mín.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="499"/>
        <source>Write the projection and top-view PNGs per frame.</source>
        <translation>Escribir por fotograma los PNG de la proyección y de la vista cenital.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="500"/>
        <source>accuracy.wall_recall: a true wall is visible in a frame when at least this much of it is in view ...</source>
        <translation>accuracy.wall_recall: una pared real es visible en un fotograma cuando al menos esta parte de ella está a la vista ...</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="501"/>
        <source>arm_pose messages closer than 1/this in the arm&apos;s time are dropped (counted).</source>
        <translation>Se descartan los mensajes arm_pose más próximos que 1/este valor en el tiempo del brazo (contados).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="502"/>
        <source>arm_pose messages older than this behind the newest are forgotten.</source>
        <translation>Se olvidan los mensajes arm_pose más atrasados que esto respecto al más reciente.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="503"/>
        <source>arm_poses.txt (base_from_end_effector, TUM); empty = beside the sensor folder.</source>
        <translation>arm_poses.txt (base_from_end_effector, TUM); vacío = junto a la carpeta del sensor.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="504"/>
        <source>custom platform: a segment raised more than this above the ground scores 0.</source>
        <translation>Plataforma custom: un segmento elevado más que esto sobre el suelo puntúa 0.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="505"/>
        <source>custom platform: points farther from the sensor are dropped.</source>
        <translation>Plataforma custom: se descartan los puntos más alejados del sensor.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="506"/>
        <source>delaunay: triangles with an edge longer than this many cells are dropped.</source>
        <translation>delaunay: se descartan los triángulos con un lado más largo que este número de celdas.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="512"/>
        <source>depth: a person&apos;s top lies at least this many footprint lengths above the floor (a desk, a table or a sofa is wider than it is tall).</source>
        <translation>depth: la parte superior de una persona está al menos a este múltiplo de la longitud de su huella sobre el suelo (un escritorio, una mesa o un sofá es más ancho que alto).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="518"/>
        <source>depth: the HOG score a cluster&apos;s box needs when it touches the image&apos;s border (a body cut off scores lower).</source>
        <translation>depth: la puntuación HOG que necesita el recuadro de un clúster cuando toca el borde de la imagen (un cuerpo cortado puntúa menos).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="519"/>
        <source>depth: the HOG score a cluster&apos;s box needs when the whole box is in view.</source>
        <translation>depth: la puntuación HOG que necesita el recuadro de un clúster cuando está entero a la vista.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="522"/>
        <source>depth: when on, a cluster reaching the image&apos;s top row (its top out of view) is not a person: fewer false people at the edge of view, but people near enough to have their heads cut off are missed.</source>
        <translation>depth: si está activo, un grupo que llega a la fila superior de la imagen (su parte alta fuera de vista) no es una persona: menos personas falsas en el borde de la imagen, pero se pierden las personas tan cercanas que tienen la cabeza cortada.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="523"/>
        <source>depth: when the colour image is registered to the depth image, OpenCV&apos;s HOG people detector must also score each cluster&apos;s box (a chair or a desk of a person&apos;s size is dropped).</source>
        <translation>depth: cuando la imagen en color está registrada con la de profundidad, el detector de personas HOG de OpenCV también debe aceptar el recuadro de cada clúster (se descarta una silla o un escritorio del tamaño de una persona).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="524"/>
        <source>device: pair by camera timestamps (cameras on a common clock, e.g. PTP or a shared trigger); host: pair by arrival time at the host.</source>
        <translation>device: emparejar por marcas de tiempo de las cámaras (cámaras con un reloj común, p. ej. PTP o un disparo compartido); host: emparejar por hora de llegada al host.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="527"/>
        <source>free: the camera runs on its own clock; software: the host triggers each frame (both cameras of a pair together); hardware: an external pulse on trigger_line.</source>
        <translation>free: la cámara funciona con su propio reloj; software: el host dispara cada fotograma (las dos cámaras de un par a la vez); hardware: un pulso externo en trigger_line.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="528"/>
        <source>grid: every n-th pixel in both directions (stands in for the voxel grid).</source>
        <translation>grid: uno de cada n píxeles en ambas direcciones (en lugar de la rejilla de vóxeles).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="529"/>
        <source>grid: grid neighbours whose depths differ by more than this fraction are apart.</source>
        <translation>grid: los vecinos de la rejilla cuyas profundidades difieren más de esta fracción están separados.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="530"/>
        <source>grid: half-width of the window of grid points each normal is fitted to.</source>
        <translation>grid: semianchura de la ventana de puntos de la rejilla a la que se ajusta cada normal.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="532"/>
        <source>hand_eye.yaml (end_effector_from_camera); empty = beside arm_poses (for arm_stream: beside the images); none = identity.</source>
        <translation>hand_eye.yaml (end_effector_from_camera); vacío = junto a arm_poses (para arm_stream: junto a las imágenes); none = identidad.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="533"/>
        <source>i_max (step E): at most this many lines.</source>
        <translation>i_max (paso E): como máximo este número de líneas.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="535"/>
        <source>multiscale: add Hough circles (round buttons, thin rings).</source>
        <translation>multiscale: añadir círculos de Hough (botones redondos, anillos finos).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="536"/>
        <source>multiscale: blur of the second scale, times blur_sigma_px.</source>
        <translation>multiscale: desenfoque de la segunda escala, multiplicado por blur_sigma_px.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="537"/>
        <source>multiscale: half size of the window around the tap that is searched.</source>
        <translation>multiscale: mitad del tamaño de la ventana alrededor del toque en la que se busca.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="538"/>
        <source>multiscale: longest over shortest side of a region&apos;s rotated box.</source>
        <translation>multiscale: cociente entre el lado más largo y el más corto del recuadro girado de una región.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="539"/>
        <source>multiscale: regions are ranked by (offset + bias) / radius, so the button&apos;s outline wins over a glyph on it.</source>
        <translation>multiscale: las regiones se ordenan por (desplazamiento + sesgo) / radio, para que el contorno del botón gane a un símbolo sobre él.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="540"/>
        <source>multiscale: the region&apos;s centroid lies at most this many radii from the tap.</source>
        <translation>multiscale: el centroide de la región está como máximo a este número de radios del toque.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="541"/>
        <source>multiscale: the two Canny pairs are the thresholds times 2/(1+s) and 2s/(1+s).</source>
        <translation>multiscale: los dos pares de Canny son los umbrales multiplicados por 2/(1+s) y 2s/(1+s).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="542"/>
        <source>multiscale: when no outline holds the tap, look for closed outlines of the strongest radial edges around it (faint or thin-ringed buttons).</source>
        <translation>multiscale: cuando ningún contorno contiene el toque, busca a su alrededor contornos cerrados de los bordes radiales más fuertes (botones tenues o de anillo fino).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="543"/>
        <source>p of the adaptive count: probability of drawing one all-inlier pair.</source>
        <translation>p del recuento adaptativo: probabilidad de extraer un par solo de inliers.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="544"/>
        <source>pcl: neighbour radius of the region growing.</source>
        <translation>pcl: radio de vecindad del crecimiento de regiones.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="545"/>
        <source>pcl: neighbours of the normal fit.</source>
        <translation>pcl: vecinos del ajuste de normales.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="546"/>
        <source>pcl: neighbours of the outlier removal.</source>
        <translation>pcl: vecinos de la eliminación de outliers.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="547"/>
        <source>pcl: voxel grid leaf size.</source>
        <translation>pcl: tamaño de hoja de la rejilla de vóxeles.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="548"/>
        <source>ratio_max (step B8): a hypothesis with more inliers than this ends the search.</source>
        <translation>ratio_max (paso B8): una hipótesis con más inliers que esto termina la búsqueda.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="549"/>
        <source>ratio_min (steps B5, B6): a line needs this fraction of the remaining points.</source>
        <translation>ratio_min (pasos B5, B6): una línea necesita esta fracción de los puntos restantes.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="550"/>
        <source>ratio_scan_max (step E): stop once this fraction of the points lies on lines.</source>
        <translation>ratio_scan_max (paso E): parar en cuanto esta fracción de los puntos está sobre líneas.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="216"/>
        <source>Kind of frames read from a ROS bag; auto picks RGB-D, then stereo, then mono, then point clouds, as the bag&apos;s topics allow.</source>
        <translation>Tipo de fotogramas leídos de una bag de ROS; auto elige RGB-D, luego estéreo, luego mono y luego nubes de puntos, según lo que permitan los topics de la bag.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="257"/>
        <source>New centre: the model centre through a RANSAC similarity of the matches, or the matched keypoints&apos; centroid (the published rule).</source>
        <translation>Nuevo centro: el centro del modelo mediante una similitud RANSAC de las coincidencias, o el centroide de los puntos clave emparejados (la regla de la publicación).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="269"/>
        <source>Occupied evidence: the polar scan&apos;s hits (visible surfaces, thin walls) or every occupied cell of the occupancy image (as published; depth noise behind walls stays).</source>
        <translation>Evidencia de ocupación: los impactos del barrido polar (superficies visibles, paredes finas) o cada celda ocupada de la imagen de ocupación (como se publicó; el ruido de profundidad detrás de las paredes permanece).</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="306"/>
        <source>Process every k-th frame (the published subsampling sweep); --subsample K.</source>
        <translation>Procesar uno de cada k fotogramas (el barrido de submuestreo de la publicación); --subsample K.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="320"/>
        <source>ROS bag: ground truth is the pose of tf_child_frame in this tf frame; empty uses the bag&apos;s only transform chain on /tf.</source>
        <translation>Bag de ROS: la referencia es la pose de tf_child_frame en este frame tf; vacío usa la única cadena de transformaciones de la bag en /tf.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="321"/>
        <source>ROS bag: largest stamp difference of a colour/depth or left/right pair; images without a partner are skipped.</source>
        <translation>Bag de ROS: mayor diferencia de marcas de tiempo de un par color/profundidad o izquierda/derecha; las imágenes sin pareja se omiten.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="323"/>
        <source>ROS bag: the CameraInfo topic of the image topic; empty looks beside the image topic, then takes the bag&apos;s only CameraInfo topic.</source>
        <translation>Bag de ROS: el topic CameraInfo del topic de imagen; vacío busca junto al topic de imagen y luego toma el único topic CameraInfo de la bag.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="324"/>
        <source>ROS bag: the PointCloud2 topic read as point-cloud frames.</source>
        <translation>Bag de ROS: el topic PointCloud2 que se lee como nubes de puntos.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="327"/>
        <source>ROS bag: the camera&apos;s tf frame whose pose in tf_parent_frame is the ground truth.</source>
        <translation>Bag de ROS: el frame tf de la cámara cuya pose en tf_parent_frame es la referencia.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="328"/>
        <source>ROS bag: the colour, left or mono image topic (Image or CompressedImage); empty picks it when the bag leaves no doubt.</source>
        <translation>Bag de ROS: el topic de la imagen en color, izquierda o mono (Image o CompressedImage); vacío lo elige cuando la bag no deja dudas.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="329"/>
        <source>ROS bag: the depth image topic (16UC1 millimetres or 32FC1 metres); empty picks it when the bag leaves no doubt.</source>
        <translation>Bag de ROS: el topic de la imagen de profundidad (16UC1 milímetros o 32FC1 metros); vacío lo elige cuando la bag no deja dudas.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="330"/>
        <source>ROS bag: the nav_msgs/Odometry topic; empty takes the bag&apos;s only one.</source>
        <translation>Bag de ROS: el topic nav_msgs/Odometry; vacío toma el único de la bag.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="332"/>
        <source>ROS bag: the right camera&apos;s CameraInfo topic; its projection matrix P gives the stereo baseline.</source>
        <translation>Bag de ROS: el topic CameraInfo de la cámara derecha; su matriz de proyección P da la línea base estéreo.</translation>
    </message>
    <message>
        <location filename="../app/sightline/option_texts.cpp" line="333"/>
        <source>ROS bag: the right image topic of a stereo pair; empty picks the topic whose name says right beside one that says left.</source>
        <translation>Bag de ROS: el topic de la imagen derecha de un par estéreo; vacío elige el topic cuyo nombre dice right junto a uno que dice left.</translation>
    </message>
</context>
<context>
    <name>sightline::ParameterPanel</name>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="47"/>
        <source>Filter options</source>
        <translation>Filtrar opciones</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="51"/>
        <source>Load profile…</source>
        <translation>Cargar perfil…</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="54"/>
        <source>Save profile…</source>
        <translation>Guardar perfil…</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="57"/>
        <source>Reset all</source>
        <translation>Restablecer todo</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="173"/>
        <source>All options reset to their defaults.</source>
        <translation>Todas las opciones vuelven a sus valores por defecto.</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="184"/>
        <source>Loaded profile %1</source>
        <translation>Perfil %1 cargado</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="195"/>
        <source>Saved profile %1</source>
        <translation>Perfil %1 guardado</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="202"/>
        <source>Load profile</source>
        <translation>Cargar perfil</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="202"/>
        <source>YAML profiles (*.yaml *.yml);;All files (*)</source>
        <translation>Perfiles YAML (*.yaml *.yml);;Todos los archivos (*)</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="209"/>
        <source>Save profile</source>
        <translation>Guardar perfil</translation>
    </message>
    <message>
        <location filename="../widgets/parameter_panel.cpp" line="210"/>
        <source>YAML profiles (*.yaml *.yml)</source>
        <translation>Perfiles YAML (*.yaml *.yml)</translation>
    </message>
</context>
<context>
    <name>sightline::PlaybackBar</name>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="37"/>
        <source>Step one frame</source>
        <translation>Avanzar una imagen</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="57"/>
        <source>Playback speed relative to the recording&apos;s timestamps</source>
        <translation>Velocidad de reproducción respecto a las marcas de tiempo de la grabación</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="61"/>
        <source>max</source>
        <translation>máx</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="67"/>
        <source>Loop</source>
        <translation>Bucle</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="121"/>
        <source>Pause</source>
        <translation>Pausa</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="121"/>
        <source>Play</source>
        <translation>Reproducir</translation>
    </message>
    <message>
        <location filename="../widgets/playback_bar.cpp" line="155"/>
        <source>frame %1</source>
        <translation>fotograma %1</translation>
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
    <name>sightline::RemoteOperatorPresenter</name>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="50"/>
        <source>Operator panel (ROS node)</source>
        <translation>Panel del operador (nodo ROS)</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="86"/>
        <source>Start did not reach the robot: still stopped</source>
        <translation>El arranque no llegó al robot: sigue parado</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="109"/>
        <source>STOP sent: waiting for the robot</source>
        <translation>PARAR enviado: esperando al robot</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="110"/>
        <source>STOP kept: sent as soon as the robot is reachable</source>
        <translation>PARAR retenido: se envía en cuanto el robot esté accesible</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="153"/>
        <source>The robot confirmed STOP</source>
        <translation>El robot confirmó PARAR</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="161"/>
        <source>Target %1, %2, %3 m (%4)</source>
        <translation>Objetivo %1, %2, %3 m (%4)</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="196"/>
        <source>The robot did not answer the tap: tap again</source>
        <translation>El robot no respondió al toque: toque de nuevo</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="253"/>
        <source>The robot did not take the tap: tap again</source>
        <translation>El robot no aceptó el toque: toque de nuevo</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="262"/>
        <source>The robot&apos;s node is gone</source>
        <translation>El nodo del robot ya no está</translation>
    </message>
    <message>
        <location filename="../app/sightline/remote_operator_presenter.cpp" line="270"/>
        <source>No picture for %1 s</source>
        <translation>Sin imagen desde hace %1 s</translation>
    </message>
</context>
<context>
    <name>sightline::RosConnectDialog</name>
    <message>
        <location filename="../app/sightline/ros_connect_dialog.cpp" line="12"/>
        <source>Connect to ROS master</source>
        <translation>Conectar al máster ROS</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_connect_dialog.cpp" line="18"/>
        <source>Master URI:</source>
        <translation>URI del máster:</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_connect_dialog.cpp" line="19"/>
        <source>Node namespace:</source>
        <translation>Espacio de nombres del nodo:</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_connect_dialog.cpp" line="21"/>
        <source>The robot&apos;s master, e.g. http://robot:11311. The robot must reach this computer too: set ROS_IP (or ROS_HOSTNAME) before starting Sightline.</source>
        <translation>El máster del robot, p. ej. http://robot:11311. El robot también debe alcanzar este ordenador: defina ROS_IP (o ROS_HOSTNAME) antes de iniciar Sightline.</translation>
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
        <translation>No conectado: Archivo &gt; Conectar al máster ROS...</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_node_view.cpp" line="100"/>
        <source>ROS: %1</source>
        <translation>ROS: %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_node_view.cpp" line="147"/>
        <source>Waiting for the map from %1 ...</source>
        <translation>Esperando el mapa de %1 ...</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_node_view.cpp" line="152"/>
        <source>ROS: not available in this build</source>
        <translation>ROS: no disponible en esta compilación</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_node_view.cpp" line="221"/>
        <source>ROS: connected to %1</source>
        <translation>ROS: conectado a %1</translation>
    </message>
    <message>
        <location filename="../app/sightline/ros_node_view.cpp" line="222"/>
        <source>ROS: disconnected — reconnecting to %1</source>
        <translation>ROS: desconectado — reconectando a %1</translation>
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
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="210"/>
        <source>tracked %1, new %2, stereo %3, inliers %4, RANSAC %5 it., residual %6 %7, %8 %9%10</source>
        <translation>seguidas %1, nuevas %2, estéreo %3, inliers %4, RANSAC %5 it., residuo %6 %7, %8 %9%10</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="220"/>
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
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="175"/>
        <source>estimate and camera</source>
        <translation>estimación y cámara</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="176"/>
        <source>ground truth</source>
        <translation>verdad de referencia</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="185"/>
        <source>inlier track</source>
        <translation>traza inlier</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="186"/>
        <source>outlier track</source>
        <translation>traza atípica</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="187"/>
        <source>new feature</source>
        <translation>característica nueva</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="199"/>
        <source>stereo match</source>
        <translation>correspondencia estéreo</translation>
    </message>
    <message>
        <location filename="../app/sightline/stereo_vo_presenter.cpp" line="229"/>
        <source>residual</source>
        <translation>residuo</translation>
    </message>
</context>
</TS>
