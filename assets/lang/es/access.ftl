# Acceso con el teclado, el sonido y los lectores de pantalla: lo que dice la ventana sobre ellos.

select-no-discs = No hay discos que seleccionar: Intro pone uno en el centro.
selected-disc-said = Disco { $disc } de { $discs } seleccionado: { $mass }; velocidad { $velocity }
launched-at-centre = Disco { $disc } en reposo en el centro: con la simulación en pausa, las flechas fijan su velocidad
launched-near-centre = Disco { $disc } en reposo junto al disco { $beside } (el centro estaba ocupado): con la simulación en pausa, las flechas fijan su velocidad

## El recorrido con el teclado (líneas de la ayuda)
keys-focus = Tab / Mayús+Tab
help-focus = recorrer los controles en el orden de lectura; Espacio o Intro activa el control, las flechas mueven un deslizador, eligen en una lista desplegable o desplazan una lista (también Re Pág, Av Pág, Inicio y Fin); Esc o un clic en el mundo reactivan los atajos de teclado
keys-regions = F6 / Mayús+F6
help-regions = saltar a la parte siguiente de la ventana: los controles (se abren si están cerrados; primero la masa del disco elegido), las pestañas, la barra superior y de vuelta al mundo; después Tab avanza dentro de ella
keys-aim-keys = Flechas, en pausa, con un disco seleccionado
help-aim-keys = fijar su velocidad: ±0,1 m/s por pulsación (Mayús: ±1 m/s)
keys-select-next = Q / Mayús+Q
help-select-next = seleccionar el disco siguiente / el anterior
keys-launch-centre = Intro
help-launch-centre = un disco nuevo en reposo en el centro de la vista, ya seleccionado; en una lección que espera con su pregunta, la pone en marcha
keys-in-panels = Las teclas manejan ahora los controles: Esc o un clic en el mundo reactivan los atajos de teclado.
keys-in-panels-short = Esc: reactivar los atajos
keys-tab-edge = Altura: flechas una fila, Inicio la más alta, Fin la más baja, Intro la suya. Esc: reactivar los atajos.
keys-tab-edge-short = Flechas, Inicio, Fin: altura
keys-after-field = Espacio, N y J actúan sobre la simulación; los demás atajos esperan: Esc o un clic en el mundo los reactivan.

## Sonido
keys-sound = F8
help-sound = activar / desactivar el sonido: un clic en cada impacto, más fuerte cuanto más violento es el choque, más agudo entre discos que contra una pared (en silencio en pausa o a más de ×2)
label-toggle-sound = Sonido
sound-on = Sonido activado: un clic en cada impacto (en silencio en pausa o a más de ×2)
sound-off = Sonido desactivado

## Lo que se le dice a un lector de pantalla (la región dinámica del navegador, la pestaña Narración)
said-pair = El disco { $a } chocó con el disco { $b }: cantidad de movimiento total antes { $before }, después { $after }
said-wall = El disco { $disc } chocó con la pared { $wall ->
    [left] izquierda
    [right] derecha
    [bottom] inferior
   *[top] superior
 }: rapidez antes { $before }, después { $after }
place-middle = en el centro
place-left = a la izquierda
place-right = a la derecha
place-bottom = abajo
place-top = arriba
place-bottom-left = abajo a la izquierda
place-bottom-right = abajo a la derecha
place-top-left = arriba a la izquierda
place-top-right = arriba a la derecha
motion-rest = en reposo
motion-moving = moviéndose { $direction } a { $speed }
direction-right = hacia la derecha
direction-up-right = hacia arriba y a la derecha
direction-up = hacia arriba
direction-up-left = hacia arriba y a la izquierda
direction-left = hacia la izquierda
direction-down-left = hacia abajo y a la izquierda
direction-down = hacia abajo
direction-down-right = hacia abajo y a la derecha
describe-box = { $discs ->
    [one] Un disco
   *[other] { $discs } discos
 } en { $edges ->
    [open] un espacio sin paredes de { $width } por { $height } metros.
    [periodic] un espacio de { $width } por { $height } metros cuyos lados se unen (un disco que sale por un lado vuelve a entrar por el opuesto).
   *[box] una caja de { $width } por { $height } metros.
 }
describe-gravity = La gravedad tira hacia abajo, con una aceleración de { $gravity }.
describe-no-gravity = Sin gravedad.
describe-restitution = Coeficiente de restitución entre discos: { $restitution }.
describe-disc = Disco { $disc }: { $mass }; { $place }; { $motion }.
describe-more = { $more ->
    [one] Y un disco más
   *[other] Y { $more } discos más
 }; la rapidez media es { $speed }.
describe-totals = { $state ->
    [paused] En pausa
   *[running] En marcha
 } en t = { $time }; cantidad de movimiento total { $momentum }, energía cinética { $energy }.
tab-words = Narración
# On the desktop; in the browser, where a screen reader reads the page.
words-line = Lo que ocurre, contado en palabras, lo más reciente primero: como mucho un choque cada { $gap } s (la pestaña { tab-collisions } los lista todos).
words-line-web = Lo que ocurre, contado en palabras, lo más reciente primero, como lo lee un lector de pantalla: como mucho un choque cada { $gap } s (la pestaña { tab-collisions } los lista todos).
words-none = Todavía no se ha dicho nada.
label-describe = Describir la escena
mirror-title = Impulse: controles para el teclado y los lectores de pantalla
mirror-canvas = Impulse, la simulación: { $keys } muestra las teclas
mirror-said = Lo que ocurre
