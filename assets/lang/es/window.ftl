# Las palabras de la ventana en español: paneles, barra superior, pestañas, pantalla de inicio.
# Todos los demás idiomas tienen los mismos mensajes con los mismos $valores.

this-language = Español
language-now = Idioma: { this-language }

## La barra superior
scene-untitled = Experimento libre
scene-edited-mark = (con cambios)
state-rewound = REBOBINADO
state-paused = EN PAUSA
state-running = EN MARCHA
state-stalled = ATASCADO
rewound-line = grabado: de { $oldest } a { $newest } s; Espacio reanuda
momentum-hover = cantidad de movimiento total de los discos
momentum-walls-push = p = { $momentum } (empujan las paredes)
momentum-walls-push-hover = empujan las paredes: la cantidad de movimiento de los discos solo cambia en las paredes; entre discos se conserva
energy-with-turning = Ec { $moving } + giro { $turning } = { $total }
energy-with-turning-hover = energía del movimiento, ½·m·v², más la del giro, ½·I·ω² con I = ½·m·r², sumadas para todos los discos
energy-line = Ec = { $energy }
energy-hover = energía cinética: la energía del movimiento, ½·m·v², sumada para todos los discos
count-hover = choques entre dos discos y de un disco contra una pared, contados por separado
com-view-line = vista del centro de masas: p = { $momentum }, Ec = { $energy }
energy-with-height = Ec + Ep = { $energy }
energy-with-height-hover = energía del movimiento (y del giro) más la energía potencial debida a la altura, que vale cero en el borde inferior de la caja
angular-momentum-hover = momento angular respecto a la esquina (0, 0), del movimiento y del giro: los choques entre discos lo conservan, las paredes lo cambian
resting-contacts = contactos en reposo: { $count }
resting-contacts-hover = discos apoyados unos sobre otros o sobre una pared: no se cuentan como choques
show-panels = Mostrar paneles
top-bar-more = … más
running-slower = simulando a { $rate }× el tiempo real
running-slower-many = simulando a { $rate }× el tiempo real: con menos discos iría más rápido
method-in-use = en uso: { $method } / { $broad }
method-in-use-auto = en uso: { $method } / { $broad } (auto: { $reason })

## Ventanas sobre el mundo
recovery-title = ¿Restaurar la última sesión?
recovery-waits = La simulación espera hasta que respondas.
recovery-restore = Restaurar (R)
recovery-set-aside = Dejar aparte (Esc)
help-title = Teclas y ratón
presets-title = Ejemplos
reopen-kept-hover = El experimento que este navegador guardó antes de que se abriera el enlace.
presets-press = Presiona la tecla o haz clic:

## La franja bajo el mundo
caption-edited = Antes de los cambios: { $caption }
caption-none = Arrastra sobre un espacio vacío para lanzar un disco; H muestra todas las teclas.

## Magnitudes, tal como las nombran los campos y las columnas
quantity-mass = masa
quantity-radius = radio
quantity-vx = v_x
quantity-vy = v_y
quantity-x = x
quantity-y = y
quantity-speed = rapidez |v|
quantity-direction = dirección
direction-hover = Grados desde la derecha, en sentido antihorario: 0 derecha, 90 arriba, 180 izquierda, −90 abajo

## Las pestañas del panel inferior
tab-totals = Totales
tab-collisions = Choques
tab-discs = Discos
tab-speeds = Rapidez
tab-momenta = Vectores p

## Las fichas de la pantalla de inicio
tile-head-on = Frontal (1D)
tile-glancing = Oblicuo (2D)
tile-inelastic = Inelástico
tile-pi-blocks = Bloques π
tile-gas = Un gas
tile-free-play = { scene-untitled }
tile-head-on-blurb = Dos discos se encuentran sobre una recta. ¿Es la cantidad de movimiento total la misma después?
tile-glancing-blurb = Un disco choca con otro sin darle en el centro. ¿Hacia dónde sale cada uno?
tile-inelastic-blurb = Discos que no rebotan del todo. ¿A dónde va la energía?
tile-pi-blocks-blurb = Un bloque ligero, uno pesado y una pared: cuenta los choques.
tile-gas-blurb = Muchos discos a la vez: ¿cómo se reparte la rapidez entre ellos?
tile-free-play-blurb = Lanza tus propios discos y cámbialo todo.
lesson-wall-pause = En pausa: el disco { $disc } chocó con la pared { $wall ->
    [left] izquierda
    [right] derecha
    [bottom] inferior
   *[top] superior
}, y el empuje de una pared cambia la cantidad de movimiento total. { $key } sigue.

## La pantalla de inicio
close = Cerrar
start-title = ¿Qué te gustaría explorar?
start-footer = Tab y Enter eligen una lección con el teclado. Esc conserva la escena que está abierta. El botón Lecciones de la barra superior vuelve a mostrar esta pantalla.

## El panel lateral
controls-for = Los controles para «{ $lesson }».
selected-disc-numbered = Disco seleccionado ({ $disc })
section-more = Más
section-more-line = Para discos que giran y para comparar cómo hace los cálculos el programa.
play = Reproducir
pause = Pausa
colour-white = blanco
colour-pink = rosa
colour-amber-outlined = ámbar, con contorno
colour-black = negro
colour-purple = morado
colour-brown-outlined = marrón, con contorno
show-velocity = flechas de velocidad ({ $colour })
show-velocity-hover = dónde estará cada disco dentro de medio segundo
show-momentum = flechas de cantidad de movimiento ({ $colour })
show-momentum-hover = cantidad de movimiento p = m·v: masa por velocidad
show-delta-p = Δp tras un choque ({ $colour })
show-delta-p-hover = el cambio de la cantidad de movimiento de cada disco, durante un segundo después de cada choque entre discos (en escenas de hasta { $most } discos: en un gas taparían los discos)
readouts-none = ninguno
readouts-selected = disco seleccionado
readouts-all = todos los discos
readouts-label = valores junto a
readouts-hover = donde las etiquetas se taparían unas a otras, algunos discos se quedan sin ellas; en la vista se indica cuántos
show-center-of-mass = centro de masas
show-center-of-mass-hover = el punto de equilibrio de todos los discos y su velocidad
show-safe-palette = apto para daltónicos
show-com-view = vista del centro de masas
show-com-view-hover = la vista se mueve con el centro de masas y las flechas muestran las velocidades relativas a él; el experimento no cambia

## La sección Choques
restitution-label = Rebote entre discos, coeficiente de restitución e
restitution-scale = 1: rebotan del todo, 0: siguen juntos a lo largo de la línea de impacto
restitution-hover = Qué parte de su rapidez de acercamiento conservan dos discos al separarse, a lo largo de la recta que une sus centros: 1 toda, 0 nada (el movimiento lateral se conserva)
wall-restitution-label = Rebote en las paredes, coeficiente de restitución e
wall-restitution-hover = Qué parte de su rapidez hacia una pared conserva un disco al alejarse de ella: 1 toda, 0 nada
gravity-label = Gravedad, hacia abajo
gravity-hover = con qué fuerza se tira de los discos hacia abajo; { $gravity } m/s² en la Tierra
edges-label = bordes
edges-box = caja
edges-open = abiertos
edges-periodic = periódicos
edges-hover = Qué hacen los lados de la caja: caja, paredes en las que rebotan los discos; abiertos, sin paredes (los discos se escapan); periódicos, un disco que sale por un lado vuelve a entrar por el opuesto
time-scale-label = escala de tiempo
time-scale-hover = segundos simulados por segundo real: por debajo de 1 es cámara lenta
roughness-hover = Cuánto se agarran los bordes en contacto durante un choque, de modo que los discos empiecen o dejen de girar: −1 lisos (sin agarre, no se transmite giro), 0 su deslizamiento se detiene, 1 perfectamente rugosos (el deslizamiento se invierte y no se pierde energía)
roughness-label = Agarre entre discos, rugosidad β (−1 lisos … 1 rugosos)
wall-roughness-label = Agarre en las paredes, rugosidad β
friction-on-label = El rozamiento μ limita el agarre
friction-hover = Rozamiento: el empuje de lado donde se tocan los discos es como máximo μ veces el empuje de frente, así que un deslizamiento rápido solo se frena; además hace que los discos apoyados unos sobre otros se froten. Desactivado: sin límite.
friction-label = Rozamiento μ

## Discos nuevos y el disco seleccionado
new-discs-line = Arrastra sobre un espacio vacío para lanzar uno.
size-follows-mass = el tamaño sigue a la masa (misma densidad)
size-follows-mass-hover = un disco de 1 kg tiene 0,4 m de radio; el radio crece como √m, para los discos nuevos y al cambiar la masa
radius-from-mass = Radio { $radius } (según la masa)
radius-label = Radio
mass-label = Masa
new-mass-hover = Los discos nuevos pesan de 0,01 a 100 kg: un deslizador necesita dos extremos, y estos llegan a razones de masas de 10 000 a 1. Un disco ya en la caja admite cualquier masa: escríbala en la pestaña Discos o en Disco seleccionado
selected-none = Ninguno: haz clic en un disco para seleccionarlo.
apply = Aplicar
apply-hover = Intro en un campo

## Las secciones Escena y Vista
preset-label = ejemplo
preset-choose = abrir un ejemplo…
scene-drop = Para abrir un archivo de escena, suéltalo sobre la página.
scene-file-label = Archivo de escena:
scene-file-hint = p. ej. assets/scenes/preset-8-gas.toml
scene-name-label = Nombre:
scene-name-hover = El nombre de la escena: encabeza la ventana y da nombre a los archivos en que se guarda. Escriba uno y pulse Intro.
open = Abrir
open-hover = Intro en el campo
share = Compartir enlace
share-hover = pone esta escena en la dirección de la página, para enviarla como enlace
saves-download = Lo que guardes, exportes o captures se descarga como archivo.
saves-go-to = Lo guardado va a { $folder }/
ui-scale-label = Tamaño del texto y los controles
theme-light = Tema claro
theme-dark = Tema oscuro
theme-hover = en una sala muy iluminada conviene el claro
language-label = idioma
language-hover = el idioma de la ventana; los números lo siguen (2,5 en español, 2.5 en inglés)

## Detalles (en Más)
method-label = método
method-hover = Cómo calcula el programa los choques: auto elige; exact encuentra cada uno en su instante; los demás avanzan en pequeños pasos de tiempo fijos y corrigen los solapamientos
broad-phase-label = fase amplia
broad-phase-hover = Cómo encuentra el programa qué discos están cerca unos de otros antes de examinarlos de cerca: solo cambia la rapidez del cálculo, no el resultado
substeps-label = subpasos
substeps-hover = En cuántos pasos más pequeños se divide cada paso de tiempo: más es más preciso y más lento
dt-line = paso de tiempo dt = { $dt }
dt-hover = cuánto tiempo simulado abarca un paso del programa
step-time-line = tiempo por paso { $time } (mediana), { $steps } pasos en el último fotograma
fps-line = { $fps } fotogramas por segundo
sim-rate-line = segundos simulados por segundo real: { $rate }
page-title = Impulse: choques de discos

## La pestaña Totales
symbol-ke = Ec
totals-energy = energía
totals-kinetic-energy = energía cinética
totals-momentum = cantidad de movimiento
totals-angular-momentum = momento angular L
totals-change = Cambio desde t = { $since }: { $p_name } { $momentum }, { $l_name } { $angular }, { $e_name } { $energy }
totals-change-line = Cambio desde t = { $since }: { $p_name } { $momentum }, { $e_name } { $energy }
totals-change-wrapping = Cambio desde t = { $since }: { $p_name } { $momentum }, { $e_name } { $energy }; { $l_name } no se conserva cuando los discos pasan de un borde al opuesto
totals-none = Aún no hay registro: pon en marcha la simulación.
totals-rotational-ke = Ec de rotación
totals-ke-sum = Ec + Ec de rotación
totals-sum = suma
totals-hover = p: cantidad de movimiento, masa por velocidad, sumada para todos los discos. L: momento angular, cuánto giran los discos alrededor de la esquina inferior izquierda de la caja (0, 0) y sobre sí mismos. Los choques entre discos conservan ambas; los empujes de las paredes las cambian (las líneas discontinuas marcan dónde). E: la energía del movimiento (Ec) y, con discos que giran, también la del giro.
totals-hover-wrapping = En este mundo los bordes se unen: un disco que sale por un lado vuelve a entrar por el opuesto. Su cantidad de movimiento no cambia, pero su posición respecto a (0, 0) salta, así que L salta también; no es un fallo de los choques.
totals-walls-push = empuje de las paredes
axis-time = tiempo (s)
axis-energy = energía (J)

## La pestaña Choques (el registro)
ledger-pair = discos { $a } y { $b }
ledger-wall = disco { $disc } y la pared { $wall ->
    [left] izquierda
    [right] derecha
    [bottom] inferior
   *[top] superior
}
ledger-empty = Ninguno todavía. Siguiente choque (J) avanza hasta el próximo, entre discos o con una pared, y se detiene en el instante del impacto.
ledger-last = { $count ->
    [one] El último
   *[other] Los últimos { $count }, del más reciente al más antiguo
}
ledger-time-hover = cuándo ocurrió
ledger-what = qué
ledger-what-hover = qué discos, o qué disco y qué pared
ledger-dp-hover = el cambio de la cantidad de movimiento total de los discos que intervienen: cero entre discos, el empuje de la pared en una pared
ledger-dke-hover = el cambio de su energía cinética, la energía del movimiento: cero en un choque elástico, menor que cero cuando se pierde parte de ella
ledger-newest = { $who }, { $when }
ledger-disc-p = disco { $disc }: p (kg·m/s)
ledger-disc-ke = disco { $disc }: { $ke } (J)
ledger-disc-v = disco { $disc }: v { $part } (m/s)
ledger-both-p = los dos discos: p (kg·m/s)
ledger-both-ke = los dos discos: { $ke } (J)
ledger-along-impact = a lo largo de la línea de impacto
ledger-across-impact = perpendicular a ella
ledger-away-from-wall = alejándose de la pared
ledger-along-wall = a lo largo de la pared
ledger-wall-push = el empuje de la pared, Δp (kg·m/s)
ledger-before = antes
ledger-after = después
ledger-detail-hover = La línea de impacto pasa por los centros de los dos discos (o va de la pared al disco) en el instante en que se tocan; en un choque sin agarre solo cambia la velocidad a lo largo de ella. A lo largo de ella, el signo más apunta del disco nombrado primero hacia el otro (en una pared, alejándose de la pared).

## La pestaña Discos
table-spin = giro ω
    (rad/s)
table-spin-hover = lo rápido que gira el disco: radianes por segundo, positivo en sentido antihorario
table-rotational-ke-hover = la energía de su giro, ½·I·ω² con I = ½·m·r²
table-angular-momentum-hover = momento angular, cuánto gira el disco alrededor de la esquina inferior izquierda de la caja (0, 0) y sobre sí mismo: m·(x·v_y − y·v_x) de su movimiento más I·ω de su giro
table-disc = disco
table-line = Haz clic en una masa o una velocidad para cambiarla; Intro aplica, Esc cancela.
table-no-discs = No hay discos: arrastra sobre un espacio vacío para lanzar uno.

## La fila de pestañas del panel y la pestaña Vectores p
dock-hide = Ocultar
dock-show = Mostrar
dock-no-room = aquí no hay espacio: L oculta el panel lateral
dock-no-room-drawer = aquí no hay espacio con este tamaño de texto: { $key } lo cambia
momenta-no-discs = No hay discos.
momenta-too-many = Total: { $total }. Demasiados discos ({ $count }) para dibujar una flecha para cada uno; el diagrama dibuja hasta { $most }.
momenta-line = Total (flecha gruesa): { $total }; la cantidad de movimiento de cada disco, una flecha a continuación de otra, en su color
momenta-hover = { $line }; p_x y p_y se dibujan a la misma escala, así que los ángulos son reales
disc-numbered = disco { $disc }
readout-disc = { $disc }:

## La pestaña Rapidez
speeds-axis-rim = rapidez, rapidez del borde (m/s)
speeds-axis = rapidez (m/s)
speeds-name = rapidez |v|
speeds-discs = discos
speeds-count = discos en cada barra
# Hovering a bar: how many discs it counts, and its speeds.
speeds-bar = { $count ->
    [one] un disco
   *[other] { $count } discos
} de { $low } a { $high } m/s
maxwell-boltzmann = Maxwell–Boltzmann
rim-speeds = rapidez del borde |ω|·r
rim-speeds-equal = rapidez del borde, reparto equitativo
speeds-too-few = Muy pocos discos en movimiento para una distribución: prueba el ejemplo 8, un gas.
speeds-line = Barras: cuántos discos se mueven con cada rapidez. Curva: cómo se reparte en un gas en equilibrio (Maxwell–Boltzmann).
speeds-line-few = Barras: cuántos discos se mueven con cada rapidez. La curva de un gas (Maxwell–Boltzmann) aparece desde { $n } discos: prueba el ejemplo 8.
speeds-hover = { $line }
    La curva muestra cómo quedan repartidas las rapideces cuando los choques ya han repartido la energía al azar, para discos con esta energía media cada uno: kT = Ec/N = { $kt } (la temperatura, en energía por disco).
speeds-rim-meaning = Barras: cuántos discos se mueven (o mueven su borde al girar) con cada rapidez. Curvas: cómo se reparten cuando la energía está repartida por igual, a la temperatura kT = Ec/N = { $kt }: Maxwell–Boltzmann para la rapidez (línea continua) y para la rapidez del borde (discontinua).
rim-speeds-hover = Lo rápido que se mueve el borde de cada disco al girar: su giro ω por su radio r.
    { $meaning }
shares-energy = energía:
shares-energy-hover = la parte de la energía (%) que hay en el movimiento y en el giro
shares-moving = movimiento
shares-turning = giro
shares-one-third = un tercio
shares-one-third-hover = Si se reparte por igual entre las tres formas en que un disco guarda energía (moverse en x, moverse en y, girar), al giro le toca un tercio
shares-moving-ke = movimiento (Ec)
shares-turning-ke = giro (Ec de rotación)

## En el mundo
readout-spin = giro ω = { $spin }   Ec de rotación = { $energy }
readout-angular-momentum = momento angular respecto a (0, 0): L = { $angular }
readouts-culled = { $wanted ->
    [one] no hay espacio aquí para los valores del disco elegido (acerca la vista con la rueda)
   *[other] valores junto a { $shown } de { $wanted } discos: no hay espacio para el resto (acerca la vista con la rueda)
}
launch-no-room = aquí no hay espacio
gas-name = Gas de { $count } discos
gas-description = { $count } discos iguales que ocupan el 30 % de una caja periódica (--gas { $count })
tab-edge = Altura de la pestaña
tab-edge-hover = Arrastre para hacer la pestaña más alta o más baja. Con el teclado (Tab hasta aquí): las flechas una fila, Inicio la más alta, Fin la más baja, Intro su altura propia; o doble clic.
