# Lo que dice el experimento: mensajes en la franja, notas bajo los campos, errores.

number-not-a-number = no es un número
discs-count = { $count ->
    [one] 1 disco
   *[other] { $count } discos
}

## Recuentos y lecciones
count-line = choques: { $pairs } entre discos
count-line-walls = choques: { $pairs } entre discos · { $walls } con paredes
pi-result = { $count } choques: π ≈ { $pi }
pi-count = { $count ->
    [one] 1 choque
   *[other] { $count } choques
}

## Lo que un método no puede prometer
warning-verlet = verlet: los choques pierden energía; no se respeta la restitución e = { $restitution }
warning-seed = seed: los discos rápidos pueden atravesarse
warning-substeps = los discos rápidos pueden atravesarse: el más rápido avanza { $radii }× su radio en un paso pequeño ({ $substeps ->
    [one] 1 subpaso
   *[other] { $substeps } subpasos
} por paso; más subpasos, en Más, lo evitan)
warning-stall = { $method }: demasiados choques a la vez, así que el tiempo se ha detenido. Deshacer quita el cambio que lo causó; para seguir así, elige el método impulse (en Más)

## Escenas y archivos
file-cannot-create = no se puede crear { $folder }: { $error }
file-cannot-write = no se puede escribir { $file }: { $error }
scene-cannot-open = No se puede abrir { $file }: { $error }
scene-opened = Se abrió { $name }
scene-opened-undo = Se abrió { $name }. { $undo } recupera { $previous } tal como lo dejó
scene-kept = { $error } (se mantiene la escena actual)
scene-not-found = No hay ningún archivo de escena { $name }, ni aquí ni en { $folder } (se mantiene la escena actual)
scene-reset = Escena reiniciada
scene-reset-edits = Escena reiniciada tal como se abrió, sin sus cambios: { $undo } los recupera
scene-back-to-setup = De vuelta a su montaje en t = { $time } s; { $reset } otra vez: la escena tal como se abrió
scene-cannot-reset = No se puede reiniciar: { $error }
scene-cleared = Discos quitados: arrastra sobre un espacio vacío para lanzar discos
scene-path-empty = Escribe primero la ruta de un archivo de escena
scene-downloaded = Se descargó { $file }
scene-saved = Se guardó { $file } en { $folder }
scene-saved-short = Se guardó { $file }
scene-saved-at = { $saved }, con los discos como están en t = { $time } s
scene-renamed = La escena se llama ahora { $name }
scene-name-empty = Un nombre necesita una letra o un dígito
scene-not-saved = No se guardó: { $error }
screenshot-saved = Se guardó la captura: { $file }
screenshot-downloaded = Se descargó la captura: { $file }
screenshot-not-saved = No se guardó la captura: { $error }
scene-shared = La dirección de la página abre ahora esta escena: cópiala de la barra de direcciones y envíala
scene-not-shared = No se compartió: { $error }
undone = Deshecho: { $what } (Ctrl+Mayús+Z o Ctrl+Y lo rehace)
nothing-to-undo = Nada que deshacer
redone = Rehecho: { $what }
nothing-to-redo = Nada que rehacer

## Lo que nombra Deshacer
edit-open-scene = abrir una escena
edit-reset = reiniciar
edit-rename = nombre de la escena
edit-clear = quitar los discos
edit-restitution = restitución
edit-wall-restitution = restitución en las paredes
edit-roughness = rugosidad
edit-wall-roughness = rugosidad en las paredes
edit-friction = rozamiento
edit-gravity = gravedad
edit-edges = bordes
edit-method = método
edit-broad-phase = fase amplia
edit-substeps = subpasos
edit-disc = editar un disco
edit-delete = borrar
edit-launch = lanzar un disco nuevo
edit-add-disc = añadir un disco
edit-fling = lanzar un disco
edit-aim = fijar una velocidad
no-room = Aquí no hay espacio para un disco nuevo

## Ajustes cambiados con una tecla
law-restitution = Restitución e
law-wall-restitution = Restitución en las paredes
law-roughness = Rugosidad β
law-wall-roughness = Rugosidad β en las paredes
time-scale = Escala de tiempo ×{ $scale }
gravity-now = Gravedad { $gravity }
method-now = Método: { $method }
broad-phase-now = Fase amplia: { $broad }
substeps-now = Subpasos: { $substeps }
new-disc-radius = Discos nuevos: radio { $radius }
new-disc-mass = Discos nuevos: masa { $mass }
palette-safe = Discos con paleta apta para daltónicos (Okabe-Ito, según el número de disco)
palette-scene = Discos con los colores de la escena
text-size = Tamaño del texto ×{ $scale }
com-view-off = Vista del centro de masas desactivada: velocidades vistas desde la caja
com-view-on = Vista del centro de masas: moviéndose con el centro de masas a { $velocity }; Z otra vez para salir

## Tiempo: siguiente choque, rebobinar, exportar
separated = El método exact necesita los discos separados: separó { $pairs ->
    [one] 1 par de discos solapados
   *[other] { $pairs } pares de discos solapados
}
separated-raised = El método exact necesita los discos separados: separó { $pairs ->
    [one] 1 par de discos solapados
   *[other] { $pairs } pares de discos solapados
}, lo que aumentó la energía en { $energy }
separated-lowered = El método exact necesita los discos separados: separó { $pairs ->
    [one] 1 par de discos solapados
   *[other] { $pairs } pares de discos solapados
}, lo que redujo la energía en { $energy }
next-collision-pair = Discos { $a } y { $b }, t = { $time }: { $momentum_kept ->
    [yes] la cantidad de movimiento total no cambió
   *[no] la cantidad de movimiento total cambió en { $momentum }
}, { $energy_change ->
    [same] la energía cinética no cambió
    [less] la energía cinética bajó { $energy }
   *[more] la energía cinética subió { $energy }
}
next-collision-wall = El disco { $disc } chocó con la pared { $wall ->
    [left] izquierda
    [right] derecha
    [bottom] inferior
   *[top] superior
}, t = { $time }: la pared lo empujó con { $impulse }; { $energy_change ->
    [same] su energía cinética no cambió
    [less] su energía cinética bajó { $energy }
   *[more] su energía cinética subió { $energy }
}
next-collision-verlet = Los discos chocaron en t = { $time }; verlet separa las posiciones, así que no tiene un antes y un después de un choque que mostrar: el registro no tiene fila para él
stepped = { $steps ->
    [one] Un paso
   *[other] { $steps } pasos
} de { $dt }: t = { $time }
next-collision-none = Ningún choque en { $limit }
next-collision-at-once = { $impacts } impactos en el mismo instante, todos en la pestaña Choques. { $first }
rewound-to = Rebobinado a t = { $time } s (grabado: de { $oldest } a { $newest } s); Espacio reanuda desde aquí
rewound-newest = En el momento grabado más reciente, t = { $time } s; Espacio sigue desde aquí
nothing-recorded = Aún no hay nada grabado
exported-downloaded = Se descargaron los totales, discos, choques e impactos en paredes como archivos CSV
exported = Se exportaron los totales, discos, choques e impactos en paredes a { $folder }/
not-exported = No se exportó a { $folder }: { $error }
wall-name = { $wall ->
    [left] pared izquierda
    [right] pared derecha
    [bottom] pared inferior
   *[top] pared superior
}

## Editar un disco
edit-type-a-number = { $name }: escribe un número
edit-not-a-number = { $name }: “{ $text }” no es un número
edit-ambiguous-number = { $name }: “{ $text }” puede ser { $decimal } o { $grouped }; escribe el que quieres decir
edit-not-finite = { $name }: debe ser un número finito
edit-speed-negative = La rapidez no puede ser negativa: escribe la dirección contraria
edit-not-positive = { $name }: debe ser mayor que 0
edit-radius-too-large = aquí el radio debe ser como máximo { $radius } m
edit-out-of-range = { $name }: debe estar entre { $lo } y { $hi }
edit-too-fast = la rapidez debe ser como máximo 10⁸ m/s
slider-out-of-range = { $typed } está fuera del intervalo de { $low } a { $high }: queda en { $value }
slider-sign-dropped = { $typed } se lee como { $value }: el nombre ya indica la dirección
edit-across-the-line = aquí los discos se mueven sobre una recta: { $name } debe ser 0
edit-nothing-changed = No cambió nada: escribe primero un valor nuevo
edit-pending = Escrito, aún sin aplicar: Intro o Aplicar
edit-applied = Aplicado al disco { $disc }
edit-applied-table = Disco { $disc }: { $values }
edit-refused-table = Disco { $disc }: { $error }; no cambió nada
edit-mass-overlaps = con { $mass } kg el disco tendría { $size } m de radio (el tamaño sigue a la masa) y se solaparía con el disco { $disc }
edit-mass-crosses-wall = con { $mass } kg el disco tendría { $size } m de radio (el tamaño sigue a la masa) y atravesaría una pared
edit-position-off-the-line = aquí los discos se mueven sobre una recta: { $name } se queda en { $value } m
edit-position-crosses-wall = en { $at } el disco atravesaría una pared
edit-position-overlaps = en { $at } el disco se solaparía con el disco { $disc }
edit-radius-crosses-wall = con { $radius } m de radio el disco atravesaría una pared
edit-radius-overlaps = con { $radius } m de radio el disco se solaparía con el disco { $disc }

## Recuperación
recovery-unreadable-moved = Un archivo de recuperación ilegible se movió a { $file }: { $error }
recovery-unreadable-kept = No se pudo mover un archivo de recuperación ilegible: { $error }
autosave-failed = Falló el guardado automático en { $place }: { $error }
browser-storage = el almacenamiento del navegador
origin-recovered = recuperado de { $file }
origin-kept = tu último experimento, guardado por este navegador
recovery-kept-in = Sesión anterior guardada en { $file }
recovery-restored = Se restauró { $name }, en pausa donde quedó: Espacio la pone en marcha
recovery-not-set-aside = No se pudo dejar aparte la sesión anterior: { $error }
kept-not-set-aside = No se pudo dejar aparte tu último experimento: { $error }
recovery-question-browser = Este navegador guardó tu último experimento, { $name } ({ $discs ->
    [one] 1 disco
   *[other] { $discs } discos
}). ¿Restaurarlo o dejarlo aparte?
recovery-question = La última sesión terminó con cambios sin guardar. ¿Restaurar su escena, { $name } ({ $discs ->
    [one] 1 disco
   *[other] { $discs } discos
}), o dejarla aparte?
sandbox-cannot-open = No se puede abrir el experimento: { $error }
link-too-many-discs = { $discs } discos son demasiados para un enlace (como máximo { $most }): guarda la escena en un archivo
link-damaged = la escena del enlace está dañada ({ $error })
settings-unreadable = No se pudieron leer los ajustes de { $file } ({ $error }): se usan los valores predeterminados
settings-not-saved = Los ajustes no se guardaron en { $place }: { $error }
aimed = Disco { $disc }: velocidad fijada en { $velocity }
aim-across-the-line = Aquí los discos se mueven sobre una recta: { $keys } apuntan a lo largo de ella
key-left-right = Izquierda y Derecha
key-up-down = Arriba y Abajo
dropped-file = archivo soltado
dropped-not-text = { $name }: no es un archivo de texto
dropped-unreadable = { $name }: { $error }
dropped-empty = un archivo soltado sin contenido
link-cannot-open = No se puede abrir la escena de este enlace: { $error }
origin-default = escena predeterminada incorporada
origin-shared-link = el enlace compartido
